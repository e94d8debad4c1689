@item:F-NET-05 @profile:crh2 @req:TST-04
Feature: F-NET-05 Frame check: a bad frame is discarded, a good one forwarded
  Requirements: NET-05 (primary), NET-03, TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And the train has been powered up for 1000 ms

  @req:NET-05 @req:NET-03
  Scenario: F-NET-05 A corrupted command frame is discarded and the good copy still arrives
    When the next command frame from "car3.LCU" to "car4.LCU" is corrupted
    And 200 ms pass
    Then "car4.LCU" discards the corrupted command frame
    And every LCU receives every command within 15 ms of its transmission
    And no CI or BCU receives a traction notch other than 3

  @req:NET-05
  Scenario: F-NET-05 A corrupted status frame is discarded
    When the next status frame from "car5.LCU" to "car6.LCU" is corrupted
    And 300 ms pass
    Then "car6.LCU" discards the corrupted status frame
