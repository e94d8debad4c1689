@item:F-CTL-10 @profile:crh2
Feature: F-CTL-10 Door open/close command
  Requirements: ILK-05 (primary), ILK-08, TST-05, TST-04.
  The side doors follow the driver's door command only while the door-open safety relay acts, i.e. below
  5 km/h (ILK-05; the band is 4..5 km/h, docs/decisions.md); open doors block traction unless the door-interlock
  bypass switch is on (ILK-08); closing them gives the driver's notch back. The monitor shows the doors'
  state within the display bound of 150 ms.
  # why: Opening and closing the side doors at a stop, interlocked with speed and traction, is one of the control commands the CRH2 network carries and displays on every trip.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:ILK-05 @req:TST-05 @req:TST-04
  Scenario: F-CTL-10 At a standstill the doors open on command and the monitor shows them open
    When the driver commands the doors open
    And 200 ms pass
    Then the "doors" is open within 100 ms
    And the "door-open relay" is acting
    And the cab 1 monitor displays "doors" as "open" within 150 ms
    When the driver commands the doors closed
    And 200 ms pass
    Then the "doors" is closed within 100 ms
    And the cab 1 monitor displays "doors" as "closed" within 150 ms

  @req:ILK-05 @req:TST-05 @req:TST-04
  Scenario Outline: F-CTL-10 At <kmh> km/h the door command is refused
    Given the train runs at <kmh> km/h
    When the driver commands the doors open
    And 500 ms pass
    Then the "doors" stays closed
    And the "door-open relay" is released
    And the cab 1 monitor displays "doors" as "closed"

    Examples:
      | kmh |
      | 5   |
      | 30  |
      | 120 |

  @req:ILK-05 @req:TST-05 @req:TST-04
  Scenario: F-CTL-10 A door command given while running takes effect once the train is below 5 km/h
    Given the train runs at 15 km/h
    When the driver commands the doors open
    And the train speed goes from 15 km/h to 0 km/h at 5 km/h per second
    And 3500 ms pass
    Then the "doors" became open while the speed was between 4 and 5 km/h
    And the "doors" is open

  @req:ILK-05 @req:ILK-08 @req:TST-05 @req:TST-04
  Scenario: F-CTL-10 Open doors keep traction off; closing them gives the notch back
    When the driver commands the doors open
    And the driver moves the traction notch of cab 1 to 4
    And 200 ms pass
    Then the "doors" is open
    And the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
    When the driver commands the doors closed
    And 200 ms pass
    Then the "traction" is permitted
    And every CI and BCU receives traction notch 4 over path 1 within 40 ms
