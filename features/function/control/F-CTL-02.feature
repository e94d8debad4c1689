@item:F-CTL-02 @profile:crh2
Feature: F-CTL-02 Brake command transmission with a rescue connection
  Requirements: NET-08 (primary), CMD-02, CMD-04, TST-04, TST-05.
  The function-level form of the routine item R-CTL-02: with two sets coupled (NET-08), the brake handle
  of the rescuing cab 16 commands every BCU of both sets: over the coupled ring (path 1, full resolution,
  40 ms) even when the rescued set's own cab is dead, and over the coupled self-diagnostic line (path 3,
  A/B steps) when the ring is down. The rescue transition device itself is not modelled. The coupled train
  runs: at standstill a product may hold a brake of its own above the handle's step (docs/decisions.md,
  "Standstill holding brake (crh2)").

  Background:
    Given two 8-car CRH2 train sets coupled together
    And the driver has inserted the key in cab 16
    And the train has been powered up for 1000 ms
    And the train runs at 30 km/h

  @req:NET-08 @req:CMD-02 @req:TST-04 @req:TST-05
  Scenario Outline: F-CTL-02 Brake step <step> from the rescuing cab 16 reaches all 16 BCUs over the ring
    When the driver moves the brake handle of cab 16 to step <step>
    And 150 ms pass
    Then every BCU receives brake step <step> over path 1 within 40 ms
    And from 40 ms on every BCU receives brake step <step>
    And only "car16.CCU.sys1" puts commands on the ring

    Examples:
      | step |
      | 2    |
      | 5    |
      | 7    |
      | 8    |

  @req:NET-08 @req:CMD-02 @req:TST-04 @req:TST-05
  Scenario: F-CTL-02 The brake command reaches the rescued set while its own cab 1 is dead
    When the supply "car1.CCU.sys1" is switched off
    And the supply "car1.CCU.sys2" is switched off
    And 600 ms pass
    And the driver moves the brake handle of cab 16 to step 6
    And 150 ms pass
    Then every BCU receives brake step 6 over path 1 within 40 ms
    And from 40 ms on every BCU receives brake step 6
    When the driver moves the brake handle of cab 16 to step 0
    And 150 ms pass
    Then every BCU receives brake step 0 over path 1 within 40 ms

  @req:NET-08 @req:CMD-04 @req:TST-04 @req:TST-05 @tentative
  Scenario Outline: F-CTL-02 With the ring down brake step <step> crosses the coupler on the self-diagnostic line
    Given every ring link is cut
    When 300 ms pass
    And the driver moves the brake handle of cab 16 to step <step>
    And 100 ms pass
    Then every BCU receives brake step "<ab>" over path 3 within 40 ms
    And the BCU of car 1 receives brake step "<ab>" over path 3 within 40 ms
    And the CI and BCU of car 2 receive nothing over path 1

    Examples:
      | step | ab |
      | 3    | A  |
      | 7    | B  |
