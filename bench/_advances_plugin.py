"""pytest plugin loaded by bench/advances_bench.py (`-p _advances_plugin`): where a run's simulation goes, advance
by advance, and why bulk advance left a long one to frame-by-frame simulation.

Wraps `sut.reference.bulk`'s advance and the three checks it makes at period boundaries (the state read, the
straight line through three reads, the two periods' trace pattern) and records per model (crh2, metro, atp: the
module the simulated train comes from) and per kind of advance (shorter than bulk.BULK_MIN_US; longer, nothing
skipped; longer, some skipped) the advances, their wall seconds, the simulated and the skipped time. For a long
advance that skipped nothing, the last reason bulk advance found (what stopped the last look): a read that
changed shape says where (the path from the train, or from its pending timers, to the first leaf that
differs, with both values), a line that is not straight which integer moved unevenly, a trace pattern its
own message, and an advance too short for three of its periods says its period; with the first scenario each
reason was seen in. Writes JSON to $ADVANCES_PLUGIN_OUT at the session's end. Only slower than a plain run (a
read that fails early is read again whole, to say where it differs); the run's verdicts and traces are
unchanged. Not a file the project's runs load.
"""
from __future__ import annotations

import json
import os
import re
import time
from collections import defaultdict
from typing import Any

from sut.reference import bulk
from sut.reference.kernel import Timer

# (model, kind) -> [advances, wall s, simulated us, skipped us]
_KINDS: dict[tuple[str, str], list] = defaultdict(lambda: [0, 0.0, 0, 0])
# (model, reason) -> [advances, wall s, simulated us, an example of the values where the state changed, the
# first scenario it was seen in]
_WHY: dict[tuple[str, str], list] = defaultdict(lambda: [0, 0.0, 0, "", ""])
_look: dict[str, Any] = {"reason": None, "last": None, "example": "", "train": None}

_snapshot, _slope, _trace_pattern, _skip, _advance = (bulk.snapshot, bulk.slope, bulk._trace_pattern, bulk._skip,
                                                      bulk.advance)


def _model(train: Any) -> str:
    parts = type(train).__module__.split(".")
    return parts[2] if parts[:2] == ["sut", "reference"] and len(parts) > 2 else type(train).__qualname__


def _plain(text: str) -> str:
    """A reason without the numbers that make each occurrence unique (times, counts, addresses)."""
    return re.sub(r"0x[0-9a-f]+|\d+", "N", text)[:120]


class _Locator(bulk._Reader):
    """A reader that also says where the leaf at shape[index] lives: the attribute and key path from the train
    (or from its pending timers) to it."""

    INLINE = False            # every leaf through read(), which keeps the path

    def __init__(self, index: int) -> None:
        super().__init__(None)
        self.index, self.path, self.named, self.found = index, [], [], None

    def read(self, value: Any, writer: tuple) -> None:
        # A part with a name of its own (a node, a board, a unit) starts the path again: "car3.LCU.seen".
        name = getattr(value, "name", None) if not isinstance(value, (type, *bulk._FUNCTIONS)) else None
        self.path.append(name if isinstance(name, str) and name else _label(value, writer))
        self.named.append(isinstance(name, str) and bool(name))
        start = len(self.shape)
        super().read(value, writer)
        if self.found is None and start <= self.index < len(self.shape):
            # the innermost read that holds the leaf finishes first
            first = max((i for i, named in enumerate(self.named) if named), default=0)
            self.found = "".join(self.path[first:])
        self.path.pop()
        self.named.pop()


def _label(value: Any, writer: tuple) -> str:
    how = writer[0]
    label = {"attr": lambda: f".{writer[2]}", "item": lambda: f"[{writer[2]!r}]",
             "tuple": lambda: f"[{writer[2]}]", "set": lambda: "{...}", "cell": lambda: ".<cell>",
             "const": lambda: "timers" if type(value) is list else type(value).__qualname__}[how]()
    if type(value) is Timer:
        label += f"<{getattr(value.fn, '__qualname__', '?')}>"
    return label


def _locate(train: Any, index: int) -> str:
    made: list[_Locator] = []
    reader, bulk._Reader = bulk._Reader, lambda expect: made.append(_Locator(index)) or made[-1]
    try:
        _snapshot(train, None)
    finally:
        bulk._Reader = reader
    return made[0].found or "?"


