@item:H-EMC-01 @profile:crh2
Feature: H-EMC-01 Fast-transient bursts at the rated level
  Hardware/software test, interference (TST-02). Requirements: NET-05, CMD-02, CMD-04.
  EN 50121-3-2 (rolling stock apparatus) asks immunity to fast transients of 2 kV on signal,
  communication and power ports. Bursts at that level on a ring link or on the self-diagnostic line damage
  no frame: nothing is discarded, every command arrives, the monitor stays clean.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:NET-05 @req:CMD-02
  Scenario: H-EMC-01 2 kV bursts on a ring link for 1 s damage nothing
    When bursts of 2 kV hit the ring link between "car3.LCU" and "car4.LCU" for 1000 ms
    And the cab 1 monitor is watched for 1500 ms
    Then no node discards a frame
    And every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor never showed a fault

  @req:TST-02 @req:CMD-04
  Scenario: H-EMC-01 2 kV bursts on the self-diagnostic line while it carries the commands damage nothing
    Given every ring link is cut
    When 300 ms pass
    And bursts of 2 kV hit the self-diagnostic line for 500 ms
    And 500 ms pass
    Then every CI and BCU receives traction step "B" over path 3 within 30 ms
    And no CI or BCU goes without a command for more than 25 ms
    And no CI or BCU receives a traction step other than "B"

  @req:TST-02 @req:NET-05 @req:CMD-02
  Scenario: H-EMC-01 2 kV bursts on two ring links at once damage nothing
    When bursts of 2 kV hit the ring link between "car1.CCU.sys1" and "car1.CCU.sys2" for 1000 ms
    And bursts of 2 kV hit the ring link between "car6.LCU" and "car7.LCU" for 1000 ms
    And the cab 1 monitor is watched for 1500 ms
    Then no node discards a frame
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor never showed a fault
