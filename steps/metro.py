"""Steps of the metro TCN profile (TCN-01..10, RED-04..07): WTB and MVB, their masters and lines, the I/O
modules, records and the display. Bus traffic is read from the trace as a bus analyser logs it:
`wtb.msg` / `mvb.msg` per poll (master, polled node or port, the line it came on, lost or not), and with an
analyser attached `bus.frame` (each frame's body in hex), decoded here with the suite's own IEC 61375-3-1
codec (sut/codecs/mvb.py), never with the SUT's. What the displays and records say is read in the SUT's own
words: the features name a message identifier of the form (sut/contract/form.yaml, metro-tcn texts), with
names filled in, and the SUT's declaration says how it words that message (any language).
"""
from __future__ import annotations

import re
from typing import Callable

from pytest_bdd import given, parsers, then, when

from sut.codecs import mvb
from sut.contract.declaration import PLACEHOLDER, ProfileDeclaration
from sut.driver import TrainDriver
from steps import messages, zh
from steps import analysis
from steps.analysis import describe, intervals, ms, us

WTB_CYCLE_US = 25_000          # TCN-03: the WTB's maximum cycle


def _sinks(sut: TrainDriver, kind: str) -> list[str]:
    found = [d for car in range(1, 7) for d in sut.devices(car) if d.endswith(f".{kind}")]
    assert found, f"the train has no {kind}"
    return found


def _polls(sut: TrainDriver, bus: str, since: int) -> list:
    kind = "wtb.msg" if bus == "WTB" else "mvb.msg"
    return sut.trace.select(kind=kind, source=bus, since=since)


def _messages() -> list[str]:
    return messages.identifiers("metro-tcn")


def _mode(declaration: ProfileDeclaration, mode: str) -> str:
    """What the SUT's display shows for the mode the feature names (its message identifier)."""
    if mode not in _messages() or PLACEHOLDER.search(mode):
        raise ValueError(f"the mode {mode!r} is no message identifier of the metro-tcn form (sut/contract/form.yaml)")
    return declaration.text(mode)


def _message(declaration: ProfileDeclaration, text: str) -> tuple[re.Pattern, str]:
    """How to find the feature's `text` in a display entry or a record line in the SUT's own words
    (steps/messages.py): the pattern to search for and how to say it in a message."""
    return messages.message(declaration, text)


# -- composition and desk -------------------------------------------------------------------------
@given("一列装有列车控制与诊断系统的6辆编组地铁列车")
@given("a 6-car metro train with its train control and diagnosis system")
def _(sut: TrainDriver) -> None:
    sut.configure(sets=1, cars_per_set=6)


@given(parsers.parse("{cab:d}号司机室的司控器处于{pct:d} %牵引位"))
@given(parsers.parse("the master controller of cab {cab:d} demands {pct:d} % traction"))
@when(parsers.parse("司机将{cab:d}号司机室的司控器移到{pct:d} %牵引位"), target_fixture="t_action")
@when(parsers.parse("the driver moves the master controller of cab {cab:d} to {pct:d} % traction"),
      target_fixture="t_action")
def _(sut: TrainDriver, cab: int, pct: int) -> int:
    sut.set_brake(cab, 0)
    sut.set_traction(cab, pct)
    return sut.now_us


@when(parsers.parse("司机将{cab:d}号司机室的司控器移到{pct:d} %制动位"), target_fixture="t_action")
@when(parsers.parse("the driver moves the master controller of cab {cab:d} to {pct:d} % brake"),
      target_fixture="t_action")
def _(sut: TrainDriver, cab: int, pct: int) -> int:
    sut.set_traction(cab, 0)
    sut.set_brake(cab, pct)
    return sut.now_us


@when(parsers.parse("司机将紧急运行开关置于{position}位"), converters={"position": zh.metro_switch},
      target_fixture="t_action")
@when(parsers.parse("the driver turns the emergency-operation switch {position:w}"), target_fixture="t_action")
def _(sut: TrainDriver, position: str) -> int:
    if position not in ("on", "off"):
        raise ValueError(f"the emergency-operation switch is turned on or off, not {position!r}")
    sut.set_input("emergency operation", position == "on")
    return sut.now_us


# -- faults ---------------------------------------------------------------------------------------
@when(parsers.parse('{units}同时故障'), target_fixture="t_action")
@when(parsers.parse('{units} fail together'), target_fixture="t_action")
def _(sut: TrainDriver, units: str) -> int:
    for unit in analysis.quoted_names(units):
        sut.fail(unit)
    return sut.now_us


# How many polls in a row a node (WTB) or a device (its unit's MVB status polls) may leave unanswered before
# it is recorded as silent: the SUT's declared counts (form: wtb_silent_polls, status_silent_polls), else the
# contract's documented 3. The articles give none (docs/decisions.md).
SILENT_POLLS = 3
STATUS_POLL_BOUND_US = 1_000_000    # only to stop a step waiting for a poll that never comes: TCN-04 gives no period


