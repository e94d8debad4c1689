@item:F-DSP-01 @profile:crh2
Feature: F-DSP-01 Status data of every node reaches both cab monitors
  Requirements: PRO-02 (primary), TST-04.
  Every node broadcasts its status data under token control once per 120 ms status cycle, and both cab
  monitors take what they display from it, whichever cab has the key. The function test allows the display
  bound of 150 ms (docs/decisions.md, "Display") between two status frames of any node at either monitor.

  @req:PRO-02 @req:TST-04
  Scenario Outline: F-DSP-01 With the key in cab <cab> both monitors hear every node at least every 150 ms
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab <cab>
    And the train has been powered up for 1000 ms
    When 2 s pass
    Then the cab 1 monitor receives status data from every other node at least every 150 ms
    And the cab 8 monitor receives status data from every other node at least every 150 ms
    And the cab 1 monitor shows no faults
    And the cab 8 monitor shows no faults

    Examples:
      | cab |
      | 1   |
      | 8   |

  @req:PRO-02 @req:TST-04
  Scenario: F-DSP-01 Without a key in either cab both monitors still hear every node
    Given an 8-car CRH2 train set
    And the train has been powered up for 1000 ms
    When 2 s pass
    Then the cab 1 monitor receives status data from every other node at least every 150 ms
    And the cab 8 monitor receives status data from every other node at least every 150 ms
    And the cab 1 monitor shows no faults

  @req:PRO-02 @req:TST-04
  Scenario: F-DSP-01 Status data keeps both monitors up to date while the train runs
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms
    When the train speed changes to 80 km/h
    And 150 ms pass
    Then the cab 1 monitor displays "speed" between 79.5 and 80.5 within 150 ms
    And the cab 8 monitor displays "speed" between 79.5 and 80.5 within 150 ms
    When the main air pipe pressure changes to 700 kPa
    And 150 ms pass
    Then the cab 1 monitor displays "main pipe pressure" between 699 and 701 within 150 ms
    And the cab 8 monitor displays "main pipe pressure" between 699 and 701 within 150 ms

  @req:PRO-02 @req:TST-04
  Scenario: F-DSP-01 A system silent since power-up is shown silent, and no longer within 150 ms of its repair
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And board "car1.CCU.sys1.CPU3" has failed
    And the train has been powered up for 1000 ms
    Then the cab 1 monitor shows "no status data from car1.CCU.sys1" and no other fault
    When board "car1.CCU.sys1.CPU3" is repaired
    And the cab 1 monitor is watched for 300 ms
    Then the cab 1 monitor stopped showing "no status data from car1.CCU.sys1" within 150 ms
    And the cab 1 monitor never showed a fault but "no status data from car1.CCU.sys1"
