@item:F-CTL-13 @profile:crh2
Feature: F-CTL-13 Control transfer between cabs
  Requirements: ILK-07 (primary), CMD-05, PRO-01, TST-05, TST-04.
  Only the cab whose master control relay is up commands the train (ILK-07): while the key is in cab 1, a key
  in cab 8 picks nothing up, cab 8's controller and monitor orders are void and cab 1 stays the only sender.
  Once the key leaves cab 1 and goes into cab 8, cab 8's CCU becomes the only sender on the ring (PRO-01),
  its controller (CMD-05) drives every CI and BCU, its monitor orders act, and cab 1's are void.
  # why: A CRH2 EMU is driven from either end, so handing command from one cab to the other without two cabs ever commanding at once is a basic control function.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And the train has been powered up for 1000 ms

  @req:ILK-07 @req:CMD-05 @req:TST-05 @req:TST-04
  Scenario: F-CTL-13 A second key in cab 8 does not take command away from cab 1
    When the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to reverse
    And the driver moves the traction notch of cab 8 to 9
    And 300 ms pass
    Then only "car1.CCU.sys1" puts commands on the ring
    And "car8.CCU.sys1" puts no commands on the ring
    And no CI or BCU receives a traction notch other than 5
    And from 0 ms on no CI or BCU receives direction "reverse"
    And the "MCR" lamp of cab 8 is dark

  @req:ILK-07 @req:TST-05 @req:TST-04
  Scenario: F-CTL-13 An order on the monitor of the cab without command is void
    Given the driver has inserted the key in cab 8
    When the driver orders "car3.CI cut-out" to "cut out" on the cab 8 monitor
    And 500 ms pass
    Then the "car3.CI contactor" stays closed
    And the "car3.CI cut-out" stays in

  @req:ILK-07 @req:CMD-05 @req:PRO-01 @req:TST-05 @req:TST-04
  Scenario: F-CTL-13 Moving the key from cab 1 to cab 8 moves command to cab 8
    When the driver removes the key from cab 1
    And 100 ms pass
    And the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to forward
    And the driver moves the traction notch of cab 8 to 3
    And 300 ms pass
    Then only "car8.CCU.sys1" puts commands on the ring
    And every LCU receives every command within 15 ms of its transmission
    And every CI and BCU receives traction notch 3 over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 3 and brake step 0 over path 1
    And the "MCR" lamp of cab 8 is lit
    And the "MCR" lamp of cab 1 is dark

  @req:ILK-07 @req:TST-05 @req:TST-04
  Scenario: F-CTL-13 After the transfer cab 8's orders act and cab 1's are void
    When the driver removes the key from cab 1
    And the driver inserts the key in cab 8
    And 200 ms pass
    And the driver orders "unit2.VCB" to "open" on the cab 8 monitor
    And 300 ms pass
    Then the "unit2.VCB" is open within 300 ms
    And the cab 8 monitor displays "unit2.VCB" as "open" within 300 ms
    When the driver orders "unit1.VCB" to "open" on the cab 1 monitor
    And 500 ms pass
    Then the "unit1.VCB" stays closed
