"""Step sentences added for the extra_records features (see steps/__init__.py): the function-class items
on mileage, service equipment, device interfaces, data recording, maintenance and diagnosis.

Watching the cab monitor: what the monitor shows as faults is a snapshot (`sut.monitor(cab)["faults"]`),
not a trace event, so "shows it within N ms" needs the monitor looked at while time passes. The When step
"the cab N monitor is watched for M ms" lets the time pass in 1 ms steps and notes what was shown at each
step; the Then steps read those notes. Several watches in one scenario add up (same cab). The monitor's fault
texts and its maintenance view are read in the SUT's declared words (steps/messages.py).
"""
from __future__ import annotations

from typing import Any, Callable, Iterable

import pytest
from pytest_bdd import parsers, then, when

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, messages, zh
from steps.analysis import ms, us

WATCH_STEP_US = 1000


# -- watching the cab monitor -------------------------------------------------------------------------
@pytest.fixture
def monitor_watch() -> dict[str, Any] | None:
    """What a watched cab monitor showed: {'cab': n, 'samples': [(t_us, (fault, ...)), ...]}; None if the
    scenario watched nothing."""
    return None


def _watched(watch: dict[str, Any] | None, cab: int) -> list[tuple[int, tuple[str, ...]]]:
    assert watch is not None, "nobody watched the cab monitor (When the cab N monitor is watched for M ms)"
    assert watch["cab"] == cab, f"the cab {watch['cab']} monitor was watched, not the cab {cab} monitor"
    assert watch["samples"], "the watch saw nothing"
    return watch["samples"]


@when(parsers.parse("持续观察{cab:d}号司机室监视器{span:d} ms"), target_fixture="monitor_watch")
@when(parsers.parse("the cab {cab:d} monitor is watched for {span:d} ms"), target_fixture="monitor_watch")
def _(sut: TrainDriver, monitor_watch: dict[str, Any] | None, cab: int, span: int) -> dict[str, Any]:
    if monitor_watch is not None and monitor_watch["cab"] == cab:
        samples = list(monitor_watch["samples"])
    else:
        samples = []
    samples.extend((t, tuple(faults)) for t, faults in sut.watch_monitor(cab, us(span), WATCH_STEP_US))
    return {"cab": cab, "samples": samples}


# The fault texts watched are read in the SUT's own words: the feature names a message of the form
# (sut/contract/form.yaml, crh2 texts, view faults) and the SUT's declaration words it (steps/messages.py).
def _fault(declaration: ProfileDeclaration, text: str) -> tuple[Callable[[Iterable[str]], bool], str]:
    """(does a fault text shown say the feature's `text`, how to say it in a failure message)."""
    pattern, said = messages.message(declaration, text, "faults")
    return (lambda shown: any(pattern.fullmatch(f) for f in shown)), said


@then(parsers.parse('{cab:d}号司机室监视器在{bound:g} ms内显示出"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor showed "{text}" within {bound:g} ms'))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, t_action: int, cab: int, text: str,
      bound: float) -> None:
    """Measured from the last action; if the text was already shown when the watch began, the watch's
    start counts as the moment it appeared (an upper bound of the delay)."""
    says, said = _fault(declaration, text)
    samples = [(t, shown) for t, shown in _watched(monitor_watch, cab) if t >= t_action]
    hit = next((t for t, shown in samples if says(shown)), None)
    assert hit is not None, (f"the cab {cab} monitor never showed {said} in {ms(samples[-1][0] - t_action)}; "
                             f"it showed {sorted({f for _, shown in samples for f in shown}) or 'no faults'}")
    assert hit - t_action <= us(bound), f"{said} was shown {ms(hit - t_action)} after the action, limit {bound} ms"


