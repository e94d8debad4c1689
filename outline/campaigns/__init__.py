"""Fault campaigns generated from the SUT's own fault space: the fault model, the single, double and metro
campaigns, and their scenario text."""
