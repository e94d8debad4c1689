@item:F-ILK-06 @profile:crh2 @req:TST-04
Feature: F-ILK-06 Main circuit protection: transformer faults, oil pump and oil temperature
  Requirements: ILK-06 (primary), TST-04.
  Transformer over-currents open the VCB, the converter input contactors and block the gate pulses; earth
  faults open the VCB; a stopped oil pump or hot oil cuts the converters but leaves the VCB closed. Each
  traction unit (cars 1-4, cars 5-8) has its own transformer and VCB; the other unit is not touched.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-06
  Scenario Outline: F-ILK-06 A transformer <fault> opens the VCB and cuts the converters of its unit
    When the vehicle input "unit1.transformer" becomes "<fault>"
    And 100 ms pass
    Then the "unit1.VCB" is open within 100 ms
    And the "car2.CI contactor" is open within 100 ms
    And the "car3.CI gates" is blocked within 100 ms
    And the "unit2.VCB" stays closed
    And the "car6.CI contactor" stays closed

    Examples:
      | fault                 |
      | primary overcurrent   |
      | secondary overcurrent |
      | tertiary overcurrent  |

  @req:ILK-06
  Scenario Outline: F-ILK-06 A transformer <fault> opens the VCB
    When the vehicle input "unit2.transformer" becomes "<fault>"
    And 100 ms pass
    Then the "unit2.VCB" is open within 100 ms
    And the "unit1.VCB" stays closed

    Examples:
      | fault                 |
      | secondary earth fault |
      | tertiary earth fault  |

  @req:ILK-06
  Scenario Outline: F-ILK-06 <what> cuts the converters and leaves the VCB closed
    When the vehicle input "<input>" becomes "<value>"
    And 100 ms pass
    Then the "car6.CI contactor" is open within 100 ms
    And the "car7.CI gates" is blocked within 100 ms
    And the "unit2.VCB" stays closed

    Examples:
      | what             | input                  | value            |
      | A stopped pump   | unit2.oil pump         | stopped          |
      | Hot oil          | unit2.oil temperature  | over-temperature |
