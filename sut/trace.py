"""The SUT's trace: every observable happening as (time us, source, kind, fields).

A rig would produce the same from bus analysers and data loggers; Then steps read only this and the
driver's snapshot observations. Sources are dotted names (`car3.LCU.MDM8`, `car1.CCU.sys2`), kinds are
dotted verbs (`cmd.rx`, `token.pass`, `frame.discard`).
"""
from __future__ import annotations

import csv
import fnmatch
import io
import json
from array import array
from bisect import bisect_left, bisect_right
from typing import Any, Callable, Iterable, Iterator, Mapping, NamedTuple


class TraceEvent(NamedTuple):
    # A tuple, not a dataclass: thousands are made per simulated second, and a snapshot (sut/snapshot.py)
    # pickles every one of them; a frozen slotted dataclass costs 40x a tuple to unpickle.
    t: int                       # microseconds since power-up
    source: str
    kind: str
    fields: Mapping[str, Any]

    @property
    def t_ms(self) -> float:
        return self.t / 1000

    def __getitem__(self, key):          # ev["field"] reads a field; ev[0] is still the tuple's item
        if type(key) is str:
            return self.fields[key]
        return tuple.__getitem__(self, key)

    def get(self, key: str, default: Any = None) -> Any:
        return self.fields.get(key, default)


def _source_matcher(pattern: str | None) -> Callable[[str], bool]:
    if pattern is None:
        return lambda s: True
    if any(ch in pattern for ch in "*?["):
        return lambda s: fnmatch.fnmatchcase(s, pattern)
    return lambda s: s == pattern or s.startswith(pattern + ".")


class Trace:
    """A read-only, growing view of a SUT's events, in time order.

    A query for one kind is answered from an index of the events by kind and source, extended as the list
    grows (a list only grows: new events are appended; bulk.py orders only what it just appended), instead
    of a walk over every event: Then steps ask per device, and a 16-car trace holds tens of thousands of
    events. A backend keeps one view per event list (TrainDriver._trace_view) so the index is built once."""

    def __init__(self, events: list[TraceEvent]):
        self._events = events
        self._indexed = 0
        self._by_kind: dict[str, dict[str | None, array]] = {}      # positions as machine ints: 8 bytes, not 36

    def __getstate__(self) -> dict:
        return {"_events": self._events}           # the index is rebuilt where it is needed, not pickled

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["_events"])

    def _positions(self, kind: str, source: str | None) -> "array | list[int]":
        """Positions of the events of `kind` from the matching sources, in list order."""
        events, by_kind = self._events, self._by_kind
        for i in range(self._indexed, len(events)):
            ev = events[i]
            sources = by_kind.get(ev.kind)
            if sources is None:
                sources = by_kind[ev.kind] = {None: array("q")}      # None: every source, for queries without one
            sources[None].append(i)
            positions = sources.get(ev.source)
            if positions is None:
                positions = sources[ev.source] = array("q")
            positions.append(i)
        self._indexed = len(events)
        sources = by_kind.get(kind)
        if not sources:
            return []
        if source is None:
            return sources[None]
        match_src = _source_matcher(source)
        lists = [positions for src, positions in sources.items() if src is not None and match_src(src)]
        if len(lists) == 1:
            return lists[0]
        if len(lists) == len(sources) - 1:
            return sources[None]
        return sorted(i for positions in lists for i in positions)

    def __len__(self) -> int:
        return len(self._events)

    def __iter__(self) -> Iterator[TraceEvent]:
        return iter(self._events)

    def __getitem__(self, index: int | slice) -> TraceEvent | list[TraceEvent]:
        return self._events[index]

    def select(self, kind: str | None = None, source: str | None = None, since: int | None = None,
               until: int | None = None, **where: Any) -> list[TraceEvent]:
        """Events matching all given criteria. `kind` may end in `.*`; `source` is exact, a dotted prefix
        or a glob; `since`/`until` are inclusive times in us; `where` compares fields for equality."""
        # A subclass may stand for another driver's events (sut/snapshot.py's journal view): it walks.
        if kind is not None and not kind.endswith("*") and type(self) is Trace:
            return self._select_indexed(kind, source, since, until, where)
        match_src = _source_matcher(source)
        prefix = kind[:-1] if kind and kind.endswith("*") else None
        out = []
        for ev in self._since(since):
            if until is not None and ev.t > until:
                break
            if kind is not None and (ev.kind != kind if prefix is None else not ev.kind.startswith(prefix)):
                continue
            if not match_src(ev.source):
                continue
            if any(ev.fields.get(k) != v for k, v in where.items()):
                continue
            out.append(ev)
        return out

    def _select_indexed(self, kind: str, source: str | None, since: int | None, until: int | None,
                        where: dict[str, Any]) -> list[TraceEvent]:
        events = self._events
        positions = self._positions(kind, source)
        start = bisect_left(positions, since, key=lambda i: events[i].t) if since else 0
        out = []
        for i in positions[start:] if start else positions:
            ev = events[i]
            if until is not None and ev.t > until:
                break
            if where and any(ev.fields.get(k) != v for k, v in where.items()):
                continue
            out.append(ev)
        return out

    def of_kinds(self, wanted: Callable[[str], bool], since: int | None = None,
                 until: int | None = None) -> list[TraceEvent]:
        """Events whose kind `wanted` accepts, within [since, until] (us, inclusive), in list order: what a
        walk over every event keeping those kinds gives, read from the index (a report picks a handful of
        kinds out of a trace that is mostly periodic frames)."""
        if type(self) is not Trace:                         # a subclass may stand for another's events: walk
            return [ev for ev in self._since(since) if (until is None or ev.t <= until) and wanted(ev.kind)]
        events = self._events
        self._positions("", None)                           # the index up to date
        t_of = lambda i: events[i].t                        # noqa: E731
        runs = []
        for kind, sources in self._by_kind.items():
            if wanted(kind):
                positions = sources[None]
                lo = bisect_left(positions, since, key=t_of) if since else 0
                hi = bisect_right(positions, until, key=t_of) if until is not None else len(positions)
                if lo < hi:
                    runs.append(positions[lo:hi])
        if len(runs) == 1:
            return [events[i] for i in runs[0]]
        return [events[i] for i in sorted(i for run in runs for i in run)]

    def _since(self, since: int | None) -> Iterable[TraceEvent]:
        events = self._events
        if not since:
            return events
        lo, hi = 0, len(events)
        while lo < hi:                      # events are appended in time order: bisect on t
            mid = (lo + hi) // 2
            if events[mid].t < since:
                lo = mid + 1
            else:
                hi = mid
        return events[lo:]

    def first(self, **criteria: Any) -> TraceEvent | None:
        found = self.select(**criteria)
        return found[0] if found else None

    def last(self, **criteria: Any) -> TraceEvent | None:
        found = self.select(**criteria)
        return found[-1] if found else None

    def to_csv(self) -> str:
        buf = io.StringIO()
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerow(["t_ms", "source", "kind", "fields"])
        for ev in self._events:
            writer.writerow([f"{ev.t / 1000:.3f}", ev.source, ev.kind,
                             json.dumps(dict(ev.fields), separators=(",", ":"), default=str)])
        return buf.getvalue()
