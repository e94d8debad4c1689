@item:F-RSD-04 @profile:crh2
Feature: F-RSD-04 Mileage on the cab monitor
  Requirements: TST-04 (primary), PRO-02.
  The mileage (the speed integrated over time) travels in car 1's LCU status data and is displayed on both
  monitors in km with 1 m resolution. After the train stops, the displayed mileage settles within 150 ms
  on the distance run, within the suite's accuracy rule (+-0.1 % or +-1 m, whichever is larger,
  docs/decisions.md), and does not change while the train stands.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04 @req:PRO-02
  Scenario: F-RSD-04 Two seconds at 180 km/h are displayed as 100 m
    When the train speed changes to 180 km/h
    And 2000 ms pass
    And the train speed changes to 0 km/h
    And 200 ms pass
    Then the mileage is between 0.099 and 0.101 km
    And the cab 1 monitor displays "mileage" between 0.099 and 0.101 within 150 ms
    And the cab 8 monitor displays "mileage" between 0.099 and 0.101 within 150 ms

  @req:TST-04 @req:PRO-02
  Scenario: F-RSD-04 An acceleration from 0 to 144 km/h in 2 s is displayed as 40 m
    When the train speed goes from 0 km/h to 144 km/h at 72 km/h per second
    And 2000 ms pass
    And the train speed changes to 0 km/h
    And 200 ms pass
    Then the mileage is between 0.039 and 0.041 km
    And the cab 1 monitor displays "mileage" between 0.039 and 0.041 within 150 ms

  @req:TST-04 @req:PRO-02
  Scenario: F-RSD-04 The displayed mileage grows while running and stands still at a standstill
    When the train speed changes to 360 km/h
    And 1000 ms pass
    Then the cab 1 monitor displays "mileage" between 0.085 and 0.101
    When the train speed changes to 0 km/h
    And 1000 ms pass
    Then the cab 1 monitor displays "mileage" between 0.099 and 0.101
    And the cab 1 monitor kept "mileage" unchanged from 150 ms on
