@item:F-IDI-02 @profile:crh2
Feature: F-IDI-02 Current-loop devices polled at their own periods, simple devices one way
  Requirements: NET-09 (primary), TST-04.
  The air-conditioning setter (ACS), passenger information display (PID) and auxiliary power unit (APU)
  hang on 20 mA or 30 mA current loops and are polled at periods of their own; the side destination
  display (SDD) and the distance detector (DD) are one-way (NET-09). The article gives neither periods
  nor which loop each device uses. The periods are the SUT's, declared (sut/contract/form.yaml crh2:
  acs_poll_period_ms ...), each interval within the declared tolerance; which devices a car has and which loop
  each uses are the project's (docs/decisions.md, "Vehicle level"): ACS and PID on 20 mA, APU (cars 2, 4, 6)
  on 30 mA, DD in the cab cars.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-09 @req:TST-04
  Scenario: F-IDI-02 Every car's ACS and PID are polled on current loops at their declared periods
    When 2 s pass
    Then the ACS of every car is polled at its declared period
    And the PID of every car is polled at its declared period
    And "car3.ACS" is on a 20 mA or a 30 mA current loop
    And "car6.PID" is on a 20 mA or a 30 mA current loop

  @req:NET-09 @req:TST-04 @tentative
  Scenario: F-IDI-02 ACS and PID are on 20 mA loops
    When 1000 ms pass
    Then "car3.ACS" is on a 20 mA current loop
    And "car6.PID" is on a 20 mA current loop

  @req:NET-09 @req:TST-04 @tentative
  Scenario: F-IDI-02 The APUs of cars 2, 4 and 6 are polled at their declared period on 30 mA loops
    When 1000 ms pass
    Then "car2.APU" is polled at its declared period
    And "car4.APU" is polled at its declared period
    And "car6.APU" is polled at its declared period
    And "car4.APU" is on a 30 mA current loop
    And car 3 has no APU

  @req:NET-09 @req:TST-04 @tentative
  Scenario: F-IDI-02 Side destination displays only receive, distance detectors only send
    When 4 s pass
    Then "car3.SDD" only receives from its LCU, at its declared period
    And "car8.SDD" only receives from its LCU, at its declared period
    And "car1.DD" only sends to its LCU, at its declared period
    And "car8.DD" only sends to its LCU, at its declared period
    And car 4 has no DD
    And "car1.DD" is on a 20 mA or a 30 mA current loop
    And "car3.SDD" is on a 20 mA or a 30 mA current loop
