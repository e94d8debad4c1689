@item:F-ATP-10 @profile:atp @req:TST-04
Feature: F-ATP-10 DEF train-interface self-test: 10 steps of 2.2 s, within 22 s
  Requirements: ATP-08 (primary), TST-04.
  At start-up each of the 10 DEF steps changes a train-interface output and reads it back 2.2 s later (was
  2.5 s); the whole test ends within 22 s. A wrong read-back stops it.

  Background:
    Given a CTCS-2 200C on-board ATP on the test rig

  @req:ATP-08
  Scenario: F-ATP-10 Ten steps 2.2 s apart, done within 22 s
    Given the ATP has completed its start-up self-test
    Then the DEF self-test ran 10 steps 2.2 s apart and finished within 22 s
    And the ATP is in mode SB

  @req:ATP-08
  Scenario: F-ATP-10 A train-interface output that does not read back stops the test and brakes
    Given "MTORE" has failed
    And the train has been powered up for 30000 ms
    Then the DEF self-test stops at a wrong read-back
    And the ATP commands emergency brake
    And the DMI shows "DEF fault"
