"""Powered-up snapshots: a scenario that reaches a state another scenario of this process already reached
starts from a copy of that state instead of simulating it again.

Most features open with the same Background (an 8-car set, powered up for 1000 ms, key in cab 1, forward):
simulated once per scenario, that was a fifth of the simulation in a conformance run. A `SnapshotDriver` stands in for the
scenario's driver and keeps a journal of every call made to it since `open()`. The key of a state is exact
because it is everything that made it: the backend class (a faulty variant is its own class, so its
parameters are in the key), the profile, and every call with its arguments, in order (composition, power-up,
desk, inputs, faults, each `advance` and so elapsed time). A deterministic backend reaches the same state
from the same journal; `tests/test_snapshot.py` checks that traces and verdicts are byte-identical with
snapshots on and off for every profile.

- Calls that change the train are journaled and, where the same call at the same key succeeded before,
  deferred: nothing runs until the scenario needs the train. A call not seen before runs at once, so its
  errors surface in the step that made it.
- Reads (`now_us`, `output`, `trace.first(...)`, ...) are answered from what the same read returned at the
  same key before (a copy), else from the driver brought up to date: from a stored state on the journal
  (a fresh copy: a scenario never sees another's objects, but for the trace's events up to the state, which
  no one writes: `State`) plus the calls after it, or by simulating the deferred calls, whichever the
  measured costs say is cheaper.
- A state is copied into the cache where journals branch (a key with two different next calls: the end
  of a shared Background, or of shared When steps), when a scenario passes it with the train up to date, if
  simulating to it costs more than restoring it; within a budget of the memory held (`State.nbytes`), least
  recently used dropped first.
- Only a backend that declares itself `DETERMINISTIC` is journaled (the `sut` fixture drives any other,
  a rig or a remote train, call by call). It offers snapshots by implementing `TrainDriver.snapshot` /
  `from_snapshot` (the references pickle themselves: `PickledState`); one that raises `NotSupported`
  simply simulates; a state whose snapshot fails otherwise (an unpicklable part in a custom backend) is
  simulated instead, and the run says why in one line (`SnapshotCache.notes`).
- A call with arguments that cannot be a key (a list of balise packets) or a method the driver interface
  does not know ends the journal for the scenario: it goes on with its own driver, as without snapshots.
"""
from __future__ import annotations

import gc
import io
import pickle
import time
from collections import OrderedDict
from typing import Any, Callable

from sut.driver import TrainDriver
from sut.errors import NotSupported, SutError
from sut.eventlog import Closed, EventLog
from sut.trace import Trace, TraceEvent

# Driver calls that only observe (besides the properties now_us, powered and trace): they never change it.
READS = frozenset({
    "counters", "input", "output", "reading", "vehicle_names", "rated_limits", "records", "ring_nodes",
    "boards", "devices", "supplies", "token_holder", "monitor", "status_table", "lamp", "block_store", "describe",
})
# Driver calls that act on the train: journaled, deferred where the cache knows them.
INPUTS = frozenset({
    "configure", "power_on", "advance", "advance_ms", "soak", "insert_key", "remove_key", "set_direction",
    "set_traction", "set_brake", "cut_link", "restore_link", "cut_ring", "corrupt_frames", "fail", "repair",
    "power_off", "restore_power", "set_input", "ramp_input", "monitor_order", "set_supply_voltage",
    "interrupt_supply", "set_temperature", "interfere", "vibrate", "withstand_test", "cut_line",
    "restore_line", "disturb_line", "tap_bus", "pass_balise", "request_block_transfer", "tap_link",
    "insulation_resistance", "watch_monitor",
})
# Inputs that return what they measured (an insulation test leaves it in the trace; a watch of the monitor
# returns what it saw while time passed): journaled, never deferred.
MEASUREMENTS = frozenset({"insulation_resistance", "watch_monitor"})

DEFAULT_BUDGET = 256 * 2**20


class State(bytes):
    """A pickled driver and the Closed stretches of its trace (sut/eventlog.py) it refers to by number: the
    trace up to the state, three quarters of what a whole pickle held, is shared with the driver it was taken
    from and with every driver restored from it, not pickled into each. `nbytes`: the memory it holds, the
    pickle's bytes and the shared events as objects (the cache's budget counts that; restoring costs what
    len() says)."""

    closed: list
    nbytes: int


