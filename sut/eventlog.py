"""A trace's event list that holds a repeated stretch as its pattern (issue 33, item 2).

Bulk advance (sut/reference/bulk.py) owes the trace of every period it skips: the traffic of the last checked
period again, times and moving fields carried on. Held as events, ten minutes of an 8-car set are ~1.7 million
tuples made, indexed, pickled with every stored state and freed again, though a Then step reads a handful. An
`EventLog` keeps such a stretch as one `Repeat` (the pattern's rows, the repetitions, and the metronomes'
events merged into it, each at its place) and makes an event only when it is read. Everything else is a plain
list: `append` and `extend` are the current tail list's own, so emitting costs what it did.

A long stretch simulated frame by frame is folded the same way as it runs (bulk.py's _Folder): a period whose
events repeat the one before becomes the next repetition of a stretch (`hold`, `grow`), so that a run bulk
cannot skip keeps its trace in bounded memory; the metronomes' events stay one by one inside it.

A powered-up snapshot (sut/snapshot.py) closes the log first: the events held one by one so far become `Closed`
stretches, which the stored state and every driver restored from it share instead of each unpickling its own
copy; new events go to a fresh tail.

Read through it, an EventLog is the list the stretch would have been, event for event: `Repeat` makes each
event by the formula bulk.py's eager repeat uses, and tests/test_eventlog.py holds the two equal (items,
slices, kinds, pickling, folding) over generated patterns. Kept eager: a model whose `events` is a plain list.
"""
from __future__ import annotations

import sys
from array import array
from bisect import bisect_left, bisect_right
from itertools import chain, repeat
from operator import attrgetter, le, sub
from typing import Any, Iterable, Iterator

from sut.trace import TraceEvent, new_event

_KIND = attrgetter("kind")


def moved(fields: dict, moving: tuple, k: int) -> dict:
    """The fields of a pattern event `k` periods on: every moving integer field carried on by its step."""
    fields = dict(fields)
    for name, d in moving:
        fields[name] += d * k
    return fields


