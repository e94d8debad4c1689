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
from operator import attrgetter
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


# `new_event(TraceEvent, (t, source, kind, fields))` is `TraceEvent(t, source, kind, fields)` without the named
# tuple's own __new__, a Python function: a model emits thousands of events a simulated second.
new_event = tuple.__new__

_KIND = attrgetter("kind")


def _pick(events: Any, positions: Iterable[int]) -> list[TraceEvent]:
    """The events at these positions of a list or an EventLog."""
    if hasattr(events, "pick"):
        return events.pick(positions)
    return list(map(events.__getitem__, positions))


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
        self._kinds: list[str] = []                   # the kind of every event indexed so far (C-speed extend)
        self._kind_set: set[str] = set()
        # kind -> [positions, kinds scanned]; kind -> [{source: positions}, kind positions filed]. Only
        # kinds a step asks for are indexed, each by a search of the kinds list rather than a Python step
        # per event: a trace holds millions of frames, and a scenario asks for a handful of kinds.
        self._by_kind: dict[str, list] = {}
        self._by_source: dict[str, list] = {}

    def __getstate__(self) -> dict:
        return {"_events": self._events}           # the index is rebuilt where it is needed, not pickled

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["_events"])

    def _catch_up(self) -> list[str]:
        events, kinds = self._events, self._kinds
        if self._indexed < len(events):
            # An EventLog (sut/eventlog.py) gives the kinds of a stretch it holds as a pattern without making
            # its events.
            fresh = (events.kinds(self._indexed) if hasattr(events, "kinds")
                     else list(map(_KIND, events[self._indexed:])))
            kinds.extend(fresh)
            self._kind_set.update(fresh)
            self._indexed = len(events)
        return kinds

    def _of_kind(self, kind: str) -> "array":
        kinds = self._catch_up()
        entry = self._by_kind.get(kind)
        if entry is None:
            entry = self._by_kind[kind] = [array("q"), 0]
        positions, scanned = entry
        if scanned < len(kinds):
            if kind in self._kind_set:
                find, append, i = kinds.index, positions.append, scanned
                try:
                    while True:
                        i = find(kind, i)
                        append(i)
                        i += 1
                except ValueError:
                    pass
            entry[1] = len(kinds)
        return positions

    def _positions(self, kind: str, source: str | None) -> "array | list[int]":
        """Positions of the events of `kind` from the matching sources, in list order."""
        positions = self._of_kind(kind)
        if source is None or not positions:
            return positions
        # The kind's positions by source, brought up to date with one pass over its new positions; a
        # source pattern is then matched against the few distinct sources, not against every event.
        entry = self._by_source.get(kind)
        if entry is None:
            entry = self._by_source[kind] = [{}, 0]
        by_source, filtered = entry
        if filtered < len(positions):
            events = self._events
            for i in positions[filtered:]:
                src = events[i].source
                mine = by_source.get(src)
                if mine is None:
                    mine = by_source[src] = array("q")
                mine.append(i)
            entry[1] = len(positions)
        match_src = _source_matcher(source)
        lists = [mine for src, mine in by_source.items() if match_src(src)]
        if len(lists) == 1:
            return lists[0]
        if len(lists) == len(by_source):
            return positions
        return sorted(i for mine in lists for i in mine)

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

    def _window(self, kind: str, source: str | None, since: int | None,
                until: int | None) -> tuple["array | list[int]", int, int]:
        """The positions of `kind` from `source`, and the range of them inside [since, until]."""
        events = self._events
        positions = self._positions(kind, source)
        t_of = lambda i: events[i].t                        # noqa: E731
        lo = bisect_left(positions, since, key=t_of) if since else 0
        hi = bisect_right(positions, until, key=t_of) if until is not None else len(positions)
        return positions, lo, hi

    def _select_indexed(self, kind: str, source: str | None, since: int | None, until: int | None,
                        where: dict[str, Any]) -> list[TraceEvent]:
        events = self._events
        positions, lo, hi = self._window(kind, source, since, until)
        taken = _pick(events, positions[lo:hi])
        if not where:
            return taken
        wanted = where.items()
        return [ev for ev in taken if not any(ev.fields.get(k) != v for k, v in wanted)]

    def _first_indexed(self, kind: str, source: str | None, since: int | None, until: int | None,
                       where: dict[str, Any], last: bool) -> TraceEvent | None:
        # A check that wants one event stops at it, instead of filtering every event of a long window.
        events = self._events
        positions, lo, hi = self._window(kind, source, since, until)
        wanted = where.items()
        for i in (reversed(range(lo, hi)) if last else range(lo, hi)):
            ev = events[positions[i]]
            if not any(ev.fields.get(k) != v for k, v in wanted):
                return ev
        return None

    def of_kinds(self, wanted: Callable[[str], bool], since: int | None = None,
                 until: int | None = None) -> list[TraceEvent]:
        """Events whose kind `wanted` accepts, within [since, until] (us, inclusive), in list order: what a
        walk over every event keeping those kinds gives, read from the index (a report picks a handful of
        kinds out of a trace that is mostly periodic frames)."""
        if type(self) is not Trace:                         # a subclass may stand for another's events: walk
            return [ev for ev in self._since(since) if (until is None or ev.t <= until) and wanted(ev.kind)]
        events = self._events
        self._catch_up()
        runs = []
        for kind in sorted(self._kind_set):
            if wanted(kind):
                positions, lo, hi = self._window(kind, None, since, until)
                if lo < hi:
                    runs.append(positions[lo:hi])
        if len(runs) == 1:
            return _pick(events, runs[0])
        return _pick(events, sorted(i for run in runs for i in run))

    def kinds(self) -> set:
        """Every kind the trace holds, as the index reads them (at C speed): the end-of-scenario check asks
        whether each is a name at all."""
        if type(self) is not Trace:                         # a subclass may stand for another's events: walk
            return {ev.kind for ev in self._events}
        self._catch_up()
        return set(self._kind_set)

    def heads(self, kinds: Iterable[str], n: int) -> dict[str, list[TraceEvent]]:
        """The first n events of each of `kinds` present, in list order: a sample of every kind that costs a
        search of the kinds list per event taken, not a Python step per event held (a trace is mostly
        periodic frames, of a few kinds)."""
        if type(self) is not Trace:                         # a subclass may stand for another's events: walk
            wanted, out = set(kinds), {}
            for ev in self._events:
                if ev.kind in wanted and len(out.setdefault(ev.kind, [])) < n:
                    out[ev.kind].append(ev)
            return out
        events, kind_list = self._events, self._catch_up()
        pick = getattr(events, "pick", None)
        out = {}
        for kind in self._kind_set.intersection(kinds):
            taken: list[int] = []
            i, find = 0, kind_list.index
            try:
                while len(taken) < n:
                    i = find(kind, i)
                    taken.append(i)
                    i += 1
            except ValueError:
                pass
            out[kind] = pick(taken) if pick is not None else [events[i] for i in taken]
        return out

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
        return self._one(criteria, last=False)

    def last(self, **criteria: Any) -> TraceEvent | None:
        return self._one(criteria, last=True)

    def _one(self, criteria: dict[str, Any], last: bool) -> TraceEvent | None:
        kind = criteria.get("kind")
        if kind is not None and not kind.endswith("*") and type(self) is Trace:
            where = dict(criteria)
            args = [where.pop(name, None) for name in ("kind", "source", "since", "until")]
            return self._first_indexed(*args, where, last)
        found = self.select(**criteria)
        return (found[-1] if last else found[0]) if found else None

    def to_csv(self) -> str:
        buf = io.StringIO()
        writer = csv.writer(buf, lineterminator="\n")
        writer.writerow(["t_ms", "source", "kind", "fields"])
        for ev in self._events:
            writer.writerow([f"{ev.t / 1000:.3f}", ev.source, ev.kind,
                             json.dumps(dict(ev.fields), separators=(",", ":"), default=str)])
        return buf.getvalue()
