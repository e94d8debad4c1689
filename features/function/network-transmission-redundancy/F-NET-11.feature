@item:F-NET-11 @profile:crh2 @req:TST-04
Feature: F-NET-11 Status data: every car broadcasts 240 bytes once per 120 ms cycle
  Requirements: PRO-02 (primary), TST-04.

  @req:PRO-02
  Scenario: F-NET-11 An 8-car set cycles its status data in 120 ms
    Given an 8-car CRH2 train set
    And an analyser is attached to the ring link between "car1.LCU" and "car2.LCU"
    And the train has been powered up for 1000 ms
    When 2 s pass
    Then the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And every status frame on the analysed link carries 240 bytes of data
