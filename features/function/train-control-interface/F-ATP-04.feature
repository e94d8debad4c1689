@item:F-ATP-04 @profile:vdx @req:TST-04
Feature: F-ATP-04 VDX emergency-brake loop: EB1R and EB2R in series, the isolation switch, the supply range
  Requirements: VDX-01 (primary), VDX-02, VDX-04, TST-04.
  The ATP opens the train's emergency-brake loop through EB1R (energised = brake, HR output) and EB2R
  (de-energised = brake, FS output) in series; the isolation switch bypasses both. The VDX works on
  110 V DC from 70 % to 125 % (77-137.5 V); the edges are tested moved inside by the supply accuracy the
  VDX declares (supply_accuracy_pct). Bound from the relay data (VDX-04): the NO contact of EB2R moves within
  6 ms of its coil losing power. The FS output's voltage no requirement gives: on is not low in VDX-03's
  sense (6 V or more), off is below 6 V.

  Background:
    Given a CTCS3-300T ATP with its VDX emergency-brake interface
    And the train has been powered up for 1000 ms

  @req:VDX-01
  Scenario: F-ATP-04 Released: EB2R energised, EB1R not, the loop closed
    When the ATP releases the emergency brake
    And 100 ms pass
    Then the emergency-brake loop is closed
    And relay EB2R is energised
    And relay EB1R is de-energised
    And the FS output reads at least 6 V

  @req:VDX-01 @req:VDX-04
  Scenario: F-ATP-04 Braking: the loop opens within 6 ms through both relays
    Given the ATP has released the emergency brake
    When 100 ms pass
    And the ATP applies the emergency brake
    And 100 ms pass
    Then the emergency-brake loop opens within 6 ms of the FS output going off
    And relay EB2R is de-energised
    And relay EB1R is energised
    And the FS output reads below 6 V

  # Fail-safe (VDX-01): EB2R is de-energised for a brake, so a VDX that loses its own supply can energise it no
  # more, and the loop opens whatever the ATP last commanded.
  @req:VDX-01
  Scenario: F-ATP-04 The VDX's supply switched off while released: EB2R drops and the loop opens
    Given the ATP has released the emergency brake
    When 100 ms pass
    And the supply "VDX" is switched off
    And 100 ms pass
    Then the emergency-brake loop is open
    And relay EB2R is de-energised
    And the FS output reads below 6 V

  @req:VDX-01
  Scenario: F-ATP-04 The isolation switch bypasses both relays
    When the ATP isolation switch is turned on
    And 100 ms pass
    Then the emergency-brake loop is closed
    And relay EB1R is energised

  # The bypass, not the relays behind it: whether a VDX keeps driving its outputs after the switch or sets them
  # to brake at once, VDX-01 does not say; the loop must not open either way.
  @req:VDX-01
  Scenario: F-ATP-04 Isolated after a release, the loop stays closed through the ATP's brake
    Given the ATP has released the emergency brake
    When 100 ms pass
    And the ATP isolation switch is turned on
    And 100 ms pass
    Then the emergency-brake loop is closed
    When the ATP applies the emergency brake
    And 100 ms pass
    Then the emergency-brake loop stays closed
    And relay EB2R is de-energised
    And relay EB1R is energised

  @req:VDX-02
  Scenario Outline: F-ATP-04 Inside 70-125 % of 110 V (<volts> V) the brake is released
    Given the FS output is fed with <volts> V
    And the ATP has released the emergency brake
    When 12 s pass
    Then the emergency-brake loop is closed
    And no C019 is raised

    Examples:
      | volts |
      | 77    |
      | 110   |
      | 137.5 |

  # VDX-02 gives the range it works in, not where it stops: a supply just outside may still be worked. Well
  # outside it, the project reads the fail-safe principle as a brake (docs/decisions.md, "VDX outside its
  # supply range"): a decision, hence @tentative, tested far from the edges.
  @req:VDX-02 @tentative
  Scenario Outline: F-ATP-04 Far outside 70-125 % of 110 V (<volts> V) the VDX brakes
    Given the ATP has released the emergency brake
    When 100 ms pass
    And the VDX supply goes to <volts> V
    And 100 ms pass
    Then the emergency-brake loop opens within 20 ms

    Examples:
      | volts |
      | 50    |
      | 165   |
