@item:F-ATP-03 @profile:crh2 @req:TST-04
Feature: F-ATP-03 Releasing the ATP brake gives the driver traction back
  Requirements: ILK-08 (primary), TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 4
    And the train runs at 100 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-08
  Scenario: F-ATP-03 Traction returns within one command cycle path after the release
    When the ATP commands a service brake
    And 300 ms pass
    And the ATP releases its brake
    And 200 ms pass
    Then the "traction" is permitted
    And every CI receives traction notch 4 within 40 ms

  @req:ILK-08
  Scenario: F-ATP-03 The emergency brake loop closes again after an ATP emergency brake is released
    When the ATP commands a emergency brake
    And 300 ms pass
    And the ATP releases its brake
    And 100 ms pass
    Then the "EB valve" is energised within 10 ms
