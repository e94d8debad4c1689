@item:F-NET-09 @profile:crh2 @req:TST-04
Feature: F-NET-09 Vehicle-level links: polled HDLC to CI and BCU, current loops to other devices
  Requirements: NET-09 (primary), TST-04.
  CI and BCU are polled every 10 ms over fibre HDLC. Air-conditioning setter, passenger information
  display and auxiliary power unit are polled over 20 mA / 30 mA loops at periods of their own (the
  article gives none: the SUT declares them); simple devices are one-way.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-09
  Scenario: F-NET-09 CI and BCU are polled every 10 ms
    When 1000 ms pass
    Then "car2.CI" is polled every 9.5 to 10.5 ms
    And "car7.CI" is polled every 9.5 to 10.5 ms
    And "car5.BCU" is polled every 9.5 to 10.5 ms

  @req:NET-09
  Scenario: F-NET-09 Current-loop devices are polled at their own periods, as the SUT declares them
    When 2 s pass
    Then "car3.ACS" is polled at its declared period
    And "car3.PID" is polled at its declared period
    And "car4.APU" is polled at its declared period

  @req:NET-09
  Scenario: F-NET-09 Simple devices are connected one way
    When 2 s pass
    Then "car3.SDD" is connected one way and never answers
    And "car1.DD" is connected one way and never answers
