@item:F-CTL-11 @profile:crh2
Feature: F-CTL-11 Direction command transmission
  Requirements: CMD-05 (primary), CMD-02, ILK-08, TST-05, TST-04.
  The direction set on the desk's direction controller (CMD-05) travels with every command over path 1 and
  reaches every CI within the project's desk-to-CI bound of 40 ms; the old direction is gone from then on.
  At neutral no traction is produced (ILK-08). The monitor shows the direction the network delivered.
  # why: A CRH2 driver's controller has a direction controller (CMD-05), and the converters can only drive the train the way the driver chose if the direction reaches every one of them.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:CMD-05 @req:CMD-02 @req:TST-05 @req:TST-04
  Scenario: F-CTL-11 Forward to reverse reaches every CI within 40 ms and the monitor shows it
    When the driver sets the direction switch of cab 1 to reverse
    And 200 ms pass
    Then every CI receives direction "reverse" within 40 ms
    And from 40 ms on no CI or BCU receives direction "forward"
    And the cab 1 monitor displays "direction" as "reverse" within 150 ms

  @req:CMD-05 @req:CMD-02 @req:TST-05 @req:TST-04
  Scenario: F-CTL-11 In reverse the driver's notch reaches every CI as in forward
    Given the direction switch of cab 1 is at reverse
    When the driver moves the traction notch of cab 1 to 3
    And 200 ms pass
    Then every CI and BCU receives traction notch 3 over path 1 within 40 ms
    And from 40 ms on no CI or BCU receives direction "forward"

  @req:CMD-05 @req:ILK-08 @req:TST-05 @req:TST-04
  Scenario: F-CTL-11 At neutral the direction reaches every CI and traction stops
    Given the traction notch of cab 1 is at 5
    When 200 ms pass
    Then every CI and BCU receives traction notch 5 over path 1 within 40 ms
    When the driver sets the direction switch of cab 1 to neutral
    And 200 ms pass
    Then every CI receives direction "neutral" within 40 ms
    And no CI receives a traction notch above 0 from 40 ms on
    And the cab 1 monitor displays "direction" as "neutral" within 150 ms
    When the driver sets the direction switch of cab 1 to forward
    And 200 ms pass
    Then every CI receives direction "forward" within 40 ms
    And every CI and BCU receives traction notch 5 over path 1 within 40 ms
