"""Powered-up snapshots (sut/snapshot.py) are invisible: the same verdicts and byte-identical traces with
snapshots on and off, for every profile (tests/test_determinism.py runs that); a scenario never sees
another's state (the trace's events up to a stored state are shared, and no one writes them); the key holds everything that makes a state (backend class and its parameters, profile,
every call); a backend that cannot snapshot simulates, saying why once."""
from __future__ import annotations

import pickle
import subprocess
import sys

import pytest

from sut.errors import NotSupported, OutOfRange
from sut.eventlog import Closed
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.profiles import Reference
from sut.snapshot import SnapshotCache, SnapshotDriver
from tests.helpers import verdicts
from tests.test_faulty_variants import ROOT

# Snapshots on and off, every profile, byte for byte: tests/test_determinism.py (its first two runs).


def test_the_journal_knows_every_call_of_the_driver_interface() -> None:
    from sut.driver import TrainDriver
    from sut.snapshot import INPUTS, READS

    public = {name for name in dir(TrainDriver) if not name.startswith("_")}
    own = {"now_us", "powered", "trace", "shutdown"}                   # SnapshotDriver's own properties
    local = {"open", "snapshot", "from_snapshot", "check_us", "check_direction", "PROFILES", "backend_name",
             "DETERMINISTIC", "DECLARATION"}
    assert public - INPUTS - READS - own - local == set(), "a driver call the journal would not know"
    assert not INPUTS & READS


def test_only_a_deterministic_backend_is_journaled() -> None:
    from sut.remote.client import RemoteTrain
    from sut.reference.atp.backend import ReferenceAtp
    from sut.reference.metro.backend import ReferenceMetro

    assert Reference.DETERMINISTIC and ReferenceTrain.DETERMINISTIC and ReferenceMetro.DETERMINISTIC
    assert ReferenceAtp.DETERMINISTIC
    assert not RemoteTrain.DETERMINISTIC          # a rig or a remote train: every call goes to it


# -- in process, on the real reference --------------------------------------------------------------------
def _background(driver) -> int:
    driver.configure(sets=1, cars_per_set=8)
    driver.power_on()
    driver.advance_ms(1000)
    t = driver.now_us
    driver.insert_key(1)
    driver.set_direction(1, "forward")
    return t


def _scenario(cache: SnapshotCache, cls=Reference, notch: int = 5) -> SnapshotDriver:
    driver = SnapshotDriver(cls, "crh2", cache)
    _background(driver)
    driver.set_traction(1, notch)
    driver.advance_ms(100)
    assert "desk.traction" in driver.trace.to_csv()       # the whole trace: needs the train itself
    return driver


# Scenarios branch after the Background (notch 1, 2, 3, ...): the first branch stores the Background's end,
# every later scenario restores it.
def test_a_restored_train_is_the_train_simulated_from_power_up() -> None:
    cache = SnapshotCache()
    runs = {notch: _scenario(cache, notch=notch) for notch in (1, 2, 3, 4, 5)}
    assert cache.stored >= 1 and cache.restored >= 3 and cache.deferred >= 15
    for notch, run in runs.items():
        plain = Reference.open("crh2")
        _background(plain)
        plain.set_traction(1, notch)
        plain.advance_ms(100)
        assert run.trace.to_csv() == plain.trace.to_csv()
        assert run.now_us == plain.now_us and run.output("car3.CI gates") == plain.output("car3.CI gates")


def test_every_branch_stores_and_restores_whatever_the_measured_costs_say() -> None:
    # Restoring made to look dearer than any simulation: the measured costs store and restore nothing.
    measured, every = SnapshotCache(), SnapshotCache(every_branch=True)
    for cache in (measured, every):
        cache._seconds_per_byte = 1.0
        runs = [_scenario(cache, notch=notch) for notch in (1, 2, 3)]
    assert measured.restored == measured.stored == 0
    assert every.stored >= 1 and every.restored >= 1
    assert runs[-1].trace.to_csv() == _scenario(SnapshotCache(), notch=3).trace.to_csv()


def test_a_repeated_scenario_is_answered_without_the_train() -> None:
    cache = SnapshotCache()
    _scenario(cache)
    again = SnapshotDriver(Reference, "crh2", cache)
    assert _background(again) == 1_000_000
    assert again._driver is None and cache.answered == 1 and cache.deferred == 5   # nothing simulated yet
    assert again.trace.first(kind="power.on") is not None and again._driver is not None


def test_a_scenario_never_sees_another_scenarios_state() -> None:
    cache = SnapshotCache()
    for notch in (1, 2):
        _scenario(cache, notch=notch)
    spoiled = _scenario(cache, notch=3)
    spoiled.fail("car1.CCU.sys1.TXC")
    spoiled.advance_ms(200)
    clean = _scenario(cache, notch=4)
    assert cache.restored >= 2
    assert not clean.trace.select(kind="fault.board")
    assert spoiled.trace.select(kind="fault.board")
    assert clean.real_driver is not spoiled.real_driver


