@item:F-NET-16 @profile:crh2 @req:TST-04
Feature: F-NET-16 Control command paths 1, 2 and 3
  Requirements: CMD-02 (primary), CMD-01, CMD-03, CMD-04, TST-04.
  Commands bypass CPU3 (TXC -> MDM8 -> MDM8 -> MDM9/RXC). Path 1 carries full notches; paths 2 and 3
  only the A/B steps. Path 2 is chosen by a failed MDM9 (docs/decisions.md: the article's "MDM8 fails" cannot
  mean the MDM8 that path 2 itself runs through).

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 9
    And the train has been powered up for 1000 ms

  @req:CMD-01 @req:CMD-02
  Scenario: F-NET-16 Commands bypass CPU3: every LCU's CPU3 failing leaves path 1 intact
    Given the CPU3 board of every LCU has failed
    And board "car1.CCU.sys1.CPU3" has failed
    When 300 ms pass
    And the driver moves the traction notch of cab 1 to 3
    And 200 ms pass
    Then every CI and BCU receives traction notch 3 over path 1 within 40 ms

  @req:CMD-01 @req:CMD-04
  Scenario: F-NET-16 An LCU without its CPU-side supply still commands CI and BCU through its RXC
    When the supply "car3.LCU" is switched off
    And 300 ms pass
    Then the CI and BCU of car 3 receive traction step "B" over path 3 within 100 ms

  @req:CMD-03 @tentative
  Scenario: F-NET-16 Path 2 carries only steps A and B
    When board "car6.LCU.MDM9" fails
    And the driver moves the traction notch of cab 1 to 2
    And 200 ms pass
    Then the CI and BCU of car 6 receive traction step "A" over path 2 within 30 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B
    And from 40 ms on every CI and BCU outside car 6 receives traction notch 2 over path 1

  @req:CMD-04 @tentative
  Scenario: F-NET-16 Path 3 carries the brake steps A and B
    When every ring link is cut
    And the driver moves the traction notch of cab 1 to 0
    And the driver moves the brake handle of cab 1 to step 2
    And 300 ms pass
    Then every BCU receives brake step "A" over path 3 within 100 ms
    And commands over paths 2 and 3 carry only the traction and brake steps A and B
