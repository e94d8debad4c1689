@item:F-ATP-16 @profile:atp-crh2 @req:TST-04
Feature: F-ATP-16 A failed DEF self-test on a fitted train: the ATP's emergency brake reaches the train
  Requirements: ILK-08 (primary), ATP-08, TST-04.
  A train-interface output that does not read back fails the DEF self-test (ATP-08); the project reads that
  as the ATP braking and telling the driver (F-ATP-10, @tentative, docs/decisions.md "A failed DEF
  self-test"; which brake, maximum service or emergency, is the product's). Fitted to a CRH2 set, that brake
  is an ATP brake command, and any brake command from the ATP suppresses traction (ILK-08): the driver's
  notch reaches no converter, and the train takes the brake the ATP chose (the atp-crh2 contract: emergency
  applies the train's emergency brake, maximum service raises every BCU to full service), whether or not the
  VDX holds the loop open (its own emergency-brake input is the rig's, released in the second scenario).

  Background:
    Given a CTCS-2 200C on-board ATP fitted to an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And "MTORE" has failed
    And the train has been powered up for 30000 ms

  @req:ILK-08 @req:ATP-08 @tentative
  Scenario: F-ATP-16 After a failed DEF self-test no traction reaches the train and its emergency brake is applied
    When 500 ms pass
    Then the ATP holds the train braked
    And every CI receives traction notch 0 within 100 ms
    And from 100 ms on the train brakes as the ATP commands

  @req:ILK-08 @req:ATP-08 @tentative
  Scenario: F-ATP-16 With the emergency-brake command to the VDX released, the failed ATP's own brake still holds the train
    When the ATP releases the emergency brake
    And 500 ms pass
    Then the ATP holds the train braked
    And every CI receives traction notch 0 within 100 ms
    And from 100 ms on the train brakes as the ATP commands
