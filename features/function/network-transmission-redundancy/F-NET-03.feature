@item:F-NET-03 @profile:crh2 @req:TST-04
Feature: F-NET-03 Ring split by two link faults
  Requirements: NET-03 (primary), PRO-05, CMD-04, TST-04.
  Two cut spans split the ring; the nodes of each segment keep communicating with each other, and a
  segment left without the token regenerates its own.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:NET-03 @req:PRO-05
  Scenario: F-NET-03 Nodes inside each segment keep exchanging status data
    When the ring link between "car3.LCU" and "car4.LCU" is cut
    And the ring link between "car6.LCU" and "car7.LCU" is cut
    And 2 s pass
    Then "car5.LCU" has status data from "car4.LCU" no older than 300 ms
    And "car5.LCU" has status data from "car6.LCU" no older than 300 ms
    And "car2.LCU" has status data from "car8.LCU" no older than 300 ms
    And "car5.LCU" has had no status data from "car2.LCU" for at least 1000 ms

  @req:NET-03 @req:CMD-04
  Scenario: F-NET-03 The commanding CCU's segment keeps path 1, the cut-off segment falls back to path 3
    When the ring link between "car3.LCU" and "car4.LCU" is cut
    And the ring link between "car6.LCU" and "car7.LCU" is cut
    And the driver moves the traction notch of cab 1 to 6
    And 300 ms pass
    Then the CI and BCU of car 2 receive traction notch 6 over path 1 within 40 ms
    And the CI and BCU of car 5 receive traction step "B" over path 3 within 100 ms
