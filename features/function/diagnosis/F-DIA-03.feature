@item:F-DIA-03 @profile:crh2
Feature: F-DIA-03 Main circuit protection and insufficient brake force shown on the cab monitor
  Requirements: ILK-06 (primary), ILK-03, TST-04.
  Protection that acts is shown on the cab monitor: main circuit protection of a traction unit (ILK-06;
  it acts within 100 ms and is shown within the 150 ms display bound: 250 ms) and insufficient brake force
  (ILK-03; the project's definition is below 50 % of the demand for 500 ms, docs/decisions.md: shown within
  650 ms). The report stays while the protection is latched and goes when the driver resets it; a shorter
  loss of brake force raises nothing.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:ILK-06 @req:TST-04 @tentative
  Scenario: F-DIA-03 A transformer over-current in unit 1 is shown within 250 ms, for unit 1 only
    When the vehicle input "unit1.transformer" becomes "primary overcurrent"
    And the cab 1 monitor is watched for 500 ms
    Then the cab 1 monitor showed "unit1: main circuit protection acted" within 250 ms
    And the cab 1 monitor never showed "unit2: main circuit protection acted"

  @req:ILK-06 @req:TST-04 @tentative
  Scenario: F-DIA-03 The report stays until the driver resets the main circuit
    When the vehicle input "unit2.transformer" becomes "secondary earth fault"
    And 300 ms pass
    And the vehicle input "unit2.transformer" becomes "normal"
    And the cab 1 monitor is watched for 500 ms
    Then the cab 1 monitor shows "unit2: main circuit protection acted"
    When the driver resets the main circuit
    And the cab 1 monitor is watched for 500 ms
    Then the cab 1 monitor stopped showing "unit2: main circuit protection acted" within 250 ms

  @req:ILK-03 @req:TST-04 @tentative
  Scenario: F-DIA-03 Insufficient brake force is shown within 650 ms
    Given the brake force of car 3 is 30 % of the demand
    When the driver moves the brake handle of cab 1 to step 4
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "insufficient brake force" within 650 ms

  @req:ILK-03 @req:TST-04 @tentative
  Scenario: F-DIA-03 Brake force lost for 300 ms only, or full brake force, raises nothing
    Given the brake force of car 3 is 30 % of the demand
    When the driver moves the brake handle of cab 1 to step 4
    And the cab 1 monitor is watched for 300 ms
    And the vehicle input "car3.brake force" becomes "100"
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor never showed "insufficient brake force"
    And the "emergency brake" never became applied
