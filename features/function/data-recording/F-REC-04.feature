@item:F-REC-04 @profile:metro-tcn @req:TST-04
Feature: F-REC-04 CCU-CCU record backup: events reach both CCU memories over the WTB as acknowledged messages
  Requirements: RED-05 (primary), RED-04, TCN-06, TCN-08, TST-04.
  An event is recorded in the memory (VMS) of both CCUs; either CCU failing leaves recording in the
  other. Events cross the WTB as numbered messages the destination acknowledges, so a lost telegram is
  sent again and a record is stored exactly once.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:RED-05 @req:TCN-08
  Scenario: F-REC-04 An event of unit 2 is recorded in both CCUs
    When "car4.VVVF" fails
    And 1000 ms pass
    Then "car6.CCU" holds a record "car4.VVVF: no status data"
    And "car1.CCU" holds a record "car4.VVVF: no status data"

  @req:RED-05 @req:RED-04
  Scenario Outline: F-REC-04 With "<failed>" failed, "<other>" still records the events of both units
    Given "<failed>" has failed
    When 500 ms pass
    And "car2.VVVF" fails
    And "car5.VVVF" fails
    And 1000 ms pass
    Then "<other>" holds a record "car2.VVVF: no status data"
    And "<other>" holds a record "car5.VVVF: no status data"

    Examples:
      | failed       | other    |
      | car1.CCU.VMS | car6.CCU |
      | car6.CCU     | car1.CCU |
      | car1.CCU     | car6.CCU |

  @req:TCN-06
  Scenario: F-REC-04 Telegrams lost on both WTB lines neither lose nor duplicate a record
    When "car4.VVVF" fails
    And 20 ms pass
    And the next 6 frames on both lines of "WTB" are disturbed
    And 1000 ms pass
    Then "car1.CCU" holds the record "car4.VVVF: no status data" exactly once

  @req:TCN-06
  Scenario: F-REC-04 A message the destination missed is sent again until it acknowledges
    When "car6.CCU.VGWS" fails
    And "car2.VVVF" fails
    And 45 ms pass
    And "car6.CCU.VGWS" is repaired
    And 1000 ms pass
    Then "car6.CCU" holds the record "car2.VVVF: no status data" exactly once
