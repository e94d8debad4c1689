"""Test-outline tooling: the registry of test items, feature-file checks, traceability and reporting glue.

Nothing here imports `sut.reference`: the outline describes what to verify, never how the reference does it.
"""
