@item:F-ILK-08 @profile:crh2 @req:TST-04
Feature: F-ILK-08 Traction command permission: every condition alone blocks traction
  Requirements: ILK-08 (primary), ILK-02, ILK-05, TST-04.
  A traction command is produced only if this cab's MCR is up, the direction switch is at forward or
  reverse, no rapid or emergency brake acts, and the side doors are closed or the door-interlock bypass
  switch is ON. Each scenario breaks one condition and checks that no converter gets traction; reverse
  meets the direction condition as forward does, so a train that drives forward only is refused too.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And the train has been powered up for 1000 ms

  @req:ILK-08
  Scenario: F-ILK-08 With every condition met traction reaches the converters
    When 200 ms pass
    Then the "traction" is permitted
    And every CI and BCU receives traction notch 5 over path 1 within 40 ms

  @req:ILK-08
  Scenario: F-ILK-08 The direction switch at reverse permits traction as forward does
    When the driver moves the traction notch of cab 1 to 0
    And the driver sets the direction switch of cab 1 to reverse
    And 200 ms pass
    And the driver moves the traction notch of cab 1 to 5
    And 200 ms pass
    Then the "traction" is permitted
    And every CI and BCU receives traction notch 5 over path 1 within 40 ms

  @req:ILK-08
  Scenario: F-ILK-08 The direction switch at neutral blocks traction
    When the driver sets the direction switch of cab 1 to neutral
    And 200 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on

  @req:ILK-08 @req:ILK-02
  Scenario: F-ILK-08 An emergency and rapid brake block traction
    When the main air pipe pressure changes to 500 kPa
    And 200 ms pass
    Then the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on

  @req:ILK-08 @req:ILK-05
  Scenario: F-ILK-08 Open doors block traction unless the bypass switch is on
    When the driver commands the doors open
    And 200 ms pass
    Then the "doors" is open
    And the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
    When the driver turns the door-interlock bypass switch on
    And 200 ms pass
    Then the "traction" is permitted
    And every CI receives traction notch 5 within 40 ms

  @req:ILK-08
  Scenario: F-ILK-08 Without the key the cab's MCR drops and traction is blocked
    When the driver removes the key from cab 1
    And 200 ms pass
    Then the "traction" is blocked
    # A command sampled before the key came out may still be on its way to the MDM8 (the TXC's loop, a
    # product's task): no requirement times the MCR's drop, so the desk-to-device budget of 40 ms is allowed.
    And "car1.CCU.sys1" puts no commands on the ring from 40 ms on
