@item:H-VIB-01 @profile:crh2
Feature: H-VIB-01 Contact micro-interruptions on supply connectors under rated vibration
  Hardware/software test, vibration (TST-02). Requirements: CMD-02, RED-02.
  IEC 61373 category 1 class B (body-mounted equipment): under the functional random vibration test the
  power contacts of the boards may chatter. Micro-interruptions of up to 1 ms (the project's figure for
  contact chatter, docs/decisions.md "Environment"), however often, are ridden out: no reset, no takeover, no
  lost command.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:RED-02
  Scenario: H-VIB-01 Chatter on CCU system 1's supply contacts causes no takeover
    When vibration opens the contacts of supply "car1.CCU.sys1" 100 times for 1 ms every 20 ms
    And the cab 1 monitor is watched for 2500 ms
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And every LCU receives every command within 15 ms of its transmission
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02
  Scenario: H-VIB-01 Chatter on every supply's contacts at once loses no command
    When vibration opens the contacts of supply "train 110V" 100 times for 1 ms every 20 ms
    And the cab 1 monitor is watched for 2500 ms
    Then no CI or BCU goes without a command for more than 25 ms
    And no CI or BCU receives a traction notch other than 7
    And no node sends a token initialisation
    And the cab 1 monitor never showed a fault

  @req:TST-02 @req:CMD-02
  Scenario: H-VIB-01 Chatter on a TXC's and an RXC's supply contacts changes nothing
    When vibration opens the contacts of supply "car1.CCU.sys1.TXC" 100 times for 1 ms every 20 ms
    And vibration opens the contacts of supply "car3.LCU.RXC" 100 times for 1 ms every 20 ms
    And the cab 1 monitor is watched for 2500 ms
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And the CI and BCU of car 3 receive traction notch 7 over path 1 within 20 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)
