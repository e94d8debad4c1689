@item:F-VSD-01 @profile:crh2
Feature: F-VSD-01 Door state on the cab monitor
  Requirements: ILK-05 (primary), TST-04.
  Doors open only below 5 km/h, when the door-open safety relay acts (ILK-05). The monitor shows the doors
  and the relay as the train has them, within the display bound of 150 ms; a door command given while the
  train runs is never shown as open doors.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-05 @req:TST-04
  Scenario: F-VSD-01 Doors opened and closed at a standstill are displayed within 150 ms
    Then the cab 1 monitor displays "doors" as "closed"
    And the cab 1 monitor displays "door-open relay" as "acting"
    When the driver commands the doors open
    And 150 ms pass
    Then the "doors" is open
    And the cab 1 monitor changes "doors" to "open" within 150 ms
    And the cab 8 monitor changes "doors" to "open" within 150 ms
    When the driver commands the doors closed
    And 150 ms pass
    Then the cab 1 monitor changes "doors" to "closed" within 150 ms

  @req:ILK-05 @req:TST-04
  Scenario: F-VSD-01 Doors commanded open at 6 km/h are never displayed open
    Given the train runs at 6 km/h
    When 300 ms pass
    And the driver commands the doors open
    And 500 ms pass
    Then the "doors" is closed
    And the cab 1 monitor displays "door-open relay" as "released"
    And the cab 1 monitor never displayed "doors" as "open"

  @req:ILK-05 @req:TST-04 @tentative
  Scenario: F-VSD-01 A door command given at 6 km/h is displayed open once the train has stopped
    Given the train runs at 6 km/h
    And the doors are open
    When 300 ms pass
    And the train speed changes to 0 km/h
    And 150 ms pass
    Then the cab 1 monitor changes "door-open relay" to "acting" within 150 ms
    And the cab 1 monitor changes "doors" to "open" within 150 ms
