@item:F-MNT-03 @profile:crh2
Feature: F-MNT-03 A TXC fail-safe cut shows in the maintenance view
  Requirements: FS-02 (primary), FS-01, TST-04.
  When a TXC's two CPU groups disagree, or its working group #1 is unhealthy, the fail-safe circuit cuts
  its outputs (FS-01, FS-02); the CCU system records this as its TXC failing, and the maintenance view
  lists it under that system ("car1.CCU.sys1.TXC failed"), not under the other one.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And the train has been powered up for 1000 ms

  @req:FS-02 @req:FS-01 @req:TST-04
  Scenario: F-MNT-03 The working system's TXC whose CPU groups disagree is listed as failed
    When board "car1.CCU.sys1.TXC.group2" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car1.CCU.sys1.TXC failed"
    And the maintenance view of cab 1 does not list "car1.CCU.sys2.TXC"
    And the maintenance view of cab 1 holds 1 line(s)

  @req:FS-02 @req:TST-04
  Scenario: F-MNT-03 A TXC whose working group #1 is unhealthy is listed as failed
    When board "car1.CCU.sys1.TXC.group1" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car1.CCU.sys1.TXC failed"
    And the maintenance view of cab 1 holds 1 line(s)

  @req:FS-02 @req:FS-01 @req:TST-04
  Scenario: F-MNT-03 The standby system's TXC cut is listed under system 2
    When board "car1.CCU.sys2.TXC.group2" fails
    And 1000 ms pass
    Then the maintenance view of cab 1 lists "car1.CCU.sys2.TXC failed"
    And the maintenance view of cab 1 does not list "car1.CCU.sys1.TXC"
    And the maintenance view of cab 1 holds 1 line(s)
