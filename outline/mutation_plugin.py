"""pytest plugin for `make mutate` (outline/mutation.py): what may judge a mutant, and what killed it.

mutmut runs the tests that reach a mutant's function in a forked child with MUTANT_UNDER_TEST naming
the mutant, and stops at the first failure (-x); it keeps only the exit code.

- What may judge it: a train reference (crh2, metro, atp) is judged by the conformance scenarios alone. The
  simulation engine they share (kernel.py, bulk.py) is no train: its specification is that a bulk advance
  gives the same state and trace as frame by frame (tests/test_bulk.py) and the kernel's own contract
  (tests/test_kernel.py), so its mutants also meet those tests, and first: they compare bulk with frame by
  frame directly, where a scenario notices a bulk mistake only in its one long advance, after hundreds of
  short ones (an engine mutant took minutes to reach it). mutmut collects all of them (pyproject.toml); this
  leaves each mutant only its own judges.
- What killed it: the failing test, one line per mutant, in the file named by $CRH2_MUTATION_KILLS.
- Snapshots only where they cannot hide a scenario: mutmut learns who reaches what in one run of every test
  (MUTANT_UNDER_TEST=stats), and a scenario restored from a stored state never calls the functions that built
  it, so that run simulates every scenario in full (--no-snapshots). A mutant's own run (a fresh pytest
  session in a forked child, so a fresh cache) keeps them: every scenario it restores was built earlier in
  that same child, under the same mutant, by a scenario sharing its Background, which reaches the same
  functions and is in the mutant's list too; verdicts with and without snapshots are the same
  (tests/test_snapshot.py). A survivor of a busy function runs hundreds of scenarios, most of them restored
  instead of simulating their Background again.
"""
from __future__ import annotations

import os

import pytest


ENGINE = ("sut.reference.kernel.", "sut.reference.bulk.")
MAPPING_RUN = "stats"            # mutmut's MUTANT_UNDER_TEST while it learns which tests reach which function


def pytest_configure(config: pytest.Config) -> None:
    if os.environ.get("MUTANT_UNDER_TEST") == MAPPING_RUN and hasattr(config.option, "no_snapshots"):
        config.option.no_snapshots = True


def judges(mutant: str, nodeids: list[str]) -> list[str]:
    """The tests that may judge `mutant`: the scenarios; for the engine its own tests first, then those."""
    scenarios = [n for n in nodeids if n.startswith("features/")]
    if mutant.startswith(ENGINE):
        return [n for n in nodeids if not n.startswith("features/")] + scenarios
    return scenarios


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    mutant = os.environ.get("MUTANT_UNDER_TEST", "")
    if "__mutmut_" not in mutant:
        return                        # mutmut's own runs (the map of who reaches what, the clean run): all
    by_id = {item.nodeid: item for item in items}
    kept = [by_id[n] for n in judges(mutant, list(by_id))]
    config.hook.pytest_deselected(items=[item for item in items if item not in kept])
    items[:] = kept


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    mutant, kills = os.environ.get("MUTANT_UNDER_TEST", ""), os.environ.get("CRH2_MUTATION_KILLS")
    if report.failed and kills and "__mutmut_" in mutant:
        with open(kills, "a", encoding="utf-8") as fh:            # one short line: appends do not interleave
            fh.write(f"{mutant}\t{report.nodeid}\n")