class PickledState:
    """`snapshot`/`from_snapshot` by pickling the whole driver: for backends that live in this process and
    hold nothing but their own state (no socket, no file, no thread)."""

    def snapshot(self) -> bytes:
        closed: list[Closed] = []
        numbers: dict[int, int] = {}

        def shared(obj: Any) -> int | None:
            kind = type(obj)
            if kind is EventLog:
                obj.close()                # the events so far: no one writes them again
            elif kind is Closed:
                number = numbers.get(id(obj))
                if number is None:
                    number = numbers[id(obj)] = len(closed)
                    closed.append(obj)
                return number
            return None

        out = io.BytesIO()
        pickler = pickle.Pickler(out, protocol=pickle.HIGHEST_PROTOCOL)
        pickler.persistent_id = shared
        pickler.dump(self)
        state = State(out.getvalue())
        state.closed = closed
        state.nbytes = len(state) + sum(chunk.nbytes() for chunk in closed)
        return state

    @classmethod
    def from_snapshot(cls, data: bytes) -> TrainDriver:
        # Tens of thousands of new objects at once would set off the cyclic collector several times over
        # the whole (large) heap of a test run: it made a restore 10x slower. Nothing here is garbage.
        enabled = gc.isenabled()
        gc.disable()
        try:
            closed = getattr(data, "closed", None)
            if closed is None:
                driver = pickle.loads(data)
            else:
                unpickler = pickle.Unpickler(io.BytesIO(data))
                unpickler.persistent_load = closed.__getitem__
                driver = unpickler.load()
        finally:
            if enabled:
                gc.enable()
        if not isinstance(driver, cls):
            raise SutError(f"a snapshot of {type(driver).__qualname__} is not a {cls.__qualname__}")
        return driver


