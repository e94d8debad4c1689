@item:F-ATP-02 @profile:crh2 @req:TST-04
Feature: F-ATP-02 ATP emergency brake opens the emergency brake loop
  Requirements: ILK-08 (primary), TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 6
    And the train runs at 200 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-08
  Scenario: F-ATP-02 The EB valve drops and traction is blocked
    When the ATP commands a emergency brake
    And 200 ms pass
    Then the "EB valve" is de-energised within 10 ms
    And the "emergency brake" is applied
    And the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on

  @req:ILK-08
  Scenario: F-ATP-02 The rapid brake is not commanded by an ATP emergency brake alone
    When the ATP commands a emergency brake
    And 200 ms pass
    Then the "rapid brake" never became commanded
