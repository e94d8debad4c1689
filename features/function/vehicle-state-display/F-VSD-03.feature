@item:F-VSD-03 @profile:crh2
Feature: F-VSD-03 Main air pipe pressure on the cab monitor within 150 ms and +-1 kPa
  Requirements: TST-04 (primary), PRO-02.
  Car 1's LCU puts the main air pipe pressure in its status data; the monitor displays a change within the
  display bound of 150 ms (one 120 ms status cycle, PRO-02, plus holding time and ring latency) and within
  +-1 kPa, in both directions, and follows a falling pressure with at most 150 ms of lag.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:TST-04 @req:PRO-02
  Scenario Outline: F-VSD-03 A pressure change to <kpa> kPa is displayed within 150 ms
    Given the main air pipe pressure is <from> kPa
    When 300 ms pass
    And the main air pipe pressure changes to <kpa> kPa
    And 150 ms pass
    Then the cab 1 monitor displays "main pipe pressure" between <lo> and <hi> within 150 ms
    And the cab 8 monitor displays "main pipe pressure" between <lo> and <hi> within 150 ms

    Examples:
      | from | kpa | lo  | hi  |
      | 780  | 650 | 649 | 651 |
      | 650  | 880 | 879 | 881 |
      | 880  | 500 | 499 | 501 |

  @req:TST-04 @req:PRO-02
  Scenario: F-VSD-03 A falling pressure is displayed with at most 150 ms of lag
    Given the main air pipe pressure is 800 kPa
    When 300 ms pass
    And the main air pipe pressure goes from 800 kPa to 700 kPa at 50 kPa per second
    And 1000 ms pass
    Then the cab 1 monitor displays "main pipe pressure" between 749 and 758.5
    When 1150 ms pass
    Then the cab 1 monitor displays "main pipe pressure" between 699 and 701 within 2150 ms

  @req:TST-04 @req:PRO-02
  Scenario: F-VSD-03 A steady pressure is displayed without wandering
    Given the main air pipe pressure is 720 kPa
    When 1500 ms pass
    Then the cab 1 monitor displays "main pipe pressure" between 719 and 721 within 150 ms
    And the cab 1 monitor kept "main pipe pressure" unchanged from 150 ms on
