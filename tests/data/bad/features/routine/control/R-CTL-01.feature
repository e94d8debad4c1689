Feature: R-CTL-01 Bad on purpose (line numbers are asserted by tests/test_check.py)

  @item:R-CTL-01 @req:CMD-02
  Scenario: R-CTL-01 Same title twice
    Given a train of 8 cars
    When the driver does something
    Then the notch is 3

  @item:R-CTL-01 @req:NET-03
  Scenario: R-CTL-01 Same title twice
    Given a train of 8 cars

  @item:R-CTL-02 @req:XXX-99
  Scenario: Title without the item ID
    Given a train of 8 cars

  @item:R-CTL-01
  Scenario: R-CTL-01 No requirement tag
    Given a train of 8 cars
    And the driver does something

  @item:R-CTL-01 @reqs:PRO-01
  Scenario: R-CTL-01 Typo in a tag kind
    Given a train of 8 cars