class SnapshotCache:
    """The states of one process, keyed by nodes of a journal trie (a node per call, so a key costs one
    dict lookup however long the journal), with what each call cost to simulate and each restore cost."""

    def __init__(self, budget_bytes: int = DEFAULT_BUDGET, every_branch: bool = False):
        self.budget = budget_bytes
        # Store at every branch and restore whenever a state is stored, whatever the costs: the measured
        # costs are wall time, so which states a loaded machine stores varies from run to run; a check of
        # the snapshots themselves (tests/test_determinism.py) needs them used every time.
        self.every_branch = every_branch
        self._children: dict[tuple[int, Any], int] = {}
        self._parent: list[int] = [0]                    # node 0: the root above every backend
        self._cost: list[float] = [0.0]                  # seconds the call leading to a node took to simulate
        self._good: set[int] = set()                     # nodes whose call succeeded
        self._states: OrderedDict[int, tuple[type[TrainDriver], bytes]] = OrderedDict()
        self._branches: dict[int, int] = {}               # node -> how many different calls followed it
        self._declined: set[int] = set()                 # cheaper to simulate to than to restore
        self._answers: dict[tuple[int, Any], Any] = {}
        self._refused: set[type] = set()
        self._seconds_per_byte = 1e-8                    # restore cost, learned from every restore
        self.size = 0
        self.notes: list[str] = []                       # one line per backend whose snapshots failed
        self.stored = self.restored = self.deferred = self.answered = self.evicted = 0
        self.restored_by: dict[str, int] = {}          # backend class name -> states restored

    # -- keys ------------------------------------------------------------------------------------
    def child(self, node: int, entry: Any) -> int:
        key = (node, entry)
        found = self._children.get(key)
        if found is None:
            found = self._children[key] = len(self._parent)
            self._parent.append(node)
            self._cost.append(0.0)
            self._branches[node] = self._branches.get(node, 0) + 1
        return found

    def known(self, node: int) -> bool:
        """The call leading to this key succeeded before (so deferring it hides no error)."""
        return node in self._good

    def ran(self, node: int, seconds: float) -> None:
        self._good.add(node)
        self._cost[node] = seconds

    # -- choosing how to catch up -----------------------------------------------------------------
    def plan(self, pending: list[int]) -> int | None:
        """Given the deferred keys (oldest first), the stored one to restore before simulating the rest,
        or None to simulate them all: whichever the costs measured so far say is cheaper (with every_branch,
        the latest stored one)."""
        cost = self._cost
        if self.every_branch:
            return next((node for node in reversed(pending) if node in self._states), None)
        best, best_cost = None, sum(cost[n] for n in pending)
        after = 0.0
        for node in reversed(pending):
            if node in self._states:
                restore = self._seconds_per_byte * len(self._states[node][1])
                if restore + after < best_cost:
                    best, best_cost = node, restore + after
            after += cost[node]
        return best

    def _reach_cost(self, node: int) -> float:
        """Seconds of simulation from the nearest stored state above `node` (or power-up) to it."""
        total = 0.0
        while node != 0 and node not in self._states:
            total += self._cost[node]
            node = self._parent[node]
        return total

    # -- states ----------------------------------------------------------------------------------
    def get(self, node: int) -> TrainDriver | None:
        """A new driver in the state stored at `node`; None if it cannot be restored (then simulate)."""
        cls, data = self._states[node]
        self._states.move_to_end(node)
        started = time.perf_counter()
        try:
            driver = cls.from_snapshot(data)
        except Exception as exc:                          # noqa: BLE001 - any failure means: simulate
            self.refuse(cls, f"cannot restore a snapshot: {exc!r:.160}")
            for other in [n for n, (c, _) in self._states.items() if c is cls]:
                self._drop(other)
            return None
        rate = (time.perf_counter() - started) / max(len(data), 1)
        self._seconds_per_byte = 0.8 * self._seconds_per_byte + 0.2 * rate
        self.restored += 1
        self.restored_by[cls.__qualname__] = self.restored_by.get(cls.__qualname__, 0) + 1
        return driver

    def checkpoint(self, node: int, driver: TrainDriver) -> None:
        """Store the driver's state at `node` if journals branch there and simulating to it costs more
        than restoring it (with every_branch, whatever it costs)."""
        if (node in self._states or node in self._declined or self._branches.get(node, 0) < 2
                or type(driver) in self._refused):
            return
        reach = self._reach_cost(node)
        if reach < 1e-3 and not self.every_branch:        # under a millisecond to simulate: never worth it
            self._declined.add(node)
            return
        try:
            data = driver.snapshot()
        except NotSupported:
            self._refused.add(type(driver))
            return
        except Exception as exc:                          # noqa: BLE001 - any failure means: simulate
            # Maybe only this state (a part that pickles only now and then): decline it, not the backend.
            self._declined.add(node)
            self.note(type(driver), f"a state could not be snapshotted: {exc!r:.160}", "it is simulated instead")
            return
        if reach < 2 * self._seconds_per_byte * len(data) and not self.every_branch:
            self._declined.add(node)
            return
        self._put(node, type(driver), data)

    def refuse(self, cls: type, why: str) -> None:
        if cls not in self._refused:
            self._refused.add(cls)
            self.note(cls, why, "snapshots off for it: its scenarios simulate from power-up")

    def note(self, cls: type, why: str, consequence: str) -> None:
        """One line for the end of the run, once per backend class and reason."""
        line = f"{cls.__module__}.{cls.__qualname__}: {why}; {consequence}"
        if not any(n.startswith(f"{cls.__module__}.{cls.__qualname__}:") for n in self.notes):
            self.notes.append(line)

    def _put(self, node: int, cls: type[TrainDriver], data: bytes) -> None:
        self._states[node] = (cls, data)
        self.size += getattr(data, "nbytes", len(data))
        self.stored += 1
        while self.size > self.budget and len(self._states) > 1:
            self._drop(next(iter(self._states)))
            self.evicted += 1

    def _drop(self, node: int) -> None:
        _, data = self._states.pop(node)
        self.size -= getattr(data, "nbytes", len(data))

    # -- answers to reads ----------------------------------------------------------------------------
    def answer(self, node: int, read: Any) -> tuple[bool, Any]:
        kept = self._answers.get((node, read), _NONE)
        if kept is _NONE:
            return False, None
        self.answered += 1
        # A container is kept pickled: the step that asked gets its own copy (pickle is 5-10x deepcopy).
        return True, (pickle.loads(kept.data) if type(kept) is _Pickled else kept)

    def remember(self, node: int, read: Any, value: Any) -> None:
        key = (node, read)
        if key in self._answers or len(self._answers) >= MAX_ANSWERS:
            return
        if type(value) in _IMMUTABLE:
            self._answers[key] = value
        elif _small(value):
            data = pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
            if len(data) <= MAX_ANSWER_BYTES:
                self._answers[key] = _Pickled(data)

    # -- figures ---------------------------------------------------------------------------------------
    FIGURES = ("restored", "deferred", "answered", "stored", "size", "evicted")

    def figures(self) -> dict[str, Any]:
        """What an xdist worker reports to the controller (`add_figures`)."""
        return {"notes": self.notes, "restored_by": self.restored_by,
                **{name: getattr(self, name) for name in self.FIGURES}}

    def add_figures(self, figures: dict[str, Any]) -> None:
        self.notes.extend(figures["notes"])
        for name in self.FIGURES:
            setattr(self, name, getattr(self, name) + figures[name])
        for name, count in figures["restored_by"].items():
            self.restored_by[name] = self.restored_by.get(name, 0) + count

    def summary(self) -> str:
        by = ", ".join(f"{name} {count}" for name, count in sorted(self.restored_by.items()))
        return (f"snapshots: {self.restored} restored{f' ({by})' if by else ''}, {self.deferred} calls and "
                f"{self.answered} reads not simulated again, {self.stored} stored ({self.size / 2**20:.1f} MB "
                f"held, {self.evicted} dropped)")


