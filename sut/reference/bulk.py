"""Bulk advance: whole periods of steady traffic skipped in closed form (72 h soaks and plain advances).

Frame by frame, 72 h of an 8-car train is about three and a half hours of wall time. A train left alone settles into
a steady state that repeats every P microseconds (P = the least common multiple of its cyclic periods and
of one token rotation): after each period every clock has moved by P, every counter by its count per
period, everything else is as it was. This module reads the whole train as a flat list of leaves (every
int, float, string... reachable from the Train, the kernel's live timers included) and simulates two
periods frame by frame: S0, S1, S2. If the structure is the same and every integer leaf moved by the same
amount in both periods (d = S1 - S0 = S2 - S1), the train is on a straight line, and k periods later each
leaf is S2 + k*d. Writing those values back is the jump. A reading shown in whole units (sut/reference/scaled.py:
the cab monitor's mileage in metres) is such an integer leaf, and an event field of one moves the same way.
An integer that moves unevenly from one period to the next and evenly over three (a metre every eight
periods) would fool this check: a model makes its period the one over which such a value moves evenly, or
says it is not steady (the CRH2 train's bulk_period_us and bulk_steady).

Nothing is assumed about what a leaf means: a new piece of state in the model is covered without being
declared, and state that is not periodic (a ramp, a pending one-shot timer that would fire inside the
skip, a counter that wraps) makes the check fail, so the train is simulated frame by frame instead. What
the model must keep to make this sound: no behaviour that depends on elapsed time except through timers
or through comparisons with bounds shorter than the two checked periods (every bound in config.py is),
counters kept unbounded (frames.py masks them on the wire), and nothing outside the Train that changes.

Metronomes (Kernel.metronome: free-running emitters that only read the model and write the trace, such
as the CRH2 current-loop devices) are left out of the state, of P and of the pattern: over a skipped
stretch their ticks are run in place (an advance) or skipped (a soak), which is what frame by frame does
because they run last at any instant and nothing depends on them.

The trace of skipped periods: a soak (`run`) leaves samples and `time.skip` marks; a plain advance
(`advance`) owes every event, and repeats the traffic of the last checked period, times and moving fields
carried on (the same rule one level up: event fields carry unbounded values, and a pattern that does not
repeat exactly is simulated). An EventLog (sut/eventlog.py) keeps such a stretch as the pattern and makes its
events when they are read. tests/test_bulk.py runs both ways, frame by frame and in bulk, through
faults, repairs, a link cut, block data, ramps and pending one-shot timers, and compares every leaf and,
for advances, the trace byte for byte; it also runs feature items both ways.
"""
from __future__ import annotations

import copy
import enum
from bisect import bisect_left, bisect_right
import math
import os
import types
import warnings
from collections import deque
from itertools import compress
from operator import attrgetter
from dataclasses import dataclass
from typing import Any, Protocol

from sut.eventlog import EventLog, Repeat, moved
from sut.reference.kernel import Kernel, Timer
from sut.reference.scaled import Scaled, ScaledStep


class Train(Protocol):
    """What bulk advance needs of a model: its kernel, its trace, how it emits, and its steady period (the
    least common multiple of everything that repeats in it; a model that repeats more slowly than its
    kernel's cyclic activities, such as a token going round a ring, says so). The CRH2 train, the metro TCDS
    and the ATP rig are such models."""

    kernel: Kernel
    events: list | EventLog          # an EventLog holds a skipped stretch's trace as its pattern

    def emit(self, source: str, kind: str, /, **fields: Any) -> None: ...

    def bulk_period_us(self) -> int: ...


class NotSteady(Exception):
    """The train is not on a straight line over the checked periods (the reason says where)."""


class Changing(NotSteady):
    """A read stopped early: the train's state already differs in shape from the last read."""


_SCALARS = (str, bytes, float, complex, type(None), bool, range, enum.Enum)
_FUNCTIONS = (types.FunctionType, types.BuiltinFunctionType, types.MethodWrapperType, type)


@dataclass
class Snapshot:
    """The train flattened: `shape` must match exactly between snapshots; `ints` may move linearly."""

    at: int
    shape: list
    ints: list[int]
    writers: list[tuple]          # how to put each int back: ("attr", obj, name), ("item", c, key), ...
    rebuild: list                 # tuples (innermost first), sets, objects with bulk_rebuild()


