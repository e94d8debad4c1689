@item:H-CHR-02 @profile:crh2
Feature: H-CHR-02 Rated transmission figures observed at the interface
  Hardware/software test, characteristics (TST-02). Requirements: NET-07, NET-09, PRO-01.
  The rated figures of the boards, measured from outside as a rig would with an analyser: the ring's bit
  rate, the pass-through time per node, the command interval and the polling cycle of CI and BCU.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7

  @req:TST-02 @req:NET-07
  Scenario: H-CHR-02 The ring runs at 2.5 Mbit/s
    Given an analyser is attached to the ring link between "car4.LCU" and "car5.LCU"
    And the train has been powered up for 1000 ms
    When 1000 ms pass
    Then the analysed link carries 2.5 Mbit/s within 0.5 %
    And the analysed link is fibre

  @req:TST-02 @req:PRO-01
  Scenario: H-CHR-02 On an idle ring each node passes a command on within 0.25 ms, at least 10 ms apart
    Given the train is powered up
    When 400 ms pass
    Then each node on the way adds at most 0.25 ms to a command
    And commands leave the CCU at intervals of at least 10 ms
    And every LCU receives every command within 15 ms of its transmission

  @req:TST-02 @req:NET-09
  Scenario: H-CHR-02 CI and BCU are polled every 10 ms with the commanded notch
    Given the train has been powered up for 1000 ms
    When 1000 ms pass
    Then every CI and BCU is polled over HDLC every 9.5 to 10.5 ms
    And no CI or BCU receives a traction notch other than 7
