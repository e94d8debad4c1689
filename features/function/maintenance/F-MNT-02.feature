@item:F-MNT-02 @profile:crh2
Feature: F-MNT-02 Faults and recoveries listed in the order they happened
  Requirements: TST-04 (primary), PRO-06.
  The maintenance view lists the fault history oldest first by the time each fault or recovery happened,
  not by when its record reached the master (docs/decisions.md, "Fault records"). The first scenario makes the
  two orders differ: car 3's record, written 20 ms after car 6's, reaches the master first because car 3
  gets the token first.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:TST-04 @req:PRO-06
  Scenario: F-MNT-02 Two faults 20 ms apart are listed in the order they happened
    When board "car6.LCU.MDM9" fails
    And 20 ms pass
    And board "car3.LCU.MDM9" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car6.LCU.MDM9 failed" before "car3.LCU.MDM9 failed"
    And the maintenance view of cab 1 holds 2 line(s)

  @req:TST-04 @req:PRO-06
  Scenario: F-MNT-02 A recovery is listed after the faults that came before it
    When board "car3.LCU.MDM9" fails
    And 500 ms pass
    And board "car6.LCU.MDM9" fails
    And 500 ms pass
    And board "car3.LCU.MDM9" is repaired
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car3.LCU.MDM9 failed" before "car6.LCU.MDM9 failed"
    And the maintenance view of cab 1 lists "car6.LCU.MDM9 failed" before "car3.LCU.MDM9 recovered"
    And the maintenance view of cab 1 holds 3 line(s)

  @req:TST-04 @req:PRO-06
  Scenario: F-MNT-02 A board that fails twice is listed failed, recovered, failed
    When board "car2.LCU.MDM9" fails
    And 500 ms pass
    And board "car2.LCU.MDM9" is repaired
    And 500 ms pass
    And board "car2.LCU.MDM9" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car2.LCU.MDM9 failed" before "car2.LCU.MDM9 recovered"
    And the maintenance view of cab 1 holds 3 line(s)
    And the maintenance view of cab 8 holds 3 line(s)
