@item:F-NET-01 @profile:crh2 @req:TST-04
Feature: F-NET-01 Two-level network, its units and their boards
  Requirements: NET-01 (primary), NET-02, TST-04.
  The train level is a ring joining every CCU and LCU; the vehicle level joins each unit to the devices
  of its car; the self-diagnostic line joins every unit as a backup.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-01 @req:NET-02
  Scenario: F-NET-01 Every car has an LCU on the ring and each cab car a CCU with two systems
    Then every car has an LCU on the ring and every cab car a CCU with systems 1 and 2
    And the boards of "car1.CCU.sys1" are CPU3, MDM8 and TXC
    And the boards of "car8.CCU.sys2" are CPU3, MDM8 and TXC
    And the boards of "car4.LCU" are CPU3, MDM8, MDM9 and RXC

  @req:NET-01
  Scenario: F-NET-01 The vehicle level reaches the devices of each car
    Then car 3 has the devices CI, BCU, ACS and PID
    And car 4 has the devices BCU, ACS, PID and APU
    When 500 ms pass
    Then every CI and BCU receives traction notch 0 over path 1 within 40 ms

  @req:NET-01
  Scenario: F-NET-01 The self-diagnostic line joins every unit when the ring is gone
    # The driver's own brake step, not the released one: at standstill a product may hold a brake of its own
    # (docs/decisions.md, "Standstill holding brake (crh2)"), and step 7 is step B either way.
    Given the brake handle of cab 1 is at step 7
    When every ring link is cut
    And 300 ms pass
    Then every BCU receives brake step "B" over path 3 within 100 ms
