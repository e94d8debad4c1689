@item:F-NET-14 @profile:crh2 @req:TST-04
Feature: F-NET-14 Token regeneration after 500 ms without a token
  Requirements: PRO-05 (primary), PRO-03, TST-04.
  500 ms without the token: a token initialisation, and the token is formed again as after power-up (PRO-03):
  by the lowest-numbered live node, at its number x 20 ms after the initialisation (docs/decisions.md).

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

  @req:PRO-05 @req:PRO-03
  Scenario: F-NET-14 After a loss node 1 forms the new token 20 ms after the initialisation
    When the next token frame from "car2.LCU" to "car3.LCU" is corrupted
    And 1500 ms pass
    Then the token is formed by "car1.CCU.sys1" 19 to 23 ms after the first token initialisation

  @req:PRO-05 @req:PRO-03
  Scenario: F-NET-14 After a loss with node 1 dead, node 2 forms the new token 40 ms after the initialisation
    When the supply "car1.CCU.sys1" is switched off
    And 1500 ms pass
    And the next token frame from "car2.LCU" to "car3.LCU" is corrupted
    And 1500 ms pass
    Then the token is formed by "car1.CCU.sys2" 39 to 43 ms after the first token initialisation

  # A ring that grew back from two segments may hold two tokens for a moment; however the SUT settles that
  # (docs/decisions.md, "Link restored"), once one token goes round no node initialises one again (PRO-05:
  # only 500 ms without a token does).
  @req:PRO-05
  Scenario: F-NET-14 After a ring link is restored the token goes round and no node initialises it again
    Given the ring link between "car5.LCU" and "car6.LCU" is cut
    When 1000 ms pass
    And the ring link between "car5.LCU" and "car6.LCU" is restored
    And 3000 ms pass
    Then no node sends a token initialisation from 1000 ms after that on
    And every node receives the token at least every 250 ms
