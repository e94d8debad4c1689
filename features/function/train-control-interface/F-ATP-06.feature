@item:F-ATP-06 @profile:vdx @req:TST-04
Feature: F-ATP-06 C019: a release just before the FS self-test, by firmware and FS voltage
  Requirements: VDX-05 (primary), VDX-06, VDX-03, TST-04.
  The field fault C019 (seed 003): a brake released less than 30 ms before an FS self-test leaves the
  relay coil charged, the FS output does not fall below 6 V in time and the VDX brakes the train. Released
  36 ms or more before, the test passes; 137 V makes it likelier than 120 V. The old firmware postpones a
  test that follows a release by 16 ms, which does not help; the new one by 48 ms, and C019 no longer
  occurs. The sweep below is the test that would have caught C019 before it reached a train; its table
  is attached to the report. The article's window (C019 for every release under 30 ms at 137 V, and at
  19.795 ms) is its measurement with a sample 1 ms into the test: a VDX sampling later in the 2nd ms (VDX-03
  allows it) sees the coil further decayed and a narrower window, so that check is informative.

  Background:
    Given a CTCS3-300T ATP with its VDX emergency-brake interface

  @req:VDX-05 @req:VDX-06 @req:VDX-03
  Scenario: F-ATP-06 Old firmware: C019 after a late release at 137 V, never from 36 ms, likelier at 137 V than at 120 V
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the release is swept from 1 to 40 ms before an FS self-test at 120 and 137 V
    Then at 137 V C019 is raised for some release under 30 ms before the test
    And at 137 V no C019 is raised for a release 36 ms or more before the test
    And at 120 V no C019 is raised for a release 36 ms or more before the test
    And C019 comes at 137 V for every offset it comes at 120 V, and for more
    And every FS self-test sampled at 6 V or more raised C019 and none below

  # Near the edge of C019 a release a quarter of a millisecond later moves the sample across 6 V: there a
  # self-test's verdict tests the threshold itself, not only which side of it the coil's fall lands.
  @req:VDX-05 @req:VDX-03
  Scenario: F-ATP-06 Old firmware near the edge of C019: each self-test's verdict follows its own sample against 6 V
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the release is swept from 24 to 32 ms in 0.25 ms steps before an FS self-test at 110, 120 and 137 V
    Then every FS self-test sampled at 6 V or more raised C019 and none below

  # The article's window, measured with a sample 1 ms in; it holds its 19.795 ms measurement too (a coil released
  # later is more charged, so C019 at 20 ms means C019 at 19.795 ms).
  @req:VDX-05 @informative
  Scenario: F-ATP-06 Old firmware, the article's window: C019 for every release under 30 ms at 137 V
    Given the VDX runs the old firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the release is swept from 1 to 30 ms before an FS self-test at 137 V
    Then at 137 V C019 is raised for every release under 30 ms before the test

  @req:VDX-06
  Scenario: F-ATP-06 New firmware: no C019 at any release offset or FS voltage
    Given the VDX runs the new firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the release is swept from 1 to 50 ms before an FS self-test at 77, 110, 120 and 137.5 V
    Then no C019 is raised at any offset
    And every FS self-test sampled at 6 V or more raised C019 and none below

  @req:VDX-05
  Scenario Outline: F-ATP-06 The article's measurements at 137 V: released <offset> ms before the test
    Given the VDX runs the <firmware> firmware
    And the FS output is fed with 137 V
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake <offset> ms before the next FS self-test
    And 6 s pass
    Then <verdict>

    Examples:
      | firmware | offset | verdict                                                |
      | old      | 35.75  | no C019 is raised                                      |
      | new      | 19.795 | no C019 is raised                                      |

  # "Postpones by 16 ms" read either way: 16 ms from the release, or 16 ms from when the test was due (5 ms
  # after the release here); so the test comes from <postpone> ms after the release to <latest> ms after it.
  @req:VDX-06
  Scenario Outline: F-ATP-06 A test that would follow a release within <postpone> ms waits <postpone> ms (<firmware> firmware)
    Given the VDX runs the <firmware> firmware
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 5 ms before the next FS self-test
    And 6 s pass
    Then an FS self-test ran at least <postpone> ms after the release
    And the first FS self-test after the release ran at most <latest> ms after the release

    Examples:
      | firmware | postpone | latest |
      | old      | 16       | 21     |
      | new      | 48       | 53     |

  # A brake applied again across a due test cancels the release before it: the postponement is owed to the
  # release that comes before the test runs. Released again just after the due time, the coil is charged.
  @req:VDX-06
  Scenario Outline: F-ATP-06 New firmware: released, braked again across a due self-test, released <again> ms after it: no C019
    Given the VDX runs the new firmware
    And the FS output is fed with 137 V
    And the train has been powered up for 1000 ms
    And the ATP has released the emergency brake
    When 11 s pass
    And the ATP releases the emergency brake 30 ms before the next FS self-test, applies it 10 ms before and releases it again <again> ms after
    And 6 s pass
    Then no C019 is raised

    Examples:
      | again |
      | 2     |
      | 10    |
