@item:F-NET-07 @profile:crh2 @req:TST-04
Feature: F-NET-07 ARCNET over fibre at 2.5 Mbit/s
  Requirements: NET-07 (primary), TST-04.

  @req:NET-07
  Scenario: F-NET-07 Every frame on a ring link goes at 2.5 Mbit/s
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And an analyser is attached to the ring link between "car2.LCU" and "car3.LCU"
    And the train has been powered up for 1000 ms
    When 300 ms pass
    Then the analysed link carries 2.5 Mbit/s within 0.5 %
    And the analysed link is fibre
