@item:F-CTL-15 @profile:metro-tcn @req:TST-04
Feature: F-CTL-15 Active-cab CCU failure: the adjacent VCU takes over and the train runs on
  Requirements: RED-05 (primary), TCN-08, TST-04.
  The CCU of the cab with the key computes traction and brake from the master controller and sends them
  over the MVB and, through the WTB, to the other unit. When it fails, the VCU next to it takes its MVB and
  the control, and the train runs on without restriction: no VVVF or BECU changes what it applies. Bound
  chosen by the suite: the VCU polls the MVB within 100 ms.

  Background:
    Given a 6-car metro train with its train control and diagnosis system
    And the direction switch of cab 1 is at forward
    And the direction switch of cab 6 is at forward

  @req:RED-05 @req:TCN-08
  Scenario Outline: F-CTL-15 The CCU of active cab <cab> fails: "<vcu>" takes over without restriction
    Given the driver has inserted the key in cab <cab>
    And the master controller of cab <cab> demands 60 % traction
    And the train has been powered up for 1000 ms
    When "<ccu>" fails
    And 1000 ms pass
    Then "<vcu>" is the master of "<bus>" within 100 ms and stays so
    And no VVVF or BECU changes what it applies
    And every VVVF applies 60 % traction
    When the driver moves the master controller of cab <cab> to 80 % traction
    And 200 ms pass
    Then every VVVF applies 80 % traction within 100 ms
    When the driver moves the master controller of cab <cab> to 70 % brake
    And 200 ms pass
    Then every BECU applies 70 % brake within 100 ms
    And every VVVF applies 0 % traction

    Examples:
      | cab | ccu      | vcu      | bus       |
      | 1   | car1.CCU | car2.VCU | unit1.MVB |
      | 6   | car6.CCU | car5.VCU | unit2.MVB |

  # Seed 26's checker: a CCU failing at the instant of power-up, before its MVB's first basic period, left the
  # watch without a time it was last heard.
  @req:RED-05
  Scenario: F-CTL-15 The CCU of active cab 1 fails at the instant of power-up: "car2.VCU" takes over all the same
    Given the driver has inserted the key in cab 1
    And the master controller of cab 1 demands 60 % traction
    And the train is powered up
    When "car1.CCU" fails
    And 1000 ms pass
    Then "car2.VCU" is the master of "unit1.MVB" within 100 ms and stays so
    And every VVVF applies 60 % traction

  @req:RED-05
  Scenario Outline: F-CTL-15 The CCU of the cab without the key fails <ms> ms after power-up: its VCU relays the command
    Given the driver has inserted the key in cab 1
    And the master controller of cab 1 demands 60 % traction
    And the train has been powered up for <ms> ms
    When "car6.CCU" fails
    And 1000 ms pass
    Then "car5.VCU" is the master of "unit2.MVB" within 100 ms and stays so
    And no VVVF or BECU changes what it applies
    And "car1.CCU" is the WTB master within 25 ms and stays so

    Examples: instants through one 25 ms WTB cycle
      | ms   |
      | 1000 |
      | 1005 |
      | 1010 |
      | 1015 |
      | 1020 |

  @req:TCN-08
  Scenario: F-CTL-15 The master controller reaches every VVVF and BECU in both units
    Given the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms
    When the driver moves the master controller of cab 1 to 45 % traction
    And 200 ms pass
    Then every VVVF applies 45 % traction within 100 ms
    And every BECU applies 0 % brake
    When the driver moves the master controller of cab 1 to 100 % brake
    And 200 ms pass
    Then every BECU applies 100 % brake within 100 ms
    And every VVVF applies 0 % traction

  @req:TCN-08
  Scenario: F-CTL-15 In reverse the master controller reaches every VVVF too
    Given the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at reverse
    And the train has been powered up for 1000 ms
    When the driver moves the master controller of cab 1 to 45 % traction
    And 200 ms pass
    Then every VVVF applies 45 % traction within 100 ms
    And every BECU applies 0 % brake

  @req:TCN-08
  Scenario: F-CTL-15 Without a key in either cab the train stays braked and the displays say so
    Given the train has been powered up for 1000 ms
    When 500 ms pass
    Then every VVVF applies 0 % traction
    And every BECU applies 100 % brake
    And the cab 1 display shows the mode "no cab"
    And the cab 6 display shows the mode "no cab"

  # Each unit's "no cab" rests on the other unit's word over the WTB that its cab has no key either; the
  # standby VCUs of that unit are not the ones that give it (its CCU, the unit's MVB master, is).
  @req:TCN-08
  Scenario Outline: F-CTL-15 Without a key in either cab, both standby VCUs of unit <unit> failing changes no display
    Given the train has been powered up for 1000 ms
    When "<vcu1>" fails
    And "<vcu2>" fails
    And 2000 ms pass
    Then the cab 1 display shows the mode "no cab"
    And the cab 6 display shows the mode "no cab"
    And every BECU applies 100 % brake

    Examples:
      | unit | vcu1     | vcu2     |
      | 1    | car2.VCU | car3.VCU |
      | 2    | car4.VCU | car5.VCU |
