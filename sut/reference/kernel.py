"""A small discrete-event kernel in integer microseconds (SimPy-shaped, no wall clock).

Why our own and not SimPy: `bench/kernel_bench.py` runs the same ring load on both (figures in
docs/decisions.md). SimPy is no faster, and ours keeps what the model needs that SimPy does not give directly:
integer microseconds end to end, cancellable timers (token watchdogs are re-armed on every status frame),
and one place to add bulk advance. Processes that read like behaviour can still be generators: they
`yield` a delay in microseconds or a `Signal` to wait for.

Ordering: entries are (time, priority, sequence). The sequence counter makes ties deterministic, so two
runs with the same inputs give the same trace. Two cheaper ways in keep that key exactly: `schedule` (no Timer
for a callback nobody cancels) and `put_off` (a watchdog moved, not replaced); docs/decisions.md, "Kernel".

Bulk advance (72 h runs) lives in bulk.py: it reads the whole train, timers included, and jumps whole
steady periods; the kernel's part is that timers carry their own heap key and the heap can be rebuilt.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass
from typing import Any, Callable, Generator, Iterable

URGENT = 0
NORMAL = 1
LATE = 2
# Free-running emitters (Kernel.metronome) run after everything else due at the same instant, in the order
# they were registered: their ticks never depend on the rest's history, so bulk.py can regenerate them.
FREE = 3


class SimulationError(RuntimeError):
    """A process of the simulated train raised: the scenario must fail, never pass silently."""


class Interrupt(Exception):
    """Thrown into a process generator, carrying its cause (power loss, link cut, ...)."""

    @property
    def cause(self) -> Any:
        return self.args[0] if self.args else None


class Timer:
    """A scheduled callback that can be cancelled before it fires. It keeps its own heap key (time,
    priority, sequence) so that the heap can be rebuilt from the live timers after a bulk advance."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    __slots__ = ("at", "prio", "seq", "fn", "args")

    def __init__(self, at: int, prio: int, seq: int, fn: Callable, args: tuple):
        self.at = at
        self.prio = prio
        self.seq = seq
        self.fn = fn
        self.args = args

    def cancel(self) -> None:
        self.fn = None

    @property
    def pending(self) -> bool:
        return self.fn is not None


