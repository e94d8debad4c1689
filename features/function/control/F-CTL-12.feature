@item:F-CTL-12 @profile:crh2
Feature: F-CTL-12 Emergency brake command from the brake handle
  Requirements: ILK-08 (primary), CMD-02, CMD-04, TST-05, TST-04.
  The brake handle's emergency position (step 8) de-energises the emergency-brake magnet valve (the
  hard-wired loop, within the suite's 100 ms protection bound) and sends brake step 8 to every BCU over path 1
  within 40 ms; braking outranks traction, so no CI keeps a notch (ILK-08). With the ring down the step still
  reaches every BCU as step B over path 3. Releasing the handle releases the emergency brake.
  # why: The driver's emergency brake is the last-resort control command of a CRH2 EMU and must act through the hard-wired loop and the network at once.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 5
    And the train runs at 150 km/h
    And the train has been powered up for 1000 ms

  @req:ILK-08 @req:CMD-02 @req:TST-05 @req:TST-04
  Scenario: F-CTL-12 Step 8 de-energises the EB valve, reaches every BCU and takes traction off
    Then the "EB valve" is energised
    When the driver moves the brake handle of cab 1 to step 8
    And 200 ms pass
    Then the "EB valve" is de-energised within 100 ms
    And the "emergency brake" is applied within 100 ms
    And every BCU receives brake step 8 over path 1 within 40 ms
    And from 40 ms on every BCU receives brake step 8
    And the "traction" is blocked
    And no CI receives a traction notch above 0 from 40 ms on
    And the cab 1 monitor displays "brake step" as "8" within 150 ms
    And the cab 1 monitor displays "emergency brake" as "applied" within 150 ms

  @req:ILK-08 @req:CMD-02 @req:TST-05 @req:TST-04
  Scenario: F-CTL-12 Releasing the handle releases the emergency brake and gives the notch back
    When the driver moves the brake handle of cab 1 to step 8
    And 200 ms pass
    Then the "EB valve" is de-energised
    When the driver moves the brake handle of cab 1 to step 0
    And 200 ms pass
    Then the "EB valve" is energised within 100 ms
    And the "emergency brake" is released within 100 ms
    And every CI and BCU receives traction notch 5 over path 1 within 40 ms
    And from 40 ms on every CI and BCU receives only traction notch 5 and brake step 0 over path 1

  @req:CMD-04 @req:TST-05 @req:TST-04 @tentative
  Scenario: F-CTL-12 With the ring down step 8 reaches every BCU as step B and the EB valve still drops
    When every ring link is cut
    And 300 ms pass
    Then the "EB valve" is energised
    When the driver moves the brake handle of cab 1 to step 8
    And 100 ms pass
    Then the "EB valve" is de-energised within 100 ms
    And every BCU receives brake step "B" over path 3 within 40 ms
    And every CI and BCU receives traction step "-" over path 3 within 40 ms