def _silent_for(sut: TrainDriver, name: str, count: int, polls_since: Callable[[int], list],
                answered: Callable[[object], bool], cycle_us: int, what: str) -> int:
    """Fail `name` just after a poll it answered and repair it just after its `count`-th unanswered one, so the
    silence spans exactly that many polls whatever the cycle; it must answer the next poll again, or the scenario
    would test a longer silence than it says. The instant it failed."""
    assert count >= 0, f"{name} cannot leave {count} {what} unanswered"

    def run_until(t: int, want: bool, n: int) -> None:
        deadline = sut.now_us + (n + 1) * cycle_us + us(5)
        while len([p for p in polls_since(t) if answered(p) == want]) < n:
            assert sut.now_us < deadline, f"{name}: {n} {'answered' if want else 'unanswered'} {what} expected " \
                                          f"since {ms(t)}, saw {describe(polls_since(t))}"
            sut.advance_ms(1)

    run_until(sut.now_us, True, 1)
    t_fail = sut.now_us
    sut.fail(name)
    run_until(t_fail, False, count)
    sut.repair(name)
    t_repair = sut.now_us
    run_until(t_repair, True, 1)
    # Counted from the failure, not the repair: the last unanswered poll may share the repair's instant.
    missed = [p for p in polls_since(t_fail) if not answered(p)]
    assert len(missed) == count, f"{name} did not answer its {what} at once after its repair at " \
                                 f"{ms(t_repair)}: {len(missed)} unanswered, not {count}: {describe(missed)}"
    return t_fail


@when(parsers.re(r'"(?P<node>[^"]+)"对WTB轮询连续不应答声明的次数(?:减(?P<less>\d+)次)?'), target_fixture="t_action")
@when(parsers.re(r'"(?P<node>[^"]+)" leaves the declared count of WTB polls unanswered(?: less (?P<less>\d+))?'),
      target_fixture="t_action")
def _(sut: TrainDriver, declaration: ProfileDeclaration, node: str, less: str | None) -> int:
    count = declaration.parameters.get("wtb_silent_polls", SILENT_POLLS) - int(less or 0)
    return _silent_for(sut, node, count,
                       lambda t: sut.trace.select(kind="wtb.msg", source="WTB", since=t, polled=node),
                       lambda p: p["answered"], WTB_CYCLE_US, "WTB polls")


@when(parsers.re(r'"(?P<device>[^"]+)"对状态轮询连续不应答声明的次数(?:减(?P<less>\d+)次)?'), target_fixture="t_action")
@when(parsers.re(r'"(?P<device>[^"]+)" leaves the declared count of status polls unanswered(?: less (?P<less>\d+))?'),
      target_fixture="t_action")
def _(sut: TrainDriver, declaration: ProfileDeclaration, device: str, less: str | None) -> int:
    # Its status polls are told by the address the master polls it at (the SUT's own address plan), read off a
    # poll it answered (F_code 15, device status: TCN-04, TCN-06).
    count = declaration.parameters.get("status_silent_polls", SILENT_POLLS) - int(less or 0)
    status = sut.trace.select(kind="mvb.msg", f_code=15, responder=device)
    assert status, f"no MVB master has polled {device} for its status and had an answer"
    address, bus = status[-1]["address"], status[-1].source
    return _silent_for(sut, device, count,
                       lambda t: sut.trace.select(kind="mvb.msg", source=bus, since=t, f_code=15, address=address),
                       lambda p: p["responder"] == device, STATUS_POLL_BOUND_US, "status polls")


@given(parsers.parse('"{bus}"的线路{line:w}已被切断'))
@given(parsers.parse('line {line:w} of "{bus}" is cut'))
@when(parsers.parse('"{bus}"的线路{line:w}被切断'), target_fixture="t_action")
@when(parsers.parse('line {line:w} of "{bus}" is cut'), target_fixture="t_action")
def _(sut: TrainDriver, line: str, bus: str) -> int:
    sut.cut_line(bus, line)
    return sut.now_us


@when(parsers.parse('"{bus}"的线路{line:w}恢复'), target_fixture="t_action")
@when(parsers.parse('line {line:w} of "{bus}" is restored'), target_fixture="t_action")
def _(sut: TrainDriver, line: str, bus: str) -> int:
    sut.restore_line(bus, line)
    return sut.now_us


@when(parsers.parse('"{bus}"的线路{line:w}上接下来的{count:d}帧受到干扰'), target_fixture="t_action")
@when(parsers.parse('the next {count:d} frames on line {line:w} of "{bus}" are disturbed'), target_fixture="t_action")
def _(sut: TrainDriver, count: int, line: str, bus: str) -> int:
    sut.disturb_line(bus, line, count)
    return sut.now_us


@when(parsers.parse('"{bus}"的两条线路上接下来的{count:d}帧都受到干扰'), target_fixture="t_action")
@when(parsers.parse('the next {count:d} frames on both lines of "{bus}" are disturbed'), target_fixture="t_action")
def _(sut: TrainDriver, count: int, bus: str) -> int:
    for line in "AB":
        sut.disturb_line(bus, line, count)
    return sut.now_us


@given(parsers.parse('"{module}"的输入{channel:w}因接线故障恒为{value:d}'))
@given(parsers.parse('a wiring fault holds input {channel:w} of "{module}" at {value:d}'))
@when(parsers.parse('发生接线故障,使"{module}"的输入{channel:w}恒为{value:d}'), target_fixture="t_action")
@when(parsers.parse('a wiring fault comes to hold input {channel:w} of "{module}" at {value:d}'),
      target_fixture="t_action")
def _(sut: TrainDriver, channel: str, module: str, value: int) -> int:
    sut.set_input(f"{module}.{channel}", value)
    return sut.now_us


