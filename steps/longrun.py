"""Long runs: continuous power-on for hours of train time (TST-02), judged by counters and samples.

A backend may skip steady traffic (TrainDriver.soak); it then says so in the trace with one `time.skip`
event per skipped stretch (fields `frm`, `to`). Checks over the whole run use the node counters, which
count skipped traffic too; checks of timing use the observed stretches only, and demand one per sample.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import pytest
from pytest_bdd import parsers, then, when

from sut.contract import catalogue
from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from sut.errors import SutError
from sut.trace import Trace
from steps.analysis import lcus, ms, record_event, us
from steps import budgets
from steps.budgets import budgeted

HOUR_US = 3_600_000_000


@dataclass
class LongRun:
    start_us: int | None = None
    end_us: int = 0
    sample_every_us: int | None = None
    before: dict[str, dict[str, int]] = field(default_factory=dict)
    after: dict[str, dict[str, int]] = field(default_factory=dict)
    counted: bool = True          # whether the profile's nodes keep counters to compare over the run

    def delta(self, node: str, counter: str) -> int:
        return self.after[node][counter] - self.before[node][counter]

    @property
    def span_us(self) -> int:
        assert self.start_us is not None, "no long run happened (a When step must run the train for hours)"
        return self.end_us - self.start_us


@pytest.fixture
def long_run(request: pytest.FixtureRequest) -> LongRun:
    run = LongRun()
    # Node counters exist where the scenario's profile's contract lists them (a ring's nodes); a metro TCN has
    # none, and its SUT need not even answer ring_nodes() (sut/contract/metro-tcn.yaml).
    profiles = [str(arg) for mark in request.node.iter_markers("profile") for arg in mark.args]
    contracts = [catalogue.load(p) for p in profiles]
    run.counted = not contracts or any(c is None or "counters" in c.methods for c in contracts)
    return run


def _counters(sut: TrainDriver, run: LongRun) -> dict[str, dict[str, int]]:
    if not run.counted:
        return {}
    try:
        nodes = sut.ring_nodes()
    except SutError:
        return {}                 # the ATP on its test rig: no ring, no node counters to compare
    return {node: sut.counters(node) for node in nodes}


def hours_us(hours: float) -> int:
    if hours <= 0:
        raise ValueError(f"a run of {hours:g} h: give a positive number of hours")
    return round(hours * HOUR_US)


@when(parsers.parse("列车连续运行{hours:g} h,每{every:g} h采样一个稳态时段"), target_fixture="t_action")
@when(parsers.parse("the train runs for {hours:g} h, sampled for one steady period every {every:g} h"),
      target_fixture="t_action")
def _(sut: TrainDriver, long_run: LongRun, hours: float, every: float) -> int:
    _run(sut, long_run, hours_us(hours), hours_us(every))
    return sut.now_us


@when(parsers.parse("列车连续运行{hours:g} h"), target_fixture="t_action")
@when(parsers.parse("the train runs for {hours:g} h"), target_fixture="t_action")
def _(sut: TrainDriver, long_run: LongRun, hours: float) -> int:
    _run(sut, long_run, hours_us(hours), long_run.sample_every_us)
    return sut.now_us


@when(parsers.parse("列车运行至上电后{hours:g} h,每{every:g} h采样一个稳态时段"), target_fixture="t_action")
@when(parsers.parse("the train runs until {hours:g} h after power-up, sampled for one steady period every "
                    "{every:g} h"), target_fixture="t_action")
def _(sut: TrainDriver, long_run: LongRun, hours: float, every: float) -> int:
    _run(sut, long_run, _until(sut, hours), hours_us(every))
    return sut.now_us


@when(parsers.parse("列车运行至上电后{hours:g} h"), target_fixture="t_action")
@when(parsers.parse("the train runs until {hours:g} h after power-up"), target_fixture="t_action")
def _(sut: TrainDriver, long_run: LongRun, hours: float) -> int:
    _run(sut, long_run, _until(sut, hours), long_run.sample_every_us)
    return sut.now_us


def _until(sut: TrainDriver, hours: float) -> int:
    target = hours_us(hours)
    if target <= sut.now_us:
        raise ValueError(f"the train is already {sut.now_us / HOUR_US:g} h after power-up, past {hours:g} h")
    return target - sut.now_us


def _run(sut: TrainDriver, run: LongRun, span: int, every: int | None) -> None:
    if run.start_us is None:
        run.start_us, run.before, run.sample_every_us = sut.now_us, _counters(sut, run), every
    sut.soak(span, sample_every_us=every)
    run.end_us, run.after = sut.now_us, _counters(sut, run)


# -- what the trace observed -----------------------------------------------------------------------
def skips(trace: Trace) -> list[tuple[int, int]]:
    return [(ev["frm"], ev["to"]) for ev in trace.select(kind="time.skip")]


def stretches(trace: Trace, start: int, end: int) -> list[tuple[int, int]]:
    """The parts of start..end that the trace observed (everything but the skips)."""
    out, at = [], start
    for frm, to in sorted(skips(trace)):
        if to <= start or frm >= end:
            continue
        if frm > at:
            out.append((at, frm))
        at = max(at, to)
    if at < end:
        out.append((at, end))
    return out


# -- whole-run checks from the counters ------------------------------------------------------------
@then("运行期间没有节点进行令牌初始化")
@then("no node initialised the token during the run")
def _(sut: TrainDriver, long_run: LongRun) -> None:
    _ = long_run.span_us
    again = {n: long_run.delta(n, "token initialisations") for n in long_run.after
             if long_run.delta(n, "token initialisations")}
    assert not again, f"token initialisations during the run: {again}"


@then("运行期间没有节点丢弃帧")
@then("no node discarded a frame during the run")
def _(sut: TrainDriver, long_run: LongRun) -> None:
    _ = long_run.span_us
    bad = {n: long_run.delta(n, "frames discarded") for n in long_run.after if long_run.delta(n, "frames discarded")}
    assert not bad, f"frames discarded during the run: {bad}"


@then(parsers.parse("整个运行期间每个节点每{lo:g}至{hi:g} ms发送一次状态数据"))
@then(parsers.parse("every node sent status data once every {lo:g} to {hi:g} ms over the whole run"))
def _(sut: TrainDriver, long_run: LongRun, lo: float, hi: float) -> None:
    _expect_count(long_run, "status sent", lo, hi, "sent status data")


@then(parsers.parse("整个运行期间每个节点每{lo:g}至{hi:g} ms收到一次令牌"))
@then(parsers.parse("every node received the token once every {lo:g} to {hi:g} ms over the whole run"))
def _(sut: TrainDriver, long_run: LongRun, lo: float, hi: float) -> None:
    _expect_count(long_run, "tokens received", lo, hi, "received the token")


def _expect_count(run: LongRun, counter: str, lo: float, hi: float, what: str) -> None:
    """Each node's `counter` grew as a cycle of lo..hi ms allows over the whole run."""
    span = run.span_us
    fewest, most = span // us(hi), -(-span // us(lo)) + 1
    for node in run.after:
        got = run.delta(node, counter)
        assert fewest <= got <= most, (
            f"{node} {what} {got} times in {span / HOUR_US:g} h: a cycle of {lo:g}..{hi:g} ms gives {fewest}..{most}")


