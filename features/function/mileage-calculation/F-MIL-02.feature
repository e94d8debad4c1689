@item:F-MIL-02 @profile:crh2
Feature: F-MIL-02 Mileage while the speed changes linearly
  Requirements: TST-04 (primary).
  Under a linear speed change the distance is the mean speed x time (exact for linear pieces,
  docs/decisions.md). Accuracy rule of the suite: +-0.1 % or +-1 m, whichever is larger (here the 1 m floor);
  each scenario checks both edges of the band.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04 @tentative
  Scenario: F-MIL-02 Accelerating from 0 to 72 km/h at 2 km/h per second covers 360 m
    When the train speed goes from 0 km/h to 72 km/h at 2 km/h per second
    And 36 s pass
    Then the mileage is between 0.359 and 0.361 km

  @req:TST-04 @tentative
  Scenario: F-MIL-02 Braking from 72 km/h to a stop at 4 km/h per second covers 180 m
    When the train speed goes from 72 km/h to 0 km/h at 4 km/h per second
    And 18 s pass
    And 10 s pass
    Then the mileage is between 0.179 and 0.181 km

  @req:TST-04 @tentative
  Scenario: F-MIL-02 A ramp followed by a cruise: 180 m accelerating and 200 m at 72 km/h
    When the train speed goes from 0 km/h to 72 km/h at 4 km/h per second
    And 18 s pass
    And 10 s pass
    Then the mileage is between 0.379 and 0.381 km

  # A speed set while a ramp is under way ends the ramp there: the train holds the new speed.
  @req:TST-04 @tentative
  Scenario: F-MIL-02 A ramp cut short: 9 s accelerating at 2 km/h per second, then 10 s at 36 km/h cover 122.5 m
    When the train speed goes from 0 km/h to 72 km/h at 2 km/h per second
    And 9 s pass
    And the train speed changes to 36 km/h
    And 10 s pass
    Then the mileage is between 0.1215 and 0.1235 km
