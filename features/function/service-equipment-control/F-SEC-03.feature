@item:F-SEC-03 @profile:crh2
Feature: F-SEC-03 Orders from a cab without the key are void
  Requirements: ILK-07 (primary), TST-04.
  Only the cab whose master control relay is up commands the train (ILK-07): service-equipment orders
  given on another cab's monitor, or on any monitor while no key is in, change nothing, then or later.

  Background:
    Given an 8-car CRH2 train set

  @req:ILK-07 @req:TST-04
  Scenario: F-SEC-03 The key is in cab 1: orders on the cab 8 monitor change nothing, even with a second key
    Given the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms
    When the driver inserts the key in cab 8
    And the driver orders "car3.air conditioning" to "off" on the cab 8 monitor
    And the driver orders "car5.lighting" to "off" on the cab 8 monitor
    And the driver orders "passenger information" to "welcome aboard" on the cab 8 monitor
    And 1000 ms pass
    Then the "car3.air conditioning" stays on
    And the "car5.lighting" stays on
    And the "passenger information" stays none
    And the cab 1 monitor displays "car3.air conditioning" as "on"
    And the cab 8 monitor displays "car5.lighting" as "on"

  @req:ILK-07 @req:TST-04
  Scenario: F-SEC-03 An order given while no key is in is void, and is not carried out once the key is in
    Given the train has been powered up for 1000 ms
    When the driver orders "car2.lighting" to "off" on the cab 1 monitor
    And 1000 ms pass
    Then the "car2.lighting" stays on
    When the driver inserts the key in cab 1
    And 1000 ms pass
    Then the "car2.lighting" stays on
    And the cab 1 monitor displays "car2.lighting" as "on"

  @req:ILK-07 @req:TST-04 @tentative
  Scenario: F-SEC-03 Once the key has moved to cab 8, cab 8 orders and cab 1 is void
    Given the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms
    When the driver removes the key from cab 1
    And the driver inserts the key in cab 8
    And the driver orders "car1.air conditioning" to "off" on the cab 1 monitor
    And 1000 ms pass
    Then the "car1.air conditioning" stays on
    When the driver orders "car7.air conditioning" to "off" on the cab 8 monitor
    And 500 ms pass
    Then the "car7.air conditioning" is off within 300 ms
    And the cab 8 monitor displays "car7.air conditioning" as "off" within 300 ms
