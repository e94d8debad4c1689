@item:F-NET-15 @profile:crh2 @req:TST-04
Feature: F-NET-15 Block data: 236-byte blocks on request and grant, at least 10 ms apart
  Requirements: PRO-06 (primary), TST-04.
  A node asks for a block transfer in its status data; the master node announces the granted node in its
  status data; the blocks follow at least 10 ms apart.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:PRO-06
  Scenario: F-NET-15 A 1000-byte record travels as five 236-byte blocks after the grant
    When "car3.LCU" asks to send a 1000-byte record as block data
    And 1000 ms pass
    Then "car1.CCU.sys1" grants "car3.LCU" the block transfer in its status data
    And "car3.LCU" sends no block before it is granted
    And "car1.CCU.sys1" receives the record of "car3.LCU" in 5 blocks of 236 bytes, each at least 10 ms after the one before
    And "car1.CCU.sys1" holds the 1000-byte record of "car3.LCU"

  @req:PRO-06
  Scenario: F-NET-15 Two requesting nodes are granted one after the other
    When "car6.LCU" asks to send a 500-byte record as block data
    And "car2.LCU" asks to send a 300-byte record as block data
    And 2 s pass
    Then "car1.CCU.sys1" grants "car6.LCU" the block transfer in its status data
    And "car1.CCU.sys1" grants "car2.LCU" the block transfer in its status data
    And "car1.CCU.sys1" holds the 500-byte record of "car6.LCU"
    And "car1.CCU.sys1" holds the 300-byte record of "car2.LCU"

  @req:PRO-06
  Scenario: F-NET-15 A long transfer ends before the next granted node sends
    When "car2.LCU" asks to send a 5000-byte record as block data
    And "car6.LCU" asks to send a 300-byte record as block data
    And 3 s pass
    Then "car1.CCU.sys1" holds the 5000-byte record of "car2.LCU"
    And "car1.CCU.sys1" holds the 300-byte record of "car6.LCU"
    And the block transfers of "car2.LCU" and "car6.LCU" do not overlap

  @req:PRO-06
  Scenario: F-NET-15 With system 1 switched off, system 2 grants the requesting nodes in turn and no other
    When the supply "car1.CCU.sys1" is switched off
    And 500 ms pass
    And "car6.LCU" asks to send a 500-byte record as block data
    And "car2.LCU" asks to send a 300-byte record as block data
    And 2 s pass
    Then "car1.CCU.sys2" grants "car6.LCU" the block transfer in its status data
    And "car1.CCU.sys2" grants "car2.LCU" the block transfer in its status data
    And the status data of "car1.CCU.sys2" grant a block transfer to none but "car6.LCU" and "car2.LCU"
    And "car1.CCU.sys2" holds the 500-byte record of "car6.LCU"
    And "car1.CCU.sys2" holds the 300-byte record of "car2.LCU"
