"""sut/eventlog.py holds a skipped stretch's trace as its pattern: read through it, the log must be the list
bulk.py's eager repeat makes, event for event, with the metronomes' events at the same places; and the trace
index must answer from it as from that list."""
from __future__ import annotations

import copy
import pickle

import pytest

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sut.eventlog import EventLog
from sut.reference import bulk
from sut.reference.kernel import Kernel
from sut.trace import Trace, TraceEvent

SOURCES = ["car1.CCU.sys1.MDM8", "car2.LCU.CPU3", "car8.SDD"]
KINDS = ["status.tx", "token.pass", "loop.cycle"]


class _Toy:
    """What _repeat needs of a train: its kernel, its events, where the metronomes' events are."""

    def __init__(self, log: bool, now: int, metronomes: list[tuple[int, int]]):
        self.kernel = Kernel()
        self.kernel.now = now
        self.events = EventLog() if log else []
        self.free_marks: list[int] = []
        for n, (period, phase) in enumerate(metronomes):
            self.kernel.metronome(period, self._tick, phase, args=(f"dev{n}",))

    def _tick(self, name: str) -> None:
        self.free_marks.append(len(self.events))
        self.events.append(TraceEvent(self.kernel.now, name, "loop.cycle", {"at": self.kernel.now // 100}))


PERIOD = 1000
rows = st.lists(st.tuples(st.integers(0, PERIOD), st.sampled_from(SOURCES), st.sampled_from(KINDS),
                          st.integers(-3, 3), st.integers(0, 2)), max_size=8)


def _pattern(drawn: list, start: int) -> list:
    """A period's events at start < t <= start + PERIOD, in time order, each with its moving field."""
    out = []
    for offset, source, kind, step, moving in sorted(drawn, key=lambda r: r[0]):
        fields = {"seq": 10, "word": "x", "count": 3}
        move = (("seq", step),) if moving == 1 and step else (("seq", step), ("count", 1)) if moving == 2 else ()
        out.append((TraceEvent(start + max(offset, 1), source, kind, fields), move))
    return out


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(drawn=rows, first=st.integers(1, 3), reps=st.integers(1, 40), before=st.integers(0, 5),
       metronomes=st.lists(st.tuples(st.integers(300, 5000), st.integers(0, 3000)), max_size=3),
       asked=st.lists(st.tuples(st.sampled_from(KINDS), st.sampled_from([None, "car1", "dev0", "car2.LCU"]),
                                st.one_of(st.none(), st.integers(0, 60_000))), max_size=4))
def test_a_held_stretch_reads_as_the_eager_one(drawn, first, reps, before, metronomes, asked):
    now = 20_000
    pattern = _pattern(drawn, now - PERIOD)
    made = {}
    for log in (False, True):
        toy = _Toy(log, now, metronomes)
        for i in range(before):                           # what the trace held before the stretch
            toy.events.append(TraceEvent(now - before + i, "train", "before", {"i": i}))
        trace = Trace(toy.events)
        trace.select(kind="status.tx")                    # an index built before the stretch, caught up after
        bulk._repeat(toy, pattern, first, first + reps - 1, PERIOD)
        toy.events.append(TraceEvent(now + (reps + 1) * PERIOD, "train", "after", {}))
        made[log] = toy, trace
    (eager, eager_trace), (held, held_trace) = made[False], made[True]
    assert type(held.events) is EventLog and type(eager.events) is list
    assert held.events.patterned == bool(pattern)
    assert list(held.events) == eager.events and len(held.events) == len(eager.events)
    assert held.free_marks == eager.free_marks
    n = len(eager.events)
    assert [held.events[i] for i in range(-n, n)] == eager.events + eager.events
    for a, b in ((0, n), (before, n - 1), (n // 3, 2 * n // 3), (n - 1, n + 5), (5, 2)):
        assert held.events[a:b] == eager.events[a:b]
    assert held.events.kinds(0) == [ev.kind for ev in eager.events]
    picked = [i for i in range(n) if i % 3 != 1] + [n // 2, 0, -1, n - 1]    # rising, then anywhere
    assert held.events.pick(picked) == [eager.events[i] for i in picked]
    with pytest.raises(IndexError):
        held.events.pick([0, n])
    for kind, source, since in asked:
        assert held_trace.select(kind=kind, source=source, since=since) == \
            eager_trace.select(kind=kind, source=source, since=since)
        assert held_trace.last(kind=kind, source=source) == eager_trace.last(kind=kind, source=source)
    for copied in (pickle.loads(pickle.dumps(held.events)), copy.deepcopy(held.events)):
        assert type(copied) is EventLog and list(copied) == eager.events
        copied.append(TraceEvent(10**9, "train", "later", {}))
        assert len(copied) == n + 1 and len(held.events) == n


def test_a_log_rewritten_from_a_position_inside_a_held_stretch_keeps_every_event() -> None:
    toy = _Toy(True, 5000, [])
    toy.events.append(TraceEvent(4000, "train", "before", {}))
    bulk._repeat(toy, _pattern([(10, SOURCES[0], KINDS[0], 1, 1)], 4000), 1, 3, PERIOD)
    whole = list(toy.events)
    assert toy.events.patterned and len(whole) == 4
    toy.events[2:] = sorted(toy.events[2:], key=lambda ev: -ev.t)
    assert list(toy.events) == whole[:2] + whole[:1:-1]
    del toy.events[1:]
    assert list(toy.events) == whole[:1]


class _Ticker(_Toy):
    """A model that emits the same events every period but at the drawn instants, where it says otherwise."""

    def __init__(self, log: bool, metronomes: list[tuple[int, int]], odd: set[int], every: int):
        super().__init__(log, 0, metronomes)
        self.odd, self.seq = odd, 0
        self.kernel.every(every, self._tick_model)

    def _tick_model(self) -> None:
        self.seq += 1
        now = self.kernel.now
        self.events.append(TraceEvent(now, "car1.CCU.sys1.MDM8", "status.tx", {"seq": self.seq, "grant": None}))
        if now // 100 in self.odd:
            self.events.append(TraceEvent(now, "car1.CCU.sys1.CPU3", "fault.record", {"n": len(self.odd)}))
        self.events.append(TraceEvent(now, "car2.LCU.CPU3", "poll", {"ok": True, "seq": self.seq % 3}))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(odd=st.sets(st.integers(0, 600), max_size=6), every=st.sampled_from([100, 200, 300]),
       period=st.sampled_from([300, 600]), metronomes=st.lists(st.tuples(st.integers(250, 2000),
                                                                          st.integers(0, 999)), max_size=2),
       runs=st.lists(st.integers(1, 20_000), min_size=1, max_size=4))
def test_folded_periods_read_as_the_simulated_ones(odd, every, period, metronomes, runs):
    made = {}
    for log in (False, True):
        toy = _Ticker(log, metronomes, odd, every)
        folder = bulk._Folder(toy, period)
        for span in runs:
            folder.run(toy.kernel.now + span)
        made[log] = toy
    eager, held = made[False], made[True]
    assert list(held.events) == eager.events and held.free_marks == eager.free_marks
    assert held.events.kinds(0) == [ev.kind for ev in eager.events]
    if not odd and not metronomes and len(runs) == 1 and runs[0] >= 10 * period and period % (3 * every) == 0:
        # the model repeats every 3 ticks: all but the last periods are held as patterns
        assert len(held.events) - held.events.tail_start <= 3 * (period // every) * 2, repr(held.events)
        assert held.events.patterned


def test_a_long_frame_by_frame_advance_holds_its_trace_as_patterns() -> None:
    """A train that bulk may not skip (here --frame-by-frame) keeps a minute and a half of its trace in a
    few stretches, not as 260,000 events; read through, the trace is the one simulated into a plain list."""
    from tests.test_bulk import S, frame_by_frame, powered
    made = {}
    for log in (True, False):
        train = powered()
        if not log:
            train.train.events = list(train.train.events)
        with frame_by_frame():
            train.advance(90 * S)
        made[log] = train.train
    held, eager = made[True], made[False]
    assert len(held.events) == len(eager.events) > 200_000
    assert list(held.events) == eager.events and held.free_marks == eager.free_marks
    loose = len(held.events) - sum(len(c) for c in held.events._chunks if type(c) is not list)
    assert loose < len(held.events) // 50, repr(held.events)


def test_a_closed_log_reads_as_the_list_and_goes_on_in_a_fresh_tail() -> None:
    """EventLog.close (a snapshot's, sut/snapshot.py): the events held one by one so far become Closed
    stretches, read as they were; later events go to a new tail, so a stretch is never written again."""
    toy = _Toy(True, 5000, [])
    for i in range(4):
        toy.events.append(TraceEvent(4000 + i, "train", KINDS[i % 2], {"i": i}))
    bulk._repeat(toy, _pattern([(10, SOURCES[0], KINDS[0], 1, 1)], 4000), 1, 3, PERIOD)
    toy.events.append(TraceEvent(9000, "train", "after", {}))
    whole = list(toy.events)
    trace = Trace(toy.events)
    trace.select(kind=KINDS[0])
    closed = toy.events.close()
    assert [list(c) for c in closed] == [whole[:4], whole[-1:]]      # the tails, not the held stretch
    assert toy.events.close() == closed                                # nothing new: nothing closed again
    assert toy.events[0] is closed[0][0] and toy.events.patterned
    toy.events.append(TraceEvent(9500, "train", "later", {}))
    whole.append(toy.events[-1])
    n = len(whole)
    assert list(toy.events) == whole and len(toy.events) == n and list(closed[1]) == whole[-2:-1]
    assert [toy.events[i] for i in range(-n, n)] == whole + whole
    for a, b in ((0, n), (2, 6), (3, n - 1), (n - 2, n + 3)):
        assert toy.events[a:b] == whole[a:b]
    assert toy.events.kinds(0) == [ev.kind for ev in whole] and toy.events.kinds(3) == [ev.kind for ev in whole[3:]]
    assert toy.events.pick([0, 3, 5, n - 2, n - 1]) == [whole[i] for i in (0, 3, 5, n - 2, n - 1)]
    assert trace.select(kind=KINDS[0]) == [ev for ev in whole if ev.kind == KINDS[0]]
    for copied in (pickle.loads(pickle.dumps(toy.events)), copy.deepcopy(toy.events)):
        assert list(copied) == whole
    only_closed = EventLog(whole[:3])
    only_closed.close()
    assert not only_closed.patterned and list(only_closed) == whole[:3]
