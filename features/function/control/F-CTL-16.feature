@item:F-CTL-16 @profile:metro-tcn @req:TST-04
Feature: F-CTL-16 Redundant MVB I/O modules: module 1 while its life signal is set, else module 2
  Requirements: RED-07 (primary), TCN-04, TCN-06, TCN-07, TCN-08, TCN-09, TST-04.
  The two I/O modules of a cab car read the same inputs (28 digital, 3 analogue). A wiring fault on one
  module's master-controller input shows which module's inputs drive the train; which channel carries the
  traction demand and the direction switch, and at what scale, is the SUT's declared I/O map (TCN-07 gives
  the channel counts only). The life signal travels in the module's port with the inputs, as process data
  (TCN-06: cyclic, of bounded latency): a master takes in module 1's life signal 0 as fast as any input, so
  module 2's inputs drive every VVVF within the suite's 100 ms from an input to the drives.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the master controller of cab 1 demands 60 % traction

  @req:RED-07
  Scenario: F-CTL-16 Module 2 is not used while module 1 lives
    Given a wiring fault holds the traction demand input of "car1.IO2" at 30 %
    And the train has been powered up for 1000 ms
    When 500 ms pass
    Then every VVVF applies 60 % traction
    And the cab 1 display does not show "inputs from car1.IO2"

  @req:RED-07 @req:TCN-06
  Scenario: F-CTL-16 Module 1's life signal drops: the inputs of module 2 are used
    Given a wiring fault holds the traction demand input of "car1.IO2" at 30 %
    And the train has been powered up for 1000 ms
    When "car1.IO1" fails
    And 500 ms pass
    Then every VVVF applies 30 % traction within 100 ms
    And the cab 1 display shows "inputs from car1.IO2"
    And "car6.CCU" holds a record "inputs from car1.IO2"

  # A living module's life signal is always set, also where a count of refreshes wraps: 16 bits of a port
  # refreshed at most every 16 ms (the period the contract allows) wrap within 18 minutes.
  @req:RED-07 @req:TCN-06
  Scenario: F-CTL-16 Module 1 stays in use for 18 minutes, through any wrap of its life signal
    Given a wiring fault holds the traction demand input of "car1.IO2" at 30 %
    And the train has been powered up for 1000 ms
    When the driver moves the master controller of cab 1 to 60 % traction
    And 18 min pass
    Then no VVVF or BECU changes what it applies
    And every VVVF applies 60 % traction
    And the cab 1 display does not show "inputs from"

  @req:RED-07
  Scenario: F-CTL-16 With module 2's inputs the train follows the master controller
    Given the train has been powered up for 1000 ms
    When "car1.IO1" fails
    And 100 ms pass
    And the driver moves the master controller of cab 1 to 85 % traction
    And 200 ms pass
    Then every VVVF applies 85 % traction within 100 ms

  # Neither module lives: the cab's inputs are lost, a fault of the cab's subsystems that the displays show and
  # the CCUs record (TCN-04, TCN-08) in the SUT's declared words.
  @req:RED-07 @req:TCN-04 @req:TCN-08
  Scenario: F-CTL-16 Both I/O modules of the active cab fail: the displays show it and the CCUs record it
    Given the train has been powered up for 1000 ms
    When "car1.IO1" fails
    And "car1.IO2" fails
    And 500 ms pass
    Then the cab 1 display shows "no MVB I/O module alive"
    And "car1.CCU" holds a record "no MVB I/O module alive"
    And "car6.CCU" holds a record "no MVB I/O module alive"

  # What the train does without the active cab's inputs the articles do not say; the suite takes the driver's
  # demand as lost, as the train command is in a network failure (TCN-09): no traction, the train brakes
  # (docs/decisions.md, "Both I/O modules of the active cab dead").
  @req:RED-07 @req:TCN-09 @tentative
  Scenario: F-CTL-16 Both I/O modules of the active cab fail: no VVVF pulls and every BECU brakes
    Given the train has been powered up for 1000 ms
    When "car1.IO1" fails
    And "car1.IO2" fails
    And 1000 ms pass
    Then every VVVF applies 0 % traction
    And every BECU applies 100 % brake

  @req:TCN-07
  Scenario Outline: F-CTL-16 The I/O modules read digital inputs DI01-DI28 and analogue inputs AI1-AI3
    Given a wiring fault holds input <channel> of "car1.IO2" at 1
    And the train has been powered up for 100 ms
    When 100 ms pass
    Then every VVVF applies 60 % traction

    Examples:
      | channel |
      | DI01    |
      | DI28    |
      | AI3     |

  @req:TCN-07 @req:RED-07
  Scenario: F-CTL-16 A digital input of module 2 drives the train once module 1's life signal is 0
    Given a wiring fault holds the forward input of "car1.IO2" at 0
    And the train has been powered up for 1000 ms
    When "car1.IO1" fails
    And 300 ms pass
    Then every VVVF applies 0 % traction within 100 ms

  @req:TCN-07 @req:RED-07
  Scenario: F-CTL-16 A digital input held at 1 on module 2 drives the train once module 1's life signal is 0
    Given the direction switch of cab 1 is at neutral
    And a wiring fault holds the forward input of "car1.IO2" at 1
    And the train has been powered up for 1000 ms
    Then every VVVF applies 0 % traction
    When "car1.IO1" fails
    And 300 ms pass
    Then every VVVF applies 60 % traction within 100 ms
