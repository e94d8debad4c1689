"""Random stimulus sequences over the driver interface (issue 31): what may be done to a SUT of a profile
(stimuli), what of it can be seen (observe), and two drivers driven side by side (differential)."""
