@item:F-ILK-07 @profile:crh2 @req:TST-04
Feature: F-ILK-07 Only one cab's master control relay picks up
  Requirements: ILK-07 (primary), CMD-05, TST-04.
  Every operation in the cab whose relay cannot pick up is void (ILK-07), and stays void when the first cab's
  key comes out while the second key is still in: the second relay picks up only when its key is turned in
  again (docs/decisions.md), so a notch set there meanwhile never commands the train by itself.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 2
    And the train has been powered up for 1000 ms

  @req:ILK-07 @req:CMD-05
  Scenario: F-ILK-07 Operations in the other cab are void
    When the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to forward
    And the driver moves the traction notch of cab 8 to 9
    And 300 ms pass
    Then only "car1.CCU.sys1" puts commands on the ring
    And no CI or BCU receives a traction notch other than 2

  @req:ILK-07
  Scenario: F-ILK-07 The second cab takes over only after the first cab's key is out
    When the driver removes the key from cab 1
    And 100 ms pass
    And the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to forward
    And the driver moves the traction notch of cab 8 to 9
    And 300 ms pass
    Then only "car8.CCU.sys1" puts commands on the ring
    And every CI receives traction notch 9 within 60 ms

  @req:ILK-07 @tentative
  Scenario: F-ILK-07 Taking cab 1's key out while a key waits in cab 8 picks nothing up
    When the driver inserts the key in cab 8
    And the driver sets the direction switch of cab 8 to forward
    And the driver moves the traction notch of cab 8 to 9
    And the driver orders "car7.air conditioning" to "off" on the cab 8 monitor
    And 300 ms pass
    And the driver removes the key from cab 1
    And 1000 ms pass
    Then "car8.CCU.sys1" puts no commands on the ring
    And "car8.CCU.sys2" puts no commands on the ring
    And the "MCR" lamp of cab 8 is dark
    And no CI or BCU ever receives a traction notch other than 0 or 2
    And the "car7.air conditioning" stays on
    When the driver removes the key from cab 8
    And the driver inserts the key in cab 8
    And the driver moves the traction notch of cab 8 to 3
    And 300 ms pass
    Then only "car8.CCU.sys1" puts commands on the ring
    And every CI receives traction notch 3 within 60 ms
    And the "car7.air conditioning" stays on
    And the cab 8 monitor displays "car7.air conditioning" as "on"
