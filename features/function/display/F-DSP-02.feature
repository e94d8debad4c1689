@item:F-DSP-02 @profile:crh2
Feature: F-DSP-02 A failed transmission board is shown on both cab monitors within 500 ms
  Requirements: NET-02 (primary), TST-04.
  Every node reports the health of its boards (CPU3, MDM8, MDM9, RXC, TXC) in its status data; the cab
  monitors turn it into a fault message. A failed board of an LCU or of a CCU system appears on both
  monitors within 500 ms, alone (no other node is blamed), and disappears again after the repair.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:NET-02 @req:TST-04
  Scenario Outline: F-DSP-02 A failed <board> is shown on both monitors within 500 ms
    Then the cab 1 monitor shows no faults
    And the cab 8 monitor shows no faults
    When board "<board>" fails
    And 500 ms pass
    Then the cab 1 monitor shows "<board> failure" and no other fault
    And the cab 8 monitor shows "<board> failure" and no other fault

    Examples:
      | board             |
      | car3.LCU.MDM9     |
      | car5.LCU.RXC      |
      | car1.CCU.sys2.TXC |
      | car8.CCU.sys1.TXC |

  @req:NET-02 @req:TST-04
  Scenario: F-DSP-02 The fault disappears from the monitors within 500 ms of the repair
    Given board "car3.LCU.MDM9" has failed
    When 500 ms pass
    Then the cab 1 monitor shows "car3.LCU.MDM9 failure" and no other fault
    When board "car3.LCU.MDM9" is repaired
    And 500 ms pass
    Then the cab 1 monitor shows no faults
    And the cab 8 monitor shows no faults

  @req:NET-02 @req:TST-04
  Scenario: F-DSP-02 A failed MDM9 leaves the rest of the display running
    When board "car2.LCU.MDM9" fails
    And the driver moves the traction notch of cab 1 to 4
    And 200 ms pass
    Then the cab 1 monitor shows "car2.LCU.MDM9 failure" and no other fault
    And the cab 1 monitor changes "traction notch" to "4" within 200 ms