class Signal:
    """Something processes can wait for; `fire(value)` resumes every waiter at the current time."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    __slots__ = ("kernel", "_waiters")

    def __init__(self, kernel: "Kernel"):
        self.kernel = kernel
        self._waiters: list[tuple[Process, int]] = []

    def fire(self, value: Any = None) -> None:
        waiters, self._waiters = self._waiters, []
        for proc, wait in waiters:
            self.kernel.call_later(0, proc._resume, wait, value, prio=URGENT)


ProcessGen = Generator[Any, Any, Any]


class Process:
    """A generator driven by the kernel: `yield <int us>` sleeps, `yield <Signal>` waits.

    Every wait gets a number; a wake-up carrying an older number (a timer or signal that an interrupt
    overtook) is ignored, so a process is never resumed twice for one wait. `alive` is a bool: True until
    the generator returns, raises, is interrupted without catching it or killed."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    __slots__ = ("kernel", "name", "_gen", "_timer", "_wait", "alive")

    def __init__(self, kernel: "Kernel", gen: ProcessGen, name: str):
        self.kernel = kernel
        self.name = name
        self._gen = gen
        self._timer: Timer | None = None
        self._wait = 0
        self.alive = True
        kernel.call_later(0, self._resume, 0, None, prio=URGENT)

    def _resume(self, wait: int, value: Any = None, throw: BaseException | None = None) -> None:
        if not self.alive or wait != self._wait:
            return
        self._wait += 1
        self._timer = None
        try:
            target = self._gen.throw(throw) if throw is not None else self._gen.send(value)
        except StopIteration:
            self.alive = False
            return
        except Interrupt:
            # An interrupt the process did not handle ends it, like a board losing power.
            self.alive = False
            return
        except Exception as exc:
            self.alive = False
            raise SimulationError(f"process {self.name} failed at t={self.kernel.now} us: {exc!r}") from exc
        if isinstance(target, int) and not isinstance(target, bool):
            if target < 0:
                self.alive = False
                raise SimulationError(f"process {self.name} asked for a negative delay {target} us")
            self._timer = self.kernel.call_later(target, self._resume, self._wait, None)
        elif isinstance(target, Signal):
            target._waiters.append((self, self._wait))
        else:
            self.alive = False
            raise SimulationError(f"process {self.name} yielded {target!r}; expected int us or Signal")

    def interrupt(self, cause: Any = None) -> None:
        """Throw `Interrupt(cause)` into the process at the current time, ahead of the ordinary callbacks due
        now (URGENT: a board losing power stops before anything else reaches it), after the urgent ones already
        due (so a process not started yet first runs to its first wait, as in SimPy)."""
        self.kernel.call_later(0, self._interrupt_now, cause, prio=URGENT)

    def _interrupt_now(self, cause: Any) -> None:
        if not self.alive:
            return
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        self._wait += 1          # whatever it was waiting for no longer wakes it
        self._resume(self._wait, None, Interrupt(cause))

    def kill(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
        self.alive = False
        self._gen.close()


@dataclass
class Cyclic:
    """A steady periodic activity: `tick()` every `period` us from `phase`. Their periods give the
    train's steady period (bulk.py)."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    period: int
    tick: Callable[..., None]
    next_at: int = 0
    timer: Timer | None = None
    args: tuple = ()                 # for tick: a bound method and its arguments pickle, a lambda does not
    rank: int = -1                   # a metronome's place among the free-running lane (its heap sequence)


class Kernel:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    __slots__ = ("now", "_heap", "_seq", "events", "_cyclics", "_metronomes")
    # bulk.py reads the live timers instead of the heap (and rebuilds it from them), counts no callback it
    # skipped, and regenerates the metronomes' ticks rather than reading them.
    BULK_SKIP = ("_heap", "events", "_metronomes")

    def __init__(self) -> None:
        self.now = 0
        self._heap: list[tuple] = []     # (at, prio, seq, Timer), or (at, prio, seq, fn, args): schedule()
        self._seq = 0
        self.events = 0  # callbacks run, for benchmarks
        self._cyclics: list[Cyclic] = []
        self._metronomes: list[Cyclic] = []

    # -- scheduling -----------------------------------------------------------------------------
    def call_at(self, at: int, fn: Callable, *args: Any, prio: int = NORMAL) -> Timer:
        if at < self.now or type(at) is not int:
            raise SimulationError(f"cannot schedule at {at!r} us (now {self.now} us): times are whole us, "
                                  "never in the past")
        self._seq += 1
        timer = Timer(at, prio, self._seq, fn, args)
        heapq.heappush(self._heap, (at, prio, self._seq, timer))
        return timer

    def call_later(self, delay: int, fn: Callable, *args: Any, prio: int = NORMAL) -> Timer:
        # The hot path of the model: pushes itself rather than going through call_at (bench/kernel_bench.py).
        # A time that is not a whole number of us is refused here, where it is made: carried on, it stops bulk
        # (no state is steady any more) and a long scenario runs frame by frame without bound.
        if delay < 0 or type(delay) is not int:
            raise SimulationError(f"cannot schedule after a delay of {delay!r} us: delays are whole us, never "
                                  "into the past")
        at = self.now + delay
        self._seq += 1
        timer = Timer(at, prio, self._seq, fn, args)
        heapq.heappush(self._heap, (at, prio, self._seq, timer))
        return timer

    def schedule(self, delay: int, fn: Callable, *args: Any) -> None:
        """`call_later(delay, fn, *args)` for a callback nobody cancels (a frame's arrival at the next node, a
        bus message): its heap entry is the key, `fn` and `args`, and no Timer is made for it unless the pending
        timers are asked for (`pending`). Thousands a simulated second."""
        if delay < 0 or type(delay) is not int:
            raise SimulationError(f"cannot schedule after a delay of {delay!r} us: delays are whole us, never "
                                  "into the past")
        self._seq += 1
        heapq.heappush(self._heap, (self.now + delay, NORMAL, self._seq, fn, args))

    def put_off(self, timer: Timer | None, delay: int, fn: Callable, *args: Any) -> Timer:
        """What `timer.cancel()` and then `call_later(delay, fn, *args)` give, the same heap key and so the same
        order, for a timer put off far more often than it fires (a token watchdog, re-armed by every status
        frame a node hears): while it is pending and would come no later, it is moved instead of replaced, and
        its entry in the heap, popped at its old time, goes back at the new one (`run`). No cancelled entries pile
        up in the heap, and no timer is made per re-arm."""
        if timer is not None:
            # A pending timer is due now or later, so `at` no earlier than it is a delay of whole us, >= 0.
            if timer.fn is not None and timer.prio == NORMAL and type(delay) is int and timer.at <= self.now + delay:
                self._seq += 1
                timer.at, timer.seq, timer.fn, timer.args = self.now + delay, self._seq, fn, args
                return timer
            timer.fn = None
        return self.call_later(delay, fn, *args)          # which refuses a delay that is not whole us, >= 0

    def process(self, gen: ProcessGen, name: str = "process") -> Process:
        return Process(self, gen, name)

    def signal(self) -> Signal:
        return Signal(self)

    def every(self, period: int, tick: Callable[..., None], phase: int = 0, args: tuple = ()) -> Cyclic:
        """Run `tick(*args)` every `period` us starting at now + phase."""
        if period <= 0:
            raise SimulationError(f"period must be positive, got {period} us")
        cyc = Cyclic(period, tick, self.now + phase, args=args)
        self._cyclics.append(cyc)
        cyc.timer = self.call_at(cyc.next_at, self._cyclic_tick, cyc)
        return cyc

    def metronome(self, period: int, tick: Callable[..., None], phase: int = 0, args: tuple = ()) -> Cyclic:
        """A free-running emitter: `tick(*args)` every `period` us from now + phase, after everything else
        due at that instant (metronomes among themselves in the order they were registered). A tick may
        read the model and write the trace, never read the trace, change the model or schedule anything (bulk.py
        runs a skipped stretch's ticks before the stretch's trace is in place): then its ticks
        are a function of time alone while the rest is steady, and its period stays out of the model's
        steady period (bulk.py regenerates its ticks over a skipped stretch; run_metronomes)."""
        if period <= 0:
            raise SimulationError(f"period must be positive, got {period} us")
        cyc = Cyclic(period, tick, self.now + phase, args=args, rank=len(self._metronomes))
        self._metronomes.append(cyc)
        self._schedule_metronome(cyc)
        return cyc

    def _schedule_metronome(self, cyc: Cyclic) -> None:
        timer = Timer(cyc.next_at, FREE, cyc.rank, self._metronome_tick, (cyc,))
        heapq.heappush(self._heap, (cyc.next_at, FREE, cyc.rank, timer))
        cyc.timer = timer

    def _metronome_tick(self, cyc: Cyclic) -> None:
        # Its timer, just popped and run, is the next tick's (as in _cyclic_tick)
        cyc.next_at += cyc.period
        timer = cyc.timer
        timer.at, timer.fn = cyc.next_at, self._metronome_tick
        heapq.heappush(self._heap, (cyc.next_at, FREE, cyc.rank, timer))
        cyc.tick(*cyc.args)

    def run_metronomes(self, until: int) -> None:
        """Run only the metronomes' ticks due up to `until`, as `run` would have run them, and leave every
        other timer where it is; `now` is back where it was afterwards. For bulk.py, which puts the rest of
        the model `until - now` further on by itself."""
        start, due = self.now, []
        for cyc in self._metronomes:
            if cyc.next_at <= until:
                cyc.timer.cancel()
                heapq.heappush(due, (cyc.next_at, cyc.rank, cyc))
        try:
            while due:
                at, rank, cyc = heapq.heappop(due)
                self.now = at
                cyc.next_at += cyc.period
                cyc.tick(*cyc.args)
                if cyc.next_at <= until:
                    heapq.heappush(due, (cyc.next_at, rank, cyc))
                else:
                    self._schedule_metronome(cyc)
        finally:
            self.now = start

    def skip_metronomes(self, until: int) -> None:
        """Put every metronome on its first tick after `until`, running none (a soak's skipped stretch has
        no trace)."""
        for cyc in self._metronomes:
            if cyc.next_at <= until:
                cyc.timer.cancel()
                cyc.next_at += (until - cyc.next_at) // cyc.period * cyc.period + cyc.period
                self._schedule_metronome(cyc)

    def periods(self) -> list[int]:
        """The periods of the cyclic activities (metronomes are not part of the model's steady period)."""
        return [c.period for c in self._cyclics]

    def stop_cyclic(self, cyc: Cyclic) -> None:
        if cyc.timer is not None:
            cyc.timer.cancel()
            cyc.timer = None
        if cyc in self._cyclics:
            self._cyclics.remove(cyc)

    def _cyclic_tick(self, cyc: Cyclic) -> None:
        # The timer that just ran is the next tick's: its heap entry is gone (popped), so it is put back with
        # the key call_at would give a new one. Only here: a timer cancelled elsewhere may still have an entry.
        cyc.next_at += cyc.period
        self._seq += 1
        timer = cyc.timer
        timer.at, timer.seq, timer.fn = cyc.next_at, self._seq, self._cyclic_tick
        heapq.heappush(self._heap, (cyc.next_at, NORMAL, self._seq, timer))
        cyc.tick(*cyc.args)

    # -- running --------------------------------------------------------------------------------
    def peek(self) -> int | None:
        """Time of the next pending callback, or None."""
        heap = self._heap
        self._hand_out()
        while heap and (heap[0][3].fn is None or heap[0][3].seq != heap[0][2]):
            timer = heapq.heappop(heap)[3]
            if timer.fn is not None:                 # put off since its entry was made: at its new time
                heapq.heappush(heap, (timer.at, timer.prio, timer.seq, timer))
        return heap[0][0] if heap else None

    def run(self, until: int) -> None:
        """Run every callback due at or before `until`, then set now = until. Resumable."""
        if until < self.now:
            raise SimulationError(f"cannot run back in time to {until} us (now {self.now} us)")
        heap = self._heap
        pop = heapq.heappop
        ran = 0                                      # counted here, not on self: once per callback
        try:
            while heap and heap[0][0] <= until:
                entry = pop(heap)
                if len(entry) == 5:                  # schedule(): the callback itself
                    self.now = entry[0]
                    ran += 1
                    entry[3](*entry[4])
                    continue
                at, _prio, seq, timer = entry
                fn = timer.fn
                if fn is None:
                    continue
                if timer.seq != seq:                 # put off since (put_off): back in at its new time
                    heapq.heappush(heap, (timer.at, timer.prio, timer.seq, timer))
                    continue
                timer.fn = None
                self.now = at
                ran += 1
                fn(*timer.args)
        finally:
            self.events += ran
        self.now = until

    def pending(self) -> Iterable[Timer]:
        self._hand_out()
        return (entry[3] for entry in self._heap if entry[3].fn is not None)

    def pending_model(self) -> Iterable[Timer]:
        """The live timers of the model proper: the metronomes' own are left out (bulk.py)."""
        self._hand_out()
        return (entry[3] for entry in self._heap if entry[3].fn is not None and entry[1] != FREE)

    def _hand_out(self) -> None:
        """Every entry of `schedule` made a Timer with its key, in place (the heap's order is the keys'), so
        that bulk.py can read and move it like any other."""
        heap = self._heap
        for i, entry in enumerate(heap):
            if len(entry) == 5:
                at, prio, seq, fn, args = entry
                heap[i] = (at, prio, seq, Timer(at, prio, seq, fn, args))

    def rebuild_heap(self) -> None:
        """After a bulk advance moved the timers' keys: the heap again, from the live timers only."""
        self._heap = [(t.at, t.prio, t.seq, t) for t in self.pending()]
        heapq.heapify(self._heap)
