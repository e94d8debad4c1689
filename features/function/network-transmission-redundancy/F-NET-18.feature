@item:F-NET-18 @profile:crh2 @req:TST-04
Feature: F-NET-18 Cab indicator lamps driven by both TXCs
  Requirements: RED-03 (primary), TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And the train has been powered up for 1000 ms

  @req:RED-03
  Scenario Outline: F-NET-18 One TXC failing leaves the lamps right (<txc>)
    When board "<txc>" fails
    And 200 ms pass
    Then the "traction" lamp of cab 1 never went dark
    And the "MCR" lamp of cab 1 never went dark
    And the "brake" lamp of cab 1 is dark

    Examples:
      | txc                |
      | car1.CCU.sys1.TXC  |
      | car1.CCU.sys2.TXC  |

  @req:RED-03
  Scenario: F-NET-18 The lamps follow the desk
    When the driver moves the traction notch of cab 1 to 0
    And the driver moves the brake handle of cab 1 to step 3
    And 50 ms pass
    Then the "traction" lamp of cab 1 is dark
    And the "brake" lamp of cab 1 is lit
