@item:H-VLT-03 @profile:crh2
Feature: H-VLT-03 Supply variation on the separate board supplies
  Hardware/software test, supply-voltage variation (TST-02). Requirements: CMD-01, RED-01, RED-02, FS-02.
  CMD-01 and RED-01 give the TXC, the RXC and each CCU system a supply of their own, so one supply can be
  varied while the others stay nominal. In range nothing changes; a TXC supply below 0.6 Un takes its TXC
  off the lines (FS-02) and system 2 takes over; an RXC supply below 0.6 Un leaves path 1 untouched.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:CMD-01
  Scenario: H-VLT-03 The TXC and RXC supplies at the ends of the continuous range change nothing
    When the input of supply "car1.CCU.sys1.TXC" changes to 70 % of Un
    And the input of supply "car3.LCU.RXC" changes to 125 % of Un
    And the input of supply "car3.LCU" changes to 70 % of Un
    And the cab 1 monitor is watched for 2000 ms
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:FS-02 @req:RED-02 @tentative
  Scenario: H-VLT-03 A TXC supply below 0.6 Un takes the TXC off the lines and system 2 takes over
    When the input of supply "car1.CCU.sys1.TXC" changes to 40 % of Un
    And the cab 1 monitor is watched for 1000 ms
    Then "car1.CCU.sys1.TXC" puts nothing on the ring or the self-diagnostic line from 110 ms on
    And system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every CI and BCU receives traction notch 7 over path 1 within 80 ms
    And the cab 1 monitor showed "car1.CCU.sys1.TXC failure" within 400 ms
    When the input of supply "car1.CCU.sys1.TXC" changes to 100 % of Un
    And the cab 1 monitor is watched for 2000 ms
    Then the cab 1 monitor stopped showing "car1.CCU.sys1.TXC failure" within 1500 ms
    And the maintenance view of cab 1 lists "car1.CCU.sys1.TXC recovered"

  @req:TST-02 @req:CMD-01 @req:FS-02 @tentative
  Scenario: H-VLT-03 An RXC supply below 0.6 Un leaves path 1 running
    When the input of supply "car3.LCU.RXC" changes to 40 % of Un
    And the cab 1 monitor is watched for 1000 ms
    Then from 40 ms on every CI and BCU outside car 3 receives traction notch 7 over path 1
    And the CI and BCU of car 3 receive traction notch 7 over path 1 within 40 ms
    And the cab 1 monitor showed "car3.LCU.RXC failure" within 400 ms
    When the input of supply "car3.LCU.RXC" changes to 100 % of Un
    And the cab 1 monitor is watched for 2000 ms
    Then the cab 1 monitor stopped showing "car3.LCU.RXC failure" within 1500 ms
