@item:F-ILK-01 @profile:crh2 @req:TST-04
Feature: F-ILK-01 Train separation applies the emergency and the rapid brake together
  Requirements: ILK-01 (primary), ILK-08, TST-04.
  When the train separates, the emergency-brake magnet valve loses power; emergency brake and rapid
  brake apply together.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 4
    And the train runs at 120 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-01
  Scenario: F-ILK-01 Separation drops both magnet valves at the same instant
    When the train separates between car 4 and car 5
    And 100 ms pass
    Then the "EB valve" is de-energised within 10 ms
    And the "rapid-brake valve" is de-energised within 10 ms
    And the "EB valve" and the "rapid-brake valve" changed at the same instant
    And the "emergency brake" is applied
    And the "rapid brake" is commanded

  @req:ILK-01 @req:ILK-08
  Scenario: F-ILK-01 After separation no traction command reaches a converter
    When the train separates between car 2 and car 3
    And 200 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on

  @req:ILK-01
  Scenario: F-ILK-01 A coupled train keeps its brakes released
    When 1000 ms pass
    Then the "EB valve" stays energised
    And the "rapid-brake valve" stays energised
