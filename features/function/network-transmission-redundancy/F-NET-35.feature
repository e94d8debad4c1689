@item:F-NET-35 @profile:metro-tcn @req:TST-04
Feature: F-NET-35 The metro TCDS holds under random stimulus sequences
  Requirements: TCN-04, TCN-08, TCN-09, RED-04, RED-05, RED-06 (each scenario its own), TST-04.
  Model-based testing: hypothesis drives fresh metro trains with random sequences of this library's own
  sentences (the key, the direction switch and the master controller of either cab, the emergency-operation
  switch, the speed, failures and repairs of CCUs, VCUs, their boards, the devices and I/O modules, bus lines cut,
  restored and disturbed, wiring faults, time passing), from a cab driving or from rest, and checks the invariant
  after every stimulus. Every sequence of a scenario holds the kinds of stimulus its invariant is about, and a few
  more drawn at random. A reaction the requirements give no time for is judged where the train has been left
  alone for 1 s (docs/decisions.md, "Random-sequence invariants"); every sequence ends so. A sequence that breaks
  an invariant is shrunk and printed as a scenario to paste into a feature file. A metro sequence costs about
  a second of simulation: 10 per invariant here, `--sequences N` hunts longer (make campaign).

  Background:
    Given random sequences of the step library's stimuli, 10 per invariant from seed 0

  @req:TCN-08 @req:RED-05
  Scenario: F-NET-35 The drives and brakes follow the active cab, also when a CCU fails
    Then after every stimulus of every sequence, every VVVF and BECU follows the active cab, through a CCU failure

  @req:TCN-09
  Scenario: F-NET-35 A unit cut off from the train command always brakes
    Then after every stimulus of every sequence, a unit cut off from the train command brakes

  @req:RED-04
  Scenario: F-NET-35 Only car 1's unit ever masters the WTB, one node at a time, by rank
    Then after every stimulus of every sequence, only car 1's unit masters the WTB, one node at a time, by rank

  @req:RED-06
  Scenario: F-NET-35 A fault on one line of a bus never loses a message
    Then after every stimulus of every sequence, a fault on one line of a bus loses no message

  @req:TCN-04
  Scenario: F-NET-35 A silent device is always shown on its unit's display
    Then after every stimulus of every sequence, a silent device is shown on its unit's display
