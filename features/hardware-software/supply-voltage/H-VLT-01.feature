@item:H-VLT-01 @profile:crh2
Feature: H-VLT-01 Continuous supply range 0.7 Un to 1.25 Un
  Hardware/software test, supply-voltage variation (TST-02). Requirements: CMD-02, PRO-01, PRO-02.
  EN 50155 (Un = 110 V): the equipment works without deviation anywhere from 0.7 Un to 1.25 Un for as long
  as the supply stays there (VDX-02 of seed 003 gives the same 70 .. 125 % for the ATP's 110 V supply). At
  both ends of the range every command reaches CI and BCU, status data keep their cycle, and the monitor
  and the maintenance records stay clean.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:CMD-02 @req:PRO-01
  Scenario: H-VLT-01 At 0.7 Un on the train supply every command still arrives
    When the input of supply "train 110V" changes to 70 % of Un
    And the cab 1 monitor is watched for 2000 ms
    Then every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 25 ms
    And no CI or BCU receives a traction notch other than 7
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02 @req:PRO-02
  Scenario: H-VLT-01 At 1.25 Un on the train supply every command still arrives and status data keep their cycle
    When the input of supply "train 110V" changes to 125 % of Un
    And the cab 1 monitor is watched for 2000 ms
    Then every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02
  Scenario: H-VLT-01 Moving between the two ends of the range changes nothing
    When the input of supply "train 110V" changes to 70 % of Un
    And 500 ms pass
    And the input of supply "train 110V" changes to 125 % of Un
    And the cab 1 monitor is watched for 1000 ms
    Then no CI or BCU goes without a command for more than 25 ms
    And no CI or BCU receives a traction notch other than 7
    And the cab 1 monitor never showed a fault
