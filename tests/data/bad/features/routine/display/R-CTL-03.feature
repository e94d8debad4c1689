@item:R-CTL-03
Feature: R-CTL-03 Control item in the display folder

  @req:PRO-01
  Scenario: R-CTL-03 Otherwise fine
    Given a train of 8 cars