# Answers are kept at every key a scenario reads at, most of them never asked again (a scenario's own
# steps): bounded so that they cost tens of MB, not hundreds (a cab monitor watched for seconds is read every
# millisecond, each view a few hundred bytes).
MAX_ANSWERS = 100_000
MAX_ANSWER_BYTES = 256
_NONE = object()
_IMMUTABLE = frozenset({int, float, str, bool, bytes, type(None)})


class _Pickled:
    __slots__ = ("data",)

    def __init__(self, data: bytes):
        self.data = data


def _small(value: Any, budget: int = 16) -> bool:
    """Whether a read's value is small enough to keep as an answer (a trace selection can be thousands)."""
    if isinstance(value, (list, tuple, dict, set, frozenset)) and not isinstance(value, TraceEvent):
        return len(value) <= budget
    return True


class _JournalTrace(Trace):
    """The trace of whatever driver currently stands behind the journal (a restore may replace it);
    queries are answered like the driver's other reads."""

    def __init__(self, owner: "SnapshotDriver"):                # noqa: super().__init__ not wanted
        self._owner = owner

    @property
    def _events(self) -> list:
        return self._owner._observe(None, lambda driver: driver.trace._events)

    def __len__(self) -> int:
        return self._owner._observe(("trace.len",), lambda driver: len(driver.trace))

    def select(self, kind=None, source=None, since=None, until=None, **where: Any) -> list:
        read = ("trace.select", kind, source, since, until, tuple(sorted(where.items())))
        return self._owner._observe(read, lambda driver: driver.trace.select(kind, source, since, until, **where))

    def of_kinds(self, wanted, since=None, until=None) -> list:
        # `wanted` is a function, no key to answer by: the driver's own (indexed) trace answers
        return self._owner._observe(None, lambda driver: driver.trace.of_kinds(wanted, since, until))

    def first(self, **criteria: Any):
        read = ("trace.first", tuple(sorted(criteria.items())))
        return self._owner._observe(read, lambda driver: driver.trace.first(**criteria))

    def last(self, **criteria: Any):
        read = ("trace.last", tuple(sorted(criteria.items())))
        return self._owner._observe(read, lambda driver: driver.trace.last(**criteria))


