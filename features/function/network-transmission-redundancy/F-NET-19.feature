@item:F-NET-19 @profile:crh2 @req:TST-04
Feature: F-NET-19 Fail-safe command boards: two CPU groups, compare, cut on disagreement, inverted I/O
  Requirements: FS-02 (primary), FS-01, FS-03, RED-02, TST-04.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And the train has been powered up for 1000 ms

  @req:FS-02 @req:FS-01 @req:RED-02
  Scenario: F-NET-19 A TXC whose CPU groups disagree stops talking, and system 2 takes over
    When board "car1.CCU.sys1.TXC.group2" fails
    And 300 ms pass
    Then "car1.CCU.sys1.TXC" puts nothing on the ring or the self-diagnostic line from 11 ms on
    And system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval

  @req:FS-02 @req:FS-01
  Scenario: F-NET-19 A TXC whose working group #1 is unhealthy stops talking
    When board "car1.CCU.sys1.TXC.group1" fails
    And 300 ms pass
    Then "car1.CCU.sys1.TXC" puts nothing on the ring or the self-diagnostic line from 11 ms on

  @req:FS-01
  Scenario: F-NET-19 An RXC whose CPU groups disagree stops driving its outputs
    When every ring link is cut
    And board "car4.LCU.RXC.group2" fails
    And 300 ms pass
    Then the CI and BCU of car 3 receive traction step "A" over path 3 within 100 ms
    And the BCU of car 4 receives nothing over path 3

  @req:FS-03
  Scenario: F-NET-19 A dead desk input reads as the safe state
    When the supply "car1.desk" is switched off
    And 200 ms pass
    Then from 20 ms on every command carries traction notch 0 and brake step 7
