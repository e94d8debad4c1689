@item:F-ATP-14 @profile:vdx @req:TST-04
Feature: F-ATP-14 The VDX's loop and C019 hold under random stimulus sequences
  Requirements: VDX-01, VDX-03, VDX-06 (each scenario its own), TST-04.
  Model-based testing: hypothesis drives fresh VDX rigs with random sequences of this library's own sentences
  (the ATP's brake, the isolation switch, the supply, restarts, time passing) and checks the invariant after
  every stimulus. A sequence that breaks one is shrunk and printed as a scenario to paste into a feature file.

  Background:
    Given random sequences of the step library's stimuli, 40 per invariant from seed 0

  @req:VDX-01
  Scenario: F-ATP-14 The loop is closed exactly when both relays or the isolation switch close it
    Then after every stimulus of every sequence, the loop is closed exactly when both relays or the isolation switch close it

  @req:VDX-03 @req:VDX-06
  Scenario: F-ATP-14 C019 stays, the FS output off, until the VDX restarts
    Then after every stimulus of every sequence, C019 stays, the FS output off, until the VDX restarts
