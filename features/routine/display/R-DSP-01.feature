@item:R-DSP-01 @profile:crh2
Feature: R-DSP-01 Status data of every car shown on the cab monitor
  Routine display test. Requirements: PRO-02 (primary), TST-03.
  Every node broadcasts its status data under token control; the cab monitor is fed from the CCU.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:PRO-02 @req:TST-03
  Scenario: R-DSP-01 The cab monitor receives every node's status data once per 120 ms cycle
    When 2 s pass
    Then the cab 1 monitor receives status data from every other node every 115 to 125 ms
    And the cab 8 monitor receives status data from every other node every 115 to 125 ms
    And the cab 1 monitor shows no faults

  @req:PRO-02 @req:TST-03
  Scenario: R-DSP-01 A status data frame carries 240 bytes of data
    Given an analyser is attached to the ring link between "car4.LCU" and "car5.LCU"
    When 500 ms pass
    Then every status frame on the analysed link carries 240 bytes of data