class _Reader:
    # Reading the whole train costs about what simulating a period does, and most reads in a short advance
    # find the train still changing. Given the last read's shape, the reader compares as it goes (every
    # CHECK_EVERY leaves, at the end of an object) and stops at the first difference.
    CHECK_EVERY = 2048
    # The leaves most of a train is made of (ints, strings, flags, None) are read in the loop over their
    # container, not by a call each: what read() would do, and a call per leaf was most of a reading's cost
    # (bench/bulk_bench.py, state_read_ms). A subclass that must see every leaf go through read() (the
    # advances bench's locator) turns it off.
    INLINE = True

    def __init__(self, expect: list | None = None) -> None:
        self.expect = expect
        self.checked = 0
        self.shape: list = []
        self.ints: list[int] = []
        self.writers: list[tuple] = []
        self.rebuild: list = []
        self.refs: dict[int, int] = {}
        self.keep: list = []      # holds what was read, so that ids stay unique while reading

    def read(self, value: Any, writer: tuple) -> None:
        t = type(value)
        if t is int:
            self.shape.append(int)
            self.ints.append(value)
            self.writers.append(writer)
            return
        if t is Scaled:
            # a display reading: its whole units are what moves (sut/reference/scaled.py), the scale is shape
            self.shape.append((Scaled, value.scale))
            self.ints.append(value.raw)
            self.writers.append(("scaled", writer, value.scale))
            return
        scalar = _SCALAR.get(t)
        if scalar is None:
            scalar = _SCALAR[t] = issubclass(t, _SCALARS)        # an Enum, a range: by type, once
        if scalar:
            self.shape.append(t)
            self.shape.append(value)
            return
        ref = self.refs.get(id(value))
        if ref is not None:
            self.shape.append(("ref", ref))
            return
        if t is tuple:
            # A tuple is a value: rebuilt from its items and handed to its owner when an item changes.
            holder = [list(value), writer]
            self.shape.append(("tuple", len(value)))
            for i, item in enumerate(value):
                self.read(item, ("tuple", holder, i))
            self.rebuild.append(("tuple", holder))
            return
        self.refs[id(value)] = len(self.refs)
        self.keep.append(value)
        if t is list or t is deque:
            self.shape.append((t, len(value)))
            self._read_items(value, enumerate(value), False)
        elif t is dict:
            self.shape.append((dict, len(value)))
            self._read_items(value, value.items(), True)   # a key that moves is a change of shape
        elif t is set or t is frozenset:
            items = sorted(value) if all(type(v) is int for v in value) else sorted(value, key=repr)
            holder = [items, value]
            self.shape.append((t, len(value)))
            for i, item in enumerate(items):
                self.read(item, ("set", holder, i))
            self.rebuild.append(("set", holder))
        elif t is types.MethodType:
            self.shape.append(value.__func__.__qualname__)
            self.read(value.__self__, ("const",))
        elif t is types.FunctionType and value.__closure__:
            self.shape.append(value.__qualname__)
            for cell in value.__closure__:
                self.read(cell.cell_contents, ("cell", cell))
        elif isinstance(value, _FUNCTIONS):
            self.shape.append(getattr(value, "__qualname__", repr(value)))
        else:
            self._read_object(value, t)

    def _read_items(self, container: Any, items: Any, keyed: bool, how: str = "item",
                    skip: frozenset = frozenset()) -> None:
        """read() of each item of a list, deque or dict (how="item") or attribute of an object ("attr"), with
        the common leaves inline (INLINE); `keyed`: each key or name is part of the shape, and those in `skip`
        are left out."""
        shape, ints, writers, read, inline = self.shape, self.ints, self.writers, self.read, self.INLINE
        for key, item in items:
            if keyed:
                if key in skip:
                    continue
                shape.append(key)
            vt = type(item)
            if not inline:
                read(item, (how, container, key))
            elif vt is int:
                shape.append(int)
                ints.append(item)
                writers.append((how, container, key))
            elif vt in _PLAIN:
                shape.append(vt)
                shape.append(item)
            else:
                read(item, (how, container, key))

    def _read_object(self, obj: Any, t: type) -> None:
        info = _CLASSES.get(t)
        if info is None:
            info = _CLASSES[t] = _class_info(t)
        skip, slots, steady, rebuild = info
        shape = self.shape
        shape.append(t)
        attrs = getattr(obj, "__dict__", None)
        named = list(attrs.items()) if attrs is not None else []
        if slots:
            named += [(name, getattr(obj, name)) for name in slots if hasattr(obj, name)]
        self._read_items(obj, named, True, "attr", skip)
        if steady and not obj.bulk_steady():
            raise NotSteady(f"{t.__qualname__} {obj!r:.60} cannot be carried over a jump")
        if rebuild:
            self.rebuild.append(("object", obj))
        if self.expect is not None and len(shape) - self.checked >= self.CHECK_EVERY:
            n = len(shape)
            if shape[self.checked:n] != self.expect[self.checked:n]:
                raise Changing(f"the train's state changed shape near leaf {self.checked}..{n}")
            self.checked = n


