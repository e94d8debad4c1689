@item:H-WSV-02 @profile:crh2
Feature: H-WSV-02 Dielectric test at 1500 V rms for 1 min: the unit survives and works afterwards
  Hardware/software test, withstand voltage (TST-02). Requirements: CMD-02, NET-03, PRO-03.
  EN 50155 dielectric test of a 110 V unit: 1500 V rms, 50 Hz, for 1 min, with the unit disconnected.
  While it is under test the rest of the train goes on without it (NET-03); reconnected, it rejoins the
  ring by itself (PRO-03) and its car is commanded over path 1 again.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:CMD-02 @req:NET-03
  Scenario: H-WSV-02 An LCU under the rated test voltage is off the ring, the other cars go on
    When "car3.LCU" is given a withstand-voltage test at 1500 V rms for 60 s
    And 2000 ms pass
    Then "car3.LCU" sends nothing on the ring from 0 ms to 2000 ms after the action
    And from 40 ms on every CI and BCU outside car 3 receives traction notch 7 over path 1
    And the cab 1 monitor shows "no status data from car3.LCU"

  @req:TST-02 @req:CMD-02 @req:PRO-03
  Scenario: H-WSV-02 After the rated test the LCU works again
    When "car3.LCU" is given a withstand-voltage test at 1500 V rms for 60 s
    And 62 s pass
    Then "car3.LCU" sends status data again within 61000 ms
    And the CI and BCU of car 3 receive traction notch 7 over path 1 within 61000 ms
    And the cab 1 monitor shows no faults
    And the maintenance view of cab 1 lists "car3.LCU.supply restarted after withstand test"
    And the insulation resistance of "car3.LCU" is at least 20 MOhm
