@item:F-ATP-12 @profile:atp @req:TST-04
Feature: F-ATP-12 Neutral sections from ETCS-68, ETCS-46 parsed, and the missing balise-group exception
  Requirements: ATP-11 (primary), ATP-12, TST-04.
  The ATP passes a neutral section announced in an ETCS-68 packet by itself; an ETCS-46 packet is read
  without a balise information error. A linked balise group that is not found brings maximum service brake,
  except groups 70-2-4-15 and 70-2-4-16 (site-specific: linking reaction none).

  Background:
    Given a CTCS-2 200C on-board ATP on the test rig
    And the ATP has completed its start-up self-test
    And the train is at 500 m running at 0 km/h

  @req:ATP-11
  Scenario: F-ATP-12 The neutral section announced by ETCS-68 is passed: the command covers the whole section
    Given the train has passed balise group "5-1-1-1" announcing a neutral section from 1000 m, 30 m long (ETCS-68)
    When the train runs from 900 m to 1200 m at 72 km/h
    Then the ATP's neutral-section passing command covers 1000 m to 1030 m, to within 1 m

  # ATP-11 gives no window: a product may command passing ahead of the section (the breaker's opening time) and
  # hold it until the pantographs behind the front are through. The section's own ends, as the reference
  # commands them, are shown as information.
  @req:ATP-11 @informative
  Scenario: F-ATP-12 The passing command begins and ends with the section itself, to within 1 m
    Given the train has passed balise group "5-1-1-1" announcing a neutral section from 1000 m, 30 m long (ETCS-68)
    When the train runs from 900 m to 1200 m at 72 km/h
    Then the ATP commands neutral-section passing from 1000 m to 1030 m, to within 1 m

  # That the command ends once the train is past is the project's reading of "passing" (docs/decisions.md,
  # "Neutral-section passing window"): 420 m past the section's end, longer than a 16-car CRH2 set (401 m).
  @req:ATP-11 @tentative
  Scenario: F-ATP-12 Inside the neutral section the ATP's output commands passing, once the train is past no longer
    Given the train has passed balise group "5-1-1-1" announcing a neutral section from 1000 m, 30 m long (ETCS-68)
    When the train runs from 900 m to 1015 m at 72 km/h
    Then the ATP is commanding neutral-section passing
    When the train runs from 1015 m to 1450 m at 72 km/h
    Then the ATP is not commanding neutral-section passing

  @req:ATP-11
  Scenario: F-ATP-12 An ETCS-46 packet is read without error
    When the train passes balise group "5-1-1-2" with an ETCS-46 packet
    And 100 ms pass
    Then the DMI does not show "balise information error"
    And the ATP commands no brake

  @req:ATP-11
  Scenario: F-ATP-12 A packet the ATP does not know is a balise information error
    When the train passes balise group "5-1-1-3" with an ETCS-99 packet
    And 100 ms pass
    Then the DMI shows "balise information error"
    And the ATP commands max service brake

  # The group announced at 800 m is read there: it is not missing, so no reaction, and no brake (seed 23 took
  # a group for missing once the train was 20 m short of its place).
  @req:ATP-12
  Scenario: F-ATP-12 A linked group read where it was announced brings no linking reaction
    Given the train has passed balise group "70-2-4-14" linking to group "70-2-4-17" at 800 m
    When the train runs from 500 m to 800 m at 72 km/h
    And the train passes balise group "70-2-4-17" with an ETCS-46 packet
    And the train runs from 800 m to 900 m at 72 km/h
    Then the ATP commands no brake
    And the DMI does not show "balise information error"

  # A group that never came is no packet the ATP could not use (ATP-11): whatever the DMI says of it, it is not
  # a balise information error.
  @req:ATP-12 @req:ATP-11
  Scenario Outline: F-ATP-12 Missing group <group>: linking reaction <reaction>
    Given the train has passed balise group "70-2-4-14" linking to group "<group>" at 800 m
    When the train runs from 500 m to 900 m at 72 km/h
    Then the linking reaction to the missing group "<group>" is <reaction>
    And the ATP commands <brake> brake
    And the DMI does not show "balise information error"

    Examples:
      | group     | reaction    | brake       |
      | 70-2-4-15 | none        | no          |
      | 70-2-4-16 | none        | no          |
      | 70-2-4-17 | max service | max service |
