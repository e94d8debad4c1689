@item:F-NET-25 @profile:metro-tcn @req:TST-04
Feature: F-NET-25 Train network failure: brake to a stop, then hard-wired emergency operation
  Requirements: TCN-09 (primary), RED-06, TST-04.
  Decision (docs/decisions.md "Metro TCDS"): the article allows braking to a stop or emergency
  operation; a train whose network has failed is not under control, so it is first braked to a stop, and
  hard-wired emergency operation is taken only at standstill. Bounds chosen by the suite: the brake is
  applied within 500 ms of the loss; braked from 30 km/h the train stands within 20 s (a mean deceleration of
  0.42 m/s2 or more: any metro's full service brake; the reference brakes at 1.0 m/s2 and stands after 8.3 s).

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the master controller of cab 1 demands 60 % traction
    And the train runs at 30 km/h

  @req:TCN-09
  Scenario: F-NET-25 Both MVB lines of unit 1 cut: every VVVF of the unit stops pulling, every BECU brakes
    Given the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms
    When line A of "unit1.MVB" is cut
    And line B of "unit1.MVB" is cut
    And 1000 ms pass
    Then every BECU applies 100 % brake within 500 ms
    And every VVVF applies 0 % traction

  # The record states a failure: a power-up, before the first commands have come, is none.
  @req:TCN-09
  Scenario: F-NET-25 A power-up with the network whole records no train network failure
    Given the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms
    Then "car1.CCU" holds no record "train network failure: braking to a stop"
    And "car6.CCU" holds no record "train network failure: braking to a stop"

  @req:TCN-09
  Scenario: F-NET-25 Unit 1 lost entirely: the train brakes to a stop, then runs in emergency operation
    Given the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms
    When "car1.CCU", "car2.VCU", "car3.VCU" fail together
    And 20 s pass
    Then every VVVF applies 0 % traction
    And every BECU applies 100 % brake
    And the train has come to a stop
    And the cab 6 display shows the mode "train network failure"
    And "car6.CCU" holds a record "train network failure: braking to a stop"
    When the driver turns the emergency-operation switch on
    And 100 ms pass
    Then every VVVF applies 60 % traction within 50 ms
    And every BECU applies 0 % brake
    And the cab 6 display shows the mode "emergency operation"
    When the driver moves the master controller of cab 1 to 40 % brake
    And 100 ms pass
    Then every BECU applies 40 % brake within 50 ms
    And every VVVF applies 0 % traction
    When the driver moves the master controller of cab 1 to 60 % traction
    And the driver sets the direction switch of cab 1 to neutral
    And 100 ms pass
    Then every VVVF applies 0 % traction within 50 ms
    When the driver removes the key from cab 1
    And 100 ms pass
    Then every BECU applies 100 % brake within 50 ms
    And every VVVF applies 0 % traction
    When the driver inserts the key in cab 1
    And the driver sets the direction switch of cab 1 to forward
    And 100 ms pass
    Then every VVVF applies 60 % traction within 50 ms
    And every BECU applies 0 % brake
    When the driver turns the emergency-operation switch off
    And 100 ms pass
    Then every BECU applies 100 % brake within 50 ms
    And every VVVF applies 0 % traction
    And the cab 6 display shows the mode "train network failure"

  @req:TCN-09
  Scenario: F-NET-25 Emergency operation is not taken at speed
    Given the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms
    When "car1.CCU", "car2.VCU", "car3.VCU" fail together
    And 1000 ms pass
    And the driver turns the emergency-operation switch on
    And 500 ms pass
    Then every VVVF applies 0 % traction
    And every BECU applies 100 % brake
    And the cab 6 display shows the mode "train network failure"

  @req:TCN-09
  Scenario: F-NET-25 A healthy network does not brake
    Given the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms
    When 3 s pass
    Then every VVVF applies 60 % traction
    And every BECU applies 0 % brake
    And the cab 1 display shows the mode "normal"

  @req:TCN-09
  Scenario: F-NET-25 A WTB dead from power-up: the unit without the key never hears a train command and brakes
    Given the direction switch of cab 1 is at forward
    And line A of "WTB" is cut
    And line B of "WTB" is cut
    And the train has been powered up for 1000 ms
    When 500 ms pass
    Then the cab 6 display shows the mode "train network failure"
    And "car6.CCU" holds a record "train network failure: braking to a stop"
    And the cab 1 display shows the mode "normal"

  @req:TCN-09
  Scenario: F-NET-25 Both MVB lines of unit 1 dead from power-up: the cab's inputs are never read and the train stays braked
    Given the direction switch of cab 1 is at forward
    And line A of "unit1.MVB" is cut
    And line B of "unit1.MVB" is cut
    And the train has been powered up for 1000 ms
    When 500 ms pass
    Then every VVVF applies 0 % traction
    And every BECU applies 100 % brake
    And the cab 6 display shows the mode "train network failure"

  @req:TCN-09 @req:RED-06
  Scenario: F-NET-25 Unit 1's first MVB frames lost on both lines at power-up: the train pulls once the inputs come through
    Given the direction switch of cab 1 is at forward
    And the train is powered up
    When the next 2 frames on both lines of "unit1.MVB" are disturbed
    And 1000 ms pass
    Then every VVVF applies 60 % traction
    And every BECU applies 0 % brake
    And the cab 1 display shows the mode "normal"

  @req:TCN-09
  Scenario: F-NET-25 Emergency operation with the direction switch never moved off neutral: the drives do not pull
    Given the train has been powered up for 1000 ms
    When "car1.CCU", "car2.VCU", "car3.VCU" fail together
    And 20 s pass
    And the driver turns the emergency-operation switch on
    And 100 ms pass
    Then every VVVF applies 0 % traction
    And every BECU applies 0 % brake
    And the cab 6 display shows the mode "emergency operation"
