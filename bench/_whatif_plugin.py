"""Experimental pytest plugin for bench/suite_bench.py --what-if: what a fix of a hot path would gain.

Loaded only into the benchmark's extra conformance pass (`-p _whatif_plugin`), switched by $BENCH_WHATIF
(comma-separated). It patches functions in that one pytest process; no file of the project changes. Each
switch is a stand-in for a fix proposed in the benchmark's findings, not the fix itself:

  bddscan     the opposite of a fix now made: pytest-bdd's own per-step scan of every fixture instead of
              the step index (outline/plugin/step_index.py, issue 14), to show what the index saves.
  noendcheck  no end-of-scenario contract check (ContractDriver.check_trace a no-op): what holding the
              events no step was handed to their contract entries costs (steps/fixtures.py, issue 31).
  (Done since, each first measured here: noattach, no report attachments without --alluredir, in
  steps/report.py; steplookup, the step index; nohypothesis, hypothesis's pytest plugin not loaded, in
  pyproject.toml's addopts.)
"""
from __future__ import annotations

import os

import pytest

WHATIF = {w.strip() for w in os.environ.get("BENCH_WHATIF", "").split(",") if w.strip()}
KNOWN = {"bddscan", "noendcheck"}


def _patch_bddscan() -> None:
    from outline.plugin import step_index

    step_index.install = lambda: None                     # the outline plugin installs it at configure
    step_index._SCENARIO.find_fixturedefs_for_step = step_index.SCAN


def pytest_configure(config: pytest.Config) -> None:
    unknown = WHATIF - KNOWN
    if unknown:
        raise pytest.UsageError(f"BENCH_WHATIF: unknown {sorted(unknown)}; known: {sorted(KNOWN)}")
    if "bddscan" in WHATIF:
        _patch_bddscan()
    if "noendcheck" in WHATIF:
        from sut.contract.guard import ContractDriver

        ContractDriver.check_trace = lambda self, trace, per_kind=0: 0
