@item:H-WSV-01 @profile:crh2
Feature: H-WSV-01 Insulation resistance of every unit type
  Hardware/software test, withstand voltage (TST-02).
  EN 50155 insulation test: measured at 500 V DC between the circuits and the case, the insulation
  resistance of a unit is at least 20 MOhm, before the dielectric test and after it.

  Background:
    Given an 8-car CRH2 train set
    And the train is powered up

  @req:TST-02
  Scenario: H-WSV-01 Every CCU system and every LCU has at least 20 MOhm
    Then the insulation resistance of "car1.CCU.sys1" is at least 20 MOhm
    And the insulation resistance of "car1.CCU.sys2" is at least 20 MOhm
    And the insulation resistance of "car8.CCU.sys1" is at least 20 MOhm
    And the insulation resistance of "car1.LCU" is at least 20 MOhm
    And the insulation resistance of "car3.LCU" is at least 20 MOhm
    And the insulation resistance of "car8.LCU" is at least 20 MOhm

  @req:TST-02
  Scenario: H-WSV-01 The insulation still has at least 20 MOhm after the rated dielectric test
    When "car5.LCU" is given a withstand-voltage test at 1500 V rms for 60 s
    And 61 s pass
    Then the insulation resistance of "car5.LCU" is at least 20 MOhm
