@item:F-SEC-02 @profile:crh2
Feature: F-SEC-02 Lighting and passenger information ordered from the cab monitor
  Requirements: TST-04 (primary).
  Lighting is switched per car, the passenger information message for the whole train. As for every
  monitor order (docs/decisions.md), the order is applied within one status cycle and displayed within two
  (features: 300 ms); equipment that was not ordered is untouched.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04 @tentative
  Scenario: F-SEC-02 Lighting of car 4 switched off, its neighbours and its air conditioning untouched
    When the driver orders "car4.lighting" to "off" on the cab 1 monitor
    And 500 ms pass
    Then the "car4.lighting" is off within 300 ms
    And the cab 1 monitor displays "car4.lighting" as "off" within 300 ms
    And the "car3.lighting" stays on
    And the "car5.lighting" stays on
    And the "car4.air conditioning" stays on

  @req:TST-04 @tentative
  Scenario: F-SEC-02 The passenger information message is set and changed
    When the driver orders "passenger information" to "next station" on the cab 1 monitor
    And 500 ms pass
    Then the "passenger information" is next station within 300 ms
    And the cab 1 monitor displays "passenger information" as "next station" within 300 ms
    When the driver orders "passenger information" to "welcome aboard" on the cab 1 monitor
    And 500 ms pass
    Then the "passenger information" is welcome aboard within 300 ms
    And the cab 1 monitor displays "passenger information" as "welcome aboard" within 300 ms
    And the "car1.lighting" stays on

  @req:TST-04 @tentative
  Scenario: F-SEC-02 Lighting switched back on
    When the driver orders "car6.lighting" to "off" on the cab 1 monitor
    And 500 ms pass
    And the driver orders "car6.lighting" to "on" on the cab 1 monitor
    And 500 ms pass
    Then the "car6.lighting" is on within 300 ms
    And the cab 1 monitor displays "car6.lighting" as "on" within 300 ms
