@item:F-CTL-06 @profile:crh2
Feature: F-CTL-06 No-power (neutral) section passing control
  Requirements: ILK-04 (primary), TST-05, TST-04.
  Automatic passing of a neutral section, seen from the commands: the advance warning takes traction off
  (no CI receives a notch above 0 from 40 ms on) and opens both VCBs before the section; traction stays off
  through the section; the exit signal closes the VCBs and the driver's notch reaches every CI again within
  40 ms without the driver touching the controller. A faulty warning signal makes the entry signal force the
  same passing (ILK-04). The 40 ms bound is the project's desk-to-CI bound (docs/decisions.md).

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 6
    And the train runs at 200 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-04 @req:TST-05 @req:TST-04
  Scenario: F-CTL-06 The warning takes traction off and opens the VCBs, the exit signal gives both back
    When 100 ms pass
    Then from 0 ms on every CI and BCU receives only traction notch 6 and brake step 0 over path 1
    When the neutral-section warning signal arrives
    And 300 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
    And the "unit1.VCB" is open within 100 ms
    And the "unit2.VCB" is open within 100 ms
    When the neutral-section entry signal arrives
    And 500 ms pass
    Then no CI receives a traction notch above 0 from 0 ms on
    And the "unit1.VCB" stays open
    And the "unit2.VCB" stays open
    When the neutral-section exit signal arrives
    And 200 ms pass
    Then the "unit1.VCB" is closed within 100 ms
    And the "unit2.VCB" is closed within 100 ms
    And the "traction" is permitted
    And every CI receives traction notch 6 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 6 and brake step 0 over path 1

  @req:ILK-04 @req:TST-05 @req:TST-04
  Scenario: F-CTL-06 The monitor shows the passing and the notch the converters received
    When the neutral-section warning signal arrives
    And 300 ms pass
    Then the cab 1 monitor displays "neutral section" as "warned" within 150 ms
    And the cab 1 monitor displays "traction notch" as "0" within 150 ms
    And the cab 1 monitor displays "unit1.VCB" as "open" within 150 ms
    When the neutral-section entry signal arrives
    And the neutral-section exit signal arrives
    And 300 ms pass
    Then the cab 1 monitor displays "neutral section" as "idle" within 150 ms
    And the cab 1 monitor displays "traction notch" as "6" within 150 ms
    And the cab 1 monitor displays "unit2.VCB" as "closed" within 150 ms

  @req:ILK-04 @req:TST-05 @req:TST-04
  Scenario: F-CTL-06 With a faulty warning signal the forced entry signal takes traction off
    Given the neutral-section device reports "warning signal fault"
    When the neutral-section entry signal arrives
    And 300 ms pass
    Then the "neutral section" is passing
    And no CI receives a traction notch above 0 from 40 ms on
    And the "unit1.VCB" is open within 100 ms
    When the neutral-section exit signal arrives
    And 200 ms pass
    Then every CI receives traction notch 6 within 40 ms
    And the "unit2.VCB" is closed within 100 ms

  @req:ILK-04 @req:TST-05 @req:TST-04
  Scenario: F-CTL-06 Braking through the section still reaches every BCU while traction is off
    When the neutral-section warning signal arrives
    And the driver moves the traction notch of cab 1 to 0
    And the driver moves the brake handle of cab 1 to step 3
    And 200 ms pass
    Then every BCU receives brake step 3 over path 1 within 40 ms
    And no CI receives a traction notch above 0 from 40 ms on
