@item:R-CTL-02 @profile:crh2
Feature: R-CTL-02 Brake command transmission with a rescue connection
  Routine control test. Requirements: NET-08 (primary), TST-03.
  A rescuing set coupled to a failed set commands the brakes of both sets, over the coupled ring and,
  with the ring down, over the coupled self-diagnostic line.

  Background:
    Given two 8-car CRH2 train sets coupled together
    And the driver has inserted the key in cab 16
    And the train has been powered up for 1000 ms

  @req:NET-08 @req:TST-03
  Scenario: R-CTL-02 The rescuing cab's brake command reaches every BCU of both sets over the ring
    When the driver moves the brake handle of cab 16 to step 4
    And 100 ms pass
    Then every BCU receives brake step 4 over path 1 within 40 ms
    And only "car16.CCU.sys1" puts commands on the ring

  @req:NET-08 @req:TST-03
  Scenario: R-CTL-02 With the ring down the brake command crosses the coupler on the self-diagnostic line
    When every ring link is cut
    And the driver moves the brake handle of cab 16 to step 7
    And 200 ms pass
    Then every BCU receives brake step "B" over path 3 within 100 ms