@then(parsers.parse('{cab:d}号司机室监视器在{bound:g} ms内不再显示"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor stopped showing "{text}" within {bound:g} ms'))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, t_action: int, cab: int, text: str,
      bound: float) -> None:
    says, said = _fault(declaration, text)
    samples = [(t, shown) for t, shown in _watched(monitor_watch, cab) if t >= t_action]
    assert samples and not says(samples[-1][1]), f"the cab {cab} monitor still shows {said}"
    shown_at = [t for t, shown in samples if says(shown)]
    gone = t_action if not shown_at else next(t for t, shown in samples if t > shown_at[-1])
    assert gone - t_action <= us(bound), f"{said} was shown until {ms(gone - t_action)} after the action, limit {bound} ms"


@then(parsers.parse('{cab:d}号司机室监视器始终未显示"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor never showed "{text}"'))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    says, said = _fault(declaration, text)
    shown_at = [t for t, shown in _watched(monitor_watch, cab) if says(shown)]
    assert not shown_at, f"the cab {cab} monitor showed {said} at {ms(shown_at[0])}"


@then(parsers.parse("{cab:d}号司机室监视器始终未显示任何故障"))
@then(parsers.parse("the cab {cab:d} monitor never showed a fault"))
def _(monitor_watch: dict[str, Any] | None, cab: int) -> None:
    odd = [(t, shown) for t, shown in _watched(monitor_watch, cab) if shown]
    assert not odd, f"the cab {cab} monitor showed {list(odd[0][1])} at {ms(odd[0][0])}"


