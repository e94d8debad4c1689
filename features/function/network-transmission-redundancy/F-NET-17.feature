@item:F-NET-17 @profile:crh2 @req:TST-04
Feature: F-NET-17 CCU systems 1 and 2: independent supplies, takeover after 50 ms of silence
  Requirements: RED-02 (primary), RED-01, TST-04.
  Both systems' TXCs sample the desk; system 2 only watches the ring while system 1 is healthy and takes
  over when it has seen no data from system 1 for 50 ms. Takeover is timed where commands enter the ring,
  as the gap between system 1's last and system 2's first command: from 50 ms up to 50 ms plus one
  command interval (measured on the SUT, at least 10 ms) plus 2 ms (one hop to system 2, at most one
  frame already on the fibre, the TXC loop).

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 6
    And the train has been powered up for 1000 ms

  @req:RED-02
  Scenario: F-NET-17 While system 1 is healthy, system 2 only watches
    When 1000 ms pass
    Then while system 1 is healthy only system 1 of the car 1 CCU sends commands

  @req:RED-01 @req:RED-02
  Scenario: F-NET-17 System 2 takes over when system 1 loses its supply
    When the supply "car1.CCU.sys1" is switched off
    And 500 ms pass
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every LCU receives every command within 15 ms of its transmission
    And every CI and BCU receives traction notch 6 over path 1 within 80 ms

  @req:RED-02
  Scenario: F-NET-17 System 2 takes over when system 1's MDM8 fails
    When board "car1.CCU.sys1.MDM8" fails
    And 500 ms pass
    Then system 2's first command follows system 1's last by 50 ms to 52 ms plus one command interval
    And every LCU receives every command within 15 ms of its transmission
