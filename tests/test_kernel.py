"""The reference model's discrete-event kernel (sut/reference/kernel.py): ordering, cancellation, time,
processes, signals, interrupts, failures, periodic activities, and whole-model determinism."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sut.reference.kernel import LATE, NORMAL, URGENT, Interrupt, Kernel, SimulationError


@pytest.fixture
def k() -> Kernel:
    return Kernel()


# -- ordering -------------------------------------------------------------------------------------
def test_equal_time_callbacks_run_in_scheduling_order(k):
    log = []
    for i in range(50):
        k.call_at(100, log.append, i)
    k.run(100)
    assert log == list(range(50))


def test_order_is_time_then_priority_then_sequence(k):
    log = []
    k.call_at(20, log.append, "t20-urgent", prio=URGENT)
    k.call_at(10, log.append, "t10-late-1", prio=LATE)
    k.call_at(10, log.append, "t10-normal-1")
    k.call_at(10, log.append, "t10-urgent", prio=URGENT)
    k.call_at(10, log.append, "t10-normal-2", prio=NORMAL)
    k.call_at(10, log.append, "t10-late-2", prio=LATE)
    k.call_at(5, log.append, "t5-late", prio=LATE)
    k.run(100)
    assert log == ["t5-late", "t10-urgent", "t10-normal-1", "t10-normal-2", "t10-late-1", "t10-late-2",
                   "t20-urgent"]


@settings(deadline=None)
@given(st.lists(st.tuples(st.integers(0, 50), st.sampled_from([URGENT, NORMAL, LATE])), max_size=60))
def test_ordering_property(entries):
    k = Kernel()
    log = []
    for seq, (at, prio) in enumerate(entries):
        k.call_at(at, lambda a=at, p=prio, s=seq: log.append((a, p, s)), prio=prio)
    k.run(50)
    assert log == sorted(log)
    assert len(log) == len(entries)


def test_callback_scheduled_for_now_runs_after_those_already_due(k):
    log = []

    def first():
        log.append(("first", k.now))
        k.call_later(0, lambda: log.append(("later0", k.now)))

    k.call_at(10, first)
    k.call_at(10, lambda: log.append(("second", k.now)))
    k.run(10)
    assert log == [("first", 10), ("second", 10), ("later0", 10)]


# -- cancellation ---------------------------------------------------------------------------------
def test_cancelled_timers_never_run(k):
    log = []
    keep = k.call_at(10, log.append, "keep")
    drop = k.call_at(10, log.append, "drop")
    assert drop.pending
    drop.cancel()
    assert not drop.pending and keep.pending
    k.run(1_000)
    assert log == ["keep"]
    assert k.events == 1


def test_cancel_from_an_earlier_callback_at_the_same_time(k):
    log = []
    victim = k.call_at(10, log.append, "victim")
    k.call_at(10, victim.cancel, prio=URGENT)
    k.run(10)
    assert log == []


def test_cancel_after_run_is_harmless_and_peek_skips_cancelled(k):
    t1 = k.call_at(5, lambda: None)
    t2 = k.call_at(7, lambda: None)
    t1.cancel()
    assert k.peek() == 7
    assert list(k.pending()) == [t2]
    k.run(10)
    t2.cancel()
    assert k.peek() is None


# -- virtual time ---------------------------------------------------------------------------------
def test_run_until_is_resumable_and_sets_now(k):
    seen = []
    for at in (0, 10, 20, 30):
        k.call_at(at, lambda: seen.append(k.now))
    k.run(15)
    assert seen == [0, 10] and k.now == 15
    k.run(15)                       # running to now again is a no-op
    assert seen == [0, 10] and k.now == 15
    k.run(20)                       # events at exactly `until` run
    assert seen == [0, 10, 20] and k.now == 20
    k.run(1_000_000)
    assert seen == [0, 10, 20, 30] and k.now == 1_000_000


def test_run_on_an_empty_kernel_still_advances(k):
    k.run(12_345)
    assert k.now == 12_345


def test_cannot_run_back_in_time(k):
    k.run(100)
    with pytest.raises(SimulationError, match="back in time"):
        k.run(99)


def test_scheduling_in_the_past_raises(k):
    k.run(100)
    with pytest.raises(SimulationError, match="past"):
        k.call_at(99, lambda: None)
    with pytest.raises(SimulationError, match="past"):
        k.call_later(-1, lambda: None)
    k.call_at(100, lambda: None)    # now itself is fine


def test_a_time_that_is_not_whole_microseconds_is_refused_where_it_is_made(k):
    # carried on, a float time stops bulk.py (no state is ever steady) and a long run goes frame by frame
    with pytest.raises(SimulationError, match=r"delay of 2\.5 us: delays are whole us"):
        k.call_later(2.5, lambda: None)
    with pytest.raises(SimulationError, match=r"at 7\.0 us"):
        k.call_at(7.0, lambda: None)


# -- processes ------------------------------------------------------------------------------------
def test_process_yielding_ints_sleeps_exactly(k):
    wakes = []
    delays = [0, 1, 250, 9_750, 10_000, 3, 1_000_000]

    def proc():
        for d in delays:
            before = k.now
            yield d
            wakes.append(k.now - before)

    p = k.process(proc(), "sleeper")
    k.run(sum(delays) + 10)
    assert wakes == delays
    assert p.alive is False


def test_process_starts_at_creation_time(k):
    started = []
    k.run(500)

    def proc():
        started.append(k.now)
        yield 1

    k.process(proc(), "late-starter")
    k.run(500)
    assert started == [500]


def test_process_waiting_on_a_signal_resumes_when_fired(k):
    sig = k.signal()
    got = []

    def waiter(tag):
        value = yield sig
        got.append((tag, k.now, value))

    k.process(waiter("a"), "a")
    k.process(waiter("b"), "b")
    k.call_at(1_234, sig.fire, "light")
    k.run(1_233)
    assert got == []
    k.run(5_000)
    assert got == [("a", 1_234, "light"), ("b", 1_234, "light")]


def test_signal_is_not_latched_and_resumes_urgently(k):
    sig = k.signal()
    got = []

    def waiter():
        yield 8                     # not waiting yet when the first fire happens
        while True:
            value = yield sig
            got.append((k.now, value))

    k.process(waiter(), "w")
    k.call_at(5, sig.fire, 0)       # nobody waiting: lost, a Signal is not a latch
    k.call_at(10, sig.fire, 1)
    # The resume is URGENT, so it runs before this NORMAL callback at the same instant and the waiter
    # has re-armed in time to see the second fire too.
    k.call_at(10, sig.fire, 2)
    k.call_at(20, sig.fire, 3)
    k.run(100)
    assert got == [(10, 1), (10, 2), (20, 3)]


def test_yielding_something_else_is_an_error(k):
    def proc():
        yield 1.5

    process = k.process(proc(), "floaty")
    with pytest.raises(SimulationError, match="floaty"):
        k.run(10)
    assert process.alive is False


def test_interrupt_carries_its_cause_and_can_be_caught(k):
    log = []

    def proc():
        try:
            yield 1_000
            log.append("slept through")
        except Interrupt as exc:
            log.append(("interrupted", k.now, exc.cause))
        yield 50
        log.append(("after", k.now))

    p = k.process(proc(), "watchdog")
    k.call_at(300, p.interrupt, "power loss")
    k.run(5_000)
    assert log == [("interrupted", 300, "power loss"), ("after", 350)]
    assert p.alive is False


def test_uncaught_interrupt_ends_the_process_quietly(k):
    log = []

    def proc():
        yield 1_000
        log.append("never")

    p = k.process(proc(), "board")
    k.call_at(10, p.interrupt, "cut")
    k.run(5_000)
    assert log == [] and p.alive is False
    p.interrupt("again")            # interrupting a dead process is a no-op
    k.run(6_000)


def test_interrupt_cause_defaults_to_none():
    assert Interrupt().cause is None
    assert Interrupt("x").cause == "x"


def test_interrupt_while_waiting_on_a_signal(k):
    sig = k.signal()
    log = []

    def proc():
        try:
            yield sig
            log.append(("signal", k.now))
        except Interrupt as exc:
            log.append(("interrupted", k.now, exc.cause))
        yield 100
        log.append(("woke", k.now))
        yield 1_000
        log.append(("woke again", k.now))

    p = k.process(proc(), "waiter")
    k.call_at(10, p.interrupt, "power")
    k.call_at(50, sig.fire, "late light")
    k.run(5_000)
    # got: [("interrupted", 10, "power"), ("woke", 50), ("woke again", 110)]
    assert log == [("interrupted", 10, "power"), ("woke", 110), ("woke again", 1_110)]


def test_a_stale_signal_never_wakes_a_process_that_has_waited_as_often_again(k):
    """Wait numbers only grow: the signal a process waited on before an interrupt cannot wake it later, even
    once it has waited as many times again."""
    sig = k.signal()
    log = []

    def proc():
        for _ in range(3):
            yield 1
        try:
            yield sig
        except Interrupt:
            log.append(("interrupted", k.now))
        for _ in range(3):
            yield 100
        log.append(("done", k.now))

    p = k.process(proc(), "waiter")
    k.call_at(10, p.interrupt, "power")
    k.call_at(250, sig.fire)
    k.run(10_000)
    assert log == [("interrupted", 10), ("done", 310)]


def test_interrupt_before_the_process_has_started(k):
    log = []

    def proc():
        try:
            yield 100
            log.append(("slept", k.now))
        except Interrupt as exc:
            log.append(("interrupted", k.now, exc.cause))
        yield 300
        log.append(("woke", k.now))
        yield 1_000
        log.append(("woke again", k.now))

    p = k.process(proc(), "early")
    p.interrupt("at once")
    k.run(5_000)
    # got: [("interrupted", 0, "at once"), ("woke", 100), ("woke again", 300)]
    assert log == [("interrupted", 0, "at once"), ("woke", 300), ("woke again", 1_300)]


def test_kill_stops_a_sleeping_process(k):
    log = []

    def proc():
        yield 100
        log.append("ran")

    p = k.process(proc(), "victim")
    k.run(50)
    p.kill()
    k.run(500)
    assert log == [] and p.alive is False


def test_kill_before_the_process_has_started(k):
    # A board that loses power at the instant its process was made (make mutate seed 10: the process's timer
    # taken for pending before its first run made this kill fail).
    log = []

    def proc():
        log.append("started")
        yield 100
        log.append("ran")

    p = k.process(proc(), "stillborn")
    p.kill()
    k.run(500)
    assert log == [] and p.alive is False


def test_exception_in_a_process_surfaces_naming_the_process(k):
    def proc():
        yield 5
        raise KeyError("boom")

    process = k.process(proc(), "car3.CCU.sys1.TXC.sampler")
    with pytest.raises(SimulationError, match=r"car3\.CCU\.sys1\.TXC\.sampler.*t=5 us.*boom") as info:
        k.run(100)
    assert isinstance(info.value.__cause__, KeyError)
    assert process.alive is False


def test_negative_delay_is_an_error_naming_the_process(k):
    def proc():
        yield -1

    process = k.process(proc(), "backwards")
    with pytest.raises(SimulationError, match="backwards.*negative"):
        k.run(10)
    assert process.alive is False                  # a failed process is over, like one that raised


# -- periodic activities --------------------------------------------------------------------------
def test_every_ticks_at_exact_multiples_over_many_ticks(k):
    ticks = []
    k.every(250, lambda: ticks.append(k.now), phase=17)
    n = 100_000
    k.run(17 + 250 * (n - 1))
    assert len(ticks) == n
    assert ticks == list(range(17, 17 + 250 * n, 250))
    assert k.now == 17 + 250 * (n - 1)


def test_every_starts_now_by_default_and_can_stop(k):
    k.run(1_000)
    ticks = []
    cyc = k.every(10_000, lambda: ticks.append(k.now))
    k.run(31_000)
    assert ticks == [1_000, 11_000, 21_000, 31_000]
    k.stop_cyclic(cyc)
    k.run(100_000)
    assert ticks == [1_000, 11_000, 21_000, 31_000]


def test_every_can_stop_itself_from_its_tick(k):
    ticks = []
    cyc = None

    def tick():
        ticks.append(k.now)
        if len(ticks) == 3:
            k.stop_cyclic(cyc)

    cyc = k.every(7, tick)
    k.run(1_000)
    assert ticks == [0, 7, 14]


def test_every_rejects_non_positive_periods(k):
    for period in (0, -10):
        with pytest.raises(SimulationError, match="period"):
            k.every(period, lambda: None)


# -- metronomes: free-running emitters ----------------------------------------------------------------
def test_a_metronome_ticks_after_everything_else_due_at_its_instant_in_registration_order(k):
    log = []
    k.metronome(100, log.append, args=("m-slow",))           # registered first: first among metronomes
    k.metronome(50, log.append, args=("m-fast",))
    k.call_at(100, log.append, "late", prio=LATE)
    k.call_at(100, lambda: k.call_later(0, log.append, "scheduled at 100 for 100"))
    k.run(100)
    assert log == ["m-slow", "m-fast", "m-fast", "scheduled at 100 for 100", "late", "m-slow", "m-fast"]


def test_metronomes_are_not_in_the_periods_and_do_not_move_the_sequence(k):
    k.every(10, lambda: None)
    k.metronome(7, lambda: None)
    k.run(1_000)
    assert k.periods() == [10]
    assert all(timer.fn != k._metronome_tick for timer in k.pending_model())
    seq = k._seq
    k.run(1_010)
    assert k._seq - seq == 1           # the one cyclic tick; the metronome's ticks take no sequence number


def _metronome_kernel() -> tuple[Kernel, list]:
    k, log = Kernel(), []
    k.metronome(30, lambda: log.append(("a", k.now)), phase=5)
    k.metronome(45, lambda: log.append(("b", k.now)))
    k.every(20, lambda: None)
    return k, log


def test_running_the_metronomes_alone_gives_their_ticks_as_run_does():
    whole, by_run = _metronome_kernel()
    whole.run(1_000)
    alone, by_metronomes = _metronome_kernel()
    alone.run_metronomes(1_000)
    assert alone.now == 0 and by_metronomes == by_run
    whole.run(2_000)
    alone.run(2_000)                  # and from there on, the same again
    assert by_metronomes == by_run


def test_skipped_metronomes_go_on_from_their_next_tick():
    k, log = _metronome_kernel()
    k.skip_metronomes(1_000)
    k.run(1_100)
    assert log == [("a", 1_025), ("b", 1_035), ("a", 1_055), ("b", 1_080), ("a", 1_085)]


# -- the whole model ------------------------------------------------------------------------------
def _reference_trace_csv(us: int) -> tuple[str, int]:
    from sut.reference.crh2.backend import ReferenceTrain

    driver = ReferenceTrain()
    driver.insert_key(1)
    driver.power_on()
    driver.advance(us)
    return driver.trace.to_csv(), driver.train.kernel.events


def test_two_identical_reference_runs_give_identical_traces():
    first, events1 = _reference_trace_csv(3_000_000)
    second, events2 = _reference_trace_csv(3_000_000)
    assert events1 == events2 and events1 > 1_000
    assert first.count("\n") > 1_000, "the run should have produced a real trace"
    assert first == second


def test_an_interrupt_goes_ahead_of_ordinary_callbacks_due_at_the_same_instant(k):
    # A board losing power stops its process before anything else scheduled for that instant reaches it.
    log = []

    def proc():
        try:
            yield 1_000
        except Interrupt:
            log.append(("interrupted", k.now))

    p = k.process(proc(), "watchdog")

    def at_10():
        k.call_later(0, log.append, ("ordinary", 10))     # scheduled first, at the same instant
        p.interrupt("power loss")

    k.call_at(10, at_10)
    k.run(100)
    assert log == [("interrupted", 10), ("ordinary", 10)]


def test_a_cycle_stopped_before_its_first_tick_never_ticks(k):
    # A board switched off in the instant it was switched on: its periodic activity never runs.
    ticks = []
    cyc = k.every(100, lambda: ticks.append(k.now), phase=50)
    k.run(10)
    k.stop_cyclic(cyc)
    k.run(1_000)
    assert ticks == []


# -- put_off: a watchdog moved, not replaced ---------------------------------------------------------
_STEP = st.tuples(st.integers(0, 30),                                     # us to run first
                  st.sampled_from(["call", "rearm", "cancel", "peek", "schedule", "pending"]),
                  st.integers(0, 2),                                      # which watchdog
                  st.integers(0, 40),                                     # delay
                  st.sampled_from([URGENT, NORMAL, LATE]))


def _watchdog_run(program: list, lazy: bool) -> tuple[list, list, list]:
    """Lazy: put_off and schedule; else what they stand for, cancel-and-call_later and call_later."""
    k = Kernel()
    log: list = []
    dogs: list = [None, None, None]

    def rearm(i: int, delay: int) -> None:
        if lazy:
            dogs[i] = k.put_off(dogs[i], delay, fired, i)
        else:
            if dogs[i] is not None:
                dogs[i].cancel()
            dogs[i] = k.call_later(delay, fired, i)

    def fired(i: int) -> None:
        log.append((k.now, "dog", i))
        dogs[i] = None

    def tick(n: int, i: int, delay: int) -> None:
        log.append((k.now, "tick", n))
        rearm(i, delay)                   # as a status frame re-arms a node's token watchdog when it arrives

    peeks = []
    for n, (run, action, i, delay, prio) in enumerate(program):
        k.run(k.now + run)
        if action == "call":
            k.call_later(delay, tick, n, i, delay // 2 + 1, prio=prio)
        elif action == "rearm":
            rearm(i, delay)
        elif action == "cancel" and dogs[i] is not None:
            dogs[i].cancel()
            dogs[i] = None
        elif action == "peek":
            peeks.append(k.peek())
        elif action == "schedule":
            (k.schedule if lazy else k.call_later)(delay, tick, n, i, delay // 3 + 1)
        elif action == "pending":                      # bulk.py reads the pending timers: schedule's made then
            peeks.append(sorted((t.at, t.prio, t.seq) for t in k.pending()))
    k.run(k.now + 200)
    return log, peeks, sorted((t.at, t.prio, t.seq) for t in k.pending())


@settings(max_examples=300, deadline=None)
@given(st.lists(_STEP, max_size=40))
def test_a_timer_put_off_fires_as_a_cancelled_and_rescheduled_one_would(program):
    """put_off moves a pending watchdog instead of cancelling it and scheduling another; the kernel pops its old
    entry and puts it back at its new time. schedule keeps no Timer for a callback until the pending timers are
    asked for. Whatever else is due at the same instants, from whichever priority, and however often a watchdog
    is put off, cancelled or peeked at, or the pending timers read, every callback runs when and in the order
    cancel-and-reschedule and call_later run it, and the same timers with the same keys are left pending."""
    assert _watchdog_run(program, lazy=True) == _watchdog_run(program, lazy=False)


def test_put_off_keeps_one_entry_per_watchdog_in_the_heap(k):
    fired = []
    dog = None
    for t in range(0, 5000, 10):
        k.run(t)
        dog = k.put_off(dog, 500, fired.append, "dog")
    assert len(k._heap) == 1 and dog.at == 4990 + 500 and not fired
    k.run(6000)
    assert fired == ["dog"] and not k._heap
    with pytest.raises(SimulationError, match="whole us"):
        k.put_off(None, 1.5, fired.append, "dog")