@then(parsers.parse('{cab:d}号司机室监视器除"{text}"外始终未显示任何故障'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor never showed a fault but "{text}"'))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    """Nothing is blamed that is not so: a monitor that has heard a node but holds none of its status fields
    yet (its own CPU3 was down when they came) shows no fault for that node's ports or boards."""
    says, said = _fault(declaration, text)
    odd = [(t, [f for f in shown if not says([f])]) for t, shown in _watched(monitor_watch, cab)]
    odd = [(t, others) for t, others in odd if others]
    assert not odd, f"the cab {cab} monitor showed {odd[0][1]} at {ms(odd[0][0])} (only {said} may be shown)"


@then(parsers.parse("{cab:d}号司机室监视器除令牌重新生成期间的短暂静默外未显示任何故障,"
                    "每次静默在{bound:g} ms内结束"))
@then(parsers.parse("the cab {cab:d} monitor showed no fault but the silences of a token regeneration, "
                    "each over within {bound:g} ms"))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, cab: int, bound: float) -> None:
    """A frame damaged on the fibre may be the token; PRO-05 then regenerates it, and nodes are silent for a
    little longer than the monitor's status limit. That is the protocol recovering, so the only faults
    allowed are "no status data" alarms (in the SUT's declared words), and each spell of them must end within
    `bound` ms."""
    silent, _ = messages.message(declaration, "no status data from <node>", "faults")
    samples = _watched(monitor_watch, cab)
    others = sorted({f for _, shown in samples for f in shown if not silent.fullmatch(f)})
    assert not others, f"the cab {cab} monitor showed {others}"
    began = None
    for t, shown in samples + [(samples[-1][0], ())]:
        if shown and began is None:
            began = t
        elif not shown and began is not None:
            assert t - began <= us(bound), f"nodes were shown silent from {ms(began)} for {ms(t - began)}, limit {bound} ms"
            began = None
    assert not samples[-1][1], f"the cab {cab} monitor still shows {list(samples[-1][1])}"


@then(parsers.parse('{cab:d}号司机室监视器除"{text}"外未显示任何故障'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor showed no fault but "{text}"'))
def _(monitor_watch: dict[str, Any] | None, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, _ = messages.message(declaration, text, "faults")      # in the SUT's declared words
    others = sorted({f for _, shown in _watched(monitor_watch, cab) for f in shown if not pattern.fullmatch(f)})
    assert not others, f"the cab {cab} monitor also showed {others}"


@then(parsers.parse('{cab:d}号司机室监视器不显示"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor does not show "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    says, said = _fault(declaration, text)
    faults = sut.monitor(cab)["faults"]
    assert not says(faults), f"the cab {cab} monitor shows {said}"


# -- vehicle-level interfaces (NET-09) ------------------------------------------------------------------
def _hdlc_polls(sut: TrainDriver, devices: list[str], since: int, lo: float, hi: float) -> None:
    assert devices, "no CI or BCU to check"
    for device in devices:
        times = [ev.t for ev in sut.trace.select(kind="cmd.in", source=device, since=since, path=1)]
        analysis.expect_period(times, lo, hi, f"{device} polled over HDLC since {ms(since)}")


@then(parsers.parse("每个CI和BCU每{lo:g}至{hi:g} ms经HDLC被轮询一次"))
@then(parsers.parse("every CI and BCU is polled over HDLC every {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, t_action: int, lo: float, hi: float) -> None:
    _hdlc_polls(sut, analysis.command_devices(sut), t_action, lo, hi)


@then(parsers.parse("{car:d}号车以外的每个CI和BCU每{lo:g}至{hi:g} ms经HDLC被轮询一次"))
@then(parsers.parse("every CI and BCU outside car {car:d} is polled over HDLC every {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, t_action: int, car: int, lo: float, hi: float) -> None:
    others = [d for d in analysis.command_devices(sut) if not d.startswith(f"car{car}.")]
    _hdlc_polls(sut, others, t_action, lo, hi)


@then(parsers.parse("{car:d}号车未装设{device:w}"))
@then(parsers.parse("car {car:d} has no {device:w}"))
def _(sut: TrainDriver, car: int, device: str) -> None:
    got = sut.devices(car)
    assert f"car{car}.{device}" not in got, f"car {car} has a {device}: {sorted(got)}"


@then(parsers.parse("每辆车的{device:w}每{lo:g}至{hi:g} ms被轮询一次"))
@then(parsers.parse("the {device:w} of every car is polled every {lo:g} to {hi:g} ms"))
def _(sut: TrainDriver, t_action: int, device: str, lo: float, hi: float) -> None:
    _every_car_polls(sut, t_action, device, lo, hi, "polled")


def _every_car_polls(sut: TrainDriver, t_action: int, device: str, lo: float, hi: float, what: str) -> None:
    """The device of every car answers every poll since the action, its polls lo..hi ms apart."""
    for car in analysis.cars(sut):
        name = f"car{car}.{device}"
        assert name in sut.devices(car), f"car {car} has no {device}: {sorted(sut.devices(car))}"
        polls = sut.trace.select(kind="loop.poll", source=name, since=t_action)
        unanswered = [ev for ev in polls if not ev["reply"]]
        assert not unanswered, f"{name} did not answer: {analysis.describe(unanswered)}"
        analysis.expect_period((ev.t for ev in polls), lo, hi, f"{name} {what}")


# NET-09: "polled, periods per device" and no figures: each device's period is the SUT's, declared (IXIT).
_LOOP_PERIODS = {"ACS": "acs_poll_period_ms", "PID": "pid_poll_period_ms", "APU": "apu_poll_period_ms",
                 "SDD": "sdd_send_period_ms", "DD": "dd_report_period_ms"}


def _declared_period(declaration: ProfileDeclaration, device: str) -> tuple[float, float]:
    """lo, hi in ms: the period the SUT declares for this kind of current-loop device, within its declared
    tolerance (per cent of the period) and timing resolution."""
    kind = device.rsplit(".", 1)[-1]
    assert kind in _LOOP_PERIODS, f"{device} is not a current-loop device with a declared period"
    period = declaration.parameter(_LOOP_PERIODS[kind])
    slack = period * declaration.parameter("loop_period_tolerance_pct") / 100 \
        + declaration.parameter("timing_resolution_us") / 1000
    return period - slack, period + slack


@then(parsers.parse("每辆车的{device:w}按其声明的周期被轮询"))
@then(parsers.parse("the {device:w} of every car is polled at its declared period"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, device: str) -> None:
    lo, hi = _declared_period(declaration, device)
    _every_car_polls(sut, t_action, device, lo, hi, "polled (declared period)")


@then(parsers.parse('"{device}"按其声明的周期被轮询'))
@then(parsers.parse('"{device}" is polled at its declared period'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, device: str) -> None:
    lo, hi = _declared_period(declaration, device)
    polls = sut.trace.select(kind="loop.poll", source=device, since=t_action)
    analysis.expect_period((ev.t for ev in polls), lo, hi, f"{device} polled (declared period)")


@then(parsers.parse('"{device}"只接收其LCU发来的数据,按其声明的周期'))
@then(parsers.parse('"{device}" only receives from its LCU, at its declared period'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, device: str) -> None:
    _one_way(sut, t_action, device, "loop.send", *_declared_period(declaration, device))


@then(parsers.parse('"{device}"只向其LCU发送数据,按其声明的周期'))
@then(parsers.parse('"{device}" only sends to its LCU, at its declared period'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, device: str) -> None:
    _one_way(sut, t_action, device, "loop.report", *_declared_period(declaration, device))


@then(parsers.parse('"{device}"接在{milliamps:d} mA电流环上'))
@then(parsers.parse('"{device}" is on a {milliamps:d} mA current loop'))
def _(sut: TrainDriver, t_action: int, device: str, milliamps: int) -> None:
    loops = {ev["loop"] for ev in sut.trace.select(kind="loop.*", source=device, since=t_action)}
    assert loops, f"nothing went over {device}'s current loop"
    assert loops == {f"{milliamps}mA"}, f"{device} is on a {', '.join(sorted(loops))} loop, not {milliamps} mA"


@then(parsers.parse('"{device}"接在20 mA或30 mA电流环上'))
@then(parsers.parse('"{device}" is on a 20 mA or a 30 mA current loop'))
def _(sut: TrainDriver, t_action: int, device: str) -> None:
    # NET-09 names the two loops and leaves which one a simple device uses open.
    loops = {ev.get("loop") for ev in sut.trace.select(kind="loop.*", source=device, since=t_action)}
    assert loops, f"nothing went over {device}'s current loop"
    assert loops <= {"20mA", "30mA"}, f"{device} is on {loops}, not a 20 mA or 30 mA loop"


def _one_way(sut: TrainDriver, since: int, device: str, kind: str, lo: float, hi: float) -> None:
    events = sut.trace.select(kind="loop.*", source=device, since=since)
    assert events, f"nothing went over {device}'s current loop"
    wrong = [ev for ev in events if ev.kind != kind or ev["reply"]]
    assert not wrong, f"{device} is not one-way ({kind}): {analysis.describe(wrong)}"
    analysis.expect_period((ev.t for ev in events), lo, hi, f"transfers with {device}")


@then(parsers.parse('"{device}"只接收其LCU发来的数据,每{lo:g}至{hi:g} ms一次'))
@then(parsers.parse('"{device}" only receives from its LCU, every {lo:g} to {hi:g} ms'))
def _(sut: TrainDriver, t_action: int, device: str, lo: float, hi: float) -> None:
    _one_way(sut, t_action, device, "loop.send", lo, hi)


@then(parsers.parse('"{device}"只向其LCU发送数据,每{lo:g}至{hi:g} ms一次'))
@then(parsers.parse('"{device}" only sends to its LCU, every {lo:g} to {hi:g} ms'))
def _(sut: TrainDriver, t_action: int, device: str, lo: float, hi: float) -> None:
    _one_way(sut, t_action, device, "loop.report", lo, hi)


# -- fault records and the maintenance view -------------------------------------------------------------
def _fault_records(sut: TrainDriver, master: str, node: str) -> list[list[str]]:
    """Fault records `F|<t ms>|<node>|<board>|<event>` of `node` held at `master` (docs/decisions.md)."""
    texts = [r.rstrip(b"\0").decode("ascii", "replace") for r in sut.block_store(master).get(node, [])]
    return [t.split("|") for t in texts if t.startswith("F|")]


def _records_saying(sut: TrainDriver, declaration: ProfileDeclaration, master: str, node: str, board: str,
                    event: str) -> list[list[str]]:
    """Those of them saying `board` `event` (failed, recovered: in the SUT's declared words)."""
    word = analysis.record_event(declaration, event)
    return [r for r in _fault_records(sut, master, node) if r[3:] == [board, word]]


@then(parsers.parse('"{master}"保存有"{node}"的{count:d}条故障记录'))
@then(parsers.parse('"{master}" holds {count:d} fault record(s) of "{node}"'))
def _(sut: TrainDriver, master: str, count: int, node: str) -> None:
    records = _fault_records(sut, master, node)
    assert len(records) == count, f"{master} holds {len(records)} fault records of {node}: {records}"


@then(parsers.parse('"{master}"保存有"{node}"关于"{board}"{event:w}的故障记录,其时间戳与该事件相差'
                    '不超过{bound:g} ms'), converters={"event": zh.core_event})
@then(parsers.parse('"{master}" holds a fault record of "{node}" saying "{board}" {event:w}, stamped within '
                    '{bound:g} ms of it'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, master: str, node: str, board: str,
      event: str, bound: float) -> None:
    records = _records_saying(sut, declaration, master, node, board, event)
    assert records, f"{master} holds no record of {node} saying {board} {event}: {_fault_records(sut, master, node)}"
    stamp_us = int(records[-1][1]) * 1000              # whole milliseconds
    assert t_action - 1000 < stamp_us <= t_action + us(bound), (
        f"the record is stamped {records[-1][1]} ms; the {event} happened at {ms(t_action)} (limit {bound} ms)")


# A record is looked for every RECORD_LOOK_US while its bound runs: a fault campaign's row waits only as long as
# its record takes (a few token rounds), not the whole bound (up to seconds under a double fault).
RECORD_LOOK_US = 10_000


@then(parsers.parse('"{master}"在该事件后{bound:g} ms内保存有"{node}"关于"{board}"{event:w}的故障记录'),
      converters={"event": zh.core_event})
@then(parsers.parse('"{master}" holds a fault record of "{node}" saying "{board}" {event:w} at most {bound:g} ms '
                    'after it'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, master: str, node: str, board: str,
      event: str, bound: float) -> None:
    deadline = t_action + us(bound)
    if sut.now_us > deadline:
        raise AssertionError(f"the step comes {ms(sut.now_us - deadline)} after its bound: when the record came "
                             f"cannot be told any more (look before {bound:g} ms have passed)")
    while True:
        if _records_saying(sut, declaration, master, node, board, event):
            return
        if sut.now_us >= deadline:
            raise AssertionError(f"{ms(deadline - t_action)} after the {event} {master} holds no record of {node} "
                                 f"saying {board} {event}: {_fault_records(sut, master, node)}")
        sut.advance(min(RECORD_LOOK_US, deadline - sut.now_us))


@then(parsers.parse("{cab:d}号司机室的检修画面共有{count:d}行"))
@then(parsers.parse("the maintenance view of cab {cab:d} holds {count:d} line(s)"))
def _(sut: TrainDriver, cab: int, count: int) -> None:
    history = sut.monitor(cab)["maintenance"]
    assert len(history) == count, f"the maintenance view of cab {cab} holds {len(history)} lines: {history}"


@then(parsers.parse('{cab:d}号司机室的检修画面未列出"{text}"'), converters={"text": zh.crh2_record})
@then(parsers.parse('the maintenance view of cab {cab:d} does not list "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = messages.message(declaration, text, "maintenance")     # in the SUT's declared words
    history = sut.monitor(cab)["maintenance"]
    odd = [line for line in history if pattern.search(line)]
    assert not odd, f"the maintenance view of cab {cab} lists {said}: {odd}"
