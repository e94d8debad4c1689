@item:F-RSD-02 @profile:crh2
Feature: F-RSD-02 Traction notch, brake step and direction on the cab monitor within 200 ms
  Requirements: CMD-05 (primary), PRO-01, PRO-02, TST-04.
  The driver's controller sets direction, traction notch and brake step; the commanding CCU broadcasts
  them (PRO-01) and the running state on the monitor is what car 1's LCU received (docs/decisions.md,
  "Display"). A desk change reaches car 1's LCU within one command interval plus the ring delay and is
  displayed with the next status data: the function test allows 200 ms (10 + 15 + 150, rounded up). Notch and
  brake step are moved while the train runs: at standstill a product may hold a brake of its own, which the
  monitor shows as the cars' brake step and takes off with the first notch (docs/decisions.md, "Standstill
  holding brake (crh2)").

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:CMD-05 @req:PRO-01 @req:PRO-02 @req:TST-04
  Scenario Outline: F-RSD-02 Traction notch <notch> is displayed within 200 ms
    Given the train runs at 100 km/h
    When 300 ms pass
    And the driver moves the traction notch of cab 1 to <notch>
    And 200 ms pass
    Then the cab 1 monitor changes "traction notch" to "<notch>" within 200 ms
    And the cab 8 monitor changes "traction notch" to "<notch>" within 200 ms
    And the cab 1 monitor kept "brake step" unchanged from 0 ms on

    Examples:
      | notch |
      | 1     |
      | 5     |
      | 10    |

  @req:CMD-05 @req:PRO-01 @req:PRO-02 @req:TST-04
  Scenario Outline: F-RSD-02 Brake step <step> is displayed within 200 ms
    Given the train runs at 100 km/h
    When 300 ms pass
    And the driver moves the brake handle of cab 1 to step <step>
    And 200 ms pass
    Then the cab 1 monitor changes "brake step" to "<step>" within 200 ms
    And the cab 8 monitor changes "brake step" to "<step>" within 200 ms
    And the cab 1 monitor kept "traction notch" unchanged from 0 ms on

    Examples:
      | step |
      | 1    |
      | 4    |
      | 7    |

  @req:CMD-05 @req:PRO-01 @req:PRO-02 @req:TST-04
  Scenario: F-RSD-02 A change of direction is displayed within 200 ms
    Then the cab 1 monitor displays "direction" as "forward"
    When the driver sets the direction switch of cab 1 to reverse
    And 200 ms pass
    Then the cab 1 monitor changes "direction" to "reverse" within 200 ms
    When the driver sets the direction switch of cab 1 to neutral
    And 200 ms pass
    Then the cab 1 monitor changes "direction" to "neutral" within 200 ms
    And the cab 8 monitor displays "direction" as "neutral"

  @req:CMD-05 @req:PRO-01 @req:PRO-02 @req:TST-04
  Scenario: F-RSD-02 A notch moved back to 0 is displayed as 0 within 200 ms
    Given the traction notch of cab 1 is at 6
    When 300 ms pass
    Then the cab 1 monitor displays "traction notch" as "6"
    When the driver moves the traction notch of cab 1 to 0
    And 200 ms pass
    Then the cab 1 monitor changes "traction notch" to "0" within 200 ms
