@item:H-TMP-01 @profile:crh2
Feature: H-TMP-01 Operating temperature class OT3: -25 °C to +70 °C
  Hardware/software test, high/low temperature (TST-02). Requirements: CMD-02, PRO-02.
  EN 50155 class OT3 (-25 .. +70 °C, equipment inside the car body, as the CRH2 CCU and LCU cabinets are):
  with the whole train at either end of the class the network works without deviation.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:CMD-02 @req:PRO-02
  Scenario: H-TMP-01 At +70 °C the whole train works without deviation
    When the temperature of "train" changes to 70 °C
    And the cab 1 monitor is watched for 2000 ms
    Then every CI and BCU receives traction notch 7 over path 1 within 40 ms
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02 @req:PRO-02
  Scenario: H-TMP-01 At -25 °C the whole train works without deviation
    When the temperature of "train" changes to -25 °C
    And the cab 1 monitor is watched for 2000 ms
    Then every CI and BCU receives traction notch 7 over path 1 within 40 ms
    And no CI or BCU goes without a command for more than 25 ms
    And the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And the cab 1 monitor never showed a fault
    And the maintenance view of cab 1 holds 0 line(s)

  @req:TST-02 @req:CMD-02
  Scenario: H-TMP-01 A change from -25 °C to +70 °C changes nothing
    Given the temperature of "train" is -25 °C
    When the temperature of "train" changes to 70 °C
    And the cab 1 monitor is watched for 1000 ms
    Then no CI or BCU goes without a command for more than 25 ms
    And while system 1 is healthy only system 1 of the car 1 CCU sends commands
    And the cab 1 monitor never showed a fault
