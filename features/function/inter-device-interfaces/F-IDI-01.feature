@item:F-IDI-01 @profile:crh2
Feature: F-IDI-01 CI and BCU polled over HDLC every 10 ms
  Requirements: NET-09 (primary), CMD-02, TST-04.
  Each LCU's MDM9 polls the main converter (CI, motor cars 2, 3, 6, 7) and the brake control unit (BCU,
  every car) over fibre HDLC every 10 ms with the freshest ring command (NET-09, CMD-02 path 1). A failed
  MDM9 ends the polling of its own car only.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 2
    And the train has been powered up for 1000 ms

  @req:NET-09 @req:TST-04
  Scenario: F-IDI-01 Every CI and every BCU is polled every 10 ms
    When 1000 ms pass
    Then every CI and BCU is polled over HDLC every 9.5 to 10.5 ms
    And car 2 has the devices CI and BCU
    And car 7 has the devices CI and BCU
    And car 1 has no CI
    And car 4 has no CI
    And car 4 has the devices BCU

  @req:NET-09 @req:CMD-02 @req:TST-04 @tentative
  Scenario: F-IDI-01 The polls carry the freshest notch and direction
    When the driver moves the traction notch of cab 1 to 7
    And 300 ms pass
    Then every CI and BCU receives traction notch 7 over path 1 within 40 ms
    And no CI or BCU goes without a command for more than 10.5 ms
    When the driver moves the traction notch of cab 1 to 0
    And the driver sets the direction switch of cab 1 to reverse
    And 300 ms pass
    Then every CI receives direction "reverse" within 40 ms

  @req:NET-09 @req:TST-04
  Scenario: F-IDI-01 A failed MDM9 ends the HDLC polling of its own car only
    When board "car6.LCU.MDM9" fails
    And 1000 ms pass
    Then the CI and BCU of car 6 receive nothing over path 1
    And every CI and BCU outside car 6 is polled over HDLC every 9.5 to 10.5 ms
