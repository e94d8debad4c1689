@item:F-NET-13 @profile:crh2 @req:TST-04
Feature: F-NET-13 Token holding, passing and return at a fault
  Requirements: PRO-04 (primary), PRO-02, TST-04.
  Each node holds the token 10 ms and passes it to its neighbour; at a fault the node beside it sends
  the token back the other way after its holding time.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:PRO-04
  Scenario: F-NET-13 The token goes round in ring order, 10 ms at each node
    When 1000 ms pass
    Then the token arrives at each next node 9.75 to 11.5 ms after the one before
    And the token visits the nodes in ring order

  @req:PRO-04 @req:PRO-02
  Scenario: F-NET-13 The nodes beside a cut link send the token back
    When the ring link between "car3.LCU" and "car4.LCU" is cut
    And 2 s pass
    Then "car3.LCU" sends the token back the way it came 9.75 to 11.5 ms after receiving it
    And "car4.LCU" sends the token back the way it came 9.75 to 11.5 ms after receiving it
    And every node receives the token at least every 250 ms
    And no node sends a token initialisation