_PLAIN = frozenset((str, bytes, float, type(None), bool))
_SCALAR: dict[type, bool] = dict.fromkeys(_PLAIN, True)
_CLASSES: dict[type, tuple] = {}


class BulkRefused(UserWarning):
    """A class read inside a train does not declare BULK_READABLE: that train runs frame by frame (the same
    verdicts, slower, and a long run's trace held whole)."""


_REFUSED: set[type] = set()


def _class_info(t: type) -> tuple:
    """What reading an object of a model class needs, worked out once per class: the attributes to leave
    out, the slots, and whether it says if it is steady and has something to rebuild after a jump."""
    # Each class says itself, not through a base, that its state keeps the rules above (BULK_READABLE = True):
    # a subclass can add state the reader does not see or a comparison with a long bound its base never had.
    # Where a class lives is no reason either way (issue 33): a user's subclass of a reference part, or a
    # variant in tests/, that declares it gets bulk advance; one that does not is told so, once per class.
    if vars(t).get("BULK_READABLE") is not True:
        if t not in _REFUSED:
            _REFUSED.add(t)
            warnings.warn(f"{t.__module__}.{t.__qualname__} does not declare BULK_READABLE = True, so a train "
                          "holding one runs frame by frame: declare it if its state keeps the rules of "
                          "sut/reference/bulk.py", BulkRefused, stacklevel=2)
        raise NotSteady(f"cannot read a {t.__module__}.{t.__qualname__} inside the train")
    skip = frozenset(getattr(t, "BULK_SKIP", ()) + getattr(t, "BULK_DERIVED", ()))
    slots = [n for klass in t.__mro__ for n in getattr(klass, "__slots__", ())
             if n != "__dict__" and n != "__weakref__"]
    return skip, slots, hasattr(t, "bulk_steady"), hasattr(t, "bulk_rebuild")


def snapshot(train: "Train", like: Snapshot | None = None) -> Snapshot:
    """The train read as leaves; with `like`, Changing as soon as its shape is seen to differ from like's."""
    kernel = train.kernel
    reader = _Reader(like.shape if like is not None else None)
    reader.read(train, ("const",))
    # Timers in an order that does not depend on absolute time: what they call, on which object, how far
    # ahead; the sequence number only separates timers that agree on all of that.
    def key(timer: Timer) -> tuple:
        fn = timer.fn
        owner = reader.refs.get(id(getattr(fn, "__self__", None)), -1)
        return (getattr(fn, "__qualname__", ""), owner, timer.at - kernel.now, timer.prio, timer.seq)
    timers = sorted(kernel.pending_model(), key=key)
    reader.read(timers, ("const",))
    return Snapshot(kernel.now, reader.shape, reader.ints, reader.writers, reader.rebuild)


def steady_period_us(train: "Train") -> int:
    return train.bulk_period_us()


def cyclic_period_us(kernel: Kernel, *others: int) -> int:
    """The least common multiple of the kernel's cyclic periods and `others`."""
    return math.lcm(*kernel.periods(), *others)


def slope(s0: Snapshot, s1: Snapshot, s2: Snapshot) -> list[int]:
    """Per-period change of every int leaf, if the train moved in a straight line from s0 over s2."""
    if s0.shape != s1.shape or s1.shape != s2.shape:
        first = next((i for i, (a, b) in enumerate(zip(s1.shape, s2.shape)) if a != b), None)
        where = s2.shape[max(0, (first or 0) - 6):(first or 0) + 2] if first is not None else "length"
        raise NotSteady(f"the train's state changed shape near {where!r}")
    deltas = []
    for a, b, c, writer in zip(s0.ints, s1.ints, s2.ints, s2.writers):
        d = b - a
        if c - b != d:
            raise NotSteady("a value did not move by the same amount in both periods")
        if d and writer[0] == "const":
            raise NotSteady("a value that moves cannot be written back")   # found before any is written
        deltas.append(d)
    return deltas


