"""What happens to control commands: on the ring (PRO-01), at CI and BCU (CMD-02..04), at takeover (RED-02)."""
from __future__ import annotations

import statistics

from pytest_bdd import parsers, then

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, budgets
from steps.budgets import budgeted
from steps.analysis import ms, us


# -- on the ring ------------------------------------------------------------------------------------
@then(parsers.parse("每个LCU在每条命令发出后{bound:g} ms内收到该命令"))
@then(parsers.parse("every LCU receives every command within {bound:g} ms of its transmission"))
def _(sut: TrainDriver, t_action: int, bound: float) -> None:
    trace, limit = sut.trace, us(bound)
    sent = trace.select(kind="cmd.tx", since=t_action, until=sut.now_us - limit)
    assert sent, f"no command left a CCU between {ms(t_action)} and {ms(sut.now_us - limit)}"
    got = {(d.node, d.system, d.sent): d for d in analysis.command_deliveries(trace, since=t_action)}
    for tx in sent:
        for lcu in analysis.lcus(sut):
            d = got.get((lcu, tx["system"], tx.t))
            assert d is not None, f"command seq {tx['seq']} sent at {ms(tx.t)} never reached {lcu}"
            assert d.latency <= limit, (f"command seq {tx['seq']} reached {lcu} after {ms(d.latency)}, "
                                        f"more than {bound} ms")


