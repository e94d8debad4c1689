@item:F-VSD-04 @profile:crh2
Feature: F-VSD-04 Air conditioning and lighting state on the cab monitor
  Requirements: TST-04 (primary).
  Each car's air conditioning and lighting are shown on both monitors. Switched from the cab monitor, the
  order is applied within one status cycle and displayed within two (docs/decisions.md, "Display": 300 ms);
  only the car ordered changes.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04
  Scenario Outline: F-VSD-04 Car <car> <equipment> switched off is displayed off within 300 ms
    Then the cab 1 monitor displays "car<car>.<equipment>" as "on"
    When the driver orders "car<car>.<equipment>" to "off" on the cab 1 monitor
    And 300 ms pass
    Then the "car<car>.<equipment>" is off
    And the cab 1 monitor changes "car<car>.<equipment>" to "off" within 300 ms
    And the cab 8 monitor changes "car<car>.<equipment>" to "off" within 300 ms
    And the cab 1 monitor never displayed "car<other>.<equipment>" as "off"

    Examples:
      | car | other | equipment        |
      | 2   | 3     | air conditioning |
      | 7   | 6     | air conditioning |
      | 1   | 8     | lighting         |
      | 5   | 4     | lighting         |

  @req:TST-04
  Scenario: F-VSD-04 Air conditioning switched back on is displayed on within 300 ms
    Given "car3.air conditioning" has been ordered to "off" on the cab 1 monitor
    When 300 ms pass
    Then the cab 1 monitor displays "car3.air conditioning" as "off"
    When the driver orders "car3.air conditioning" to "on" on the cab 1 monitor
    And 300 ms pass
    Then the "car3.air conditioning" is on
    And the cab 1 monitor changes "car3.air conditioning" to "on" within 300 ms

  @req:TST-04
  Scenario: F-VSD-04 Lighting is displayed on after power-up, alike on both monitors
    When 200 ms pass
    Then the cab 1 monitor displays "car1.lighting" as "on"
    And the cab 1 monitor displays "car4.lighting" as "on"
    And the cab 1 monitor displays "car8.lighting" as "on"
    And the cab 1 and cab 8 monitors display the same values
