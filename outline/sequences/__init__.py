"""Random stimulus sequences over the driver interface (issue 31): the invariants judged after every stimulus,
the differential checker of two SUTs, and the evidence for equivalent mutants."""