def test_the_key_holds_the_backend_class_and_every_argument() -> None:
    class SlowTakeover(ReferenceTrain):
        TIMING = {"takeover_us": 100_000}

    cache = SnapshotCache()
    for notch in (1, 2, 3):
        _scenario(cache, notch=notch)
    restored = cache.restored
    other_class = _scenario(cache, cls=SlowTakeover)
    assert cache.restored == restored and cache.deferred     # the variant shares nothing
    assert "takeover_us" in str(other_class.describe())
    other_notch = _scenario(cache, notch=6)
    assert [ev["notch"] for ev in other_notch.trace.select(kind="desk.traction")] == [6]


def test_a_bad_call_fails_in_its_own_step_and_ends_the_journal() -> None:
    cache = SnapshotCache()
    for notch in (1, 2, 3):
        _scenario(cache, notch=notch)
    driver = SnapshotDriver(Reference, "crh2", cache)
    _background(driver)
    with pytest.raises(OutOfRange, match="traction notch 99"):
        driver.set_traction(1, 99)
    driver.advance_ms(10)                          # goes on, on its own driver
    assert driver.now_us == 1_010_000


class Unpicklable(ReferenceTrain):
    """A custom backend with a part that cannot be copied."""

    def __init__(self) -> None:
        super().__init__()
        self.probe = lambda: None


def test_a_backend_that_cannot_snapshot_simulates_and_says_why_once() -> None:
    cache = SnapshotCache()
    runs = [_scenario(cache, cls=Unpicklable, notch=notch) for notch in (1, 2, 3)]
    assert cache.stored == 0 and cache.restored == 0
    assert len(cache.notes) == 1 and "Unpicklable" in cache.notes[0] and "simulated instead" in cache.notes[0]
    assert all(run.now_us == 1_100_000 for run in runs)


def test_a_run_whose_backend_cannot_snapshot_passes_and_says_why_in_one_line() -> None:
    result = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-rA", "-p", "no:cacheprovider",
                             "-p", "no:xdist", "--item=R-CTL-01,R-CTL-02,R-CTL-03",
                             "--sut=tests.test_snapshot:Unpicklable"],
                            cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    lines = [line for line in result.stdout.splitlines() if "could not be snapshotted" in line]
    assert len(lines) == 1 and "Unpicklable" in lines[0] and "simulated instead" in lines[0], result.stdout[-2000:]
    assert len(verdicts(result.stdout)) >= 10


class Rig(ReferenceTrain):
    """Stands for a rig: its state is not its own objects, so it declares no snapshots."""

    def snapshot(self) -> bytes:
        raise NotSupported("a rig cannot copy its hardware")


def test_a_backend_without_snapshots_simply_simulates() -> None:
    cache = SnapshotCache()
    runs = [_scenario(cache, cls=Rig, notch=notch) for notch in (1, 2, 3)]
    assert cache.stored == 0 and cache.restored == 0 and cache.notes == []
    assert all(run.now_us == 1_100_000 for run in runs)


def test_a_restored_train_shares_the_trace_up_to_the_snapshot_and_nothing_it_writes() -> None:
    """PickledState keeps the trace up to the state out of the pickle (sut/eventlog.py, Closed): the stored
    state and every train restored from it hold those very events; what any of them emits later is its own."""
    train = Reference.open("crh2")
    _background(train)
    data = train.snapshot()
    assert data.closed and len(data) < data.nbytes
    first, second = ReferenceTrain.from_snapshot(data), ReferenceTrain.from_snapshot(data)
    n = len(train.trace)
    assert first.trace[n - 1] is second.trace[n - 1] is train.trace[n - 1]
    first.set_traction(1, 3)
    first.advance_ms(100)
    second.advance_ms(100)
    train.advance_ms(100)
    assert first.trace.select(kind="desk.traction") and not second.trace.select(kind="desk.traction")
    assert second.trace.to_csv() == train.trace.to_csv() != first.trace.to_csv()
    third = ReferenceTrain.from_snapshot(data)
    plain = ReferenceTrain.from_snapshot(pickle.dumps(third, protocol=pickle.HIGHEST_PROTOCOL))
    assert plain.trace.to_csv() == third.trace.to_csv()       # a plain pickle of a restored train restores too


def test_the_budget_counts_the_shared_events_as_the_objects_they_are() -> None:
    """A stored state's nbytes counts its Closed stretches as objects in memory, not as their few pickled
    bytes (~6x fewer): between what tracemalloc sees a stretch take and twice that, so the budget bounds the
    memory the cache keeps alive."""
    import gc
    import tracemalloc

    train = Reference.open("crh2")
    _background(train)
    train.set_traction(1, 3)
    train.advance_ms(3000)
    events = list(train.trace)
    gc.collect()
    tracemalloc.start()
    try:
        chunk = pickle.loads(pickle.dumps(Closed(events)))
        held, _ = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    estimate = chunk.nbytes()
    assert held <= estimate <= 2 * held, (estimate, held)
    data = train.snapshot()
    assert data.nbytes == len(data) + sum(chunk.nbytes() for chunk in data.closed) > 4 * len(data)