def jump(train: "Train", snap: Snapshot, deltas: list[int], periods: int) -> None:
    """Put the train where `periods` more steady periods would have left it (snap is the current state)."""
    dirty: set[int] = set()
    for value, d, writer in zip(snap.ints, deltas, snap.writers):
        if d:
            _write(writer, value + d * periods, dirty)
    for kind, item in snap.rebuild:
        if kind == "tuple":
            items, writer = item
            if id(item) in dirty:
                _write(writer, tuple(items), dirty)
        elif kind == "set":
            items, target = item
            if id(item) in dirty:
                target.clear()
                target.update(items)
        else:
            item.bulk_rebuild()
    train.kernel.rebuild_heap()


def _write(writer: tuple, value: Any, dirty: set[int]) -> None:
    kind = writer[0]
    if kind == "attr":
        object.__setattr__(writer[1], writer[2], value)      # frozen dataclasses too (the metro's ports)
    elif kind == "item":
        writer[1][writer[2]] = value
    elif kind in ("tuple", "set"):
        writer[1][0][writer[2]] = value           # rebuilt from its items once all are written
        dirty.add(id(writer[1]))
    elif kind == "cell":
        writer[1].cell_contents = value
    elif kind == "scaled":
        _write(writer[1], Scaled(value, writer[2]), dirty)
    else:                                         # slope() refuses such a line before any write
        raise AssertionError(f"a moving value cannot be written back ({kind})")


def fixed_timer_limit(snap: Snapshot, deltas: list[int]) -> int | None:
    """The earliest timer that does not move with the periods (a one-shot still to fire): the jump must
    stop short of it so that it fires frame by frame."""
    limit = None
    for value, d, writer in zip(snap.ints, deltas, snap.writers):
        if (writer[0] == "attr" and writer[2] == "at" and isinstance(writer[1], Timer) and d == 0
                and writer[1].fn is not None):
            limit = value if limit is None else min(limit, value)
    return limit


@dataclass
class BulkReport:
    """What one bulk run did, for the trace and the benchmark."""

    simulated_us: int = 0          # frame by frame
    skipped_us: int = 0            # jumped over
    replayed_us: int = 0           # samples: the traffic pattern repeated, the state jumped with it
    jumps: int = 0
    checks: int = 0                # snapshots read
    period_us: int = 0


