@item:H-WSV-03 @profile:crh2
Feature: H-WSV-03 Dielectric test of a CCU system in a running train
  Hardware/software test, withstand voltage (TST-02). Requirements: RED-01, RED-02.
  Testing CCU system 1 disconnects it for a minute; RED-01/02 keep the train commanded by system 2, and
  after the test system 1 rejoins as standby without taking mastership back.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:RED-01 @req:RED-02
  Scenario: H-WSV-03 System 2 takes over while system 1 is under test
    When "car1.CCU.sys1" is given a withstand-voltage test at 1500 V rms for 60 s
    And 1000 ms pass
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every LCU receives every command within 15 ms of its transmission
    And every CI and BCU receives traction notch 7 over path 1 within 80 ms

  @req:TST-02 @req:RED-02
  Scenario: H-WSV-03 After the test system 1 rejoins as standby
    When "car1.CCU.sys1" is given a withstand-voltage test at 1500 V rms for 60 s
    And 62 s pass
    Then "car1.CCU.sys1" sends status data again within 61000 ms
    And "car1.CCU.sys1" puts no commands on the ring from 100 ms on
    And the cab 1 monitor shows no faults
    And the insulation resistance of "car1.CCU.sys1" is at least 20 MOhm
