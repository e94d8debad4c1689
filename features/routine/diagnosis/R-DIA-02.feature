@item:R-DIA-02 @profile:crh2
Feature: R-DIA-02 Device transmission diagnosis
  Routine diagnosis test. Requirements: NET-09 (primary), NET-02, TST-03.
  A failed transmission board or a silent unit is shown on the cab monitor.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-09 @req:NET-02 @req:TST-03
  Scenario: R-DIA-02 A failed MDM9 (the CI/BCU link) is shown on the cab monitor
    When board "car5.LCU.MDM9" fails
    And 500 ms pass
    Then the cab 1 monitor shows "car5.LCU.MDM9 failure"

  @req:NET-02 @req:TST-03
  Scenario: R-DIA-02 An LCU that has lost its supply is shown as silent
    When the supply "car6.LCU" is switched off
    And 1000 ms pass
    Then the cab 1 monitor shows "no status data from car6.LCU"
