@item:F-ATP-05 @profile:vdx @req:TST-04
Feature: F-ATP-05 FS output self-test every 5 s, 3 ms, sampled from the 2nd ms against 6 V
  Requirements: VDX-03 (primary), VDX-04, VDX-06, TST-04.
  Every 5 s the VDX removes one of the four excitation sources of the FS output for 3 ms and samples the
  output from the start of the 2nd ms: below 6 V passes; otherwise C019, the FS output stays off (emergency
  brake) until restart: a restart is what recovers from C019 (VDX-06), nothing else. The relay rides
  through the 3 ms: the loop stays closed. To raise C019 the ATP releases 1 ms before a test: the old
  firmware then runs it 16 ms after the release (VDX-06), on the most charged coil it ever tests: if the
  old firmware shows C019 at all, wherever in the 2nd ms it samples, it does there.

  Background:
    Given a CTCS3-300T ATP with its VDX emergency-brake interface
    And the FS output is fed with 137 V

  @req:VDX-03 @req:VDX-04
  Scenario: F-ATP-05 A minute of self-tests: every 5 s, 3 ms each, sampled 1 ms in, the loop stays closed
    Given the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 60 s pass
    Then an FS self-test comes every 5 s
    And each FS self-test pulls the FS output low for 3 ms and samples it 1 ms in
    And the emergency-brake loop stays closed
    And no C019 is raised

  @req:VDX-03 @req:VDX-04
  Scenario: F-ATP-05 Inside a self-test the FS output is low and the relay holds; after it the output is back
    Given the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 6 s pass
    And the VDX is 1.5 ms into its next FS self-test
    Then the FS output reads below 6 V
    And relay EB2R is energised
    When 5 ms pass
    Then the FS output reads at least 6 V
    And the emergency-brake loop is closed

  @req:VDX-03 @req:VDX-06
  Scenario: F-ATP-05 A self-test that finds the FS output high raises C019, which stays until restart
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 1 ms before the next FS self-test
    And 30 s pass
    Then C019 is raised and the emergency-brake loop stays open
    And every FS self-test sampled at 6 V or more raised C019 and none below

  @req:VDX-03 @req:VDX-06
  Scenario: F-ATP-05 C019 still holds the emergency brake two hours later, without a restart
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 1 ms before the next FS self-test
    And 2 h pass
    Then C019 is raised and the emergency-brake loop stays open

  @req:VDX-03 @req:VDX-06
  Scenario: F-ATP-05 After C019 the emergency-brake loop is still open after a six-minute run
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 1 ms before the next FS self-test
    And 1000 ms pass
    Then C019 is raised and the emergency-brake loop stays open
    When the train runs for 0.1 h
    Then the emergency-brake loop is open

  @req:VDX-03 @req:VDX-06
  Scenario: F-ATP-05 A restart clears C019
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 1 ms before the next FS self-test
    And 1000 ms pass
    And the VDX is restarted
    And the ATP releases the emergency brake
    And 12 s pass
    Then no C019 is raised
    And the emergency-brake loop is closed
