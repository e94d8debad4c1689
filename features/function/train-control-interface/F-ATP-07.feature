@item:F-ATP-07 @profile:atp @req:TST-04
Feature: F-ATP-07 CFSK track-circuit decoding: health, 3-comparison confirmation, carrier sets, records
  Requirements: ATP-01 (primary), ATP-03, ATP-04, ATP-05, TST-04.
  The CFSK board decodes the track circuit for the safety computer: its decoded result while healthy, its
  fault information when not. A new carrier is confirmed only after 3 agreeing comparisons and reported
  with its low-frequency code. Balise up/down-line information switches the carrier set, as the driver can
  at the DMI. Each report is recorded with code, carrier, amplitude, CFSK state and track-circuit type, and
  so is each fault, however soon after the last one.

  Background:
    Given a CTCS-2 200C on-board ATP on the test rig
    And the ATP has completed its start-up self-test
    And the train is at 500 m running at 0 km/h

  @req:ATP-03
  Scenario: F-ATP-07 A new carrier is reported with its code after 3 agreeing comparisons
    When the signal generator switches to 2300 Hz with code L2
    And 1000 ms pass
    Then the CFSK reports 2300 Hz with code L2 together, after 3 agreeing comparisons

  @req:ATP-03
  Scenario: F-ATP-07 A carrier heard in only 2 comparisons is never reported
    Given the signal generator sends 1700 Hz with code L
    When 1000 ms pass
    And the signal generator sends 2300 Hz for 2 comparisons, then 1700 Hz again
    And 1000 ms pass
    Then the CFSK does not report 2300 Hz

  @req:ATP-01
  Scenario: F-ATP-07 A faulty CFSK sends its fault information, never a decoded result
    Given the signal generator sends 1700 Hz with code L
    When 1000 ms pass
    And "CFSK" fails
    And the signal generator switches to 2300 Hz with code U
    And 1000 ms pass
    Then the safety computer gets the CFSK fault and no decoded result
    And the DMI shows "CFSK fault"
    And the ATP records for the CFSK state fault

  @req:ATP-01 @req:ATP-05
  Scenario: F-ATP-07 Two CFSK faults a second apart are both recorded
    Given the signal generator sends 1700 Hz with code L
    When 1000 ms pass
    And "CFSK" fails
    And 500 ms pass
    And "CFSK" is repaired
    And 500 ms pass
    And "CFSK" fails
    And 500 ms pass
    Then the safety computer gets the CFSK fault and no decoded result
    And from 0 ms on the ATP records for the CFSK state fault

  @req:ATP-01
  Scenario: F-ATP-07 A repaired CFSK decodes the track circuit again
    Given the signal generator sends 1700 Hz with code L
    When 1000 ms pass
    And "CFSK" fails
    And 1000 ms pass
    And "CFSK" is repaired
    And the signal generator switches to 2300 Hz with code U
    And 1000 ms pass
    Then the CFSK reports 2300 Hz with code U together, after 3 agreeing comparisons

  @req:ATP-04
  Scenario: F-ATP-07 An up-line balise switches the CFSK to the up-line carriers
    Given the signal generator sends 2000 Hz with code L
    When 1000 ms pass
    Then the CFSK uses the down-line carrier set
    And the CFSK does not report 2000 Hz
    When the train passes balise group "1-2-3-4" with up-line information
    And 1000 ms pass
    Then the CFSK uses the up-line carrier set
    And the CFSK reports 2000 Hz with code L together, after 3 agreeing comparisons

  @req:ATP-04
  Scenario: F-ATP-07 The driver selects the up-line carrier set at the DMI
    When the driver selects the up-line carrier set at the DMI
    And 100 ms pass
    Then the CFSK uses the up-line carrier set

  @req:ATP-05
  Scenario: F-ATP-07 The CFSK records code, carrier, amplitude, state and track-circuit type
    Given the signal generator reports amplitude 420 mV on a ZPW-2000A track circuit
    And the signal generator sends 2300 Hz with code LU
    When 1000 ms pass
    Then the ATP records for the CFSK code LU, carrier 2300, amplitude 420mV, state ok and type ZPW-2000A

  # ATP-05 records the carrier and the code; a failed CFSK has decoded neither (ATP-01). That its record then
  # says carrier 0 (no carrier, not a frequency) and code - (no code, not the last one heard) is the project's
  # reading (docs/decisions.md, "A CFSK record with no carrier"): a decision, hence @tentative.
  @req:ATP-05 @req:ATP-01 @tentative
  Scenario: F-ATP-07 A failed CFSK's record names no carrier
    Given the signal generator sends 1700 Hz with code L
    When 1000 ms pass
    And "CFSK" fails
    And 500 ms pass
    Then from 0 ms on the ATP records for the CFSK state fault, carrier 0 Hz and code -