def _value(shape: list, i: int) -> str:
    value = shape[i] if i < len(shape) else "(end)"
    if isinstance(value, tuple) and len(value) == 2 and isinstance(value[0], type):
        value = f"{value[0].__name__} of {value[1]}"              # a container's shape: its type and length
    elif isinstance(value, type):
        value = value.__name__
    return str(value)[:24]


def _changed_shape(train: Any, old: list, new: list) -> None:
    i = next((i for i, (a, b) in enumerate(zip(old, new)) if a != b), min(len(old), len(new)))
    _say(f"the state changed at {_locate(train, i)}", f"{_value(old, i)} -> {_value(new, i)}")


def _say(reason: str | None, example: str = "") -> None:
    _look["reason"], _look["example"] = reason, example


def snapshot(train: Any, like: Any = None) -> Any:
    _look["train"] = train
    try:
        read = _snapshot(train, like)
    except bulk.Changing:
        _changed_shape(train, like.shape, _snapshot(train, None).shape)
        _look["last"] = None
        raise
    except bulk.NotSteady as exc:
        _say(_plain(str(exc)))
        _look["last"] = None
        raise
    last = _look["last"]
    if last is not None and last.shape != read.shape:      # advance drops the window without an exception
        _changed_shape(train, last.shape, read.shape)
    _look["last"] = read
    return read


def slope(s0: Any, s1: Any, s2: Any) -> list[int]:
    try:
        return _slope(s0, s1, s2)
    except bulk.NotSteady as exc:
        j = next((j for j, (a, b, c) in enumerate(zip(s0.ints, s1.ints, s2.ints)) if b - a != c - b), None)
        if j is None:
            _say(_plain(str(exc)))
        else:
            # the j-th int leaf: the reader marks each with `int` in the shape (read only now: the train is s2)
            i = [k for k, leaf in enumerate(s2.shape) if leaf is int][j]
            _say(f"an integer moved unevenly: {_locate(_look['train'], i)}",
                 f"{s0.ints[j]}, {s1.ints[j]}, {s2.ints[j]}")
        raise


def _trace_pattern_looked(first: list, second: list, period: int) -> list:
    try:
        return _trace_pattern(first, second, period)
    except bulk.NotSteady as exc:
        _say("the periods' traces differ: " + _plain(str(exc)).split(": ", 1)[-1])
        raise


def skip(train: Any, window: list, until: int, period: int) -> int:
    _say(None)
    periods = _skip(train, window, until, period)
    if not periods and _look["reason"] is None:
        _say("a one-shot timer is due before the next period ends")
    return periods


def advance(train: Any, until: int) -> Any:
    kernel = train.kernel
    span = until - kernel.now
    _say(None)
    _look["last"] = None
    started = time.perf_counter()
    report = _advance(train, until)
    wall = time.perf_counter() - started
    model = _model(train)
    if span < bulk.BULK_MIN_US:
        kind = "shorter than 1 s"
    elif report.skipped_us:
        kind = "1 s or more, some skipped"
    else:
        kind = "1 s or more, nothing skipped"
        reason = _look["reason"]
        if reason is None:
            reason = (f"shorter than three periods of {report.period_us // 1000} ms" if report.checks == 0
                      else "found no line in the time it had")
        why = _WHY[(model, reason)]
        why[0] += 1
        why[1] += wall
        why[2] += report.simulated_us
        why[3] = why[3] or _look["example"]
        why[4] = why[4] or os.environ.get("PYTEST_CURRENT_TEST", "").split("::")[-1].split(" ")[0]
    row = _KINDS[(model, kind)]
    row[0] += 1
    row[1] += wall
    row[2] += report.simulated_us
    row[3] += report.skipped_us
    return report


def pytest_configure(config: Any) -> None:
    bulk.snapshot, bulk.slope, bulk._trace_pattern, bulk._skip = snapshot, slope, _trace_pattern_looked, skip
    bulk.advance = advance


def pytest_sessionfinish(session: Any) -> None:
    out = os.environ.get("ADVANCES_PLUGIN_OUT")
    if out:
        with open(out, "w", encoding="utf-8") as fh:
            json.dump({"kinds": [[m, k, *v] for (m, k), v in _KINDS.items()],
                       "why": [[m, r, *v] for (m, r), v in _WHY.items()]}, fh)
