@item:H-TMP-03 @profile:crh2
Feature: H-TMP-03 An LCU below its rated temperature: fail-safe and recovery
  Hardware/software test, high/low temperature (TST-02). Requirements: FS-02, NET-03, CMD-02.
  An LCU colder than its rating stops talking (FS-02, project decision); the rest of the ring goes on
  (NET-03: the dead node's two spans are one fault), the other cars keep path 1, the monitor names the
  silent node, and when the LCU is warm again it restarts and its car's CI and BCU are commanded again.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:FS-02 @req:NET-03 @tentative
  Scenario: H-TMP-03 An LCU too cold stops talking, the other cars go on
    When the temperature of "car3.LCU" falls to 15 °C below its rated minimum
    And the cab 1 monitor is watched for 1000 ms
    Then "car3.LCU" sends nothing on the ring from 100 ms to 1000 ms after the action
    And from 40 ms on every CI and BCU outside car 3 receives traction notch 7 over path 1
    And no CI or BCU receives a traction notch other than 7
    And the cab 1 monitor showed "no status data from car3.LCU" within 750 ms

  @req:TST-02 @req:FS-02 @req:CMD-02 @tentative
  Scenario: H-TMP-03 Warm again, the LCU restarts and its car is commanded over path 1 again
    When the temperature of "car3.LCU" falls to 15 °C below its rated minimum
    And 1000 ms pass
    And the temperature of "car3.LCU" changes to 20 °C
    And the cab 1 monitor is watched for 2000 ms
    Then "car3.LCU" sends status data again within 1000 ms
    And the CI and BCU of car 3 receive traction notch 7 over path 1 within 1000 ms
    And the cab 1 monitor stopped showing "no status data from car3.LCU" within 1500 ms
    And the maintenance view of cab 1 lists "car3.LCU.supply restarted after under-temperature"

  @req:TST-02 @req:CMD-02
  Scenario: H-TMP-03 An LCU at its rated minimum keeps its car on path 1
    When the temperature of "car3.LCU" changes to -25 °C
    And the cab 1 monitor is watched for 1000 ms
    Then the CI and BCU of car 3 receive traction notch 7 over path 1 within 20 ms
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor never showed a fault
