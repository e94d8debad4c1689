@item:H-EMC-03 @profile:crh2
Feature: H-EMC-03 Bursts above the rated level on the self-diagnostic line while it carries the commands
  Hardware/software test, interference (TST-02). Requirements: CMD-04, NET-04, NET-05, FS-02.
  With the ring down the commands run over the self-diagnostic line (path 3, CMD-04). Bursts above the
  rated level damage its HDLC frames; the RXCs check the frame check sequence and drop them, so CI and
  BCU get nothing rather than something wrong (FS-02), and path 3 resumes when the bursts stop.

  Background:
    Given an 8-car CRH2 train set
    And the driver has inserted the key in cab 1
    And the direction switch of cab 1 is at forward
    And the traction notch of cab 1 is at 7
    And the train has been powered up for 1000 ms
    And every ring link is cut

  @req:TST-02 @req:NET-05 @req:FS-02 @req:CMD-04
  Scenario: H-EMC-03 Damaged self-diagnostic frames are dropped: nothing wrong reaches CI or BCU
    When 300 ms pass
    And bursts of 2 times the rated immunity level hit the self-diagnostic line for 500 ms
    And 400 ms pass
    Then the damaged frames on the self-diagnostic line are discarded
    And the CI and BCU of car 3 receive nothing over path 3
    And no CI or BCU receives a traction step other than "B"

  @req:TST-02 @req:CMD-04 @req:NET-04
  Scenario: H-EMC-03 Path 3 resumes when the bursts stop
    When 300 ms pass
    And bursts of 2 times the rated immunity level hit the self-diagnostic line for 500 ms
    And 1000 ms pass
    Then every CI and BCU receives traction step "B" over path 3 within 530 ms
    And no CI or BCU receives a traction step other than "B"
    And commands over paths 2 and 3 carry only the traction and brake steps A and B

  @req:TST-02 @req:CMD-04
  Scenario: H-EMC-03 Short bursts cost at most the commands sent while they last
    When 300 ms pass
    And bursts of 2 times the rated immunity level hit the self-diagnostic line for 20 ms
    And 500 ms pass
    Then no CI or BCU goes without a command for more than 40 ms
    And no CI or BCU receives a traction step other than "B"
