@item:F-NET-06 @profile:crh2 @req:TST-04
Feature: F-NET-06 Three priorities: control commands are never held up by status or block data
  Requirements: NET-06 (primary), PRO-01, TST-04.
  Priority 1 control commands, 2 status data, 3 block data. A waiting command leaves before any waiting
  status or block frame; it waits only for a frame already on the fibre (frames are not pre-empted).
  The load: two LCUs send long records as block data while status data circulates; the analyser watches
  the fibre leaving car 1's LCU, where its own status data, its blocks and the passing commands meet.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And an analyser is attached to the ring link between "car1.LCU" and "car2.LCU"
    And the train has been powered up for 1000 ms

  @req:NET-06 @req:PRO-01
  Scenario: F-NET-06 Commands go ahead of waiting status and block data
    When "car1.LCU" asks to send a 6000-byte record as block data
    And "car5.LCU" asks to send a 6000-byte record as block data
    And 2 s pass
    Then on the analysed link no status or block frame of "car1.LCU" goes ahead of a waiting command
    And every LCU receives every command within 15 ms of its transmission

  # The commands car1's LCU passes on from the CCU: a second analyser on the span into it shows when each
  # arrived; from PRO-01's pass-through on, it is the next frame to start toward car 2.
  @req:NET-06 @req:PRO-01
  Scenario: F-NET-06 A command passing through an LCU goes ahead of the status and block data waiting there
    Given an analyser is attached to the ring link between "car1.CCU.sys2" and "car1.LCU"
    When "car1.LCU" asks to send a 6000-byte record as block data
    And "car5.LCU" asks to send a 6000-byte record as block data
    And 2 s pass
    Then on the analysed links no status or block frame leaves "car1.LCU" for "car2.LCU" ahead of a command that reached it more than 0.25 ms before
    And on the analysed links one frame at a time leaves each node
