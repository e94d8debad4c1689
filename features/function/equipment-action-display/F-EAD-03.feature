@item:F-EAD-03 @profile:crh2
Feature: F-EAD-03 Converter contactor and gate pulses on the cab monitor after an oil-pump stop
  Requirements: ILK-06 (primary), TST-04.
  A stopped transformer oil pump or oil over-temperature opens the converter input contactors and blocks
  the gate pulses of its traction unit, and leaves the VCB closed (ILK-06). The monitor shows the action
  within the display bound of 150 ms; the other unit's converters and both VCBs stay displayed as before.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-06 @req:TST-04
  Scenario: F-EAD-03 A stopped oil pump of unit 2 is displayed as its converters cut within 150 ms
    When the vehicle input "unit2.oil pump" becomes "stopped"
    And 150 ms pass
    Then the cab 1 monitor changes "car6.CI contactor" to "open" within 150 ms
    And the cab 1 monitor changes "car7.CI contactor" to "open" within 150 ms
    And the cab 1 monitor changes "car6.CI gates" to "blocked" within 150 ms
    And the cab 1 monitor changes "car7.CI gates" to "blocked" within 150 ms
    And the cab 8 monitor changes "car6.CI gates" to "blocked" within 150 ms
    And the cab 1 monitor never displayed "unit2.VCB" as "open"
    And the cab 1 monitor never displayed "car2.CI contactor" as "open"
    And the cab 1 monitor never displayed "car3.CI gates" as "blocked"

  @req:ILK-06 @req:TST-04
  Scenario: F-EAD-03 Hot oil in unit 1 is displayed as its converters cut within 150 ms
    When the vehicle input "unit1.oil temperature" becomes "over-temperature"
    And 150 ms pass
    Then the cab 1 monitor changes "car2.CI contactor" to "open" within 150 ms
    And the cab 1 monitor changes "car3.CI gates" to "blocked" within 150 ms
    And the cab 1 monitor never displayed "unit1.VCB" as "open"
    And the cab 1 monitor never displayed "car6.CI contactor" as "open"

  @req:ILK-06 @req:TST-04
  Scenario: F-EAD-03 A transformer over-current is displayed as VCB open and converters cut
    When the vehicle input "unit1.transformer" becomes "primary overcurrent"
    And 150 ms pass
    Then the cab 1 monitor changes "unit1.VCB" to "open" within 150 ms
    And the cab 1 monitor changes "car2.CI contactor" to "open" within 150 ms
    And the cab 1 monitor changes "car3.CI gates" to "blocked" within 150 ms
    And the cab 1 monitor never displayed "unit2.VCB" as "open"
