@item:H-PWR-01 @profile:crh2
Feature: H-PWR-01 Interruptions of 10 ms (class S2) without reset
  Hardware/software test, momentary power interruption (TST-02). Requirements: CMD-02, PRO-04, RED-02.
  EN 50155 interruption class S2: an interruption of the supply of up to 10 ms causes no reset and no
  deviation of function. No node restarts (no token initialisation, no restart record), system 1 keeps
  commanding, and no CI or BCU misses a poll.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:CMD-02 @req:PRO-04
  Scenario: H-PWR-01 A 10 ms interruption of the train supply resets nothing
    When the supply "train 110V" is interrupted for 10 ms
    And the cab 1 monitor is watched for 1500 ms
    Then no CI or BCU goes without a command for more than 25 ms
    And no CI or BCU receives a traction notch other than 7
    And no node sends a token initialisation
    And every node receives the token at least every 130 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:RED-02
  Scenario: H-PWR-01 A 10 ms interruption of CCU system 1 causes no takeover
    When the supply "car1.CCU.sys1" is interrupted for 10 ms
    And 1000 ms pass
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And every LCU receives every command within 15 ms of its transmission
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02
  Scenario: H-PWR-01 Repeated 10 ms interruptions of an LCU supply reset nothing
    When the supply "car3.LCU" is interrupted for 10 ms
    And 300 ms pass
    And the supply "car3.LCU" is interrupted for 10 ms
    And the cab 1 monitor is watched for 1000 ms
    Then the CI and BCU of car 3 receive traction notch 7 over path 1 within 20 ms
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)
