@item:F-CTL-01 @profile:crh2
Feature: F-CTL-01 Traction/brake command transmission at every notch and brake step
  Requirements: CMD-02 (primary), CMD-05, PRO-01, TST-04, TST-05.
  The function-level form of the routine item R-CTL-01: every traction notch (1-10) and every service brake
  step (1-7) set on the desk of the key-inserted cab reaches every CI and BCU over path 1 (MDM9, HDLC over
  fibre) with full resolution, within the project's desk-to-CI bound of 40 ms (docs/decisions.md, "Command paths"),
  and the commands on the ring keep PRO-01's interval and delay. The brake steps are set while the train runs:
  at standstill a product may hold a brake of its own, and the command then carries the higher step
  (docs/decisions.md, "Standstill holding brake (crh2)").

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:CMD-02 @req:CMD-05 @req:TST-04 @req:TST-05
  Scenario Outline: F-CTL-01 Traction notch <notch> reaches every CI and BCU over path 1 with full resolution
    When the driver moves the traction notch of cab 1 to <notch>
    And 150 ms pass
    Then every CI and BCU receives traction notch <notch> over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch <notch> and brake step 0 over path 1

    Examples:
      | notch |
      | 1     |
      | 2     |
      | 3     |
      | 4     |
      | 5     |
      | 6     |
      | 7     |
      | 8     |
      | 9     |
      | 10    |

  @req:CMD-02 @req:CMD-05 @req:TST-04 @req:TST-05
  Scenario Outline: F-CTL-01 Brake step <step> reaches every BCU over path 1 with full resolution
    Given the train runs at 100 km/h
    When the driver moves the brake handle of cab 1 to step <step>
    And 150 ms pass
    Then every BCU receives brake step <step> over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 0 and brake step <step> over path 1

    Examples:
      | step |
      | 1    |
      | 2    |
      | 3    |
      | 4    |
      | 5    |
      | 6    |
      | 7    |

  @req:CMD-02 @req:CMD-05 @req:TST-04 @req:TST-05
  Scenario: F-CTL-01 Notching up one notch at a time, each notch reaches every CI within 40 ms
    When the driver moves the traction notch of cab 1 to 1
    And 100 ms pass
    Then every CI and BCU receives traction notch 1 over path 1 within 40 ms
    When the driver moves the traction notch of cab 1 to 2
    And 100 ms pass
    Then every CI and BCU receives traction notch 2 over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 2 and brake step 0 over path 1
    When the driver moves the traction notch of cab 1 to 1
    And 100 ms pass
    Then every CI and BCU receives traction notch 1 over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 1 and brake step 0 over path 1

  @req:PRO-01 @req:CMD-05 @req:TST-04 @req:TST-05
  Scenario: F-CTL-01 While the driver changes notch and brake step the ring keeps PRO-01's interval and delay
    When the driver moves the traction notch of cab 1 to 6
    And 100 ms pass
    And the driver moves the traction notch of cab 1 to 0
    And the driver moves the brake handle of cab 1 to step 4
    And 300 ms pass
    Then only "car1.CCU.sys1" puts commands on the ring
    And commands leave the CCU at intervals of at least 10 ms
    And every LCU receives every command within 15 ms of its transmission
    And from 40 ms on every command carries traction notch 0 and brake step 4
