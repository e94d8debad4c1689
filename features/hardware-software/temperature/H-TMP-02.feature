@item:H-TMP-02 @profile:crh2
Feature: H-TMP-02 A CCU system above its rated temperature: fail-safe, takeover, recovery
  Hardware/software test, high/low temperature (TST-02). Requirements: FS-02, RED-01, RED-02.
  Beyond its rated temperature a unit cannot vouch for its outputs, so it stops talking (FS-02; the
  reaction is a project decision, docs/decisions.md "Environment"). For CCU system 1 that means system 2 takes
  over (RED-02); back in range, system 1 restarts by itself as standby and records why.
  The stimulus is placed relative to the SUT's declared maximum, so a wider rating is tested beyond itself.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:FS-02 @req:RED-01 @req:RED-02 @tentative
  Scenario: H-TMP-02 CCU system 1 too hot: it stops talking and system 2 takes over
    When the temperature of "car1.CCU.sys1" rises to 15 °C above its rated maximum
    And the cab 1 monitor is watched for 1000 ms
    Then "car1.CCU.sys1" sends nothing on the ring from 100 ms to 1000 ms after the action
    And system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every CI and BCU receives traction notch 7 over path 1 within 80 ms
    And the cab 1 monitor showed "no status data from car1.CCU.sys1" within 750 ms

  @req:TST-02 @req:FS-02 @req:RED-02 @tentative
  Scenario: H-TMP-02 Back in range, CCU system 1 restarts as standby and records the over-temperature
    When the temperature of "car1.CCU.sys1" rises to 15 °C above its rated maximum
    And 1000 ms pass
    And the temperature of "car1.CCU.sys1" changes to 20 °C
    And the cab 1 monitor is watched for 2000 ms
    Then "car1.CCU.sys1" sends status data again within 1000 ms
    And the cab 1 monitor stopped showing "no status data from car1.CCU.sys1" within 1500 ms
    And "car1.CCU.sys1" puts no commands on the ring
    And the maintenance view of cab 1 lists "car1.CCU.sys1.supply restarted after over-temperature"

  @req:TST-02 @req:RED-02
  Scenario: H-TMP-02 CCU system 1 at its rated maximum keeps commanding
    When the temperature of "car1.CCU.sys1" changes to 70 °C
    And the cab 1 monitor is watched for 1000 ms
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And the cab 1 monitor never showed a fault
