@item:F-DSP-05 @profile:metro-tcn @req:TST-04
Feature: F-DSP-05 Metro display units: the train's state in both cabs, through a fallback
  Requirements: TCN-08 (primary), RED-04, TCN-02, TCN-04, TST-04.
  The display unit (DU) of each cab car shows what its unit's bus master knows: the mode, the WTB master and
  the events of both units. After a WTB fallback both displays show the new master and the event.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the master controller of cab 1 demands 50 % traction
    And the train has been powered up for 1000 ms

  @req:TCN-08 @req:TCN-02
  Scenario Outline: F-DSP-05 The cab <cab> display shows normal mode and the car 1 CCU as WTB master
    When 500 ms pass
    Then the cab <cab> display shows the mode "normal"
    And the cab <cab> display shows "car1.CCU" as WTB master

    Examples:
      | cab |
      | 1   |
      | 6   |

  @req:TCN-08 @req:RED-04
  Scenario Outline: F-DSP-05 After the car 1 CCU fails the cab <cab> display shows the car 2 VCU as WTB master
    When "car1.CCU" fails
    And 1000 ms pass
    Then the cab <cab> display shows "car2.VCU" as WTB master
    And the cab <cab> display shows "WTB master (car1.CCU silent)"
    And the cab <cab> display shows the mode "normal"

    Examples:
      | cab |
      | 1   |
      | 6   |

  @req:TCN-08
  Scenario: F-DSP-05 A failed display unit goes dark; the other cab's display still shows the train
    When "car1.DU" fails
    And 100 ms pass
    Then the cab 1 display is dark
    And the cab 6 display shows the mode "normal"
    And the cab 6 display shows "car1.CCU" as WTB master

  # Project decision (docs/decisions.md, "A display whose bus master is silent"): a DU hears the train only
  # through its unit's MVB master (TCN-04). With every node that can master unit 1's MVB failed it has nothing
  # current to show and shows nothing, rather than the last mode and master as if the train were still so.
  @req:TCN-08 @req:TCN-04 @tentative
  Scenario: F-DSP-05 With no bus master left in its unit the cab 1 display goes dark
    When "car1.CCU" fails
    And "car2.VCU" fails
    And "car3.VCU" fails
    And 1000 ms pass
    Then the cab 1 display is dark
