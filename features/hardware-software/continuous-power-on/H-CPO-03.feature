@item:H-CPO-03 @profile:crh2
Feature: H-CPO-03 Continuous power-on for 72 h with faults on the way: the recorder loses nothing
  Hardware/software test, continuous power-on (TST-02). Faults come and go during the 72 h; every
  fault record (CPU3 writes one per board failure and recovery, sent as block data to the master,
  PRO-06) is still held at the end, in order and stamped with the time it happened, and the network is
  back in its steady state after each fault.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the train has been powered up for 1000 ms

  @req:TST-02 @req:PRO-06 @req:RED-02
  Scenario: H-CPO-03 Board failures and recoveries at hours 24, 25, 48 and 71 are all held by the master after 72 h
    When the train runs until 24 h after power-up, sampled for one steady period every 3 h
    And board "car4.LCU.MDM9" fails
    And the train runs until 25 h after power-up
    And board "car4.LCU.MDM9" is repaired
    And the train runs until 48 h after power-up
    And board "car6.LCU.RXC" fails
    And the train runs until 71 h after power-up
    And board "car6.LCU.RXC" is repaired
    And the train runs until 72 h after power-up
    Then "car1.CCU.sys1" holds these fault records, oldest first, each stamped within 5 ms:
      | node      | board | event     | at h |
      | car4.LCU  | MDM9  | failed    | 24   |
      | car4.LCU  | MDM9  | recovered | 25   |
      | car6.LCU  | RXC   | failed    | 48   |
      | car6.LCU  | RXC   | recovered | 71   |
    And no node initialised the token during the run
    And every node sent status data once every 115 to 125 ms over the whole run
