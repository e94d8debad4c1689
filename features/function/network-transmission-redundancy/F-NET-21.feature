@item:F-NET-21 @profile:metro-tcn @req:TST-04
Feature: F-NET-21 Metro train network: WTB between the units, one MVB in each, their cycles
  Requirements: TCN-01 (primary), TCN-02, TCN-03, TCN-04, TST-04.
  Six cars in two units of three: CCUs in cars 1 and 6, VCUs in cars 2 to 5, each joined to the WTB
  through its gateway (VGWS); each unit has its own MVB, mastered by its CCU. The RS-485 level (PIS, doors,
  HVAC behind a VCU) is outside what this item checks.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TCN-02 @req:TCN-08
  Scenario: F-NET-21 Two CCUs with memory, four VCUs without, I/O modules and displays in the cab cars
    Then the boards of "car1.CCU" are VCPUS, VGWS, VMS, VDIS, VDOS and VPS
    And the boards of "car6.CCU" are VCPUS, VGWS, VMS, VDIS, VDOS and VPS
    And the boards of "car3.VCU" are VCPUS, VGWS, VDOS and VPS
    And car 1 has the devices CCU, DU, IO1, IO2, BECU, APU and VATC
    And car 6 has the devices CCU, DU, IO1, IO2, BECU, APU and VATC
    And car 2 has the devices VCU, VVVF and BECU
    And car 5 has the devices VCU, VVVF and BECU

  @req:TCN-01 @req:TCN-03
  Scenario: F-NET-21 The WTB master in car 1 polls all six gateways within every 25 ms cycle
    When 1000 ms pass
    Then "car1.CCU" is the WTB master within 25 ms and stays so
    And the WTB master polls every node at least every 25 ms
    And every WTB poll is answered
    And no WTB master frame comes from "car6.CCU", "car4.VCU", "car5.VCU"

  @req:TCN-01 @req:TCN-03 @req:TCN-04
  Scenario Outline: F-NET-21 The CCU of unit <unit> masters its own MVB with a basic period of 1 ms
    When 500 ms pass
    Then "<ccu>" is the master of "unit<unit>.MVB" within 1 ms and stays so
    And the master frames of "<ccu>" on "unit<unit>.MVB" are never more than 1 ms apart
    And the exchanges on "unit<unit>.MVB" never overlap: each master frame follows the frames of the one before
    And every device of <cars> answers the status polls of "<ccu>" on "unit<unit>.MVB"

    Examples:
      | unit | ccu      | cars           |
      | 1    | car1.CCU | cars 1, 2 and 3 |
      | 2    | car6.CCU | cars 4, 5 and 6 |
