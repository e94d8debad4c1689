@item:F-NET-10 @profile:crh2 @req:TST-04
Feature: F-NET-10 Control command broadcast: 12 bytes, at least 10 ms apart, at most 15 ms on the ring
  Requirements: PRO-01 (primary), NET-06, TST-04.
  The active cab's CCU broadcasts commands no other node can disturb; per-node pass-through 0.25 ms.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 1

  @req:PRO-01
  Scenario: F-NET-10 On an idle ring each node adds at most 0.25 ms
    Given the train is powered up
    When 400 ms pass
    Then each node on the way adds at most 0.25 ms to a command
    And every LCU receives every command within 15 ms of its transmission

  @req:PRO-01
  Scenario: F-NET-10 Commands are 12 bytes long and at least 10 ms apart
    Given an analyser is attached to the ring link between "car5.LCU" and "car6.LCU"
    And the train has been powered up for 1000 ms
    When 1000 ms pass
    Then every command frame on the analysed link carries 12 bytes of data
    And commands leave the CCU at intervals of at least 10 ms
    And only "car1.CCU.sys1" puts commands on the ring

  @req:PRO-01 @req:NET-06
  Scenario: F-NET-10 The worst case with status and block traffic stays within 15 ms
    Given the train has been powered up for 1000 ms
    When "car5.LCU" asks to send a 3000-byte record as block data
    And 3 s pass
    Then every LCU receives every command within 15 ms of its transmission