@then(parsers.parse('每个LCU都收到了"{ccu}"在运行期间发出的每条命令'))
@then(parsers.parse('every LCU received every command "{ccu}" sent during the run'))
def _(sut: TrainDriver, long_run: LongRun, ccu: str) -> None:
    sent = long_run.delta(ccu, "commands sent")
    # PRO-01 gives a 10 ms minimum interval and no rate: this floor (one a second) only keeps the check from
    # passing on a run without commands; what is checked is that no LCU missed one.
    assert sent >= long_run.span_us // us(1000), f"{ccu} sent only {sent} commands in the run"
    for lcu in lcus(sut):
        got = long_run.delta(lcu, "commands received")
        # one command may be on its way at either end of the run
        assert abs(got - sent) <= 1, f"{lcu} received {got} of the {sent} commands {ccu} sent"


@then(parsers.parse("每个LCU的时钟与上电以来的时间相差不超过{bound:g} ms"))
@then(parsers.parse("the clock of every LCU reads the time since power-up within {bound:g} ms"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, long_run: LongRun, bound: float) -> None:
    """PRO-01 carries the clock correction on the commands: an LCU's clock is as old as the last correction it
    took, so the bound is a budget of the same kind as a command's way (docs/decisions.md, "Reaction-time
    budgets"), with the SUT's declared margin."""
    _ = long_run.span_us
    now_ms = sut.now_us / 1000
    limit = budgets.window_us(declaration, bound) / 1000
    for lcu in lcus(sut):
        clock = sut.counters(lcu)["clock ms"]
        assert abs(clock - now_ms) <= limit, (
            f"{lcu} clock reads {clock} ms at {now_ms:.0f} ms since power-up ({(now_ms - clock) / 1000:+.3f} s)")


# -- timing in the samples -------------------------------------------------------------------------
@then(parsers.parse("每个采样时段内,{cab:d}号司机室监视器每{lo:g}至{hi:g} ms收到其他每个节点的状态数据"))
@then(parsers.parse("in every sample the cab {cab:d} monitor receives status data from every other node "
                    "every {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, long_run: LongRun, cab: int, lo: float, hi: float) -> None:
    trace = sut.trace
    observed = stretches(trace, long_run.start_us if long_run.start_us is not None else 0, long_run.end_us)
    every = long_run.sample_every_us or long_run.span_us
    assert len(observed) >= long_run.span_us // every, (
        f"the trace observed {len(observed)} stretches of the {long_run.span_us / HOUR_US:g} h run; one sample "
        f"every {every / HOUR_US:g} h needs {long_run.span_us // every}")
    monitor = f"car{cab}.monitor"
    fed_by = sut.monitor(cab)["fed_by"]      # the node feeding the monitor; every other node's status reaches it
    for a, b in observed:
        by_node: dict[str, list[int]] = {}
        for ev in trace.select(kind="status.rx", source=monitor, since=a, until=b):
            by_node.setdefault(ev["frm"], []).append(ev.t)
        for node in sut.ring_nodes():
            if node == fed_by:
                continue
            times = by_node.get(node, [])
            assert len(times) >= 3, f"sample {ms(a)}..{ms(b)}: only {len(times)} status frames from {node}"
            gaps = [y - x for x, y in zip(times, times[1:])]
            assert us(lo) <= min(gaps) and max(gaps) <= us(hi), (
                f"sample {ms(a)}..{ms(b)}: status data from {node} every {ms(min(gaps))}..{ms(max(gaps))}, "
                f"outside {lo:g}..{hi:g} ms")


# -- the recorder ----------------------------------------------------------------------------------
@then(parsers.parse('"{master}"按时间先后保存以下故障记录,每条的时间戳误差不超过{bound:g} ms:'))
@then(parsers.parse('"{master}" holds these fault records, oldest first, each stamped within {bound:g} ms:'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, master: str, bound: float,
      datatable: list[list[str]]) -> None:
    header, *rows = datatable
    want = [dict(zip(header, row)) for row in rows]
    held = []
    for node, records in sut.block_store(master).items():
        for record in records:
            text = record.rstrip(b"\0").decode("ascii", "replace")
            if text.startswith("F|"):
                _, t_ms, owner, board, event = text.split("|")
                held.append((int(t_ms), owner, board, event))
    held.sort()
    assert len(held) == len(want), f"{master} holds {len(held)} fault records, expected {len(want)}: {held}"
    for (t_ms, owner, board, event), row in zip(held, want):
        at_ms = float(row["at h"]) * HOUR_US / 1000
        word = record_event(declaration, row["event"])          # in the SUT's declared words
        assert (owner, board, event) == (row["node"], row["board"], word), (
            f"record {t_ms} ms {owner} {board} {event} where {row} was expected")
        assert at_ms <= t_ms <= at_ms + bound, (
            f"record of {owner} {board} {event} stamped {t_ms} ms, the {event} happened at {at_ms:.0f} ms")


# -- the counters against the trace: what the long-run checks stand on -----------------------------------
# Event kinds that each count one per event at a node, by the counter that counts them and the part of the
# node that emits them (sut/contract/crh2.yaml: token.rx from `<node>.MDM8`, status.tx from `<node>.CPU3`).
COUNTED_EVENTS = {"tokens received": ("token.rx", ".MDM"), "status sent": ("status.tx", ".CPU"),
                  "token initialisations": ("token.init", ".MDM")}


@then("每个节点的令牌、状态数据和令牌初始化计数与上电以来的记录一致")
@then("every node's counts of token visits, status data and token initialisations agree with the trace since power-up")
def _(sut: TrainDriver, declaration: ProfileDeclaration) -> None:
    """The long runs judge the token and the status cycle by the node counters (TST-02): a counter must count
    what the node did. Read after a plain advance from power-up (the whole trace is owed), each counter lies
    between the events logged up to one time step (the declared timing resolution) before now and those up
    to now: a node may count an event at the instant it logs it or within that step."""
    trace = sut.trace
    assert not skips(trace), "a skipped stretch: the trace does not hold every event since power-up"
    now, step = sut.now_us, declaration.parameter("timing_resolution_us")
    logged = {kind: trace.select(kind=kind) for kind, _part in COUNTED_EVENTS.values()}
    wrong = []
    for node in sut.ring_nodes():
        counters = sut.counters(node)
        for counter, (kind, part) in COUNTED_EVENTS.items():
            times = [ev.t for ev in logged[kind] if ev.source.startswith(node + part)]
            lo, hi = sum(t <= now - step for t in times), len(times)
            if not lo <= counters[counter] <= hi:
                wrong.append(f"{node} {counter} {counters[counter]}, its trace shows {lo}..{hi} {kind}")
    assert not wrong, "counters that do not count what the trace shows: " + "; ".join(wrong[:6])
