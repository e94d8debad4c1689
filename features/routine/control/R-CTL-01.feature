@item:R-CTL-01 @profile:crh2
Feature: R-CTL-01 Traction and brake command transmission
  Routine control test. Requirements: CMD-02 (primary), CMD-05, PRO-01, TST-03.
  The active cab's CCU broadcasts the driver's commands; every CI and BCU takes them over path 1
  (MDM9, HDLC over fibre) with full notch resolution.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:CMD-02 @req:CMD-05 @req:TST-03
  Scenario: R-CTL-01 A traction notch reaches every CI and BCU over path 1 with full resolution
    When the driver moves the traction notch of cab 1 to 7
    And 100 ms pass
    Then every CI and BCU receives traction notch 7 over path 1 within 40 ms
    And only "car1.CCU.sys1" puts commands on the ring

  @req:CMD-02 @req:CMD-05 @req:TST-03
  Scenario: R-CTL-01 A brake step reaches every BCU over path 1
    When the driver moves the brake handle of cab 1 to step 5
    And 100 ms pass
    Then every BCU receives brake step 5 over path 1 within 40 ms

  @req:PRO-01 @req:CMD-05 @req:TST-03
  Scenario: R-CTL-01 The cab holding the key commands the train
    When the driver removes the key from cab 1
    And 100 ms pass
    And the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to forward
    And the driver moves the traction notch of cab 8 to 3
    And 200 ms pass
    Then only "car8.CCU.sys1" puts commands on the ring
    And every CI and BCU receives traction notch 3 over path 1 within 40 ms
