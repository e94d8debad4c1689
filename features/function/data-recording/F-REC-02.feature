@item:F-REC-02 @profile:crh2
Feature: F-REC-02 A recovered board writes a "recovered" record
  Requirements: PRO-06 (primary), TST-04.
  A board that comes back writes a second record, "recovered", beside the "failed" one; every record has
  its own number, so several records of one node are kept apart (docs/decisions.md, "Fault records").

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-02 A repaired MDM9 is recorded as recovered, after its failure
    When board "car3.LCU.MDM9" fails
    And 1000 ms pass
    And board "car3.LCU.MDM9" is repaired
    And 1000 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car3.LCU" saying "MDM9" failed
    And "car1.CCU.sys1" holds a fault record of "car3.LCU" saying "MDM9" recovered, stamped within 100 ms of it
    And "car1.CCU.sys1" holds 2 fault record(s) of "car3.LCU"

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-02 An RXC whose supply goes and comes back is recorded failed and recovered
    When the supply "car5.LCU.RXC" is switched off
    And 1000 ms pass
    And the supply "car5.LCU.RXC" is switched on again
    And 1000 ms pass
    Then "car1.CCU.sys1" holds a fault record of "car5.LCU" saying "RXC" failed
    And "car1.CCU.sys1" holds a fault record of "car5.LCU" saying "RXC" recovered
    And "car1.CCU.sys1" holds 2 fault record(s) of "car5.LCU"

  @req:PRO-06 @req:TST-04
  Scenario: F-REC-02 Without a repair no recovered record is written
    When board "car7.LCU.MDM9" fails
    And 2 s pass
    Then "car1.CCU.sys1" holds a fault record of "car7.LCU" saying "MDM9" failed
    And "car1.CCU.sys1" holds 1 fault record(s) of "car7.LCU"
