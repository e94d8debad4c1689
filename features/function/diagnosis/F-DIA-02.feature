@item:F-DIA-02 @profile:crh2
Feature: F-DIA-02 A silent LCU is shown on the cab monitor
  Requirements: PRO-02 (primary), TST-04.
  Every node sends status data once per status cycle (PRO-02); the cab monitor reports a node it has not
  heard from. The bound is the project's: 650 ms = 500 ms of silence (the PRO-05 figure, so that a token
  regeneration does not raise false reports) + one 120 ms status cycle + holding time and ring. An LCU
  without its CPU-side supply is also dark on the ring (its neighbours report the links); an LCU whose
  CPU3 alone has failed still passes the token but sends no status data, so only its silence is shown.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:PRO-02 @req:TST-04 @tentative
  Scenario: F-DIA-02 An LCU without supply is shown as silent within 650 ms
    When the supply "car6.LCU" is switched off
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "no status data from car6.LCU" within 650 ms
    And the cab 1 monitor never showed "no status data from car5.LCU"
    And the cab 1 monitor never showed "no status data from car7.LCU"

  @req:PRO-02 @req:TST-04 @tentative
  Scenario: F-DIA-02 An LCU whose CPU3 has failed is shown as silent, and only that
    When board "car6.LCU.CPU3" fails
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "no status data from car6.LCU" within 650 ms
    And the cab 1 monitor showed no fault but "no status data from car6.LCU"

  @req:PRO-02 @req:TST-04 @tentative
  Scenario: F-DIA-02 The report clears within 300 ms of the supply coming back
    Given the supply "car4.LCU" is off
    When 1000 ms pass
    And the supply "car4.LCU" is switched on again
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor stopped showing "no status data from car4.LCU" within 300 ms
