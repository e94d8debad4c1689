@item:F-ATP-13 @profile:atp-crh2 @req:TST-04
Feature: F-ATP-13 The ATP's brake reaches the train: traction suppressed, brake commanded (ILK-08)
  Requirements: ATP-02 (primary), ATP-11, VDX-01, ILK-08, ILK-03, ILK-05, CMD-02, CMD-05, TST-04.
  The ATP fitted to a CRH2 train set: its maximum service brake reaches the train as an ATP brake, which
  suppresses traction and raises the brake command to full service (ILK-08); its emergency brake opens the
  train's emergency-brake loop through the VDX. Without an ATP brake, the driver's own brake handle reaches
  the train as on a set without ATP. The ATP's brake is a brake demand the train's brake-force supervision
  watches as it watches the handle's (ILK-03).

  Background:
    Given a CTCS-2 200C on-board ATP fitted to an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 3
    And the ATP has completed its start-up self-test
    And the ATP has released the emergency brake
    And the train is at 500 m running at 100 km/h

  @req:ILK-08
  Scenario: F-ATP-13 Without an ATP brake the train pulls
    When 500 ms pass
    Then every CI receives traction notch 3 within 500 ms
    And the "emergency brake" is released

  # The train runs at the speed the ATP's odometry gives: above 30 km/h with the doors closed its doors are
  # pressed airtight (a fitting that left the train at standstill would leave them unsealed).
  @req:ILK-05
  Scenario: F-ATP-13 The fitted train runs at the ATP's speed: its doors are pressed airtight
    When 500 ms pass
    Then the "press-seal valve" is energised

  @req:CMD-05 @req:CMD-02
  Scenario: F-ATP-13 Without an ATP brake the driver's own brake handle reaches the train
    When the driver moves the brake handle of cab 1 to step 4
    And 500 ms pass
    Then every BCU receives brake step 4 over path 1 within 100 ms

  @req:ATP-11 @req:ILK-08
  Scenario: F-ATP-13 A balise information error: maximum service brake, no traction on the train
    When the train passes balise group "6-1-1-1" with an ETCS-99 packet
    And 300 ms pass
    Then the ATP commands max service brake
    And every CI receives traction notch 0 within 100 ms
    And from 100 ms on every BCU receives brake step 7
    And the "emergency brake" is released

  @req:ATP-02 @req:ILK-08
  Scenario: F-ATP-13 A carrier inconsistency brakes the train
    Given the signal generator sends 1700 Hz with code L
    And the train has passed balise group "6-1-1-2" describing track circuits 0-1000 m 1700 Hz, 1000-2000 m 2300 Hz and an end of authority at 5000 m
    When the train is set to 980 m running at 100 km/h
    And the train runs until the rear of the receiver range has passed 1000 m
    Then the ATP declares the carrier inconsistent
    And the ATP commands max service brake
    And no CI receives a traction notch above 0 from 500 ms after the carrier inconsistency on

  @req:VDX-01 @req:ILK-08
  Scenario: F-ATP-13 The ATP's emergency brake opens the train's loop through the VDX
    When 500 ms pass
    And the ATP applies the emergency brake
    And 300 ms pass
    Then the emergency-brake loop opens within 6 ms of the FS output going off
    And the "emergency brake" is applied
    And every CI receives traction notch 0 within 100 ms

  @req:ILK-03 @tentative
  Scenario: F-ATP-13 The ATP's maximum service brake with the handle at 0: a car short of brake force trips the emergency brake
    Given the brake force of car 3 is 30 % of the demand
    And the brake handle of cab 1 is at step 0
    When the train passes balise group "6-1-1-1" with an ETCS-99 packet
    And 1000 ms pass
    Then the ATP commands max service brake
    And the "emergency brake" is applied
