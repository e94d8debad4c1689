@item:H-CPO-02 @profile:crh2
Feature: H-CPO-02 Continuous power-on for 72 h: no lost command, clocks and counters stay right
  Hardware/software test, continuous power-on (TST-02). Over 72 h the commanding CCU sends a command
  every 10 ms (PRO-01); every LCU must take each one, its clock (set by the clock correction in every
  command) must still read the time since power-up, and at the end a new command reaches every CI and
  BCU as it did at the start. Counters and clocks that wrap within 72 h fail here.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:PRO-01 @req:CMD-02
  Scenario: H-CPO-02 After 72 h every LCU has taken every command and its clock reads the run time
    When the train runs for 72 h, sampled for one steady period every 3 h
    Then every LCU received every command "car1.CCU.sys1" sent during the run
    And the clock of every LCU reads the time since power-up within 20 ms

  @req:TST-02 @req:CMD-02 @req:CMD-05
  Scenario: H-CPO-02 After 72 h a traction notch still reaches every CI and BCU within the bound
    When the train runs for 72 h, sampled for one steady period every 3 h
    And the driver moves the traction notch of cab 1 to 4
    And 100 ms pass
    Then every CI and BCU receives traction notch 4 over path 1 within 40 ms
    And only "car1.CCU.sys1" puts commands on the ring
