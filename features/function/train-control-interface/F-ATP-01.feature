@item:F-ATP-01 @profile:crh2 @req:TST-04
Feature: F-ATP-01 ATP service brake command through the network
  Requirements: ILK-08 (primary), TST-04.
  The ATP's service brake reaches every BCU as full service brake and suppresses traction.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 6
    And the train runs at 150 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-08
  Scenario: F-ATP-01 Every BCU gets full service brake from the ATP
    When the ATP commands a service brake
    And 300 ms pass
    Then from 40 ms on every BCU receives brake step 7
    And no CI receives a traction notch above 0 from 40 ms on

  @req:ILK-08
  Scenario: F-ATP-01 A stronger handle brake is not weakened by the ATP
    Given the brake handle of cab 1 is at step 8
    When the ATP commands a service brake
    And 300 ms pass
    Then from 40 ms on every BCU receives brake step 8
