"""pytest plugin for `make mutate` (outline/mutation.py): which scenario killed a mutant.

mutmut runs the scenarios that reach a mutant's function in a forked child with MUTANT_UNDER_TEST naming
the mutant, and stops at the first failure (-x); it keeps only the exit code. This notes the failing
scenario, one line per mutant, in the file named by $CRH2_MUTATION_KILLS.
"""
from __future__ import annotations

import os

import pytest


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    mutant, kills = os.environ.get("MUTANT_UNDER_TEST", ""), os.environ.get("CRH2_MUTATION_KILLS")
    if report.failed and kills and "__mutmut_" in mutant:
        with open(kills, "a", encoding="utf-8") as fh:            # one short line: appends do not interleave
            fh.write(f"{mutant}\t{report.nodeid}\n")
