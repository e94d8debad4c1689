@item:F-REC-03 @profile:crh2
Feature: F-REC-03 Records reach the master the other way round a cut ring link and read back whole
  Requirements: PRO-06 (primary), NET-03, TST-04.
  A record travels as 236-byte block data to the master node (PRO-06) and is read back there whole. With
  the ring link between the recording car and the master cut, the blocks go the other way round the ring
  (NET-03) and the record still arrives whole.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-03 A 1000-byte record reads back whole from five blocks
    When "car3.LCU" asks to send a 1000-byte record as block data
    And 1500 ms pass
    Then "car1.CCU.sys1" receives the record of "car3.LCU" in 5 blocks of 236 bytes, each at least 10 ms after the one before
    And "car1.CCU.sys1" holds the 1000-byte record of "car3.LCU"

  @req:PRO-06 @req:NET-03 @req:TST-04
  Scenario: F-REC-03 With the short way cut, a 1000-byte record goes round the other way and reads back whole
    Given the ring link between "car2.LCU" and "car3.LCU" is cut
    When 500 ms pass
    And "car3.LCU" asks to send a 1000-byte record as block data
    And 1500 ms pass
    Then "car1.CCU.sys1" holds the 1000-byte record of "car3.LCU"

  @req:PRO-06 @req:NET-03 @req:TST-04
  Scenario: F-REC-03 With the short way cut, a board failure is still recorded at the master
    Given the ring link between "car1.LCU" and "car2.LCU" is cut
    When 500 ms pass
    And board "car2.LCU.MDM9" fails
    And 1500 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car2.LCU" saying "MDM9" failed
    And "car1.CCU.sys1" holds 1 fault record(s) of "car2.LCU"
