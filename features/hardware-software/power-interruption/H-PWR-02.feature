@item:H-PWR-02 @profile:crh2
Feature: H-PWR-02 A longer interruption of one CCU system: takeover, nothing lost, recovery
  Hardware/software test, momentary power interruption (TST-02). Requirements: RED-01, RED-02, PRO-06, FS-02.
  An interruption beyond class S2 (100 ms) may reset the unit; when it is one CCU system, RED-01/02 keep
  the train commanded: system 2 takes over within the RED-02 bound, block data reach the recorder all the
  same, and system 1 comes back as standby and records why it restarted.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:RED-01 @req:RED-02 @req:FS-02 @tentative
  Scenario: H-PWR-02 A 100 ms interruption of CCU system 1: system 2 takes over, system 1 comes back as standby
    When the supply "car1.CCU.sys1" is interrupted for 100 ms
    And the cab 1 monitor is watched for 2000 ms
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 75 ms
    And "car1.CCU.sys1" sends status data again within 1000 ms
    And "car1.CCU.sys1" puts no commands on the ring from 100 ms on
    And the maintenance view of cab 1 lists "car1.CCU.sys1.supply restarted"

  @req:TST-02 @req:RED-01 @req:RED-02 @tentative
  Scenario: H-PWR-02 A second interruption while CCU system 1 boots: it still comes back as standby once the supply holds
    When the supply "car1.CCU.sys1" is interrupted for 100 ms
    And 200 ms pass
    And the supply "car1.CCU.sys1" is interrupted for 100 ms
    And the cab 1 monitor is watched for 2000 ms
    Then "car1.CCU.sys1" sends status data again within 1000 ms
    And "car1.CCU.sys1" puts no commands on the ring from 100 ms on
    And no CI or BCU goes without a command for more than 75 ms

  @req:TST-02 @req:RED-02 @req:PRO-06
  Scenario: H-PWR-02 The recorder loses no block data across the takeover
    When "car5.LCU" asks to send a 600-byte record as block data
    And the supply "car1.CCU.sys1" is interrupted for 100 ms
    And 3000 ms pass
    Then "car1.CCU.sys2" holds the 600-byte record of "car5.LCU"

  @req:TST-02 @req:RED-02 @req:FS-02 @tentative
  Scenario: H-PWR-02 A 100 ms interruption of system 1's TXC: system 2 takes over, the TXC reports back
    When the supply "car1.CCU.sys1.TXC" is interrupted for 100 ms
    And the cab 1 monitor is watched for 2000 ms
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every CI and BCU receives traction notch 7 over path 1 within 80 ms
    And the maintenance view of cab 1 lists "car1.CCU.sys1.TXC recovered"
