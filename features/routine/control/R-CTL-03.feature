@item:R-CTL-03 @profile:crh2
Feature: R-CTL-03 Backup transmission of running control commands
  Routine control test. Requirements: CMD-03, CMD-04, RED-01, RED-02, TST-03.
  When the first-choice path fails, traction and brake commands still reach CI and BCU.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 4
    And the train has been powered up for 1000 ms

  @req:CMD-03 @req:TST-03 @tentative
  Scenario: R-CTL-03 A failed MDM9 moves its car to path 2, the other cars stay on path 1
    When board "car3.LCU.MDM9" fails
    And 200 ms pass
    Then the CI and BCU of car 3 receive traction step "A" over path 2 within 30 ms
    And from 40 ms on every CI and BCU outside car 3 receives traction notch 4 over path 1

  @req:CMD-04 @req:TST-03
  Scenario: R-CTL-03 With the ring down every car runs on path 3
    When every ring link is cut
    And 300 ms pass
    Then every CI and BCU receives traction step "A" over path 3 within 100 ms

  @req:RED-01 @req:RED-02 @req:TST-03
  Scenario: R-CTL-03 Commands continue when CCU system 1 loses power
    When the supply "car1.CCU.sys1" is switched off
    And 500 ms pass
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 75 ms
