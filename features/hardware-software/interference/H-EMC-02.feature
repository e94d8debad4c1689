@item:H-EMC-02 @profile:crh2
Feature: H-EMC-02 Bursts above the rated level on a ring link: damaged frames are discarded
  Hardware/software test, interference (TST-02). Requirements: NET-05, NET-03, CMD-02.
  Above the rated immunity level frames on the disturbed link are damaged. Every node checks every frame
  (NET-05) and discards the damaged ones, so no wrong command ever reaches CI or BCU; the commands arrive
  the other way round the ring (NET-03); when the bursts stop the ring is clean again by itself.
  The level is placed relative to the SUT's declared immunity.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:NET-05
  Scenario: H-EMC-02 Frames damaged by the bursts are discarded, no wrong command reaches CI or BCU
    When bursts of 2 times the rated immunity level hit the ring link between "car3.LCU" and "car4.LCU" for 1000 ms
    And 1000 ms pass
    Then the nodes beside the ring link between "car3.LCU" and "car4.LCU" discard the damaged frames
    And no CI or BCU receives a traction notch other than 7
    And from 0 ms on every CI and BCU receives only traction notch 7 and brake step 0 over path 1

  @req:TST-02 @req:NET-03 @req:CMD-02
  Scenario: H-EMC-02 During the bursts every command still arrives the other way round
    When bursts of 2 times the rated immunity level hit the ring link between "car3.LCU" and "car4.LCU" for 1000 ms
    And 1000 ms pass
    Then every LCU receives every command within 15 ms of its transmission
    And no CI or BCU goes without a command for more than 25 ms

  @req:TST-02 @req:NET-05 @tentative
  Scenario: H-EMC-02 After the bursts the ring recovers by itself and the monitor is clean
    When bursts of 2 times the rated immunity level hit the ring link between "car3.LCU" and "car4.LCU" for 1000 ms
    And 2000 ms pass
    And the cab 1 monitor is watched for 1000 ms
    Then the cab 1 monitor never showed a fault
    And no CI or BCU receives a traction notch other than 7
