@item:F-NET-06 @profile:crh2
Feature: F-NET-06 Three priorities: control commands are never held up by status or block data
  Requirements: NET-06 (primary), PRO-01.
  Priority 1 control commands, 2 status data, 3 block data. Under full status and block traffic a
  command waits at most for the one frame already on a fibre at each node.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the traction notch of cab 1 is at 5
    And the train has been powered up for 1000 ms

  @req:NET-06 @req:PRO-01
  Scenario: F-NET-06 Commands keep their latency while block and status data load the ring
    When "car8.LCU" asks to send a 6000-byte record as block data
    And "car2.LCU" asks to send a 6000-byte record as block data
    And 2 s pass
    Then every LCU receives every command within 15 ms of its transmission
    And each node on the way adds at most 1.35 ms to a command
