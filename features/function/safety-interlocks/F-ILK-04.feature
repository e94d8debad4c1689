@item:F-ILK-04 @profile:crh2 @req:TST-04
Feature: F-ILK-04 Automatic neutral-section passing and its signal faults
  Requirements: ILK-04 (primary), TST-04.
  Normal passing opens the VCBs on the advance warning and closes them on the exit signal. A severe
  device fault raises a network alarm and leaves passing to the driver; a faulty warning signal makes the
  network force automatic passing on the entry signal; a missing entry or exit signal hands the step to
  the driver. The timeouts for "missing" (15 s after the warning, 10 s after the entry) are the project's.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train runs at 200 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-04
  Scenario: F-ILK-04 The warning opens the VCBs, the exit signal closes them again
    When the neutral-section warning signal arrives
    And 100 ms pass
    Then the "unit1.VCB" is open within 100 ms
    And the "unit2.VCB" is open within 100 ms
    When the neutral-section entry signal arrives
    And the neutral-section exit signal arrives
    And 100 ms pass
    Then the "unit1.VCB" is closed within 100 ms
    And the "neutral section" is idle

  @req:ILK-04
  Scenario: F-ILK-04 With a faulty warning signal the entry signal forces automatic passing
    Given the neutral-section device reports "warning signal fault"
    When the neutral-section entry signal arrives
    And 100 ms pass
    Then the "unit1.VCB" is open within 100 ms
    And the cab 1 monitor shows "neutral section: warning signal fault, forced automatic passing"

  @req:ILK-04
  Scenario: F-ILK-04 A severe device fault raises an alarm and leaves passing to the driver
    Given the neutral-section device reports "severe fault"
    When the neutral-section warning signal arrives
    And 100 ms pass
    Then the cab 1 monitor shows "neutral section: severe fault, pass manually"
    And the "unit1.VCB" stays closed
    And the "neutral section" is manual passing

  @req:ILK-04
  Scenario: F-ILK-04 A repaired neutral-section device clears its alarm
    Given the neutral-section device reports "severe fault"
    When 100 ms pass
    Then the cab 1 monitor shows "neutral section: severe fault, pass manually"
    When the neutral-section device comes to report "normal"
    And 100 ms pass
    Then the cab 1 monitor does not show "neutral section: severe fault, pass manually"

  @req:ILK-04 @tentative
  Scenario: F-ILK-04 Without an entry signal the driver is told to enter manually
    When the neutral-section warning signal arrives
    And 16 s pass
    Then the cab 1 monitor shows "neutral section: no entry signal, enter manually"

  @req:ILK-04 @tentative
  Scenario: F-ILK-04 Without an exit signal the driver restores the pre-section state by hand
    When the neutral-section warning signal arrives
    And the neutral-section entry signal arrives
    And 11 s pass
    Then the cab 1 monitor shows "neutral section: no exit signal, restore manually"
    And the "unit1.VCB" is open
    When the driver restores the pre-section state manually
    And 100 ms pass
    Then the "unit1.VCB" is closed within 100 ms
