@item:F-NET-26 @profile:crh2 @req:TST-04
Feature: F-NET-26 ARCNET frames on the ring, read by an analyser
  Requirements: NET-10 (primary), NET-05, TST-04.
  A bus analyser on a ring span decodes every frame with the suite's own ARCNET codec (ATA 878.1): tokens
  (ITT: 04, destination twice) and packets (PAC: 01, source, destination twice, length, data, CRC-16 with
  x^16+x^15+x^2+1), at most 508 data bytes a packet. A SUT with its own frame layout fails this item even if
  its nodes understand each other.

  Background:
    Given an 8-car CRH2 train set
    And an analyser is attached to the ring link between "car3.LCU" and "car4.LCU"
    And the driver has inserted the key in cab 1
    And the train has been powered up for 1000 ms

  @req:NET-10
  Scenario: F-NET-26 Every frame on a span decodes as an ARCNET token or packet
    When 500 ms pass
    Then every frame the analyser saw decodes as an ARCNET token or packet, 50 packets at least

  @req:NET-10 @req:NET-05
  Scenario: F-NET-26 A frame corrupted on the span fails the ARCNET check
    When the next command frame from "car3.LCU" to "car4.LCU" is corrupted
    And 100 ms pass
    Then the analyser finds the corrupted command frame failing its ARCNET check

  @req:NET-10
  Scenario: F-NET-26 Tokens and packets on a span carry the IDs of the exchange they belong to
    When 500 ms pass
    Then every token the analyser saw is addressed to the node across the span and every packet carries its sender's node ID
