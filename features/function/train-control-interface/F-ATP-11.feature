@item:F-ATP-11 @profile:atp @req:TST-04
Feature: F-ATP-11 Precise stopping, modes CS, SL and AM, and the ATO, door and platform-screen-door permissions
  Requirements: ATP-09 (primary), ATP-10, TST-04.
  After standstill the ATP checks that the train stopped within -0.5 m .. +0.5 m of the stopping point from
  the precise-positioning balise: only then does it grant door enable, and platform-screen-door permission
  where the platform has them. ATO is allowed only under full supervision without a brake.

  Background:
    Given a CTCS-2 200C on-board ATP on the test rig
    And the ATP has completed its start-up self-test
    And the train is at 900 m running at 30 km/h
    And the train has passed balise group "4-1-1-1" giving a stop point at 1000 m with platform screen doors

  @req:ATP-09 @req:ATP-10
  Scenario Outline: F-ATP-11 Stopped at <position> m: inside the window, doors and screen doors enabled
    When the train stops at <position> m
    And 100 ms pass
    Then the ATP grants door enable
    And the ATP grants PSD permission

    Examples:
      | position |
      | 999.5    |
      | 1000     |
      | 1000.5   |

  @req:ATP-09 @req:ATP-10
  Scenario Outline: F-ATP-11 Stopped at <position> m: outside the window, no door enable
    When the train stops at <position> m
    And 100 ms pass
    Then the ATP withholds door enable
    And the ATP withholds PSD permission

    Examples:
      | position |
      | 999.4    |
      | 1000.6   |

  @req:ATP-09
  Scenario: F-ATP-11 No door enable while moving, even inside the window
    When the train is set to 1000 m running at 3 km/h
    Then the ATP withholds door enable

  @req:ATP-10
  Scenario: F-ATP-11 ATO allowed under full supervision; AM when it starts
    Given the train has passed balise group "4-1-1-2" describing track circuits 0-5000 m 1700 Hz and an end of authority at 5000 m
    When 100 ms pass
    Then the ATP is in mode FS
    And the ATP grants ATO allowed
    When the ATP input "ATO start" is set
    Then the ATP is in mode AM

  @req:ATP-10
  Scenario: F-ATP-11 No ATO without full supervision; cab signal mode without line data; sleep
    Then the ATP withholds ATO allowed
    When the ATP input "ATO start" is set
    Then the ATP is in mode SB
    When the ATP input "cab signal mode" is set
    Then the ATP is in mode CS
    When the ATP input "sleep" is set
    Then the ATP is in mode SL
    When the ATP input "sleep" is cleared
    Then the ATP is in mode SB
