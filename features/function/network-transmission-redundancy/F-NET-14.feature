@item:F-NET-14 @profile:crh2 @req:TST-04
Feature: F-NET-14 Token regeneration after 500 ms without a token
  Requirements: PRO-05 (primary), PRO-03, TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:PRO-05 @req:PRO-03
  Scenario: F-NET-14 A lost token is regenerated after 500 ms of silence
    When the next token frame from "car2.LCU" to "car3.LCU" is corrupted
    And 1500 ms pass
    Then a token initialisation follows the last token pass by 500 to 510 ms
    And within 1000 ms one token circulates again through every node
