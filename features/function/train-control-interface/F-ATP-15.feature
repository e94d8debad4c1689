@item:F-ATP-15 @profile:atp @req:TST-04
Feature: F-ATP-15 The 200C ATP's supervision, CFSK and permissions hold under random stimulus sequences
  Requirements: ATP-01, ATP-03, ATP-04, ATP-05, ATP-06, ATP-07, ATP-09, ATP-10 (each scenario its own), TST-04.
  Model-based testing: hypothesis drives fresh ATP rigs, each started under full supervision at 80 km/h, with
  random sequences of this library's own sentences (odometry, the signal generator, the driver's carrier-set
  order and mode inputs, balises with track circuits and an end of authority, the default telegram, line
  information, packets and stop points, the CFSK failing and repaired, time passing) and checks the invariant
  after every stimulus. Every sequence of a scenario holds the kinds of stimulus its invariant is about, and a few
  more drawn at random. A reaction the requirements give no time for is judged where the rig has been left alone
  for 1 s (docs/decisions.md, "Random-sequence invariants"); every sequence ends so. A sequence that breaks an
  invariant is shrunk and printed as a scenario to paste into a feature file. `--sequences N` hunts longer
  (make campaign).

  Background:
    Given random sequences of the step library's stimuli, 100 per invariant from seed 0

  @req:ATP-07
  Scenario: F-ATP-15 A default telegram always brakes until the train is below 45 km/h, then PS
    Then after every stimulus of every sequence, a default telegram brakes, and below 45 km/h the ATP is in PS without line data

  @req:ATP-01 @req:ATP-05
  Scenario: F-ATP-15 A faulty CFSK is always recorded and never sends a decoded result
    Then after every stimulus of every sequence, a faulty CFSK is recorded and sends no decoded result

  @req:ATP-03 @req:ATP-04
  Scenario: F-ATP-15 The CFSK never reports a carrier outside its selected set or before 3 agreeing comparisons
    Then after every stimulus of every sequence, the CFSK reports a carrier of its selected set only after 3 agreeing comparisons

  @req:ATP-09 @req:ATP-10
  Scenario: F-ATP-15 ATO, door and screen-door permissions are never granted against their conditions
    Then after every stimulus of every sequence, ATO, door and screen-door permissions are granted only when their conditions hold

  @req:ATP-06
  Scenario: F-ATP-15 Full supervision lasts until 150 m before the end of authority, no longer and no shorter
    Then after every stimulus of every sequence, full supervision lasts until 150 m before the end of authority