@then(parsers.parse("命令经过的每个节点增加的延时不超过{bound:g} ms"))
@then(parsers.parse("each node on the way adds at most {bound:g} ms to a command"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, bound: float) -> None:
    """PRO-01's pass-through per node, measured between nodes: one command, one direction round the ring, the
    arrival at an LCU n spans further on is at most n x bound after the arrival at the nearer LCU. The time
    from the CCU's handover (cmd.tx) to the first LCU is left out: it holds the sender's wait for the line and
    its own transmission, which PRO-01 bounds with the 15 ms, not with the pass-through. Each arrival time is
    good to the SUT's declared timing resolution."""
    tick = declaration.parameter("timing_resolution_us")
    deliveries = analysis.command_deliveries(sut.trace, since=t_action)
    by_command: dict[tuple[int, int, str], list[analysis.Delivery]] = {}
    for d in deliveries:
        by_command.setdefault((d.system, d.sent, d.direction), []).append(d)
    pairs = []
    for way in by_command.values():
        way.sort(key=lambda d: d.hops)
        pairs += [(a, b) for a, b in zip(way, way[1:]) if b.hops > a.hops]
    assert pairs, "no command reached two LCUs one after the other to examine"
    worst = max(pairs, key=lambda p: (p[1].received - p[0].received) / (p[1].hops - p[0].hops))
    a, b = worst
    nodes = b.hops - a.hops
    added = b.received - a.received
    assert added <= nodes * us(bound) + tick, (
        f"command seq {b.seq} reached {a.node} at {ms(a.received)} and {b.node}, {nodes} node(s) further on, "
        f"at {ms(b.received)}: {ms(added // nodes)} per node, more than {bound} ms")


@then(parsers.parse("CCU发送命令的间隔不小于{bound:g} ms"))
@then(parsers.parse("commands leave the CCU at intervals of at least {bound:g} ms"))
def _(sut: TrainDriver, t_action: int, bound: float) -> None:
    by_node: dict[str, list[int]] = {}
    for ev in sut.trace.select(kind="cmd.tx", since=t_action):
        by_node.setdefault(ev.source, []).append(ev.t)
    assert by_node, "no commands were transmitted"
    for node, times in by_node.items():
        gaps = analysis.intervals(times)
        assert len(gaps) >= 5, f"{node} sent only {len(times)} commands"
        assert min(gaps) >= us(bound), f"{node} sent two commands {ms(min(gaps))} apart, less than {bound} ms"


@then(parsers.parse('只有"{node}"在环网上发送命令'))
@then(parsers.parse('only "{node}" puts commands on the ring'))
def _(sut: TrainDriver, t_action: int, node: str) -> None:
    senders = {ev.source.rsplit(".", 1)[0] for ev in sut.trace.select(kind="cmd.tx", since=t_action)}
    assert senders == {node}, f"commands came from {sorted(senders) or 'nobody'}, expected only {node}"


@then(parsers.parse('"{node}"不在环网上发送命令'))
@then(parsers.parse('"{node}" puts no commands on the ring'))
def _(sut: TrainDriver, t_action: int, node: str) -> None:
    found = sut.trace.select(kind="cmd.tx", source=f"{node}.MDM8", since=t_action)
    assert not found, f"{node} sent commands: {analysis.describe(found)}"


@then(parsers.parse('{after:g} ms起"{node}"不在环网上发送命令'))
@then(parsers.parse('"{node}" puts no commands on the ring from {after:g} ms on'))
def _(sut: TrainDriver, t_action: int, node: str, after: float) -> None:
    found = sut.trace.select(kind="cmd.tx", source=f"{node}.MDM8", since=t_action + us(after))
    assert not found, f"{node} sent commands: {analysis.describe(found)}"


@then(parsers.parse('{after:g} ms起"{txc}"既不向环网也不向自诊断传输线发送任何数据'))
@then(parsers.parse('"{txc}" puts nothing on the ring or the self-diagnostic line from {after:g} ms on'))
def _(sut: TrainDriver, t_action: int, txc: str, after: float) -> None:
    system = txc.rsplit(".", 1)[0]
    since = t_action + us(after)
    ring = sut.trace.select(kind="cmd.tx", source=f"{system}.MDM8", since=since)
    line = sut.trace.select(kind="sd.rx", since=since, frm=txc)
    assert not ring and not line, f"{txc} kept transmitting: {analysis.describe(ring + line)}"


@then(parsers.parse("{after:g} ms起每条命令都带牵引级位{notch:d}和制动级位{step:d}"))
@then(parsers.parse("from {after:g} ms on every command carries traction notch {notch:d} and brake step {step:d}"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, notch: int, step: int) -> None:
    window = budgets.window_us(declaration, after)
    sent = sut.trace.select(kind="cmd.tx", since=t_action + window)
    assert sent, "no command was transmitted"
    wrong = [ev for ev in sent if (ev["traction"], ev["brake"]) != (notch, step)]
    assert not wrong, f"commands with other values: {analysis.describe(wrong)}"


# -- at CI and BCU ----------------------------------------------------------------------------------
@then(parsers.parse("每个CI和BCU在{bound:g} ms内经路径1收到牵引级位{notch:d}"))
@then(parsers.parse("every CI and BCU receives traction notch {notch:d} over path 1 within {bound:g} ms"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, notch: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    analysis.expect_taken(sut, analysis.command_devices(sut), t_action, window, f"notch {notch} over path 1",
                   path=1, traction=notch)


@then(parsers.parse("{car:d}号车的CI和BCU在{bound:g} ms内经路径1收到牵引级位{notch:d}"))
@then(parsers.parse("the CI and BCU of car {car:d} receive traction notch {notch:d} over path 1 within {bound:g} ms"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, car: int, notch: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    analysis.expect_taken(sut, analysis.command_devices(sut, car), t_action, window, f"notch {notch} over path 1",
                   path=1, traction=notch)


@then(parsers.parse("每个BCU在{bound:g} ms内经路径1收到制动级位{step:d}"))
@then(parsers.parse("every BCU receives brake step {step:d} over path 1 within {bound:g} ms"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, step: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    bcus = [d for d in analysis.command_devices(sut) if d.endswith(".BCU")]
    analysis.expect_taken(sut, bcus, t_action, window, f"brake step {step} over path 1", path=1, brake=step)


@then(parsers.parse('每个BCU在{bound:g} ms内经路径{path:d}收到制动级位"{step}"'))
@then(parsers.parse('every BCU receives brake step "{step}" over path {path:d} within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, step: str, path: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    bcus = [d for d in analysis.command_devices(sut) if d.endswith(".BCU")]
    analysis.expect_taken(sut, bcus, t_action, window, f"brake step {step} over path {path}", path=path,
                   brake_step=step)


@then(parsers.parse('每个CI和BCU在{bound:g} ms内经路径{path:d}收到牵引级位"{step}"'))
@then(parsers.parse('every CI and BCU receives traction step "{step}" over path {path:d} within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, step: str, path: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    analysis.expect_taken(sut, analysis.command_devices(sut), t_action, window,
                          f"traction step {step} over path {path}",
                   path=path, traction_step=step)


@then(parsers.parse('{car:d}号车的CI和BCU在{bound:g} ms内经路径{path:d}收到牵引级位"{step}"'))
@then(parsers.parse('the CI and BCU of car {car:d} receive traction step "{step}" over path {path:d} within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, car: int, step: str, path: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    analysis.expect_taken(sut, analysis.command_devices(sut, car), t_action, window,
                   f"traction step {step} over path {path}", path=path, traction_step=step)


@then(parsers.parse('{car:d}号车的BCU在{bound:g} ms内经路径{path:d}收到制动级位"{step}"'))
@then(parsers.parse('the BCU of car {car:d} receives brake step "{step}" over path {path:d} within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, car: int, step: str, path: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    analysis.expect_taken(sut, [f"car{car}.BCU"], t_action, window, f"brake step {step} over path {path}", path=path,
                   brake_step=step)


def _only_path_1(sut: TrainDriver, devices: list[str], since: int, notch: int) -> None:
    assert devices, "no CI or BCU to check"
    for device in devices:
        takes = sut.trace.select(kind="cmd.in", source=device, since=since)
        assert takes, f"{device} received nothing after {ms(since)}"
        odd = [ev for ev in takes if ev["path"] != 1 or ev["traction"] != notch]
        assert not odd, f"{device} left path 1 / notch {notch}: {analysis.describe(odd)}"


@then(parsers.parse("{after:g} ms起{car:d}号车以外的每个CI和BCU经路径1收到牵引级位{notch:d}"))
@then(parsers.parse("from {after:g} ms on every CI and BCU outside car {car:d} receives traction notch {notch:d} "
                    "over path 1"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, car: int, notch: int) -> None:
    window = budgets.window_us(declaration, after)
    others = [d for d in analysis.command_devices(sut) if not d.startswith(f"car{car}.")]
    _only_path_1(sut, others, t_action + window, notch)


@then(parsers.parse("{after:g} ms起每个CI和BCU只经路径1收到牵引级位{notch:d}"))
@then(parsers.parse("from {after:g} ms on every CI and BCU receives traction notch {notch:d} over path 1"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, notch: int) -> None:
    window = budgets.window_us(declaration, after)
    _only_path_1(sut, analysis.command_devices(sut), t_action + window, notch)


def _nothing_over(sut: TrainDriver, devices: list[str], since: int, path: int) -> None:
    for device in devices:
        got = sut.trace.select(kind="cmd.in", source=device, since=since, path=path)
        assert not got, f"{device} received commands over path {path}: {analysis.describe(got)}"


# From the action on, but a command the device had before it may still be acted on within the SUT's declared
# reaction margin (the reference: none).
@then(parsers.parse("{car:d}号车的{device:w}经路径{path:d}收不到任何命令"))
@then(parsers.parse("the {device:w} of car {car:d} receives nothing over path {path:d}"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, device: str, car: int, path: int) -> None:
    _nothing_over(sut, [f"car{car}.{device}"], t_action + budgets.margin_us(declaration), path)


@then(parsers.parse("{car:d}号车的CI和BCU都收不到经路径{path:d}的命令"))
@then(parsers.parse("the CI and BCU of car {car:d} receive nothing over path {path:d}"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, car: int, path: int) -> None:
    _nothing_over(sut, analysis.command_devices(sut, car), t_action + budgets.margin_us(declaration), path)


@then("经路径2和3传送的命令只含牵引A、B挡和制动A、B挡")
@then("commands over paths 2 and 3 carry only the traction and brake steps A and B")
def _(sut: TrainDriver, t_action: int) -> None:
    takes = [ev for ev in sut.trace.select(kind="cmd.in", since=t_action) if ev["path"] in (2, 3)]
    assert takes, "no command travelled over path 2 or 3"
    _only_steps_a_b(takes)


def _only_steps_a_b(takes: list) -> None:
    """CMD-03/04: the digital outputs of paths 2 and 3 carry the A/B steps, never a notch or a step number."""
    odd = [ev for ev in takes if ev["traction"] is not None or ev["brake"] is not None
           or ev["traction_step"] not in ("-", "A", "B") or ev["brake_step"] not in ("-", "A", "B")]
    assert not odd, f"paths 2/3 carried more than the A/B steps: {analysis.describe(odd)}"


@then(parsers.parse("没有CI或BCU收到{notch:d}级以外的牵引级位"))
@then(parsers.parse("no CI or BCU receives a traction notch other than {notch:d}"))
def _(sut: TrainDriver, t_action: int, notch: int) -> None:
    _no_notch_but(sut, {notch}, since=t_action)


def _no_notch_but(sut: TrainDriver, allowed: set[int], since: int | None = None) -> None:
    odd = [ev for ev in sut.trace.select(kind="cmd.in", since=since, path=1) if ev["traction"] not in allowed]
    assert not odd, f"devices received notches other than {sorted(allowed)}: {analysis.describe(odd)}"


def _notches(text: str) -> set[int]:
    return {int(n) for n in text.replace(" or ", ",").replace("或", ",").split(",")}


@then(parsers.parse("没有CI或BCU在任何时刻收到{notches}级以外的牵引级位"), converters={"notches": _notches})
@then(parsers.parse("no CI or BCU ever receives a traction notch other than {notches}"), converters={"notches": _notches})
def _(sut: TrainDriver, notches: set[int]) -> None:
    # Fail-safety over the whole trace, from power-up: a wrong notch for one cycle is a wrong command.
    _no_notch_but(sut, notches)


@then("经路径2和3传送的命令从未包含A、B挡以外的级位")
@then("no command over path 2 or 3 ever carried more than the traction and brake steps A and B")
def _(sut: TrainDriver) -> None:
    _only_steps_a_b([ev for ev in sut.trace.select(kind="cmd.in") if ev["path"] in (2, 3)])


def _paths(text: str) -> list[int | None]:
    """"1,1,3,-,2,1,1,1": per car in order, the path its CI and BCU take a command by ("-": none)."""
    return [None if p.strip() == "-" else int(p) for p in text.split(",")]


def _by_car(sut: TrainDriver, paths: list[int | None]) -> dict[int, int | None]:
    cars = analysis.cars(sut)
    assert len(paths) == len(cars), f"{len(paths)} paths for the {len(cars)} cars {cars}"
    return dict(zip(cars, paths))


@then(parsers.parse('各车的CI和BCU在{bound:g} ms内按路径{paths}收到牵引级位{notch:d}或牵引级位"{step}"'),
      converters={"paths": _paths})
@then(parsers.parse('car by car the CI and BCU receive traction notch {notch:d} or traction step "{step}" by the '
                    "paths {paths} within {bound:g} ms"), converters={"paths": _paths})
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, notch: int, step: str, paths: list, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    for car, path in _by_car(sut, paths).items():
        devices = analysis.command_devices(sut, car)
        if path == 1:
            analysis.expect_taken(sut, devices, t_action, window, f"notch {notch} over path 1", path=1, traction=notch)
        elif path is not None:
            analysis.expect_taken(sut, devices, t_action, window, f"traction step {step} over path {path}",
                                  path=path, traction_step=step)
            # Its MDM9 is dead or has no fresh ring command: a path 1 command now would contradict the step.
            _nothing_over(sut, devices, t_action + window, 1)
        else:        # the design leaves the car no path: the new command must not reach it by any
            got = [ev for d in devices for ev in sut.trace.select(kind="cmd.in", source=d, since=t_action)
                   if ev["traction"] == notch or ev["traction_step"] == step]
            assert not got, f"car {car} has no path left, yet took the command: {analysis.describe(got)}"


@then(parsers.parse("路径{paths}中有路径的车的CI和BCU都不会超过{bound:g} ms收不到命令"), converters={"paths": _paths})
@then(parsers.parse("no CI or BCU of a car with a path in {paths} goes without a command for more than {bound:g} ms"),
      converters={"paths": _paths})
def _(sut: TrainDriver, t_action: int, paths: list, bound: float) -> None:
    served = [d for car, path in _by_car(sut, paths).items() if path is not None
              for d in analysis.command_devices(sut, car)]
    _no_gap(sut, served, t_action, bound)


@then(parsers.parse("没有CI或BCU超过{bound:g} ms收不到命令"))
@then(parsers.parse("no CI or BCU goes without a command for more than {bound:g} ms"))
def _(sut: TrainDriver, t_action: int, bound: float) -> None:
    _no_gap(sut, analysis.command_devices(sut), t_action, bound)


def _no_gap(sut: TrainDriver, devices: list[str], since: int, bound: float) -> None:
    for device in devices:
        times = [since] + [ev.t for ev in sut.trace.select(kind="cmd.in", source=device, since=since)]
        times.append(sut.now_us)
        worst = max(analysis.intervals(times))
        assert worst <= us(bound), f"{device} went {ms(worst)} without a command (limit {bound} ms)"


# -- RED-02: takeover --------------------------------------------------------------------------------
@then(parsers.parse("系统{new:d}的第一条命令比系统{old:d}的最后一条晚{lo:g} ms至{hi:g} ms加一个命令周期"))
@then(parsers.parse("system {new:d}'s first command follows system {old:d}'s last by {lo:g} ms to {hi:g} ms plus "
                    "one command interval"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, new: int, old: int, lo: float,
      hi: float) -> None:
    """RED-02, timed where the commands enter the ring (the CCU's MDM8): ring latency jitter is PRO-01's
    business, not the takeover's. RED-02 gives the 50 ms of silence; system 2 then puts its first sample
    on the ring at its next command slot, so the top of the band is the sentence's (50 ms, the last command's
    way to system 2 and its handover: docs/decisions.md "Takeover") plus the SUT's own command interval
    (>= 10 ms) plus its declared timing resolution."""
    before = [ev.t for ev in sut.trace.select(kind="cmd.tx", until=t_action, system=old)]
    assert len(before) >= 3, f"system {old} sent {len(before)} commands before {ms(t_action)}"
    interval = statistics.median_low(analysis.intervals(before))
    last_old = sut.trace.last(kind="cmd.tx", system=old)
    first_new = sut.trace.first(kind="cmd.tx", since=t_action, system=new)
    assert first_new is not None, f"system {new} never put a command on the ring"
    gap = first_new.t - last_old.t
    top = us(hi) + interval + declaration.parameter("timing_resolution_us")
    assert us(lo) <= gap <= top, (f"system {new} followed system {old} after {ms(gap)}, outside {lo} ms.."
                                   f"{ms(top)} (command interval {ms(interval)})")


@then(parsers.parse('系统1正常时只有{cab:d}号车CCU的系统1发送命令'))
@then(parsers.parse('while system 1 is healthy only system 1 of the car {cab:d} CCU sends commands'))
def _(sut: TrainDriver, t_action: int, cab: int) -> None:
    sent = sut.trace.select(kind="cmd.tx", since=t_action)
    assert sent, "no commands were sent"
    odd = [ev for ev in sent if ev.source != f"car{cab}.CCU.sys1.MDM8"]
    assert not odd, f"other senders while system 1 was healthy: {analysis.describe(odd)}"


# -- RED-03: cab lamps -------------------------------------------------------------------------------
@then(parsers.parse('{cab:d}号司机室的"{lamp}"指示灯点亮'))
@then(parsers.parse('the "{lamp}" lamp of cab {cab:d} is lit'))
def _(sut: TrainDriver, lamp: str, cab: int) -> None:
    assert sut.lamp(cab, lamp), f"the {lamp} lamp of cab {cab} is dark"


@then(parsers.parse('{cab:d}号司机室的"{lamp}"指示灯熄灭'))
@then(parsers.parse('the "{lamp}" lamp of cab {cab:d} is dark'))
def _(sut: TrainDriver, lamp: str, cab: int) -> None:
    assert not sut.lamp(cab, lamp), f"the {lamp} lamp of cab {cab} is lit"


@then(parsers.parse('{cab:d}号司机室的"{lamp}"指示灯始终未熄灭'))
@then(parsers.parse('the "{lamp}" lamp of cab {cab:d} never went dark'))
def _(sut: TrainDriver, t_action: int, lamp: str, cab: int) -> None:
    offs = sut.trace.select(kind="lamp.off", source=f"car{cab}.cab", since=t_action, lamp=lamp)
    assert not offs, f"the {lamp} lamp of cab {cab} went dark: {analysis.describe(offs)}"
    assert sut.lamp(cab, lamp), f"the {lamp} lamp of cab {cab} is dark now"
