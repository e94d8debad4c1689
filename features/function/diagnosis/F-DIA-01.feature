@item:F-DIA-01 @profile:crh2
Feature: F-DIA-01 Optical transmission diagnosis on the cab monitor
  Requirements: NET-03 (primary), TST-04.
  A cut optical link is reported in the status data of the nodes beside it and shown on the cab monitor
  within the display bound of 150 ms (docs/decisions.md); with one link fault every node still reaches every
  other (NET-03), so nothing else is shown. After the link is restored the ring re-forms its token and
  the report clears within two status cycles (300 ms). A healthy train shows no fault at all.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-03 @req:TST-04 @tentative
  Scenario: F-DIA-01 A cut link between car 3 and car 4 is shown within 150 ms, and nothing else
    When the ring link between "car3.LCU" and "car4.LCU" is cut
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "optical transmission fault between car3.LCU and car4.LCU" within 150 ms
    And the cab 1 monitor showed no fault but "optical transmission fault between car3.LCU and car4.LCU"

  @req:NET-03 @req:TST-04 @tentative
  Scenario: F-DIA-01 A cut link at the far end of the ring is shown within 150 ms
    When the ring link between "car7.LCU" and "car8.LCU" is cut
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "optical transmission fault between car7.LCU and car8.LCU" within 150 ms
    And the cab 1 monitor showed no fault but "optical transmission fault between car7.LCU and car8.LCU"

  # The nodes beside a dark one report its links; where one of them is the CCU system feeding the monitor, that
  # system reports its own port (seed 25 lost that report and no scenario had the fault beside the feeder).
  @req:NET-03 @req:TST-04 @tentative
  Scenario: F-DIA-01 A CCU system gone dark beside the one feeding the monitor: both of its links are shown
    When the supply "car1.CCU.sys2" is switched off
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor showed "optical transmission fault between car1.CCU.sys1 and car1.CCU.sys2" within 650 ms
    And the cab 1 monitor showed "optical transmission fault between car1.CCU.sys2 and car1.LCU" within 650 ms

  @req:NET-03 @req:TST-04 @tentative
  Scenario: F-DIA-01 The report clears within 300 ms of the link being restored
    Given the ring link between "car5.LCU" and "car6.LCU" is cut
    When 1000 ms pass
    And the ring link between "car5.LCU" and "car6.LCU" is restored
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor stopped showing "optical transmission fault between car5.LCU and car6.LCU" within 300 ms
    And the cab 1 monitor never showed "no status data from car5.LCU"

  @req:TST-04
  Scenario: F-DIA-01 A healthy train shows no fault
    When the cab 1 monitor is watched for 1500 ms
    Then the cab 1 monitor never showed a fault
    And the cab 8 monitor shows no faults
