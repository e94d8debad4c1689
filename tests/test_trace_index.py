"""sut/trace.py answers a query for one kind from its index of kinds and sources: the same events, in the same
order, as a walk over the whole list, also while the list grows between queries."""
from __future__ import annotations

import pickle

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sut.trace import Trace, TraceEvent

SOURCES = ["car1.CI", "car1.BCU", "car10.CI", "car1.CI.loop", "car2.BCU", "WTB"]
KINDS = ["cmd.in", "cmd.tx", "cmd.inx", "frame.discard"]


class Walk(Trace):
    """The plain walk: a subclass of Trace is never answered from the index."""


events = st.lists(st.tuples(st.integers(0, 3), st.sampled_from(SOURCES), st.sampled_from(KINDS),
                            st.sampled_from([1, 2, 3])), max_size=120)
queries = st.lists(st.tuples(st.sampled_from(KINDS + ["cmd.*", "nothing"]),
                             st.sampled_from([None, "car1", "car1.CI", "car1*", "car?.BCU", "car10.CI", "car", "*"]),
                             st.one_of(st.none(), st.integers(0, 200)), st.one_of(st.none(), st.integers(0, 200)),
                             st.sampled_from([{}, {"path": 1}, {"path": 3}])), min_size=1, max_size=6)


def _timed(steps: list) -> list[TraceEvent]:
    out, t = [], 0
    for dt, source, kind, path in steps:
        t += dt
        out.append(TraceEvent(t, source, kind, {"path": path}))
    return out


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(first=events, more=events, asked=queries)
def test_the_index_answers_as_the_walk_does_while_the_trace_grows(first, more, asked):
    timed = _timed(first + more)
    grown: list[TraceEvent] = timed[:len(first)]
    indexed, walk = Trace(grown), Walk(grown)
    for step in (0, 1):
        for kind, source, since, until, where in asked:
            assert indexed.select(kind, source, since, until, **where) == walk.select(kind, source, since, until,
                                                                                     **where)
            criteria = dict(kind=kind, source=source, since=since, until=until, **where)
            assert indexed.first(**criteria) == walk.first(**criteria)       # stops at the first it finds
            assert indexed.last(**criteria) == walk.last(**criteria)
        grown.extend(timed[len(first):])            # appended between two queries, as a train does


def test_a_pickled_view_leaves_its_index_behind_and_still_answers():
    view = Trace(_timed([(1, "car1.CI", "cmd.in", 1), (1, "car2.BCU", "cmd.in", 2)]))
    assert len(view.select("cmd.in", "car1")) == 1
    again = pickle.loads(pickle.dumps(view))          # a snapshot of a backend holds its view
    assert (again._indexed, again._by_kind, again._by_source) == (0, {}, {})
    assert again.select("cmd.in") == view.select("cmd.in")


kind_sets = st.sets(st.sampled_from(KINDS + ["nothing"]), max_size=4)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(first=events, more=events, wanted=st.lists(st.tuples(kind_sets, st.one_of(st.none(), st.integers(0, 200)),
                                                           st.one_of(st.none(), st.integers(0, 200))),
                                                 min_size=1, max_size=4))
def test_events_of_several_kinds_come_from_the_index_as_the_walk_gives_them(first, more, wanted):
    timed = _timed(first + more)
    grown: list[TraceEvent] = timed[:len(first)]
    indexed, walk = Trace(grown), Walk(grown)
    for step in (0, 1):
        for kinds, since, until in wanted:
            expected = [ev for ev in grown if ev.kind in kinds and (since is None or ev.t >= since)
                        and (until is None or ev.t <= until)]
            assert indexed.of_kinds(kinds.__contains__, since, until) == expected
            assert walk.of_kinds(kinds.__contains__, since, until) == expected
        grown.extend(timed[len(first):])


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(first=events, more=events, kinds=kind_sets, n=st.integers(0, 5))
def test_the_first_events_of_each_kind_come_from_the_index_as_the_walk_gives_them(first, more, kinds, n):
    timed = _timed(first + more)
    grown: list[TraceEvent] = timed[:len(first)]
    indexed, walk = Trace(grown), Walk(grown)
    for step in (0, 1):
        expected = {k: [ev for ev in grown if ev.kind == k][:n] for k in kinds if any(ev.kind == k for ev in grown)}
        assert indexed.heads(kinds, n) == expected
        assert walk.heads(kinds, n) == expected
        grown.extend(timed[len(first):])
