@item:F-NET-20 @profile:crh2 @req:TST-04
Feature: F-NET-20 The driver's controller in each cab sets master control, direction and notches
  Requirements: CMD-05 (primary), PRO-01, TST-04.

  Background:
    Given an 8-car CRH2 train set

  @req:CMD-05
  Scenario: F-NET-20 Without master control no command is broadcast
    Given the train has been powered up for 500 ms
    When 500 ms pass
    Then "car1.CCU.sys1" puts no commands on the ring
    And "car8.CCU.sys1" puts no commands on the ring

  @req:CMD-05 @req:PRO-01
  Scenario Outline: F-NET-20 Notch <notch> set in cab <cab> reaches every CI
    Given the driver has inserted the key in cab <cab>
    And the direction switch of cab <cab> is at forward
    And the train has been powered up for 1000 ms
    When the driver moves the traction notch of cab <cab> to <notch>
    And 100 ms pass
    Then every CI and BCU receives traction notch <notch> over path 1 within 40 ms

    Examples:
      | cab | notch |
      | 1   | 1     |
      | 1   | 10    |
      | 8   | 5     |
