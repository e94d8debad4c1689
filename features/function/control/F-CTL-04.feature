@item:F-CTL-04 @profile:crh2
Feature: F-CTL-04 Remote cut-out command transmission
  Requirements: TST-05 (primary), TST-04.
  A converter (CI) cut out from the cab monitor: the order travels in the commanding CCU's status data to
  the car's LCU, which opens that CI's input contactor and blocks its gate pulses; the other converters stay
  in, the traction commands keep flowing, and the monitor shows the cut-out. Ordering "in" brings the CI
  back. An equipment order is applied within one status cycle and displayed within two: 300 ms
  (docs/decisions.md, "Display, orders, records").

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:TST-05 @req:TST-04
  Scenario: F-CTL-04 Cutting out car 3's CI opens its contactor and blocks its gates, the others stay in
    Then the "car3.CI contactor" is closed
    And the "car3.CI gates" is enabled
    When the driver orders "car3.CI cut-out" to "cut out" on the cab 1 monitor
    And 300 ms pass
    Then the "car3.CI cut-out" is cut out within 300 ms
    And the "car3.CI contactor" is open within 300 ms
    And the "car3.CI gates" is blocked within 300 ms
    And the "car2.CI contactor" stays closed
    And the "car6.CI contactor" stays closed
    And the "car7.CI gates" stays enabled
    And the "unit1.VCB" stays closed
    And the cab 1 monitor displays "car3.CI cut-out" as "cut out" within 300 ms
    And the cab 1 monitor displays "car3.CI contactor" as "open" within 300 ms

  @req:TST-05 @req:TST-04
  Scenario: F-CTL-04 Ordering the cut-out CI back in closes its contactor again
    When the driver orders "car6.CI cut-out" to "cut out" on the cab 1 monitor
    And 300 ms pass
    Then the "car6.CI contactor" is open within 300 ms
    When the driver orders "car6.CI cut-out" to "in" on the cab 1 monitor
    And 300 ms pass
    Then the "car6.CI cut-out" is in within 300 ms
    And the "car6.CI contactor" is closed within 300 ms
    And the "car6.CI gates" is enabled within 300 ms
    And the "car7.CI contactor" stays closed
    And the cab 1 monitor displays "car6.CI cut-out" as "in" within 300 ms
    And the cab 1 monitor displays "car6.CI contactor" as "closed" within 300 ms

  @req:TST-05 @req:TST-04
  Scenario: F-CTL-04 A cut-out converter leaves the traction commands to every car untouched
    Given the traction notch of cab 1 is at 5
    When the driver orders "car2.CI cut-out" to "cut out" on the cab 1 monitor
    And 300 ms pass
    Then the "car2.CI contactor" is open within 300 ms
    And the "traction" is permitted
    And from 40 ms on every CI and BCU receives only traction notch 5 and brake step 0 over path 1

  @req:TST-05 @req:TST-04
  Scenario: F-CTL-04 Two converters of different units cut out independently
    When the driver orders "car3.CI cut-out" to "cut out" on the cab 1 monitor
    And the driver orders "car7.CI cut-out" to "cut out" on the cab 1 monitor
    And 300 ms pass
    Then the "car3.CI contactor" is open within 300 ms
    And the "car7.CI contactor" is open within 300 ms
    And the "car2.CI contactor" stays closed
    And the "car6.CI contactor" stays closed
    And the cab 1 monitor displays "car7.CI cut-out" as "cut out" within 300 ms