def run(train: "Train", until: int, sample_every_us: int | None = None) -> BulkReport:
    """Advance to `until`: frame by frame until the train is steady, then in jumps of whole steady periods
    P, with a sample of the train's traffic (the trace shows it) near every `sample_every_us` of the run
    and the last stretch before `until`.

    A sample is at least SAMPLE_US of traffic: whole periods P where P is shorter (a token rotation, 120 ms
    for an 8-car set), else SAMPLE_US. Where the two periods that showed the line also showed one traffic
    pattern (as for a plain advance), the sample is that pattern's next repetitions, the state jumped along
    with them: what simulating them would give, without the cost. Otherwise it is simulated on the train,
    followed by a check that the train is still on the line the jumps extrapolate (if not, something
    changed: it is simulated frame by frame until steady again). Where P is longer than SAMPLE_US (a token
    rotation incommensurate with the 10 ms cycles: 10.3 ms x 12 nodes gives P = 3.09 s), the sample is
    SAMPLE_US simulated on a copy of the train, which is cheaper than P on the train. The last stretch
    before `until`, at least a sample long, is always simulated on the train itself."""
    kernel = train.kernel
    period = steady_period_us(train)
    report = BulkReport(period_us=period)
    every = sample_every_us or (until - kernel.now)
    next_sample = kernel.now + every

    def frame_by_frame(to: int) -> None:
        report.simulated_us += to - kernel.now
        kernel.run(to)

    # A sample in whole periods where they are short; the last stretch, simulated on the train, is at least
    # that long (where a period is longer than a sample: a sample, so on average half a period less).
    sample = -(-SAMPLE_US // period) * period if period <= SAMPLE_US else SAMPLE_US
    end = until - sample
    # The first stretch the trace observes is a sample too (a jump always lands just before the next one);
    # where a period is long, it also lets what was done just before (a fault, a repair) settle before
    # three periods are spent finding the line.
    frame_by_frame(min(until, kernel.now + sample))

    snaps: list[Snapshot] = []          # [anchor, ...]: the anchor is where the line was found
    marks: list[int] = []               # the trace's length at each snapshot
    line: list[int] | None = None
    pattern: list | None = None         # the traffic of the period that ended at pattern_end, for samples
    pattern_end = 0
    jumped = False                      # the state is the line's own extrapolation: no need to read it
    from_base = False                   # ... of snaps[-1], with nothing simulated since: a jump may follow
    was = -1                            # the clock at the last pass
    while kernel.now < until:
        now = kernel.now
        # Every pass simulates or jumps ahead, so the loop ends by the clock; a pass that left the clock where
        # it was or set it back (a jump that wrote nothing to the kernel, or one of fewer periods than it had
        # already come) would go round for ever.
        if now <= was:
            raise RuntimeError(f"bulk advance made no progress: the clock went from {was} us to {now} us "
                               f"(period {period} us)")
        was = now
        if until - now < period or now >= end:
            frame_by_frame(until)
            break
        base_is_current = not jumped or from_base
        if not jumped:
            try:
                snaps.append(snapshot(train))
                marks.append(len(train.events))
            except NotSteady:                         # e.g. a damaged frame in flight right now
                snaps, marks, line, pattern = [], [], None, None
                frame_by_frame(now + period)
                continue
            report.checks += 1
            if line is not None:
                anchor, last = snaps[0], snaps[-1]
                n = (last.at - anchor.at) // period
                if last.shape != anchor.shape or last.ints != [v + d * n for v, d in zip(anchor.ints, line)]:
                    snaps, marks, line, pattern = snaps[-1:], marks[-1:], None, None   # off the line
                else:
                    snaps, marks = [anchor, last], [marks[0], marks[-1]]
            if line is None and len(snaps) >= 3:
                try:
                    line = slope(*snaps[-3:])
                    if period <= SAMPLE_US:
                        pattern, pattern_end = _replayable(train, marks[-3:], period), snaps[-1].at
                    snaps, marks = snaps[-1:], marks[-1:]
                except NotSteady:
                    snaps, marks = snaps[-2:], marks[-2:]
        jumped = from_base = False
        if line is None:
            frame_by_frame(now + period)
            continue
        base = snaps[-1]
        sampled_until = now
        if now + period > next_sample:                # a sample is due within the coming period
            next_sample += every * ((now + period - next_sample) // every + 1)
            if period <= SAMPLE_US:
                if pattern is not None and base_is_current and _before_one_shots(base, line, now + sample, period):
                    k = (now + period - pattern_end) // period
                    _repeat(train, pattern, k, k + sample // period - 1, period)
                    jump(train, base, line, (now + sample - base.at) // period)
                    report.replayed_us += sample
                    jumped = from_base = True
                    continue
                frame_by_frame(now + sample)          # checked against the line next time round
                continue
            sampled_until = _probe(train, SAMPLE_US, report)
        if not base_is_current:
            frame_by_frame(now + period)
            continue
        # jump to the next sample (or to the last stretch), never past a one-shot timer
        periods = (min(next_sample, end) - now) // period
        limit = fixed_timer_limit(base, line)
        if limit is not None:
            periods = min(periods, (limit - now) // period - 1)
        if periods <= 0:
            frame_by_frame(now + period)
            continue
        jump(train, base, line, (now - base.at) // period + periods)
        kernel.skip_metronomes(kernel.now)            # a skipped stretch has no trace
        report.jumps += 1
        report.skipped_us += periods * period
        train.emit("train", "time.skip", frm=sampled_until, to=kernel.now, periods=periods, period_us=period)
        jumped = period <= SAMPLE_US                  # a probing run reads the jumped state as its next base
        from_base = jumped and pattern is not None
    return report


def _replayable(train: "Train", marks: list[int], period: int) -> list | None:
    """The traffic pattern of the two periods between three snapshots, if they show one (_trace_pattern)."""
    try:
        return _trace_pattern(_model_events(train, marks[0], marks[1]), _model_events(train, marks[1], marks[2]),
                              period)
    except NotSteady:
        return None


def _before_one_shots(base: Snapshot, line: list[int], to: int, period: int) -> bool:
    """No one-shot timer fires up to `to` (plus the period a jump keeps clear of it)."""
    limit = fixed_timer_limit(base, line)
    return limit is None or to + period <= limit


def _repeat(train: "Train", pattern: list, first: int, last: int, period: int) -> None:
    """Append the pattern's repetitions `first`..`last` periods after the period it was taken from (they
    start now), with the metronomes' ticks of the same stretch run in place, merged as the kernel would have
    run them: by time, and at one instant the model's events before the metronomes'. Into an EventLog the
    stretch goes as a pattern (sut/eventlog.py), its events made when read; into a plain list, as events."""
    rows = _rows(pattern)
    events, marks = train.events, getattr(train, "free_marks", None)
    if type(events) is EventLog and rows and _monotone(rows, period):
        _repeat_held(train, events, marks, rows, first, last, period)
        return
    if not rows:
        model: list = []
    else:
        make, kind = tuple.__new__, type(pattern[0][0])
        model = []
        for k in range(first, last + 1):
            shift = k * period
            model.extend([make(kind, (t + shift, source, what,
                                      fields if not moving else
                                      {**fields, one: fields[one] + d * k} if one is not None else
                                      moved(fields, moving, k)))
                          for t, source, what, fields, moving, (one, d) in rows])
    n = len(events)
    events.extend(model)
    if marks is None:
        return
    m = len(marks)
    train.kernel.run_metronomes(train.kernel.now + (last - first + 1) * period)
    free = events[n + len(model):]
    if not free:
        return
    del marks[m:]
    # Both runs are in time order: a stable sort of model-then-metronome merges them with the model's
    # events first at any instant; each metronome event lands after every model event up to its time.
    times = [ev.t for ev in model]
    marks.extend(n + j + bisect_right(times, ev.t) for j, ev in enumerate(free))
    events[n:] = sorted(events[n:], key=_time)


def _rows(pattern: list) -> tuple:
    # Most events move one field (a sequence number): that one is set in a copy without a call.
    return tuple((ev.t, ev.source, ev.kind, ev.fields, moving, moving[0] if len(moving) == 1 else (None, 0))
                 for ev, moving in pattern)


def _monotone(rows: tuple, period: int) -> bool:
    """The repetitions are in time order one after the other (what placing the metronomes' events by a
    search of their times needs; the eager repeat sorts instead)."""
    times = [row[0] for row in rows]
    return all(a <= b for a, b in zip(times, times[1:])) and times[-1] <= times[0] + period


def _repeat_held(train: "Train", events: EventLog, marks: list[int] | None, rows: tuple, first: int, last: int,
                 period: int) -> None:
    free: list = []
    if marks is not None:
        n, m = len(events), len(marks)
        train.kernel.run_metronomes(train.kernel.now + (last - first + 1) * period)
        free = events[n:]
        del events[n:]
        del marks[m:]
    reps = last - first + 1
    free_at = Repeat.place(rows, first, reps, period, free)
    n = len(events)
    events.repeat(Repeat(rows, first, reps, period, free, free_at))
    if marks is not None:
        marks.extend(n + pos for pos in free_at)


_time = attrgetter("t")         # a C-level key: a skipped stretch sorts millions of events


# Advances at least this long fold what they simulate frame by frame: a period whose events are the one
# before's again (times one period on, moving fields carried on) is held as the next repetition of a pattern
# (sut/eventlog.py), so that a long stretch bulk cannot skip (a train never steady, a part that does not
# declare BULK_READABLE, --frame-by-frame) keeps its trace in bounded memory. Only the trace's form changes:
# the simulation runs as it would, a period at a time.
FOLD_MIN_US = 60_000_000


class _Folder:
    """A frame-by-frame stretch run a period at a time, each period folded into the trace's pattern if it
    repeats it (_fold); the boundaries (time, trace length) of the periods run one after another."""

    def __init__(self, train: "Train", period: int):
        self.train, self.period = train, period
        self.bounds: list[tuple[int, int]] = []

    def run(self, to: int) -> None:
        kernel = self.train.kernel
        self._mark()
        while to - kernel.now >= self.period:
            kernel.run(kernel.now + self.period)
            self._mark()
        kernel.run(to)

    def _mark(self) -> None:
        now, bounds = self.train.kernel.now, self.bounds
        if bounds and bounds[-1][0] != now - self.period:
            bounds.clear()                       # not a period on from the last (a jump, a shorter run)
        if bounds and bounds[-1][0] == now:
            return
        bounds.append((now, len(self.train.events)))
        if len(bounds) >= 2:
            _fold(self.train, bounds[-3][1] if len(bounds) >= 3 else None, bounds[-2][1], self.period)
            del bounds[:-2]


def _fold(train: "Train", a: int | None, b: int, period: int) -> None:
    """The events from `b` on are one period's, those from `a` to `b` the period's before: held as the next
    repetition of the stretch that ends at `b`, or with the period before as a new stretch, where they repeat
    it as bulk's pattern check reads a repetition (_trace_pattern)."""
    events = train.events
    if type(events) is not EventLog:
        return
    marks = getattr(train, "free_marks", None) or []
    stretch = events.held_before(b)
    if stretch is not None:
        if stretch.period == period and stretch.continues(_model_events(train, b, len(events))):
            events.grow(marks[bisect_left(marks, b):])
        return
    if a is None or a < events.tail_start:
        return
    try:
        pattern = _trace_pattern(_model_events(train, a, b), _model_events(train, b, len(events)), period)
    except NotSteady:
        return
    if pattern:
        free = marks[bisect_left(marks, a):]
        # The later period's events are the rows, so the earlier one is repetition -1.
        events.hold(a, Repeat(_rows(pattern), -1, 2, period, [events[i] for i in free], [i - a for i in free]))


def _model_events(train: "Train", start: int, stop: int) -> list:
    """The trace between two marks without the metronomes' events (the pattern is the model's own)."""
    events, marks = train.events, getattr(train, "free_marks", None)
    if not marks:
        return events[start:stop]
    lo, hi = bisect_left(marks, start), bisect_left(marks, stop)
    if lo == hi:
        return events[start:stop]
    keep = bytearray(b"\1") * (stop - start)
    for i in marks[lo:hi]:
        keep[i - start] = 0
    return list(compress(events[start:stop], keep))


def advance(train: "Train", until: int) -> BulkReport:
    """TrainDriver.advance for a bulk model: the same state AND the same trace as frame by frame, with whole
    steady periods skipped where the train is on a straight line.

    Unlike a soak, an advance owes the full trace of the time it covers (a Then step may read any of it).
    So, at every period boundary from now on, the state is read and the trace's length noted; once three
    boundaries in a row show a steady line (slope()) and the two periods' events are one pattern (same
    events in the same order, each exactly one period later, every field equal or an integer, or a
    Scaled reading's units, that moved by a fixed amount), the periods up to `until` (or up to a pending
    one-shot timer, after which the line is looked for again) are skipped: the state by jump(), the trace
    by repeating the second period's events with their times and moving fields carried on. The rest is
    frame by frame.
    The metronomes' ticks (Kernel.metronome: the CRH2 loop devices) are not part of the pattern: they are
    run in place over the skipped stretch and merged in as the kernel orders them.
    Advances shorter than three periods or than BULK_MIN_US are simulated as they are (nothing to gain),
    and where a period is short, a look that finds no line is followed by 2, 4 ... 16 periods frame by
    frame before the next. What makes the copied trace exact is what makes the jump exact (the module
    docstring), and one thing more: event fields carry the model's unbounded values (a wire image that
    wraps is a string or bytes, and then the pattern check fails). tests/test_bulk.py and
    tests/test_snapshot.py hold the two ways byte-identical."""
    kernel = train.kernel
    if until - kernel.now < BULK_MIN_US:
        # Most advances are short (a watch looks every 1 ms): simulated as they are, with no period worked
        # out for them (the report's period stays 0: none was looked for).
        report = BulkReport(simulated_us=until - kernel.now)
        kernel.run(until)
        return report
    period = steady_period_us(train)
    report = BulkReport(period_us=period)
    folder = _Folder(train, period) if until - kernel.now >= FOLD_MIN_US else None
    if until - kernel.now < 3 * period or frame_by_frame():
        report.simulated_us = until - kernel.now
        folder.run(until) if folder else kernel.run(until)
        return report
    events = train.events
    window: list[tuple[Snapshot, int]] = []           # (state, trace length) at the last period boundaries
    misses = 0                                        # looks in a row that found no line
    while until - kernel.now >= (3 - len(window)) * period:    # enough left to find the line and skip a period
        failed = False
        try:
            # Where a look that fails clears the window anyway (short periods, below), stop reading at the
            # first difference from the last read; else the new read is kept to start the next line from.
            like = window[-1][0] if window and period < BULK_MIN_US else None
            window.append((snapshot(train, like), len(events)))
            report.checks += 1
        except NotSteady:                        # Changing too: the shape differs from the last read's
            window.clear()
            failed = True
        if len(window) > 1 and window[-1][0].shape != window[-2][0].shape:
            del window[:-1]                      # changing: look again from here
            failed = True
        if len(window) == 3:
            periods = _skip(train, window, until, period)
            if periods:                          # to `until`, or to just before a one-shot timer: then on
                report.jumps += 1
                report.skipped_us += periods * period
                window.clear()
                misses = 0
                continue
            del window[0]
            failed = True
        step = period
        if failed:
            misses += 1
            if period < BULK_MIN_US:
                # Reading the train costs about what simulating a short period does: a train that is not
                # steady (a ramp, a supply restarting) is read again after 2, 4 ... 16 periods (at least
                # 1/8 s, 1/4 s ... 2 s), not at every one.
                window.clear()
                wait = max(period, BULK_MIN_US // 8) << min(misses, 4)
                step = -(-wait // period) * period
        to = min(kernel.now + step, until)
        report.simulated_us += to - kernel.now
        folder.run(to) if folder else kernel.run(to)
    report.simulated_us += until - kernel.now
    folder.run(until) if folder else kernel.run(until)
    return report


def _skip(train: "Train", window: list[tuple[Snapshot, int]], until: int, period: int) -> int:
    """Jump over the whole periods left before `until` (or before a one-shot timer) if the state and the
    trace of the window are steady; the periods skipped, 0 if not."""
    (s0, n0), (s1, n1), (s2, n2) = window
    try:
        line = slope(s0, s1, s2)
        pattern = _trace_pattern(_model_events(train, n0, n1), _model_events(train, n1, n2), period)
    except NotSteady:
        return 0
    now = train.kernel.now
    periods = (until - now) // period
    limit = fixed_timer_limit(s2, line)
    if limit is not None:
        periods = min(periods, (limit - now) // period - 1)
    if periods <= 0:
        return 0
    _repeat(train, pattern, 1, periods, period)
    jump(train, s2, line, periods)
    return periods


def _trace_pattern(first: list, second: list, period: int) -> list[tuple[Any, tuple]]:
    """The second period's events, each with the fields that move per period and by how much, if both
    periods are one pattern; NotSteady if not."""
    if len(first) != len(second):
        raise NotSteady(f"the periods' traces differ in length ({len(first)} and {len(second)} events)")
    pattern = []
    for a, b in zip(first, second):
        if b.t - a.t != period or a.source != b.source or a.kind != b.kind:
            raise NotSteady(f"the periods' traces differ: {a.t} {a.source} {a.kind} and {b.t} {b.source} {b.kind}")
        fa, fb = a.fields, b.fields
        if list(fa) != list(fb):
            raise NotSteady(f"the fields of {b.kind} from {b.source} differ between the periods")
        moving = []
        for name, vb in fb.items():
            va = fa[name]
            if type(va) is int and type(vb) is int:
                if vb != va:
                    moving.append((name, vb - va))
            elif type(va) is Scaled and type(vb) is Scaled and va.scale == vb.scale:
                if vb.raw != va.raw:
                    moving.append((name, ScaledStep(vb.raw - va.raw, vb.scale)))
            elif type(va) is not type(vb) or va != vb:
                raise NotSteady(f"field {name} of {b.kind} from {b.source} is not periodic")
        pattern.append((b, tuple(moving)))
    return pattern


SAMPLE_US = 3_000_000
# Shorter advances are simulated as they are: three readings of the train cost about what a second of it
# does frame by frame (bench/bulk_bench.py).
BULK_MIN_US = 1_000_000

# Every advance frame by frame: the other way round, to prove the two equal. Soaks still skip (72 h frame
# by frame is hours). Set here by tests, or by CRH2_FRAME_BY_FRAME=1 (pytest --frame-by-frame), which a
# remote server started from the run inherits.
FRAME_BY_FRAME = False


def frame_by_frame() -> bool:
    return FRAME_BY_FRAME or os.environ.get("CRH2_FRAME_BY_FRAME") == "1"


def soak(train: "Train", us: int, sample_every_us: int | None) -> BulkReport:
    """TrainDriver.soak for a reference train: `run`, then what it did as one `bulk.report` in the trace."""
    report = run(train, train.kernel.now + us, sample_every_us)
    train.emit("train", "bulk.report", simulated_us=report.simulated_us, skipped_us=report.skipped_us,
               replayed_us=report.replayed_us,
               jumps=report.jumps, period_us=report.period_us)
    return report


def _probe(train: "Train", span: int, report: BulkReport) -> int:
    """Simulate `span` frame by frame on a copy of the train and put what happened in the train's trace;
    the train itself stays where it is. Returns the end of the sample."""
    marks = getattr(train, "free_marks", None)
    memo = {id(train.events): []}
    if marks is not None:
        memo[id(marks)] = []
    probe = copy.deepcopy(train, memo)
    probe.kernel.run(probe.kernel.now + span)
    if marks is not None:
        marks.extend(len(train.events) + i for i in probe.free_marks)
    train.events.extend(probe.events)
    report.simulated_us += span
    return probe.kernel.now
