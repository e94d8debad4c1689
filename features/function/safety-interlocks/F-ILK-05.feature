@item:F-ILK-05 @profile:crh2 @req:TST-04
Feature: F-ILK-05 Doors: pressed airtight above 30 km/h, opened only below 5 km/h
  Requirements: ILK-05 (primary), TST-04.
  Speed bands (docs/decisions.md): the press-seal valve energises above 30 km/h and by 32 km/h; the door-open
  safety relay acts below 5 km/h and by 4 km/h, never at 5 km/h or more.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-05
  Scenario: F-ILK-05 The press-seal valve energises between 30 and 32 km/h with the doors closed
    When the train speed goes from 0 km/h to 40 km/h at 2 km/h per second
    And 21 s pass
    Then the "press-seal valve" became energised while the speed was between 30 and 32 km/h

  @req:ILK-05
  Scenario: F-ILK-05 The door-open safety relay acts between 5 and 4 km/h when slowing down
    Given the train runs at 20 km/h
    When the train speed goes from 20 km/h to 0 km/h at 2 km/h per second
    And 11 s pass
    Then the "door-open relay" became acting while the speed was between 4 and 5 km/h

  @req:ILK-05
  Scenario: F-ILK-05 Doors commanded open at 10 km/h stay closed until the train is below 5 km/h
    Given the train runs at 10 km/h
    When the driver commands the doors open
    And 200 ms pass
    Then the "doors" stays closed
    And the "door-open relay" is released
    When the train speed changes to 3 km/h
    And 100 ms pass
    Then the "doors" is open within 100 ms

  @req:ILK-05
  Scenario: F-ILK-05 The press-seal valve stays off at 30 km/h
    When the train speed changes to 30 km/h
    And 1000 ms pass
    Then the "press-seal valve" stays de-energised

  @req:ILK-05
  Scenario: F-ILK-05 Doors open at standstill and the train at 40 km/h at once: the doors close and are sealed
    When the driver commands the doors open
    And 200 ms pass
    Then the "doors" is open
    When the train speed changes to 40 km/h
    And 100 ms pass
    Then the "doors" is closed
    And the "press-seal valve" is energised
