@item:F-REC-01 @profile:crh2
Feature: F-REC-01 A board failure is recorded at the master node as a fault record
  Requirements: PRO-06 (primary), TST-04.
  When an LCU detects a failed board, its CPU3 writes a fault record and sends it as block data (PRO-06)
  to the master node, car 1's CCU system 1 (docs/decisions.md, "Fault records"); the record read back there
  names the node, the board and the event, and carries the time it happened. Block data waits for a grant
  (at most one 120 ms status cycle), so 1 s is ample.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-01 A failed MDM9 of car 3 is recorded once, and only for car 3
    When board "car3.LCU.MDM9" fails
    And 1000 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car3.LCU" saying "MDM9" failed
    And "car1.CCU.sys1" holds 1 fault record(s) of "car3.LCU"
    And "car1.CCU.sys1" holds no record of "car2.LCU"
    And "car1.CCU.sys1" holds no record of "car4.LCU"

  @req:PRO-06 @req:TST-04 @tentative
  Scenario: F-REC-01 The fault record carries the time of the failure
    When board "car6.LCU.MDM9" fails
    And 1000 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car6.LCU" saying "MDM9" failed, stamped within 100 ms of it

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-01 An RXC whose CPU groups disagree is recorded as failed
    When board "car4.LCU.RXC.group2" fails
    And 1000 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car4.LCU" saying "RXC" failed
    And "car1.CCU.sys1" holds 1 fault record(s) of "car4.LCU"
