@item:F-RSD-03 @profile:crh2
Feature: F-RSD-03 The running state displayed is what the network delivered, not the desk setting
  Requirements: ILK-08 (primary), FS-03, TST-04.
  The monitor shows the traction notch, brake step and direction that car 1's LCU last received over the
  ring (docs/decisions.md, "Display"), so it shows what the cars were told: a notch the interlocks suppressed
  is shown as 0, an ATP brake as the full-service step 7, and a dead desk input supply as the safe state
  (FS-03: brake step 7, neutral). The figures are the project's decisions (docs/decisions.md), hence tentative.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And the train has been powered up for 1000 ms

  @req:ILK-08 @req:TST-04 @tentative
  Scenario: F-RSD-03 A brake handle moved with the notch still at 5 is displayed as notch 0
    Then the cab 1 monitor displays "traction notch" as "5"
    When the driver moves the brake handle of cab 1 to step 3
    And 200 ms pass
    Then the cab 1 monitor changes "traction notch" to "0" within 200 ms
    And the cab 1 monitor changes "brake step" to "3" within 200 ms
    And the cab 1 monitor never displayed "traction notch" as "5"

  @req:ILK-08 @req:TST-04 @tentative
  Scenario: F-RSD-03 An ATP service brake is displayed as brake step 7 with the handle released
    When the ATP commands a service brake
    And 200 ms pass
    Then the cab 1 monitor changes "brake step" to "7" within 200 ms
    And the cab 1 monitor changes "traction notch" to "0" within 200 ms
    When the ATP releases its brake
    And 200 ms pass
    Then the cab 1 monitor changes "brake step" to "0" within 200 ms
    And the cab 1 monitor changes "traction notch" to "5" within 200 ms

  # Not that the brake step stays 0: with the notch suppressed at standstill a product may hold a brake of its
  # own (docs/decisions.md, "Standstill holding brake (crh2)"); no requirement says open doors brake or not.
  @req:ILK-08 @req:TST-04 @tentative
  Scenario: F-RSD-03 Open doors without the bypass are displayed as notch 0
    When the driver commands the doors open
    And 200 ms pass
    Then the "doors" is open
    And the cab 1 monitor changes "traction notch" to "0" within 200 ms

  @req:FS-03 @req:TST-04 @tentative
  Scenario: F-RSD-03 A dead desk input supply is displayed as brake step 7 and neutral
    When the supply "car1.desk" is switched off
    And 200 ms pass
    Then the cab 1 monitor changes "brake step" to "7" within 200 ms
    And the cab 1 monitor changes "direction" to "neutral" within 200 ms
    And the cab 1 monitor changes "traction notch" to "0" within 200 ms
