"""Experimental pytest plugin for bench/suite_bench.py --what-if: what a fix of a hot path would gain.

Loaded only into the benchmark's extra conformance pass (`-p _whatif_plugin`), switched by $BENCH_WHATIF
(comma-separated). It patches functions in that one pytest process; no file of the project changes. Each
switch is a stand-in for a fix proposed in the benchmark's findings, not the fix itself:

  steplookup  pytest-bdd's find_fixturedefs_for_step (used by pytest-bdd before every step, and by the outline
              plugin's collection-time step check for every distinct step text) asks pytest for the visible
              definitions of EVERY fixture name, for every step: O(steps x fixtures) getfixturedefs calls, each
              walking the node's parents and building their node ids. Stand-in: list the visible step
              definitions once per module (same pytest-bdd semantics and order; step definitions are never
              registered per test), then match the step text against that list, memoised per
              (module, type, text).
  (noattach, skipping report attachments when no --alluredir is given, measured -16 % here and is now
  done by steps/report.py itself.)
"""
from __future__ import annotations

import os

import pytest

WHATIF = {w.strip() for w in os.environ.get("BENCH_WHATIF", "").split(",") if w.strip()}
KNOWN = {"steplookup"}


def _patch_steplookup() -> None:
    import pytest_bdd.scenario as bdd_scenario
    from pytest_bdd.compat import get_fixture_names, getfixturedefs
    from pytest_bdd.steps import step_function_context_registry

    visible: dict[str, list] = {}          # scope nodeid -> [(fixturedef, context)] in pytest-bdd's order
    found: dict[tuple, tuple] = {}         # (scope nodeid, step type, step text) -> matching fixturedefs

    def find_fixturedefs_for_step(step, fixturemanager, node):
        scope = node.parent if isinstance(node, pytest.Function) and node.parent is not None else node
        key = (scope.nodeid, step.type, step.name)
        hit = found.get(key)
        if hit is None:
            cands = visible.get(scope.nodeid)
            if cands is None:
                cands = visible[scope.nodeid] = [
                    (fd, ctx)
                    for name in get_fixture_names(fixturemanager=fixturemanager)
                    for fd in getfixturedefs(fixturemanager, name, node) or []
                    if (ctx := step_function_context_registry.get(fd.func)) is not None]
            hit = found[key] = tuple(
                fd for fd, ctx in cands
                if (ctx.type is None or ctx.type == step.type) and ctx.parser.is_matching(step.name))
        return iter(hit)

    bdd_scenario.find_fixturedefs_for_step = find_fixturedefs_for_step
    try:
        import outline.pytest_plugin as outline_plugin
        outline_plugin.find_fixturedefs_for_step = find_fixturedefs_for_step
    except ImportError:
        pass


def pytest_configure(config: pytest.Config) -> None:
    unknown = WHATIF - KNOWN
    if unknown:
        raise pytest.UsageError(f"BENCH_WHATIF: unknown {sorted(unknown)}; known: {sorted(KNOWN)}")
    if "steplookup" in WHATIF:
        _patch_steplookup()
