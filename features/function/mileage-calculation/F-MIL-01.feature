@item:F-MIL-01 @profile:crh2
Feature: F-MIL-01 Mileage at constant speed
  Requirements: TST-04 (primary).
  Mileage is speed integrated over time; at a constant speed it is speed x time. Accuracy rule of the
  suite (docs/decisions.md): +-0.1 % or +-1 m, whichever is larger; each scenario checks both edges of that
  band, once where the 1 m floor governs and once where the 0.1 % does.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04 @tentative
  Scenario: F-MIL-01 108 km/h for 20 s is 0.600 km, within 1 m
    When the train speed changes to 108 km/h
    And 20 s pass
    Then the mileage is between 0.599 and 0.601 km

  @req:TST-04 @tentative
  Scenario: F-MIL-01 300 km/h for 24 s is 2.000 km, within 0.1 %
    When the train speed changes to 300 km/h
    And 24 s pass
    Then the mileage is between 1.998 and 2.002 km

  @req:TST-04 @tentative
  Scenario: F-MIL-01 Two constant speeds add up: 54 km/h for 10 s and 180 km/h for 10 s is 0.650 km
    When the train speed changes to 54 km/h
    And 10 s pass
    And the train speed changes to 180 km/h
    And 10 s pass
    Then the mileage is between 0.649 and 0.651 km
