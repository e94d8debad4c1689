@item:F-NET-08 @profile:crh2 @req:TST-04
Feature: F-NET-08 Coupling two sets couples the ring and the self-diagnostic line
  Requirements: NET-08 (primary), PRO-01, TST-04.

  Background:
    Given two 8-car CRH2 train sets coupled together
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 2
    And an analyser is attached to the ring link between "car8.CCU.sys1" and "car9.CCU.sys1"
    And the train has been powered up for 1000 ms

  @req:NET-08 @req:PRO-01
  Scenario: F-NET-08 The coupled ring runs over twisted pair and carries commands to all 16 cars
    When 500 ms pass
    Then the analysed link is twisted-pair
    And every LCU receives every command within 15 ms of its transmission
    And every CI and BCU receives traction notch 2 over path 1 within 40 ms

  @req:NET-08
  Scenario: F-NET-08 The coupled self-diagnostic line carries commands to the second set
    When every ring link is cut
    And 300 ms pass
    Then the CI and BCU of car 15 receive traction step "A" over path 3 within 100 ms