# The cab inputs by what they carry (TCN-07 gives only the channel counts): the channel and the raw count from the
# SUT's declared I/O map (form: traction_demand_ai, forward_di, demand_full_scale), else the contract's documented
# one (AI1 traction, DI02 forward, 10000 counts for 100 %).
IO_MAP = {"traction_demand_ai": 1, "brake_demand_ai": 2, "forward_di": 2, "demand_full_scale": 10_000}


def _io(declaration: ProfileDeclaration, name: str) -> int:
    return declaration.parameters.get(name, IO_MAP[name])


@given(parsers.parse('"{module}"的牵引指令输入因接线故障恒为{pct:d} %'))
@given(parsers.parse('a wiring fault holds the traction demand input of "{module}" at {pct:d} %'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, module: str, pct: int) -> None:
    raw = pct * _io(declaration, "demand_full_scale")
    assert raw % 100 == 0, f"{pct} % is no whole count of the declared full scale {raw / pct:g}"
    sut.set_input(f"{module}.AI{_io(declaration, 'traction_demand_ai')}", raw // 100)


@given(parsers.parse('"{module}"的向前输入因接线故障恒为{value:d}'))
@given(parsers.parse('a wiring fault holds the forward input of "{module}" at {value:d}'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, module: str, value: int) -> None:
    sut.set_input(f"{module}.DI{_io(declaration, 'forward_di'):02d}", value)


@given(parsers.parse('在总线"{bus}"上接入分析仪'))
@given(parsers.parse('an analyser is attached to "{bus}"'))
def _(sut: TrainDriver, bus: str) -> None:
    sut.tap_bus(bus)


# -- masters ------------------------------------------------------------------------------------------
@then(parsers.parse('"{node}"在{bound:g} ms内成为WTB主站并一直保持'))
@then(parsers.parse('"{node}" is the WTB master within {bound:g} ms and stays so'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, node: str, bound: float) -> None:
    polls = _polls(sut, "WTB", t_action)
    first = next((p for p in polls if p["master"] == node), None)
    assert first is not None, f"{node} sent no WTB master frame after {ms(t_action)}; masters seen: " \
                              f"{sorted({p['master'] for p in polls}) or 'none'}"
    tick = declaration.parameter("timing_resolution_us")      # every bound +- the declared resolution
    assert first.t - t_action <= us(bound) + tick, \
        f"{node} became WTB master after {ms(first.t - t_action)}, > {bound} ms"
    others = [p for p in polls if p.t >= first.t and p["master"] != node]
    assert not others, f"after {node} took over, others sent WTB master frames: {describe(others)}"
    # Still master now: a master polls within every WTB cycle, at most 25 ms (TCN-03), +- the declared resolution.
    quiet = sut.now_us - polls[-1].t
    assert quiet <= WTB_CYCLE_US + tick, \
        f"{node} stopped sending WTB master frames at {ms(polls[-1].t)} ({ms(quiet)} before the end, > 25 ms)"


@then(parsers.parse('{nodes}均不发出WTB主帧'))
@then(parsers.parse('no WTB master frame comes from {nodes}'))
def _(sut: TrainDriver, t_action: int, nodes: str) -> None:
    banned = set(analysis.quoted_names(nodes))
    bad = [p for p in sut.trace.select(kind="wtb.msg", source="WTB") if p["master"] in banned]
    assert not bad, f"WTB master frames from {sorted({p['master'] for p in bad})}: {describe(bad)}"


@then(parsers.parse("WTB通信在{bound:g} ms内中止"))
@then(parsers.parse("the WTB falls silent within {bound:g} ms"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, bound: float) -> None:
    late = _polls(sut, "WTB", t_action + us(bound) + declaration.parameter("timing_resolution_us") + 1)
    assert not late, f"the WTB still carries frames {bound} ms after the fault: {describe(late)}"


@then(parsers.parse("WTB主站至少每{bound:g} ms轮询每个节点一次"))
@then(parsers.parse("the WTB master polls every node at least every {bound:g} ms"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, bound: float) -> None:
    # Every node of the train (the CCUs and VCUs devices(car) names) but the master itself: whether a master
    # polls itself on the wire is its own affair (the WTB carries its own telegram either way).
    polls = _polls(sut, "WTB", t_action)
    masters = {p["master"] for p in polls}
    nodes = sorted(d for car in range(1, 7) for d in sut.devices(car) if d.endswith((".CCU", ".VCU")))
    polled = {p["polled"] for p in polls}
    missing = [n for n in nodes if n not in polled and n not in masters]
    assert not missing, f"the WTB master never polled {missing}"
    for node in sorted(polled):
        times = [p.t for p in polls if p["polled"] == node]
        assert len(times) >= 3, f"{node} polled only {len(times)} times"
        worst = max(intervals([t_action, *times, sut.now_us]))
        assert worst <= us(bound) + declaration.parameter("timing_resolution_us"), \
            f"{node} went {ms(worst)} without a WTB poll (bound {bound} ms)"


@then(parsers.parse('"{node}"在{bound:g} ms内成为"{bus}"的主站并一直保持'))
@then(parsers.parse('"{node}" is the master of "{bus}" within {bound:g} ms and stays so'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, node: str, bus: str, bound: float) -> None:
    polls = _polls(sut, bus, t_action)
    first = next((p for p in polls if p["master"] == node), None)
    assert first is not None, f"{node} sent no master frame on {bus}; masters seen: " \
                              f"{sorted({p['master'] for p in polls}) or 'none'}"
    assert first.t - t_action <= us(bound) + declaration.parameter("timing_resolution_us"), \
        f"{node} became master of {bus} after {ms(first.t - t_action)}"
    others = [p for p in polls if p.t >= first.t and p["master"] != node]
    assert not others, f"after {node} took {bus}, others polled it: {describe(others)}"


@then(parsers.parse('"{node}"在"{bus}"上发出的主帧间隔从不超过{bound:g} ms'))
@then(parsers.parse('the master frames of "{node}" on "{bus}" are never more than {bound:g} ms apart'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, node: str, bus: str, bound: float) -> None:
    times = [p.t for p in _polls(sut, bus, t_action) if p["master"] == node]
    assert len(times) >= 10, f"{node} sent only {len(times)} master frames on {bus}"
    worst = max(intervals([t_action, *times, sut.now_us]))
    assert worst <= us(bound) + declaration.parameter("timing_resolution_us"), \
        f"{node} left {bus} without a master frame for {ms(worst)} (bound {bound} ms)"


MVB_BIT_US = 1 / 1.5      # TCN-03: 1.5 Mbit/s


def _exchange_floor_us(poll) -> float:
    """The least time a poll holds its line: the master frame's bytes and, if a slave frame answered intact,
    its bytes (the suite's codec: TCN-05's layout, check sequences included), at 1.5 Mbit/s (TCN-03).
    Delimiters, the reply delay and the gap after are left out, so every conforming bus takes longer."""
    size = mvb.MASTER_FRAME_BYTES
    if poll["responder"] is not None and not mvb.is_reserved(poll["f_code"]):
        size += mvb.slave_frame_bytes(poll["f_code"])
    return 8 * size * MVB_BIT_US


@then(parsers.parse('"{bus}"上的报文互不重叠:每个主帧都在前一次交换的帧之后发出'))
@then(parsers.parse('the exchanges on "{bus}" never overlap: each master frame follows the frames of the one before'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, bus: str) -> None:
    """One MVB carries one frame at a time: a master frame cannot go on the bus before the exchange before it
    had time to pass, at its bit rate and frame layout (TCN-03, TCN-05)."""
    polls = _polls(sut, bus, t_action)
    assert len(polls) >= 10, f"only {len(polls)} master frames on {bus}"
    slack = declaration.parameter("timing_resolution_us")
    for before, after in zip(polls, polls[1:]):
        floor = _exchange_floor_us(before)
        assert after.t - before.t + slack >= floor, (
            f"a master frame (F_code {after['f_code']}) went on {bus} {after.t - before.t} us after the one before "
            f"(F_code {before['f_code']}, answered by {before['responder']}), which holds the line at least "
            f"{floor:.1f} us")


@then(parsers.parse('{cars}的每个设备都应答"{node}"在"{bus}"上发出的状态数据请求'))
@then(parsers.parse('every device of {cars} answers the status polls of "{node}" on "{bus}"'))
def _(sut: TrainDriver, t_action: int, cars: str, node: str, bus: str) -> None:
    polls = [p for p in _polls(sut, bus, t_action) if p["master"] == node and mvb.data_class(p["f_code"])
             is mvb.DataClass.SUPERVISORY]
    assert polls, f"{node} sent no device status request on {bus}"
    answered = {p["responder"] for p in polls if p["responder"]}
    # Every device the SUT lists in those cars answers (TCN-04), its control units and I/O modules may (they
    # are MVB devices too); nothing of another car does.
    listed = {d for c in map(int, re.findall(r"\d+", cars)) for d in sut.devices(c)}
    wanted = {d for d in listed if not d.endswith((".CCU", ".VCU", ".IO1", ".IO2"))}
    missing = wanted - answered
    assert not missing, f"no status data from {sorted(missing)} on {bus}"
    strangers = answered - listed
    assert not strangers, f"{bus} carries status data of devices of other cars: {sorted(strangers)}"


# -- lines (RED-06) -------------------------------------------------------------------------------------
@then(parsers.parse('"{bus}"上没有丢失任何报文'))
@then(parsers.parse('no message on "{bus}" is lost'))
def _(sut: TrainDriver, t_action: int, bus: str) -> None:
    _none_lost(sut, bus, t_action, at_least=10)


def _none_lost(sut: TrainDriver, bus: str, since: int, at_least: int) -> None:
    """At least `at_least` messages on `bus` from `since` on, none of them lost."""
    polls = _polls(sut, bus, since)
    assert len(polls) >= at_least, f"only {len(polls)} messages on {bus} since {ms(since)}"
    lost = [p for p in polls if p["lost"]]
    assert not lost, f"{len(lost)} of {len(polls)} messages on {bus} lost since {ms(since)}: {describe(lost)}"


@then(parsers.parse('"{bus}"上有报文丢失'))
@then(parsers.parse('a message on "{bus}" is lost'))
def _(sut: TrainDriver, t_action: int, bus: str) -> None:
    # The analyser's view of a frame that got through on neither line: the message is lost, not answered.
    polls = _polls(sut, bus, t_action)
    assert any(p["lost"] for p in polls), f"no message on {bus} lost since {ms(t_action)} ({len(polls)} polls)"


@then(parsers.parse('"{bus}"上自{after:g} ms起没有丢失任何报文'))
@then(parsers.parse('no message on "{bus}" is lost from {after:g} ms on'))
def _(sut: TrainDriver, t_action: int, bus: str, after: float) -> None:
    _none_lost(sut, bus, t_action + us(after), at_least=1)


@then(parsers.parse('"{bus}"上的接收端采用线路{line:w}'))
@then(parsers.parse('the receivers on "{bus}" take line {line:w}'))
def _(sut: TrainDriver, t_action: int, bus: str, line: str) -> None:
    polls = [p for p in _polls(sut, bus, t_action) if p["line"] is not None]
    assert polls, f"nothing came on {bus}"
    assert polls[-1]["line"] == line, f"the last frame on {bus} was taken from line {polls[-1]['line']}"


@then(parsers.parse('"{bus}"的线路{line:w}上校验失败的帧被丢弃'))
@then(parsers.parse('frames from line {line:w} of "{bus}" that fail their check are discarded'))
def _(sut: TrainDriver, t_action: int, line: str, bus: str) -> None:
    discards = sut.trace.select(kind="frame.discard", source=bus, since=t_action)
    assert any(d["error"].startswith(f"line {line}") for d in discards), \
        f"no discarded frame from line {line} of {bus}"


@then(parsers.parse('线路{line:w}上受干扰的{n:d}帧都被"{bus}"丢弃'))
@then(parsers.parse('all {n:d} disturbed frames from line {line:w} of "{bus}" are discarded'))
def _(sut: TrainDriver, t_action: int, n: int, line: str, bus: str) -> None:
    # Each frame the stimulus disturbed fails its check on that line: at least that many discards (a rig
    # may log one per receiver).
    discards = [d for d in sut.trace.select(kind="frame.discard", source=bus, since=t_action)
                if d["error"].startswith(f"line {line}")]
    assert len(discards) >= n, f"{len(discards)} frames from line {line} of {bus} discarded, {n} disturbed"


@then(parsers.parse('"{bus}"自{after:g} ms起不再丢弃线路{line:w}上的帧'))
@then(parsers.parse('no frame from line {line:w} of "{bus}" is discarded from {after:g} ms on'))
def _(sut: TrainDriver, t_action: int, line: str, bus: str, after: float) -> None:
    # A disturbance of some frames is over once they passed: the line carries intact frames again.
    discards = [d for d in sut.trace.select(kind="frame.discard", source=bus, since=t_action + us(after))
                if d["error"].startswith(f"line {line}")]
    assert not discards, f"line {line} of {bus} still loses frames {after:g} ms on: {describe(discards[:5])}"


@then(parsers.parse("WTB主站对{nodes}以外节点的每次轮询都得到应答"))
@then(parsers.parse("every WTB poll of a node other than {nodes} is answered"))
def _(sut: TrainDriver, t_action: int, nodes: str) -> None:
    # RED-04/RED-06: the WTB carries on without a loss while a node is down: every node still up answers every
    # poll (the failed node's own polls, unanswered, are no loss of a message: nothing was sent to lose).
    down = set(analysis.quoted_names(nodes))
    polls = [p for p in _polls(sut, "WTB", t_action) if p["polled"] not in down]
    silent = [p for p in polls if not p["answered"]]
    assert polls and not silent, f"{len(silent)} of {len(polls)} WTB polls unanswered: {describe(silent[:5])}"


@then("WTB主站的每次轮询都得到应答")
@then("every WTB poll is answered")
def _(sut: TrainDriver, t_action: int) -> None:
    polls = _polls(sut, "WTB", t_action)
    silent = [p for p in polls if not p["answered"]]
    assert polls and not silent, f"{len(silent)} of {len(polls)} WTB polls unanswered: {describe(silent[:5])}"


# -- traction and brake at the VVVF and BECU -----------------------------------------------------------
@then(parsers.parse("每个VVVF施加{pct:g} %牵引"))
@then(parsers.parse("every VVVF applies {pct:g} % traction"))
def _(sut: TrainDriver, pct: float) -> None:
    wrong = {d: _applied(sut, d, "traction") for d in _sinks(sut, "VVVF")}
    wrong = {d: v for d, v in wrong.items() if v != pct}
    assert not wrong, f"VVVF traction other than {pct} %: {wrong}"


@then(parsers.parse("每个BECU施加{pct:g} %制动"))
@then(parsers.parse("every BECU applies {pct:g} % brake"))
def _(sut: TrainDriver, pct: float) -> None:
    wrong = {d: _applied(sut, d, "brake") for d in _sinks(sut, "BECU")}
    wrong = {d: v for d, v in wrong.items() if v != pct}
    assert not wrong, f"BECU brake other than {pct} %: {wrong}"


@then(parsers.parse("每个VVVF在{bound:g} ms内施加{pct:g} %牵引"))
@then(parsers.parse("every VVVF applies {pct:g} % traction within {bound:g} ms"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, pct: float, bound: float) -> None:
    _reached(sut, "VVVF", pct, t_action, bound, declaration.parameter("timing_resolution_us"))


@then(parsers.parse("每个BECU在{bound:g} ms内施加{pct:g} %制动"))
@then(parsers.parse("every BECU applies {pct:g} % brake within {bound:g} ms"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, pct: float, bound: float) -> None:
    _reached(sut, "BECU", pct, t_action, bound, declaration.parameter("timing_resolution_us"))


def _applied(sut: TrainDriver, device: str, quantity: str) -> float:
    """What a device applies now, as its reading says and as its pd.change events say (the contract: the
    reading is the value of its last pd.change; before the first, nothing): the two must agree."""
    now = sut.reading(f"{device}.{quantity}")
    last = sut.trace.last(kind="pd.change", source=device)
    said = last["value"] if last is not None else 0
    assert now == said, (f"{device} reads {now} % {quantity}, but its pd.change events say {said} % "
                         f"({'the last at ' + ms(last.t) if last is not None else 'none yet'})")
    return now


def _reached(sut: TrainDriver, kind: str, pct: float, t_action: int, bound: float, tick: int) -> None:
    """Every device applies `pct` within `bound` ms of the action and still does. A bound on reaching a state
    holds when the state already held: a device that changed nothing since the action and applies `pct` now
    applied it throughout (the contract: a pd.change for every change of what it applies)."""
    quantity = "traction" if kind == "VVVF" else "brake"
    for device in _sinks(sut, kind):
        now = _applied(sut, device, quantity)
        change = sut.trace.first(kind="pd.change", source=device, since=t_action, value=pct)
        if change is None and now == pct and not sut.trace.select(kind="pd.change", source=device, since=t_action):
            continue
        assert change is not None, f"{device} never applied {pct} % {quantity} after {ms(t_action)}; it applies {now} %"
        assert change.t - t_action <= us(bound) + tick, f"{device} applied {pct} % after {ms(change.t - t_action)}"
        assert now == pct, f"{device} no longer applies {pct} % {quantity}"


@then("各VVVF和BECU施加的牵引、制动均保持不变")
@then("no VVVF or BECU changes what it applies")
def _(sut: TrainDriver, t_action: int) -> None:
    changes = [e for e in sut.trace.select(kind="pd.change", since=t_action)
               if e.source.endswith((".VVVF", ".BECU"))]
    assert not changes, f"traction or brake changed after {ms(t_action)}: {describe(changes)}"


# Fail-safety over the whole trace (the metro single-fault campaign, F-NET-34): what a VVVF or BECU applies is
# read from its `pd.change` events; before its first one a device applies nothing.
def _changes(sut: TrainDriver, kind: str, since: int | None = None, until: int | None = None) -> list:
    return [ev for device in _sinks(sut, kind)
            for ev in sut.trace.select(kind="pd.change", source=device, since=since, until=until)]


@then(parsers.parse("没有VVVF在任何时刻施加{a:g}或{b:g} %以外的牵引"))
@then(parsers.parse("no VVVF ever applies a traction other than {a:g} or {b:g} %"))
def _(sut: TrainDriver, a: float, b: float) -> None:
    # From power-up: a wrong or stale traction for one cycle is a wrong command.
    wrong = [ev for ev in _changes(sut, "VVVF") if ev["value"] not in (a, b)]
    assert not wrong, f"VVVF traction other than {a:g} or {b:g} %: {describe(wrong)}"


@then("没有VVVF在任何时刻于BECU制动时施加牵引")
@then("no VVVF ever pulls while a BECU brakes")
def _(sut: TrainDriver) -> None:
    # Instant by instant (a unit changes its VVVFs and BECUs at one instant, one after the other): traction
    # against an applied brake anywhere in the train is never commanded (docs/decisions.md, TCN-09: 0 % traction
    # and the brake go together).
    applied: dict[str, float] = {}
    events = sorted(_changes(sut, "VVVF") + _changes(sut, "BECU"), key=lambda ev: ev.t)
    for i, ev in enumerate(events):
        applied[ev.source] = ev["value"]
        if i + 1 < len(events) and events[i + 1].t == ev.t:
            continue
        pulling = sorted(d for d, v in applied.items() if v and d.endswith(".VVVF"))
        braking = sorted(d for d, v in applied.items() if v and d.endswith(".BECU"))
        assert not (pulling and braking), f"{ms(ev.t)}: {pulling} pull while {braking} brake"


@then("自故障起没有BECU施加制动")
@then("no BECU applies a brake from the fault on")
def _(sut: TrainDriver, t_action: int) -> None:
    # The train runs on (RED-05 "without restriction", RED-06 "without loss"): no BECU puts a brake on from the
    # fault on, and each ends released. A brake already on at the fault is not the fault's doing (a standstill
    # holding brake, an option a product may add, tests/freedom_metro.py): taking it off is a change to 0.
    for device in _sinks(sut, "BECU"):
        after = sut.trace.select(kind="pd.change", source=device, since=t_action)
        braked = [ev for ev in after if ev["value"]]
        assert not braked, f"{device} braked from {ms(t_action)} on: {describe(braked)}"
        now = _applied(sut, device, "brake")
        assert not now, f"{device} still applies {now} % brake {ms(sut.now_us - t_action)} after the fault"


@then("列车已停车")
@then("the train has come to a stop")
def _(sut: TrainDriver) -> None:
    assert sut.reading("speed") == 0, f"the train still runs at {sut.reading('speed')} km/h"


# -- records and the display ----------------------------------------------------------------------------
# The feature names a message (sut/contract/form.yaml, metro-tcn texts); the SUT's declaration says how its
# display and records word it (any language): `_message` and `_mode`.
@then(parsers.parse('"{unit}"保存有记录"{text}"'), converters={"text": zh.metro_text})
@then(parsers.parse('"{unit}" holds a record "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, unit: str, text: str) -> None:
    pattern, said = _message(declaration, text)
    records = sut.records(unit)
    assert any(pattern.search(r) for r in records), f"{unit} holds no record with {said}; it holds {records}"


@then(parsers.parse('"{unit}"没有保存记录"{text}"'), converters={"text": zh.metro_text})
@then(parsers.parse('"{unit}" holds no record "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, unit: str, text: str) -> None:
    pattern, said = _message(declaration, text)
    found = [r for r in sut.records(unit) if pattern.search(r)]
    assert not found, f"{unit} holds records with {said}: {found}"


@then(parsers.parse('"{unit}"中记录"{text}"恰好保存了一次'), converters={"text": zh.metro_text})
@then(parsers.parse('"{unit}" holds the record "{text}" exactly once'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, unit: str, text: str) -> None:
    pattern, said = _message(declaration, text)
    found = [r for r in sut.records(unit) if pattern.search(r)]
    assert len(found) == 1, f"{unit} holds {len(found)} records with {said}: {found}"


@then(parsers.parse('"{unit}"没有保存任何记录'))
@then(parsers.parse('"{unit}" holds no record'))
def _(sut: TrainDriver, unit: str) -> None:
    records = sut.records(unit)
    assert not records, f"{unit} stores records although it has no memory board: {records}"


@then(parsers.parse('{cab:d}号司机室的DU显示"{text}"'), converters={"text": zh.metro_text})
@then(parsers.parse('the cab {cab:d} display shows "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = _message(declaration, text)
    shown = sut.monitor(cab)
    assert any(pattern.search(f) for f in shown["faults"]), f"the cab {cab} display does not show {said}: {shown}"


@then(parsers.parse('{cab:d}号司机室的DU不显示"{text}"'), converters={"text": zh.metro_text})
@then(parsers.parse('the cab {cab:d} display does not show "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = _message(declaration, text)
    shown = sut.monitor(cab)
    assert not any(pattern.search(f) for f in shown["faults"]), f"the cab {cab} display shows {said}: {shown}"


@then(parsers.parse('{cab:d}号司机室的DU显示运行模式为"{mode}"'), converters={"mode": zh.metro_mode})
@then(parsers.parse('the cab {cab:d} display shows the mode "{mode}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, mode: str) -> None:
    words = _mode(declaration, mode)
    shown = sut.monitor(cab)
    said = repr(mode) if words == mode else f"{mode!r} (declared as {words!r})"
    assert shown["mode"] == words, f"the cab {cab} display shows mode {shown['mode']!r}, not {said}"


# -- frames on the wire (TCN-05, TCN-06, TCN-10) ----------------------------------------------------------
def _frames(sut: TrainDriver, bus: str, since: int) -> list[tuple[mvb.MasterFrame, mvb.SlaveFrame | None]]:
    """Pair each master frame with the slave frame that follows it, decoding both with the suite's codec."""
    out: list = []
    for ev in sut.trace.select(kind="bus.frame", source=bus, since=since):
        raw = bytes.fromhex(ev["hex"])
        if ev["type"] == "master":
            try:
                out.append([mvb.decode_master(raw), None])
            except mvb.MvbFrameError as exc:
                raise AssertionError(f"{ms(ev.t)}: a master frame on {bus} is not IEC 61375-3-1: {exc}") from None
        else:
            assert out and out[-1][1] is None, f"{ms(ev.t)}: a slave frame on {bus} without a master frame"
            assert not out[-1][0].reserved, (f"{ms(ev.t)}: a device on {bus} answered the reserved F_code "
                                             f"{out[-1][0].f_code} (a device ignores it)")
            size = mvb.slave_size_bits(out[-1][0].f_code)
            try:
                out[-1][1] = mvb.decode_slave(raw, size)
            except mvb.MvbFrameError as exc:
                raise AssertionError(f"{ms(ev.t)}: the {size}-bit slave frame answering F_code "
                                     f"{out[-1][0].f_code} on {bus} is not IEC 61375-3-1: {exc}") from None
    return [tuple(pair) for pair in out]


@then(parsers.parse('"{bus}"上的每一帧都能解码为符合IEC 61375-3-1的MVB帧,且长度与其F_code所要求的一致'))
@then(parsers.parse('every frame on "{bus}" decodes as an IEC 61375-3-1 MVB frame of the size its F_code asks'))
def _(sut: TrainDriver, t_action: int, bus: str) -> None:
    pairs = _frames(sut, bus, t_action)
    reserved = [m for m, _ in pairs if m.reserved]
    assert not reserved, f"the master on {bus} sent {len(reserved)} frames with a reserved F_code, first {reserved[0]}"
    # Each slave frame was decoded at the size its F_code asks, one of TCN-05's 16..256 bits: which ports a
    # product gives which size is its own layout.
    answered = [(m, s) for m, s in pairs if s is not None]
    assert len(answered) >= 20, f"only {len(answered)} answered master frames on {bus}"


@then(parsers.parse('"{bus}"上每个主帧都带着应答它的端口或设备的地址,每个设备一个地址'))
@then(parsers.parse('every master frame on "{bus}" carries the address of the port or device that answers it, '
                    'one address each'))
def _(sut: TrainDriver, t_action: int, bus: str) -> None:
    """The wire against the exchange (TCN-05): the master frame sent at a poll's instant carries the F_code
    and address of that poll, one port or device answers at each address, and each answers at one address
    per F_code. A SUT whose frames name the wrong port passes every decode check; this one it does not."""
    # The analyser logs one mvb.msg per master frame, in the order sent: the n-th master frame on the wire is
    # the n-th poll (paired by order, not by the stamps, which an analyser and a bus log need not share).
    wire = [mvb.decode_master(bytes.fromhex(ev["hex"]))
            for ev in sut.trace.select(kind="bus.frame", source=bus, since=t_action) if ev["type"] == "master"]
    logged = _polls(sut, bus, t_action)
    assert abs(len(wire) - len(logged)) <= 1, (f"{len(wire)} master frames on the wire of {bus} but {len(logged)} "
                                               f"polls logged since {ms(t_action)}")
    paired = list(zip(logged, wire))
    assert sum(1 for p, _ in paired if p["responder"]) >= 20, f"only a few answered polls on {bus}"
    at: dict[tuple[int, int], set[str]] = {}
    of: dict[tuple[str, int], set[int]] = {}
    for p, frame in paired:
        if not p["responder"]:
            continue
        assert (frame.f_code, frame.address) == (p["f_code"], p["address"]), (
            f"{ms(p.t)}: the poll of {p['responder']} (F_code {p['f_code']}, address {p['address']:#05x}) went "
            f"out as F_code {frame.f_code}, address {frame.address:#05x}")
        at.setdefault((frame.f_code, frame.address), set()).add(p["responder"])
        of.setdefault((p["responder"], frame.f_code), set()).add(frame.address)
    shared = {f"F_code {f} address {a:#05x}": sorted(r) for (f, a), r in at.items() if len(r) > 1}
    assert not shared, f"several answer at one address on {bus}: {shared}"
    several = {f"{r} (F_code {f})": sorted(map(hex, a)) for (r, f), a in of.items() if len(a) > 1}
    assert not several, f"some answer at several addresses on {bus}: {several}"


@then(parsers.parse('"{bus}"上的主帧请求{classes}'), converters={"classes": zh.metro_data_classes})
@then(parsers.parse('the master frames on "{bus}" ask for {classes}'))
def _(sut: TrainDriver, t_action: int, bus: str, classes: str) -> None:
    seen = {mvb.data_class(m.f_code).value for m, _ in _frames(sut, bus, t_action)}
    wanted = {c.strip() for c in re.split(r",| and ", classes) if c.strip()}
    assert wanted <= seen, f"{bus} carried {sorted(seen)}; missing {sorted(wanted - seen)}"


@then(parsers.parse('"{bus}"上的每个过程数据端口都以不超过{bound:g} ms的固定周期被轮询'))
@then(parsers.parse('every process-data port on "{bus}" is polled at one fixed period of at most {bound:g} ms'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, bus: str, bound: float) -> None:
    # Cyclic (TCN-06): each port in every n-th basic period of the master's schedule, so its polls are spaced
    # alike, give or take where in the 1 ms basic period (TCN-03) the poll falls and the declared resolution.
    spread = us(1) + 2 * declaration.parameter("timing_resolution_us")
    by_port: dict[tuple[int, int], list[int]] = {}
    for p in _polls(sut, bus, t_action):
        if mvb.data_class(p["f_code"]) is mvb.DataClass.PROCESS:
            by_port.setdefault((p["f_code"], p["address"]), []).append(p.t)
    assert by_port, f"no process data on {bus}"
    for (f_code, address), times in sorted(by_port.items()):
        gaps = intervals(times)
        assert len(gaps) >= 5, f"port {address:#05x} polled only {len(times)} times"
        assert max(gaps) - min(gaps) < spread, f"port {address:#05x} is not polled cyclically: gaps " \
                                                f"{ms(min(gaps))}..{ms(max(gaps))}"
        assert max(gaps) <= us(bound) + declaration.parameter("timing_resolution_us"), \
            f"port {address:#05x} polled every {ms(max(gaps))} (bound {bound} ms)"


@then(parsers.parse('{cab:d}号司机室的DU显示WTB主站为"{node}"'))
@then(parsers.parse('the cab {cab:d} display shows "{node}" as WTB master'))
def _(sut: TrainDriver, cab: int, node: str) -> None:
    shown = sut.monitor(cab)
    assert shown.get("WTB master") == node, f"the cab {cab} display shows WTB master {shown.get('WTB master')!r}"


@then(parsers.parse("{cab:d}号司机室的DU黑屏"))
@then(parsers.parse("the cab {cab:d} display is dark"))
def _(sut: TrainDriver, cab: int) -> None:
    # A dead DU shows nothing: no mode, no WTB master, no event (read with get: a driver need not list
    # what a dark screen does not show, nor say `blank`; one that says it must not say false).
    shown = sut.monitor(cab)
    lit = {k: shown.get(k) for k in ("mode", "WTB master") if shown.get(k) is not None}
    assert shown.get("blank") is not False and not shown.get("faults") and not lit, \
        f"the cab {cab} display shows {shown}"
