@item:R-CTL-01
Feature: R-CTL-01 Traction and brake command transmission
  CMD-02 (primary), PRO-01, TST-03.

  Background:
    Given a train of 8 cars

  @req:CMD-02 @req:TST-03 @profile:crh2
  Scenario: R-CTL-01 Traction notch reaches every car
    When the driver sets traction notch 3
    Then every car receives traction notch 3

  @req:PRO-01 @tentative
  Scenario: R-CTL-01 Commands repeat every 10 ms
    When the driver sets traction notch 1
    Then every car receives traction notch 1
    And the command interval is 10 ms
