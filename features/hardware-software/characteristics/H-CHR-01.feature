@item:H-CHR-01 @profile:crh2
Feature: H-CHR-01 Board inventory and health at power-up
  Hardware/software test, characteristics (TST-02). Requirements: NET-01, NET-02, PRO-02, PRO-03.
  Before any environment is applied the units under test are counted and checked: every car has its LCU,
  every cab car a CCU with two systems, each with the boards of NET-02, and after power-up every node is
  healthy and heard on the ring, so a later fault can only come from the environment.

  Background:
    Given an 8-car CRH2 train set

  @req:TST-02 @req:NET-01 @req:NET-02
  Scenario: H-CHR-01 Every unit carries the boards of its type
    Given the train is powered up
    Then every car has an LCU on the ring and every cab car a CCU with systems 1 and 2
    And the boards of "car1.CCU.sys1" are CPU3, MDM8 and TXC
    And the boards of "car8.CCU.sys2" are CPU3, MDM8 and TXC
    And the boards of "car3.LCU" are CPU3, MDM8, MDM9 and RXC
    And the boards of "car8.LCU" are CPU3, MDM8, MDM9 and RXC

  @req:TST-02 @req:PRO-03
  Scenario: H-CHR-01 At power-up the nodes form the token within the protocol's times
    Given the train is powered up
    When 1000 ms pass
    Then token initialisations are sent 500 to 510 ms after power-up and at no other time
    And the token is formed by "car1.CCU.sys1" 19 to 21 ms after the first token initialisation

  @req:TST-02 @req:PRO-02
  Scenario: H-CHR-01 After power-up every node is healthy and heard every status cycle
    Given the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms
    When 1000 ms pass
    Then the cab 1 monitor shows no faults
    And the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And the maintenance view of cab 1 holds 0 line(s)
