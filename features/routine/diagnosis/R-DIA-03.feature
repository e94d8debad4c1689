@item:R-DIA-03 @profile:crh2
Feature: R-DIA-03 DI/DO diagnosis
  Routine diagnosis test. Requirements: FS-02 (primary), FS-01, FS-03, TST-03.
  The command boards check their digital inputs and outputs: disagreement between the CPU groups cuts the
  output and is shown on the cab monitor; a dead desk input reads as the safe state.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 2
    And the train has been powered up for 1000 ms

  @req:FS-02 @req:TST-03
  Scenario: R-DIA-03 A TXC whose CPU groups read different inputs is shown as failed
    When board "car1.CCU.sys1.TXC.group2" fails
    And 500 ms pass
    Then the cab 1 monitor shows "car1.CCU.sys1.TXC failure"

  @req:FS-01 @req:TST-03
  Scenario: R-DIA-03 An RXC whose CPU groups disagree is shown as failed
    When board "car4.LCU.RXC.group2" fails
    And 500 ms pass
    Then the cab 1 monitor shows "car4.LCU.RXC failure"

  @req:FS-03 @req:TST-03
  Scenario: R-DIA-03 A desk whose input supply is lost commands the brake, not traction
    When the supply "car1.desk" is switched off
    And 200 ms pass
    Then from 20 ms on every command carries traction notch 0 and brake step 7
