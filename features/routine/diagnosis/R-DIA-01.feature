@item:R-DIA-01 @profile:crh2
Feature: R-DIA-01 Optical transmission diagnosis
  Routine diagnosis test. Requirements: NET-03 (primary), TST-03.
  A cut optical link is reported in the status data of the nodes beside it and shown on the cab monitor.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-03 @req:TST-03
  Scenario: R-DIA-01 The cab monitor names a cut optical link within 500 ms
    When the ring link between "car3.LCU" and "car4.LCU" is cut
    And 500 ms pass
    Then the cab 1 monitor shows "optical transmission fault between car3.LCU and car4.LCU"

  @req:NET-03 @req:TST-03
  Scenario: R-DIA-01 A healthy ring shows no optical fault
    When 500 ms pass
    Then the cab 1 monitor shows no faults
