@item:F-ILK-10 @profile:crh2 @req:TST-04
Feature: F-ILK-10 The interlocks hold under random stimulus sequences
  Requirements: ILK-01, ILK-02, ILK-05, ILK-06, ILK-07, ILK-08 (each scenario one), TST-04.
  Model-based testing: hypothesis drives fresh trains with random sequences of this library's own sentences
  (the desk, the train's inputs, the network's faults, time passing), from rest or from a cab driving, and
  checks the invariant after every stimulus. The interlocks give no reaction time, so an invariant about a
  reaction is checked where the train has been left alone for 1 s (docs/decisions.md, "Random-sequence
  invariants"); every sequence ends so. A sequence that breaks an invariant is shrunk and printed as a
  scenario to paste into a feature file. `--sequences N` hunts longer (make campaign).

  Background:
    Given random sequences of the step library's stimuli, 25 per invariant from seed 0

  @req:ILK-07
  Scenario: F-ILK-10 Only one cab's master control relay is ever up
    Then after every stimulus of every sequence, only one cab's master control relay is up

  @req:ILK-01
  Scenario: F-ILK-10 A separated train always brakes
    Then after every stimulus of every sequence, a separated train brakes

  @req:ILK-02
  Scenario: F-ILK-10 A main pipe below the trip band always brakes
    Then after every stimulus of every sequence, a main pipe below the trip band brakes

  @req:ILK-08
  Scenario: F-ILK-10 Traction is never permitted against a condition
    Then after every stimulus of every sequence, traction is permitted only when every condition holds

  @req:ILK-06
  Scenario: F-ILK-10 A transformer or oil fault always opens the main circuit
    Then after every stimulus of every sequence, a transformer or oil fault opens the main circuit

  @req:ILK-05
  Scenario: F-ILK-10 The door-open relay never acts at speed
    Then after every stimulus of every sequence, the door-open relay acts only below 5 km/h
