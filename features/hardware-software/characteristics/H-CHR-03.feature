@item:H-CHR-03 @profile:crh2
Feature: H-CHR-03 The rated environment the train declares covers the standards
  Hardware/software test, characteristics (TST-02).
  The environment tests below apply the standards' ranges; here the train's own declaration is checked
  against them: EN 50155 supply range (Un = 110 V, continuous 0.7 .. 1.25 Un, 0.6 Un for 0.1 s, 1.4 Un
  for 1 s, interruption class S2: 10 ms), operating temperature class OT3 (-25 .. +70 °C), EN 50121-3-2
  fast transients (2 kV), EN 50155 insulation (20 MOhm at 500 V DC) and dielectric test (1500 V rms).
  Stimuli "outside the rated range" in the other items are placed beyond these declared figures.

  Background:
    Given an 8-car CRH2 train set
    And the train is powered up

  @req:TST-02
  Scenario: H-CHR-03 The declared supply range covers EN 50155 for a 110 V supply
    Then the rated "nominal supply voltage V" is at least 110
    And the rated "nominal supply voltage V" is at most 110
    And the rated "continuous supply voltage V" covers 77 to 137.5
    And the rated "short dip supply voltage V" is at most 66
    And the rated "short dip ms" is at least 100
    And the rated "short surge supply voltage V" is at least 154
    And the rated "short surge ms" is at least 1000
    And the rated "interruption bridged ms" is at least 10

  @req:TST-02
  Scenario: H-CHR-03 The declared temperature, interference and insulation ratings cover the standards
    Then the rated "operating temperature C" covers -25 to 70
    And the rated "burst immunity kV" is at least 2
    And the rated "insulation resistance MOhm" is at least 20
    And the rated "withstand voltage V rms" is at least 1500
    And the rated "contact interruption bridged ms" is at least 1
