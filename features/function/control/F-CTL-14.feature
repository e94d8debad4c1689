@item:F-CTL-14 @profile:crh2
Feature: F-CTL-14 Main circuit reset after a protection trip
  Requirements: ILK-06 (primary), TST-05, TST-04.
  A main circuit protection trip (ILK-06) latches: the VCB and the converters stay off after the fault has
  gone, and the monitor keeps the message, until the driver resets the main circuit. A reset while the fault
  persists does nothing, and neither does a VCB order from the monitor (docs/decisions.md, "The vehicle").
  # why: After a protection trip the driver must be able to restore the main circuit from the cab, and only once the fault is gone, or a CRH2 EMU could not run on after a transient fault.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-06 @req:TST-05 @req:TST-04
  Scenario: F-CTL-14 After the fault has gone the reset closes the VCB and brings the converters back
    When the vehicle input "unit1.transformer" becomes "secondary overcurrent"
    And 200 ms pass
    Then the "unit1.VCB" is open within 100 ms
    And the "car2.CI contactor" is open within 100 ms
    And the cab 1 monitor shows "unit1: main circuit protection acted"
    When the vehicle input "unit1.transformer" becomes "normal"
    And 500 ms pass
    Then the "unit1.VCB" stays open
    And the "car3.CI gates" stays blocked
    And the cab 1 monitor shows "unit1: main circuit protection acted"
    When the driver resets the main circuit
    And 200 ms pass
    Then the "unit1.VCB" is closed within 100 ms
    And the "car2.CI contactor" is closed within 100 ms
    And the "car3.CI gates" is enabled within 100 ms
    And the cab 1 monitor no longer shows "unit1: main circuit protection acted"
    And the cab 1 monitor displays "unit1.VCB" as "closed" within 150 ms

  @req:ILK-06 @req:TST-05 @req:TST-04
  Scenario: F-CTL-14 A reset while the fault persists leaves the main circuit open
    When the vehicle input "unit2.transformer" becomes "tertiary earth fault"
    And 200 ms pass
    Then the "unit2.VCB" is open within 100 ms
    When the driver resets the main circuit
    And 500 ms pass
    Then the "unit2.VCB" stays open
    And the "car6.CI contactor" stays open
    And the "unit1.VCB" stays closed
    And the cab 1 monitor shows "unit2: main circuit protection acted"

  @req:ILK-06 @req:TST-05 @req:TST-04
  Scenario: F-CTL-14 A VCB close order does not override a latched trip
    When the vehicle input "unit1.transformer" becomes "primary overcurrent"
    And 200 ms pass
    And the vehicle input "unit1.transformer" becomes "normal"
    And the driver orders "unit1.VCB" to "closed" on the cab 1 monitor
    And 500 ms pass
    Then the "unit1.VCB" stays open
    And the "car3.CI contactor" stays open
    When the driver resets the main circuit
    And 300 ms pass
    Then the "unit1.VCB" is closed within 100 ms

  @req:ILK-06 @req:TST-05 @req:TST-04
  Scenario Outline: F-CTL-14 A reset while the oil fault persists leaves the converters cut
    When the vehicle input "unit2.<input>" becomes "<fault>"
    And 200 ms pass
    Then the "car7.CI contactor" is open within 100 ms
    When the driver resets the main circuit
    And 500 ms pass
    Then the "car7.CI contactor" stays open
    And the "car7.CI gates" stays blocked
    And the "unit2.VCB" stays closed

    Examples:
      | input           | fault            |
      | oil pump        | stopped          |
      | oil temperature | over-temperature |

  @req:ILK-06 @req:TST-05 @req:TST-04
  Scenario: F-CTL-14 A restarted oil pump brings the converters back only after a reset, the VCB never opened
    When the vehicle input "unit2.oil pump" becomes "stopped"
    And 200 ms pass
    Then the "car7.CI contactor" is open within 100 ms
    And the "unit2.VCB" stays closed
    When the vehicle input "unit2.oil pump" becomes "running"
    And 500 ms pass
    Then the "car7.CI contactor" stays open
    And the "unit2.VCB" stays closed
    When the driver resets the main circuit
    And 200 ms pass
    Then the "car6.CI contactor" is closed within 100 ms
    And the "car7.CI gates" is enabled within 100 ms
    And the "unit2.VCB" stays closed
