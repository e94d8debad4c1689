@item:F-NET-02 @profile:crh2 @req:TST-04
Feature: F-NET-02 Ring with one link fault
  Requirements: NET-03 (primary), PRO-01, TST-04.
  With one span cut, every node still reaches every other through the opposite direction.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And the train has been powered up for 1000 ms

  @req:NET-03 @req:PRO-01
  Scenario Outline: F-NET-02 Every LCU keeps receiving every command with the link <a>~<b> cut
    When the ring link between "<a>" and "<b>" is cut
    And 500 ms pass
    Then every LCU receives every command within 15 ms of its transmission
    And no CI or BCU receives a traction notch other than 3

    Examples:
      | a             | b             |
      | car1.CCU.sys1 | car1.CCU.sys2 |
      | car3.LCU      | car4.LCU      |
      | car8.CCU.sys1 | car1.CCU.sys1 |

  @req:NET-03
  Scenario: F-NET-02 Status data still reaches the cab monitor from every node
    When the ring link between "car4.LCU" and "car5.LCU" is cut
    And 2 s pass
    Then the cab 1 monitor receives status data from every other node at least every 300 ms
