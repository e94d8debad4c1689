"""pytest plugin loaded by bench/events_bench.py (`-p _events_plugin`): counts the kernel's callbacks by kind.

Gives the kernel module a heapq whose heappop also counts each live timer it hands `Kernel.run`, by the
qualified name of the function the timer calls (a cyclic activity by its tick, so `Lcu._poll` rather than
`Kernel._cyclic_tick`), and writes the counts as JSON to $EVENTS_PLUGIN_OUT at the end of the session. Only
`run` pops live timers (`peek` pops cancelled ones, the metronomes' catch-up keeps its own heap), so the
count is the callbacks run; the run is otherwise unchanged, only slower. Not a file the project's runs load.
"""
from __future__ import annotations

import heapq
import json
import os
from collections import Counter
from types import SimpleNamespace

from sut.reference import kernel

_COUNTS: Counter = Counter()


def _kind(fn, args: tuple) -> str:
    if getattr(fn, "__func__", None) is kernel.Kernel._cyclic_tick:
        fn = args[0].tick
    return getattr(fn, "__qualname__", type(fn).__name__)


def _heappop(heap: list):
    entry = heapq.heappop(heap)
    if len(entry) == 5:                                     # Kernel.schedule: the callback itself
        _COUNTS[_kind(entry[3], entry[4])] += 1
        return entry
    timer = entry[-1]                                       # (the metronomes' catch-up pops its own triples)
    if isinstance(timer, kernel.Timer) and timer.fn is not None and timer.seq == entry[2]:   # not put off since
        _COUNTS[_kind(timer.fn, timer.args)] += 1
    return entry


def pytest_configure(config) -> None:
    kernel.heapq = SimpleNamespace(heappush=heapq.heappush, heappop=_heappop, heapify=heapq.heapify)


def pytest_sessionfinish(session) -> None:
    out = os.environ.get("EVENTS_PLUGIN_OUT")
    if out:
        with open(out, "w", encoding="utf-8") as fh:
            json.dump(dict(_COUNTS), fh)
