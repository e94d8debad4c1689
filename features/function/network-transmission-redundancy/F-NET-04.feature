@item:F-NET-04 @profile:crh2 @req:TST-04
Feature: F-NET-04 Whole ring down: the self-diagnostic line carries control commands only
  Requirements: NET-04 (primary), CMD-04, TST-04.
  With every ring span cut, traction and brake commands still reach every car over the self-diagnostic
  line (path 3), but no status data and no block data travel on it.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 8
    And the train has been powered up for 1000 ms

  @req:NET-04 @req:CMD-04
  Scenario: F-NET-04 Commands keep reaching every car over the self-diagnostic line
    When every ring link is cut
    And 500 ms pass
    Then every CI and BCU receives traction step "B" over path 3 within 100 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B

  @req:NET-04
  Scenario: F-NET-04 No status data reaches the cab monitor without the ring
    When every ring link is cut
    And 2 s pass
    Then the cab 1 monitor receives no status data from other nodes after 5 ms
    And the cab 8 monitor receives no status data from other nodes after 5 ms

  @req:NET-04
  Scenario: F-NET-04 No block data is transferred without the ring
    When every ring link is cut
    And "car3.LCU" asks to send a 500-byte record as block data
    And 2 s pass
    Then "car1.CCU.sys1" holds no record of "car3.LCU"

  @req:CMD-04
  Scenario: F-NET-04 With the self-diagnostic line failed as well, no path is left
    Given board "selfdiag" has failed
    When every ring link is cut
    And 500 ms pass
    Then the BCU of car 4 receives nothing over path 3
    And the CI and BCU of car 3 receive nothing over path 3
