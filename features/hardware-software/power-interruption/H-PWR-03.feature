@item:H-PWR-03 @profile:crh2
Feature: H-PWR-03 An interruption of the train supply beyond class S2: a safe restart
  Hardware/software test, momentary power interruption (TST-02). Requirements: PRO-03, CMD-02, FS-02, FS-03.
  A 100 ms interruption of the 110 V train supply is beyond class S2, so every unit may reset. While the
  units are down no wrong command may reach CI or BCU (FS-02/03); afterwards the train comes back by
  itself: commands over path 1 again, one token through every node (PRO-03), a clean monitor.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:FS-02 @req:FS-03 @req:CMD-02 @tentative
  Scenario: H-PWR-03 No wrong command while the train supply is gone, commands again after the restart
    When the supply "train 110V" is interrupted for 100 ms
    And 2000 ms pass
    Then no CI or BCU receives a traction notch other than 7
    And every CI and BCU receives traction notch 7 over path 1 within 1000 ms
    And no CI or BCU goes without a command for more than 1000 ms

  @req:TST-02 @req:PRO-03 @tentative
  Scenario: H-PWR-03 After the restart one token circulates and the monitor is clean again
    When the supply "train 110V" is interrupted for 100 ms
    And the cab 1 monitor is watched for 4000 ms
    Then within 2500 ms one token circulates again through every node
    And the cab 1 monitor stopped showing "no status data from car8.CCU.sys1" within 3000 ms
    And the cab 1 monitor shows no faults
    And the maintenance view of cab 1 lists "car1.CCU.sys1.supply restarted"

  @req:TST-02 @req:CMD-02
  Scenario: H-PWR-03 Interruptions of 10 ms every second resets nothing
    When the supply "train 110V" is interrupted for 10 ms
    And 1000 ms pass
    And the supply "train 110V" is interrupted for 10 ms
    And 1000 ms pass
    And the supply "train 110V" is interrupted for 10 ms
    And the cab 1 monitor is watched for 1000 ms
    Then no CI or BCU goes without a command for more than 25 ms
    And no node sends a token initialisation
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)
