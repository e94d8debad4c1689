"""pytest plugin for one shard of mutmut's map (outline/mutate/sharded_map.py): after each test, the functions
of the references its trampolines met, as mutmut's own StatsCollector keeps them, written to
$MUTMUT_MAP_SHARD.<xdist worker> as JSON when the session ends."""
from __future__ import annotations

import json
import os
from collections import defaultdict

import pytest

_tests_by_function: dict[str, set[str]] = defaultdict(set)
_durations: dict[str, float] = {}


def _state():
    from mutmut.state import state
    return state()


def pytest_runtest_logstart(nodeid: str, location: object) -> None:
    _durations[nodeid] = 0.0


def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo) -> None:
    if call.when == "call":
        _durations[item.nodeid] += call.duration


def pytest_runtest_teardown(item: pytest.Item, nextitem: pytest.Item | None) -> None:
    hits = _state()._stats
    for function in hits:
        _tests_by_function[function].add(item.nodeid.removeprefix("mutants/"))
    hits.clear()


def pytest_unconfigure(config: pytest.Config) -> None:
    out = os.environ.get("MUTMUT_MAP_SHARD")
    # A worker knows itself by its workerinput (its environment may be inherited: make test runs this under
    # xdist too); xdist's controller runs no test, it only hears of the workers' starts.
    worker = config.workerinput["workerid"] if hasattr(config, "workerinput") else None
    if not out or (worker is None and getattr(config.option, "numprocesses", None)):
        return
    out = f"{out}.{worker or 'main'}"
    deps = _state().function_dependencies
    with open(out, "w", encoding="utf-8") as fh:
        json.dump({"tests_by_mangled_function_name": {k: sorted(v) for k, v in _tests_by_function.items()},
                   "duration_by_test": _durations,
                   "function_dependencies": {k: sorted(v) for k, v in deps.items()}}, fh)
