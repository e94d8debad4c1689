@item:F-DSP-04 @profile:crh2
Feature: F-DSP-04 A monitor whose CCU system 1 has failed is fed by system 2
  Requirements: RED-01 (primary), NET-02, TST-04.
  CCU systems 1 and 2 are independent, each with its own supply. A cab monitor normally takes its status
  data through system 1; when system 1's CPU3 fails, or its supply goes off, system 2 feeds the monitor,
  which keeps displaying the train and reports the silent system 1. With system 1's supply off its node
  drops out of the ring, the token turns back at the gap and a node beside the gap is heard up to
  200 ms apart (11 live nodes, 10 ms each, there and back), so that scenario allows 300 ms.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:RED-01 @req:TST-04
  Scenario Outline: F-DSP-04 With the CPU3 of car <cab> CCU system 1 failed its monitor still displays the speed
    Then the cab <cab> monitor is fed by "car<cab>.CCU.sys1"
    When board "car<cab>.CCU.sys1.CPU3" fails
    And 500 ms pass
    Then the cab <cab> monitor is fed by "car<cab>.CCU.sys2"
    When the train speed changes to 120 km/h
    And 150 ms pass
    Then the cab <cab> monitor displays "speed" between 119.5 and 120.5 within 150 ms

    Examples:
      | cab |
      | 1   |
      | 8   |

  @req:RED-01 @req:NET-02 @req:TST-04
  Scenario: F-DSP-04 The monitor fed by system 2 reports the silent system 1
    When board "car1.CCU.sys1.CPU3" fails
    And 1000 ms pass
    Then the cab 1 monitor shows "no status data from car1.CCU.sys1" and no other fault
    And the cab 8 monitor shows "no status data from car1.CCU.sys1" and no other fault

  @req:RED-01 @req:TST-04
  Scenario: F-DSP-04 With system 1's supply off the monitor fed by system 2 displays the running state
    When the supply "car1.CCU.sys1" is switched off
    And 1500 ms pass
    Then the cab 1 monitor is fed by "car1.CCU.sys2"
    When the driver moves the traction notch of cab 1 to 4
    And 300 ms pass
    Then the cab 1 monitor changes "traction notch" to "4" within 300 ms
    When the train speed changes to 90 km/h
    And 300 ms pass
    Then the cab 1 monitor displays "speed" between 89.5 and 90.5 within 300 ms
