@item:F-IDI-03 @profile:crh2
Feature: F-IDI-03 The RXC's digital outputs to CI and BCU carry only steps A and B
  Requirements: CMD-03 (primary), CMD-04, TST-04.
  When a car's MDM9 has failed, its RXC drives CI and BCU through digital outputs (path 2), which carry
  only traction steps A/B and brake steps A/B (CMD-03); the same outputs serve path 3 (CMD-04). The
  mapping is the project's (docs/decisions.md): notch 1-5 -> A, 6-10 -> B; brake step 1-4 -> A, 5-7 and
  emergency -> B; both edges of each step are tested. Path 2 is in use within 30 ms of a notch change
  (one 10 ms command interval, 15 ms on the ring, the 20 mA loop).

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:CMD-03 @req:TST-04 @tentative
  Scenario Outline: F-IDI-03 Traction notch <notch> leaves the RXC as step <step>
    When board "car3.LCU.MDM9" fails
    And the driver moves the traction notch of cab 1 to <notch>
    And 300 ms pass
    Then the CI and BCU of car 3 receive traction step "<step>" over path 2 within 30 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B
    And the CI and BCU of car 3 receive nothing over path 1
    And from 40 ms on every CI and BCU outside car 3 receives traction notch <notch> over path 1

    Examples:
      | notch | step |
      | 1     | A    |
      | 5     | A    |
      | 6     | B    |
      | 10    | B    |

  @req:CMD-03 @req:TST-04 @tentative
  Scenario Outline: F-IDI-03 Brake step <brake> leaves the RXC as step <step>
    When board "car4.LCU.MDM9" fails
    And the driver moves the brake handle of cab 1 to step <brake>
    And 300 ms pass
    Then the BCU of car 4 receives brake step "<step>" over path 2 within 30 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B

    Examples:
      | brake | step |
      | 1     | A    |
      | 4     | A    |
      | 5     | B    |
      | 7     | B    |
      | 8     | B    |

  @req:CMD-04 @req:TST-04 @tentative
  Scenario: F-IDI-03 With the ring down, the self-diagnostic line drives the same outputs
    Given the traction notch of cab 1 is at 4
    When every ring link is cut
    And 500 ms pass
    Then every CI and BCU receives traction step "A" over path 3 within 100 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B
