@item:F-ILK-09 @profile:crh2 @req:TST-04
Feature: F-ILK-09 Braking outranks traction
  Requirements: ILK-08 (primary), TST-04.
  Any brake command, from the brake handle or from the ATP, suppresses traction.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train runs at 80 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-08
  Scenario: F-ILK-09 The lowest brake step from the handle suppresses traction
    When the driver moves the brake handle of cab 1 to step 1
    And 200 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
    And from 40 ms on every BCU receives brake step 1

  @req:ILK-08
  Scenario: F-ILK-09 Releasing the brake gives traction back
    When the driver moves the brake handle of cab 1 to step 3
    And 200 ms pass
    And the driver moves the brake handle of cab 1 to step 0
    And 200 ms pass
    Then the "traction" is permitted
    And every CI receives traction notch 7 within 40 ms

  @req:ILK-08
  Scenario: F-ILK-09 An ATP service brake suppresses traction
    When the ATP commands a service brake
    And 200 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
