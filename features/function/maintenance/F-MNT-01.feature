@item:F-MNT-01 @profile:crh2
Feature: F-MNT-01 The maintenance view lists each fault with its node and board
  Requirements: TST-04 (primary), PRO-06.
  The maintenance view (fault history) of the cab monitor lists the fault records held at the master node,
  one line per record, as "<time> ms <node>.<board> <event>" (docs/decisions.md, "Fault records"). The records
  come as block data (PRO-06), so the scenarios allow 1 s.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:TST-04 @req:PRO-06
  Scenario: F-MNT-01 A failed MDM9 is listed with its node and board, once
    When board "car3.LCU.MDM9" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car3.LCU.MDM9 failed"
    And the maintenance view of cab 1 holds 1 line(s)
    And the maintenance view of cab 1 does not list "car3.LCU.MDM9 recovered"

  @req:TST-04 @req:PRO-06
  Scenario: F-MNT-01 Faults of two cars are listed under their own nodes and boards
    When board "car5.LCU.MDM9" fails
    And board "car7.LCU.RXC.group2" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car5.LCU.MDM9 failed"
    And the maintenance view of cab 1 lists "car7.LCU.RXC failed"
    And the maintenance view of cab 1 holds 2 line(s)
    And the maintenance view of cab 1 does not list "car5.LCU.RXC"
    And the maintenance view of cab 1 does not list "car7.LCU.MDM9"

  @req:TST-04
  Scenario: F-MNT-01 A healthy train's maintenance view is empty
    When 2 s pass
    Then the maintenance view of cab 1 holds 0 line(s)
    And the maintenance view of cab 8 holds 0 line(s)
