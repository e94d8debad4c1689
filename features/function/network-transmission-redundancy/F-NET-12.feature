@item:F-NET-12 @profile:crh2 @req:TST-04
Feature: F-NET-12 Token formation after power-up
  Requirements: PRO-03 (primary), TST-04.
  No status data within 500 ms of power-up: the nodes send a token initialisation
  (a node that hears another's first may stay quiet); the token is formed
  at node number x 20 ms, so the lowest-numbered live node forms it.

  Background:
    Given an 8-car CRH2 train set

  @req:PRO-03
  Scenario: F-NET-12 Node 1 forms the token 20 ms after the initialisation
    Given the train is powered up
    When 1000 ms pass
    Then token initialisations are sent 500 to 510 ms after power-up and at no other time
    And the token is formed by "car1.CCU.sys1" 19 to 21 ms after the first token initialisation

  @req:PRO-03
  Scenario: F-NET-12 With node 1 dead, node 2 forms the token at 40 ms
    Given the supply "car1.CCU.sys1" is off
    And the train is powered up
    When 1000 ms pass
    Then the token is formed by "car1.CCU.sys2" 39 to 41 ms after the first token initialisation