class Repeat:
    """Repetitions `first` .. `first + reps - 1` of a pattern (rows: t, source, kind, fields, moving,
    (one, d)), with `free` events (the metronomes' ticks of the same stretch) at the local positions
    `free_at`, as a stable sort by time of the repetitions followed by the free events puts them."""

    __slots__ = ("rows", "first", "reps", "period", "free", "free_at", "size")

    def __init__(self, rows: tuple, first: int, reps: int, period: int, free: list, free_at: list[int]):
        self.rows, self.first, self.reps, self.period = rows, first, reps, period
        self.free, self.free_at = free, free_at
        self.size = len(rows) * reps + len(free)

    @staticmethod
    def place(rows: tuple, first: int, reps: int, period: int, free: list) -> list[int]:
        """Where each free event lands among the repetitions: after every model event up to its time. The
        repetitions follow one another in time, so the ones wholly before it are counted, not searched."""
        times = [row[0] for row in rows]
        per, last, out = len(times), times[-1], []
        for j, ev in enumerate(free):
            k = min(max((ev.t - last) // period - first + 1, 0), reps)     # repetitions wholly up to ev.t
            count = k * per
            while k < reps:                       # the one ev.t falls in (two where they touch)
                inside = bisect_right(times, ev.t - (first + k) * period)
                if not inside:
                    break
                count += inside
                k += 1
            out.append(j + count)
        return out

    def __len__(self) -> int:
        return self.size

    @staticmethod
    def _fields(row: tuple, k: int) -> dict:
        """A row's fields `k` periods on (most rows move one field, a sequence number: set in a copy)."""
        _, _, _, fields, moving, (one, d) = row
        if not moving:
            return fields
        return {**fields, one: fields[one] + d * k} if one is not None else moved(fields, moving, k)

    def _model(self, m: int) -> TraceEvent:
        k, r = divmod(m, len(self.rows))
        k += self.first
        row = self.rows[r]
        return new_event(TraceEvent, (row[0] + k * self.period, row[1], row[2], self._fields(row, k)))

    def __getitem__(self, j: int) -> TraceEvent:
        free_at = self.free_at
        if free_at:
            p = bisect_left(free_at, j)
            if p < len(free_at) and free_at[p] == j:
                return self.free[p]
            j -= p
        return self._model(j)

    def __iter__(self) -> Iterator[TraceEvent]:
        free, free_at, model, m = self.free, self.free_at, self._model, 0
        for p, pos in enumerate(free_at):
            while m + p < pos:
                yield model(m)
                m += 1
            yield free[p]
        for m in range(m, self.size - len(free)):
            yield model(m)

    def continues(self, model: list[TraceEvent]) -> bool:
        """These events are the pattern's next repetition: the same times one period on, sources, kinds and
        fields (equal, in the same order, each of the same type: as bulk.py's pattern check compares them)."""
        if len(model) != len(self.rows):
            return False
        k = self.first + self.reps
        shift = k * self.period
        for row, ev in zip(self.rows, model):
            if ev.t != row[0] + shift or ev.kind != row[2] or ev.source != row[1]:
                return False
            fields, got = self._fields(row, k), ev.fields
            if got is not fields and (got != fields or list(got) != list(fields)
                                      or list(map(type, got.values())) != list(map(type, fields.values()))):
                return False
        return True

    def slice(self, a: int, b: int) -> list[TraceEvent]:
        return [self[j] for j in range(a, b)]

    def kinds(self, a: int, b: int) -> list[str]:
        model = [row[2] for row in self.rows] * self.reps
        if self.free:
            merged, m = [], 0
            for p, pos in enumerate(self.free_at):
                merged.extend(model[m:pos - p])
                merged.append(self.free[p].kind)
                m = pos - p
            merged.extend(model[m:])
            model = merged
        return model[a:b] if (a, b) != (0, self.size) else model


class Closed(tuple):
    """Events one by one that no one will write again: the part of a log before a powered-up snapshot
    (`EventLog.close`). A stored state and every driver restored from it hold the same Closed stretch
    (sut/snapshot.py), so restoring one does not make its events again; the kinds are worked out once."""

    def kinds(self, a: int, b: int) -> list[str]:
        every = self.__dict__.get("_kinds")
        if every is None:
            every = self._kinds = list(map(_KIND, self))
        return every[a:b] if (a, b) != (0, len(self)) else every

    def nbytes(self) -> int:
        """The memory its events take as objects, estimated once from a sample of SAMPLE_EVENTS (each object
        on its own: shared strings and numbers are counted again; tests/test_snapshot.py holds the estimate
        between what tracemalloc sees and twice that). A snapshot cache's budget counts this, not the few
        pickled bytes (~6x fewer) such events would take."""
        size = self.__dict__.get("_nbytes")
        if size is None:
            size_of = sys.getsizeof
            sample = self[::max(1, len(self) // SAMPLE_EVENTS)]
            each = sum(size_of(ev) + size_of(ev.fields) + sum(map(size_of, ev.fields.values())) for ev in sample)
            size = self._nbytes = size_of(self) + round(each * len(self) / max(len(sample), 1))
        return size

    def __reduce__(self) -> tuple:
        return (Closed, (tuple(self),))            # the kinds and the size are worked out again where needed


SAMPLE_EVENTS = 256


class EventLog:
    """A list of trace events, in time order, whose closed stretches may be Repeats or Closed (see the
    module)."""

    __slots__ = ("_chunks", "_starts", "_tail", "append", "extend", "__weakref__")

    def __init__(self, events: Iterable[TraceEvent] = ()):
        self._chunks: list = []
        self._starts: list[int] = []
        self._open(list(events), 0)

    def _open(self, tail: list, start: int) -> None:
        self._chunks.append(tail)
        self._starts.append(start)
        self._tail = tail
        self.append = tail.append
        self.extend = tail.extend

    # -- writing ---------------------------------------------------------------------------------
    def repeat(self, stretch: Repeat) -> None:
        """Close the tail and put the stretch after it; new events go to a fresh tail."""
        if not stretch.size:
            return
        start = len(self)
        if not self._tail:
            self._chunks.pop()
            self._starts.pop()
        self._chunks.append(stretch)
        self._starts.append(start)
        self._open([], start + stretch.size)

    def close(self) -> list[Closed]:
        """The events held one by one so far become Closed stretches (the same events: only who may share
        them changes), new ones go to a fresh tail; every Closed stretch of the log."""
        chunks = self._chunks
        for i, chunk in enumerate(chunks):
            if type(chunk) is list and chunk:
                chunks[i] = Closed(chunk)
        if type(chunks[-1]) is Closed:
            self._open([], self._starts[-1] + len(chunks[-1]))
        return [chunk for chunk in chunks if type(chunk) is Closed]

    def held_before(self, pos: int) -> Repeat | None:
        """The stretch that ends at `pos`, where every event from `pos` on is in the tail: the one a period
        simulated from there may become the next repetition of."""
        if len(self._chunks) < 2 or self._starts[-1] != pos or type(self._chunks[-2]) is not Repeat:
            return None
        return self._chunks[-2]

    def grow(self, free_marks: list[int]) -> None:
        """Every event of the tail is the next repetition of the stretch before it (held_before), the free
        ones at these positions: the stretch takes them over."""
        stretch, tail = self._chunks[-2], self._tail
        base = self._starts[-2]
        stretch.free.extend(self[i] for i in free_marks)
        stretch.free_at.extend(i - base for i in free_marks)
        stretch.reps += 1
        stretch.size += len(tail)
        self._starts[-1] += len(tail)
        tail.clear()

    def hold(self, pos: int, stretch: Repeat) -> None:
        """The events from `pos` to the end, all in the tail, are this stretch: held as it from now on."""
        base = self._starts[-1]
        if pos < base or len(self) - pos != stretch.size:
            raise ValueError(f"events {pos}.. are not the tail's last {stretch.size}")
        del self._tail[pos - base:]
        self.repeat(stretch)

    @property
    def tail_start(self) -> int:
        """Where the events still held one by one begin (every one from here on is)."""
        return self._starts[-1]

    @property
    def patterned(self) -> bool:
        """Some stretch is held as a pattern (otherwise every event is held one by one)."""
        return any(type(chunk) is Repeat for chunk in self._chunks)

    # -- reading ---------------------------------------------------------------------------------
    def __len__(self) -> int:
        return self._starts[-1] + len(self._tail)

    def __bool__(self) -> bool:
        return len(self) > 0

    def _locate(self, i: int) -> tuple[Any, int]:
        c = bisect_right(self._starts, i) - 1
        return self._chunks[c], i - self._starts[c]

    def __getitem__(self, index: int | slice) -> Any:
        if type(index) is slice:
            start, stop, step = index.indices(len(self))
            if step != 1:
                return list(self)[index]
            return self._range(start, stop)
        n = len(self)
        if index < 0:
            index += n
        if not 0 <= index < n:
            raise IndexError("event index out of range")
        start = self._starts[-1]
        if index >= start:
            return self._tail[index - start]
        chunk, j = self._locate(index)
        return chunk[j]

    def _range(self, start: int, stop: int) -> list[TraceEvent]:
        if start >= stop:
            return []
        if start >= self._starts[-1]:
            base = self._starts[-1]
            return self._tail[start - base:stop - base]
        out: list = []
        c = bisect_right(self._starts, start) - 1
        while c < len(self._chunks) and self._starts[c] < stop:
            chunk, base = self._chunks[c], self._starts[c]
            a, b = max(start, base) - base, min(stop, base + len(chunk)) - base
            out.extend(chunk[a:b] if type(chunk) is not Repeat else chunk.slice(a, b))
            c += 1
        return out

    def pick(self, positions: Iterable[int]) -> list[TraceEvent]:
        """The events at these positions (the trace index's answer), made at C speed where the log is one
        list, or the positions rise and lie inside it (as the index gives them): each chunk's positions, found
        by bisection, are looked up in it in one go. Others (from the end, out of order) are read one by one,
        as self[i] reads them."""
        if len(self._chunks) == 1:
            return list(map(self._tail.__getitem__, positions))
        if type(positions) is not list and type(positions) is not array:
            positions = list(positions)
        n = len(self)
        if not positions:
            return []
        if positions[0] < 0 or positions[-1] >= n or not all(map(le, positions, positions[1:])):
            return [self[i] for i in positions]
        starts, chunks, out = self._starts, self._chunks, []
        lo = 0
        for c in range(bisect_right(starts, positions[0]) - 1, len(chunks)):
            end = starts[c + 1] if c + 1 < len(starts) else n
            hi = bisect_left(positions, end, lo)
            if hi > lo:
                out.extend(map(chunks[c].__getitem__, map(sub, positions[lo:hi], repeat(starts[c]))))
                lo = hi
            if lo == len(positions):
                break
        return out

    def kinds(self, start: int) -> list[str]:
        """The kind of every event from `start` on (the trace index reads these)."""
        out: list = []
        c = bisect_right(self._starts, start) - 1
        for chunk, base in zip(self._chunks[c:], self._starts[c:]):
            a = max(start, base) - base
            out.extend(map(_KIND, chunk[a:]) if type(chunk) is list else chunk.kinds(a, len(chunk)))
        return out

    def __iter__(self) -> Iterator[TraceEvent]:
        return chain.from_iterable(self._chunks)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (EventLog, list)):
            return len(self) == len(other) and all(a == b for a, b in zip(self, other))
        return NotImplemented

    __hash__ = None         # type: ignore[assignment]  # a list's kind of equality

    def __setitem__(self, index: slice, value: Iterable[TraceEvent]) -> None:
        start = index.indices(len(self))[0] if type(index) is slice else None
        if start is None or index.step not in (None, 1) or index.stop is not None:
            raise TypeError("an event log is only ever rewritten from a position to its end")
        if start < self._starts[-1]:
            self._flatten()
        self._tail[start - self._starts[-1]:] = value

    def __delitem__(self, index: slice) -> None:
        self[index] = []

    def _flatten(self) -> None:
        events = list(self)
        self._chunks, self._starts = [], []
        self._open(events, 0)

    def __repr__(self) -> str:
        held = sum(len(c) for c in self._chunks if type(c) is Repeat)
        return f"EventLog({len(self)} events, {held} held as patterns)"

    def __getstate__(self) -> tuple:
        return self._chunks, self._starts

    def __setstate__(self, state: tuple) -> None:
        chunks, starts = state
        self._chunks, self._starts = chunks[:-1], starts[:-1]
        self._open(chunks[-1], starts[-1])

    def __reduce_ex__(self, protocol: int) -> tuple:
        return (EventLog, (), self.__getstate__())