class SnapshotDriver:
    """A scenario's driver: the journal in front of the real one (see the module docstring). Every call of
    the driver interface goes through; nothing else is offered."""

    def __init__(self, cls: type[TrainDriver], profile: str | None, cache: SnapshotCache):
        self._cls, self._profile, self._cache = cls, profile, cache
        self._node = cache.child(0, (cls, profile))      # the key of the state the journal describes
        self._pending: list[tuple[int, str, tuple, dict]] = []   # deferred calls: (node, name, args, kwargs)
        self._driver: TrainDriver | None = None
        self._live = True                                # the journal still describes the driver
        self.stimuli: list[tuple[str, tuple, dict]] = []  # every call that acts on the train, in order

    # -- the journal -----------------------------------------------------------------------------
    def _call(self, name: str, args: tuple, kwargs: dict) -> Any:
        self.stimuli.append((name, args, kwargs))
        if self._live:
            try:
                entry = (name, args, tuple(sorted(kwargs.items())))
                hash(entry)
            except TypeError:                             # not a key: this scenario goes on on its own
                self._live = False
            else:
                node = self._cache.child(self._node, entry)
                if self._cache.known(node) and name not in MEASUREMENTS:
                    self._pending.append((node, name, args, kwargs))
                    self._node = node
                    self._cache.deferred += 1
                    return None
                driver = self._needed()
                try:
                    result = self._run(driver, node, name, args, kwargs)
                except BaseException:
                    self._live = False                    # whatever it left half done is not a key
                    raise
                self._node = node
                return result
        return getattr(self._up_to_date(), name)(*args, **kwargs)

    def _up_to_date(self) -> TrainDriver:
        """The real driver, in the state the journal describes."""
        replay, self._pending = self._pending, []
        if replay:
            stored = self._cache.plan([node for node, *_ in replay])
            restored = self._cache.get(stored) if stored is not None else None
            if restored is not None:
                if self._driver is not None:
                    self._driver.shutdown()
                self._driver = restored
                replay = replay[[node for node, *_ in replay].index(stored) + 1:]
        if self._driver is None:
            self._driver = self._cls.open(self._profile)
        for node, name, args, kwargs in replay:
            self._run(self._driver, node, name, args, kwargs)
            self._cache.checkpoint(node, self._driver)   # a branch passed on the way is worth keeping
        return self._driver

    def _run(self, driver: TrainDriver, node: int, name: str, args: tuple, kwargs: dict) -> Any:
        """One journaled call on the real driver, its cost noted for the key it leads to."""
        started = time.perf_counter()
        result = getattr(driver, name)(*args, **kwargs)
        self._cache.ran(node, time.perf_counter() - started)
        return result

    def _needed(self) -> TrainDriver:
        """The driver up to date, because the scenario needs the train itself at this key."""
        driver = self._up_to_date()
        if self._live:
            self._cache.checkpoint(self._node, driver)
        return driver

    def _observe(self, read: Any, fn: Callable[[TrainDriver], Any]) -> Any:
        """What `fn` reads from the driver at this key: the answer the same read gave here before, or read."""
        if self._live and read is not None:
            try:
                hash(read)
            except TypeError:
                read = None
            else:
                if self._pending:                        # worth answering only if the train is behind
                    found, value = self._cache.answer(self._node, read)
                    if found:
                        return value
        value = fn(self._needed())
        if self._live and read is not None:
            self._cache.remember(self._node, read, value)
        return value

    # -- the driver interface ----------------------------------------------------------------------
    @property
    def now_us(self) -> int:
        return self._observe(("now_us",), lambda driver: driver.now_us)

    @property
    def powered(self) -> bool:
        return self._observe(("powered",), lambda driver: driver.powered)

    @property
    def trace(self) -> Trace:
        return _JournalTrace(self)

    @property
    def real_driver(self) -> TrainDriver:
        """The driver behind the journal, up to date (the journal ends: it may be changed behind our back)."""
        driver = self._up_to_date()
        self._live = False
        return driver

    @property
    def simulated_trace(self) -> Trace | None:
        """The trace of the driver as far as it has been simulated, without replaying deferred calls: their
        events were made, and seen, by the scenario that first ran them (None: nothing simulated here)."""
        return self._driver.trace if self._driver is not None else None

    def shutdown(self) -> None:
        if self._driver is not None:
            self._driver.shutdown()
        self._live = False

    def __enter__(self) -> "SnapshotDriver":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.shutdown()

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        if name in INPUTS:
            return lambda *args, **kwargs: self._call(name, args, kwargs)
        if name in READS:
            return lambda *args, **kwargs: self._observe(
                (name, args, tuple(sorted(kwargs.items()))), lambda driver: getattr(driver, name)(*args, **kwargs))
        # Not part of the driver interface: hand over the real driver and stop keeping a journal.
        return getattr(self.real_driver, name)
