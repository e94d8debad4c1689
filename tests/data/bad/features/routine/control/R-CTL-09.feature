@item:R-CTL-09
Feature: R-CTL-09 Not in the registry

  @req:PRO-01
  Scenario: R-CTL-09 Otherwise fine
    Given a train of 8 cars
