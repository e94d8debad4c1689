@item:F-NET-23 @profile:metro-tcn @req:TST-04
Feature: F-NET-23 Dual lines A and B on the WTB and on each MVB
  Requirements: RED-06 (primary), TCN-08, TST-04.
  Every frame goes on both lines. A cut or disturbed line switches the receivers to the other line without
  losing a message; the line fault is diagnosed, shown and recorded.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the master controller of cab 1 demands 60 % traction
    And the train has been powered up for 1000 ms

  @req:RED-06
  Scenario Outline: F-NET-23 Line <line> of "<bus>" cut: nothing lost, the other line taken
    When line <line> of "<bus>" is cut
    And 500 ms pass
    Then no message on "<bus>" is lost
    And the receivers on "<bus>" take line <other>
    And no VVVF or BECU changes what it applies
    And the cab 1 display shows "<bus> line <line>: fault"
    And "car6.CCU" holds a record "<bus> line <line>: fault"

    Examples:
      | bus       | line | other |
      | unit1.MVB | A    | B     |
      | unit2.MVB | A    | B     |
      | WTB       | A    | B     |

  @req:RED-06
  Scenario: F-NET-23 Line B cut while line A carries: no switch, nothing lost, the fault still found
    When line B of "unit1.MVB" is cut
    And 300 ms pass
    Then no message on "unit1.MVB" is lost
    And the receivers on "unit1.MVB" take line A
    And the cab 1 display shows "unit1.MVB line B: fault"

  @req:RED-06 @req:TCN-10
  Scenario: F-NET-23 Disturbed frames on line A are discarded and their copies on line B used
    When the next 3 frames on line A of "unit2.MVB" are disturbed
    And 100 ms pass
    Then frames from line A of "unit2.MVB" that fail their check are discarded
    And all 3 disturbed frames from line A of "unit2.MVB" are discarded
    And no frame from line A of "unit2.MVB" is discarded from 10 ms on
    And no message on "unit2.MVB" is lost
    And no VVVF or BECU changes what it applies

  @req:RED-06
  Scenario: F-NET-23 A line that brings a hundred disturbed frames in a row is diagnosed faulty and recorded
    When the next 100 frames on line B of "unit1.MVB" are disturbed
    And 300 ms pass
    Then no message on "unit1.MVB" is lost
    And "car6.CCU" holds a record "unit1.MVB line B: fault"

  @req:RED-06
  Scenario Outline: F-NET-23 Frames disturbed on both lines of "<bus>" lose their messages; the bus carries on
    When the next 2 frames on both lines of "<bus>" are disturbed
    And 100 ms pass
    Then a message on "<bus>" is lost
    And no message on "<bus>" is lost from <after> ms on

    Examples:
      | bus       | after |
      | unit2.MVB | 10    |
      | WTB       | 30    |

  @req:RED-06
  Scenario: F-NET-23 Restored line A is diagnosed healthy again
    When line A of "WTB" is cut
    And 300 ms pass
    And line A of "WTB" is restored
    And 300 ms pass
    Then no message on "WTB" is lost
    And the cab 6 display shows "WTB line A: restored"

  @req:RED-06
  Scenario Outline: F-NET-23 Line A of "<bus>" cut and restored, then line B cut: the receivers go back to line A without a loss
    When line A of "<bus>" is cut
    And 300 ms pass
    And line A of "<bus>" is restored
    And 300 ms pass
    And line B of "<bus>" is cut
    And 300 ms pass
    Then the receivers on "<bus>" take line A
    And no message on "<bus>" is lost
    And no VVVF or BECU changes what it applies

    Examples:
      | bus       |
      | WTB       |
      | unit1.MVB |
