@item:F-ATP-09 @profile:atp @req:TST-04
Feature: F-ATP-09 FS to PS at 150 m before the end of authority; the default telegram on a diverging entry
  Requirements: ATP-06 (primary), ATP-07, TST-04.
  Full supervision (FS) turns into partial supervision (PS) 150 m before the end of authority (was 300 m).
  A default telegram from a side-line balise on a diverging entry brings maximum service brake; below
  45 km/h the ATP enters PS and deletes the line data.

  Background:
    Given a CTCS-2 200C on-board ATP on the test rig
    And the ATP has completed its start-up self-test
    And the train is at 2000 m running at 0 km/h
    And the train has passed balise group "3-1-1-1" describing track circuits 0-5000 m 1700 Hz and an end of authority at 3000 m

  @req:ATP-06
  Scenario Outline: F-ATP-09 <distance> m before the end of authority the ATP is in <mode>
    When the train is set to <position> m running at 0 km/h
    And 100 ms pass
    Then the ATP is in mode <mode>

    Examples:
      | distance | position | mode |
      | 300      | 2700     | FS   |
      | 151      | 2849     | FS   |
      | 150      | 2850     | PS   |
      | 149      | 2851     | PS   |

  # Within 150 m of the end of authority the ATP supervises partially (ATP-06), whatever balise group it passes
  # meanwhile: line data repeated inside that distance does not bring full supervision back.
  @req:ATP-06
  Scenario: F-ATP-09 Within 150 m of the end of authority, the line data passed again keeps PS
    When the train is set to 2900 m running at 0 km/h
    And 100 ms pass
    Then the ATP is in mode PS
    When the train passes balise group "3-1-1-3" describing track circuits 0-5000 m 1700 Hz and an end of authority at 3000 m
    Then the ATP is in mode PS
    When 100 ms pass
    Then the ATP is in mode PS

  # ATP-06 puts the change 150 m before the end of authority: an authority extended far beyond the train brings
  # full supervision back (seed 25 kept PS for good once it was entered).
  @req:ATP-06
  Scenario: F-ATP-09 An end of authority moved 2100 m ahead of a train in PS brings FS back
    When the train is set to 2900 m running at 0 km/h
    And 100 ms pass
    Then the ATP is in mode PS
    When the train passes balise group "3-1-1-3" describing track circuits 0-5000 m 1700 Hz and an end of authority at 5000 m
    And 100 ms pass
    Then the ATP is in mode FS

  @req:ATP-07
  Scenario: F-ATP-09 A default telegram on a diverging entry: maximum service brake, FS kept at 45 km/h
    When the train is set to 2200 m running at 80 km/h
    And the train passes side-line balise group "3-1-1-2" sending the default telegram
    And 100 ms pass
    Then the ATP commands max service brake
    And the DMI shows "default telegram"
    When the train speed changes to 45 km/h
    And 100 ms pass
    Then the ATP is in mode FS
    And the line data is kept

  @req:ATP-07
  Scenario: F-ATP-09 Below 45 km/h after the default telegram: PS and the line data deleted
    When the train is set to 2200 m running at 80 km/h
    And the train passes side-line balise group "3-1-1-2" sending the default telegram
    And 100 ms pass
    And the train speed changes to 44 km/h
    And 100 ms pass
    Then the ATP is in mode PS
    And the line data is deleted
