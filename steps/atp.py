"""Steps of the CTCS-2 200C on-board ATP on a lab rig (ATP-01..12): balises, the track-circuit signal
generator, odometry, and what the ATP decides. Positions where an edge lies are computed from what the SUT
declares (its declaration: D_Sen, position uncertainty, decode delay, CFSK comparison period) with the
project's formula (ATP-02):

    Dmin = (front - uncertainty) - D_Sen - v * dt        Dmax = (front + uncertainty) - D_Sen

the receiver can have been anywhere in [Dmin, Dmax] when it decoded; the range reaches v * dt further to
the rear because the decoded carrier is dt old.
"""
from __future__ import annotations

import re

import pytest
from pytest_bdd import given, parsers, then, when

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps.analysis import describe, intervals, ms, us
from steps import analysis, budgets, zh

SECTION = re.compile(r"(?P<a>[\d.]+)-(?P<b>[\d.]+) m (?P<f>\d+) Hz")


def _front_edge(d: ProfileDeclaration, boundary: float) -> float:
    """The front position at which Dmax reaches `boundary` (at standstill)."""
    return boundary - d.parameter("position_uncertainty_m") + d.parameter("d_sen_m")


def _rear_edge(d: ProfileDeclaration, boundary: float, kmh: float) -> float:
    """The front position at which Dmin leaves `boundary` behind, at `kmh`."""
    return boundary + d.parameter("position_uncertainty_m") + d.parameter("d_sen_m") \
        + kmh / 3.6 * d.parameter("decode_delay_ms") / 1000


# -- rig set-up ---------------------------------------------------------------------------------------
@given("试验台上的一套CTCS-2 200C型车载ATP")
@given("a CTCS-2 200C on-board ATP on the test rig")
def _(sut: TrainDriver) -> None:
    sut.configure(sets=1)


@given(parsers.parse("一列装有CTCS-2 200C型车载ATP的{cars:d}辆编组CRH2动车组"))
@given(parsers.parse("a CTCS-2 200C on-board ATP fitted to an {cars:d}-car CRH2 train set"))
def _(sut: TrainDriver, cars: int) -> None:
    sut.configure(sets=1, cars_per_set=cars)


@given("ATP已完成启机自检", target_fixture="t_action")
@given("the ATP has completed its start-up self-test", target_fixture="t_action")
def _(sut: TrainDriver) -> int:
    sut.power_on()
    for _ in range(60):
        if sut.trace.first(kind="def.done") is not None:
            break
        sut.advance(us(1000))
    assert sut.trace.first(kind="def.done") is not None, "the ATP did not finish its DEF self-test in 60 s"
    return sut.now_us


@given(parsers.parse("列车位于{pos:g} m处,速度为{kmh:g} km/h"))
@given(parsers.parse("the train is at {pos:g} m running at {kmh:g} km/h"))
@when(parsers.parse("将列车置于{pos:g} m处,速度设为{kmh:g} km/h"), target_fixture="t_action")
@when(parsers.parse("the train is set to {pos:g} m running at {kmh:g} km/h"), target_fixture="t_action")
def _(sut: TrainDriver, motion: dict, pos: float, kmh: float) -> int:
    sut.set_input("position", pos)
    sut.set_input("speed", kmh)
    motion.update(pos=pos, kmh=kmh, t=sut.now_us)
    return sut.now_us


@pytest.fixture
def motion() -> dict:
    """Where the train was put and how fast it runs ({pos, kmh, t}), for steps that run it to a place."""
    return {}


@when(parsers.parse("列车行驶至接收范围后端越过{boundary:g} m处"))
@when(parsers.parse("the train runs until the rear of the receiver range has passed {boundary:g} m"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, motion: dict, boundary: float) -> None:
    """Run as long as the SUT's own figures need (its declared D_Sen, uncertainty and decode delay put the
    edge), plus one comparison period and a second: a fixed wait would cap what a SUT may declare."""
    assert motion.get("kmh"), "the train was not set running (the train is at <pos> m running at <kmh> km/h)"
    edge = _rear_edge(declaration, boundary, motion["kmh"])
    travel_s = max(0.0, edge - motion["pos"]) / (motion["kmh"] / 3.6)
    until = motion["t"] + us(travel_s * 1000 + declaration.parameter("cfsk_period_ms") + 1000)
    sut.advance(max(0, until - sut.now_us))


@given(parsers.parse("列车静止于{boundary:g} m区段分界点的前端临界位置前方{delta:g} m处"))
@given(parsers.parse("the train stands {delta:g} m ahead of the front edge for the section boundary at {boundary:g} m"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, delta: float, boundary: float) -> None:
    sut.set_input("speed", 0)
    sut.set_input("position", _front_edge(declaration, boundary) + delta)


@when(parsers.parse("列车停在{pos:g} m处"), target_fixture="t_action")
@when(parsers.parse("the train stops at {pos:g} m"), target_fixture="t_action")
def _(sut: TrainDriver, pos: float) -> int:
    sut.set_input("speed", 0)
    sut.set_input("position", pos)
    return sut.now_us


@given(parsers.parse("信号发生器发送载频{carrier:d} Hz、低频码{code:w}"))
@given(parsers.parse("the signal generator sends {carrier:d} Hz with code {code:w}"))
@when(parsers.parse("信号发生器切换为载频{carrier:d} Hz、低频码{code:w}"), target_fixture="t_action")
@when(parsers.parse("the signal generator switches to {carrier:d} Hz with code {code:w}"), target_fixture="t_action")
def _(sut: TrainDriver, carrier: int, code: str) -> int:
    sut.set_input("carrier", carrier)
    sut.set_input("low frequency code", code)
    return sut.now_us


@when(parsers.parse("信号发生器发送载频{carrier:d} Hz,仅持续{comparisons:d}次比较,随后恢复为{back:d} Hz"),
      target_fixture="t_action")
@when(parsers.parse("the signal generator sends {carrier:d} Hz for {comparisons:d} comparisons, then {back:d} Hz again"),
      target_fixture="t_action")
def _(sut: TrainDriver, declaration: ProfileDeclaration, carrier: int, comparisons: int, back: int) -> int:
    start = sut.now_us
    sut.set_input("carrier", carrier)
    # n periods less one declared resolution: a comparison up to a tick off its slot must not make it n + 1.
    sut.advance(us(declaration.parameter("cfsk_period_ms") * comparisons) - declaration.parameter("timing_resolution_us"))
    sut.set_input("carrier", back)
    return start


@given(parsers.parse("信号发生器模拟{kind}轨道电路,信号幅度为{mv:g} mV"))
@given(parsers.parse("the signal generator reports amplitude {mv:g} mV on a {kind} track circuit"))
def _(sut: TrainDriver, mv: float, kind: str) -> None:
    sut.set_input("amplitude", mv)
    sut.set_input("track circuit type", kind)


@when(parsers.parse("司机在DMI上选择{which:w}载频"), converters={"which": zh.atp_line}, target_fixture="t_action")
@when(parsers.parse("the driver selects the {which:w}-line carrier set at the DMI"), target_fixture="t_action")
def _(sut: TrainDriver, which: str) -> int:
    sut.monitor_order(1, "carrier set", which)
    return sut.now_us


@when(parsers.parse('ATP输入"{name}"被置位'), target_fixture="t_action")
@when(parsers.parse('the ATP input "{name}" is set'), target_fixture="t_action")
def _(sut: TrainDriver, name: str) -> int:
    sut.set_input(name, True)
    return sut.now_us


@when(parsers.parse('ATP输入"{name}"被复位'), target_fixture="t_action")
@when(parsers.parse('the ATP input "{name}" is cleared'), target_fixture="t_action")
def _(sut: TrainDriver, name: str) -> int:
    sut.set_input(name, False)
    return sut.now_us


# -- balises --------------------------------------------------------------------------------------------
def _balise(sut: TrainDriver, group: str, *packets: dict) -> int:
    sut.pass_balise(group, list(packets))
    return sut.now_us


@given(parsers.parse('列车已通过应答器组"{group}",其描述的轨道电路为{spec},行车许可终点为{eoa:g} m'))
@given(parsers.parse('the train has passed balise group "{group}" describing track circuits {spec} '
                     'and an end of authority at {eoa:g} m'))
@when(parsers.parse('列车通过应答器组"{group}",其描述的轨道电路为{spec},行车许可终点为{eoa:g} m'),
      target_fixture="t_action")
@when(parsers.parse('the train passes balise group "{group}" describing track circuits {spec} '
                    'and an end of authority at {eoa:g} m'), target_fixture="t_action")
def _(sut: TrainDriver, group: str, spec: str, eoa: float) -> int:
    sections = [(float(m["a"]), float(m["b"]) - float(m["a"]), int(m["f"])) for m in SECTION.finditer(spec)]
    assert sections, f"no track circuits in {spec!r} (write them as 0-1000 m 1700 Hz, ...)"
    return _balise(sut, group, {"type": "CTCS-1", "sections": sections}, {"type": "MA", "end_m": eoa})


@when(parsers.parse('列车通过侧线应答器组"{group}",收到默认报文'), target_fixture="t_action")
@when(parsers.parse('the train passes side-line balise group "{group}" sending the default telegram'),
      target_fixture="t_action")
def _(sut: TrainDriver, group: str) -> int:
    return _balise(sut, group, {"type": "default", "side_line": True})


@given(parsers.parse('列车已通过应答器组"{group}",收到{direction:w}信息'), converters={"direction": zh.atp_line})
@given(parsers.parse('the train has passed balise group "{group}" with {direction:w}-line information'))
@when(parsers.parse('列车通过应答器组"{group}",收到{direction:w}信息'), converters={"direction": zh.atp_line},
      target_fixture="t_action")
@when(parsers.parse('the train passes balise group "{group}" with {direction:w}-line information'),
      target_fixture="t_action")
def _(sut: TrainDriver, group: str, direction: str) -> int:
    return _balise(sut, group, {"type": "line direction", "direction": direction})


@given(parsers.parse('列车已通过应答器组"{group}",其预告自{start:g} m起、长{length:g} m的分相区(ETCS-68)'))
@given(parsers.parse('the train has passed balise group "{group}" announcing a neutral section from {start:g} m, '
                     '{length:g} m long (ETCS-68)'))
def _(sut: TrainDriver, group: str, start: float, length: float) -> None:
    _balise(sut, group, {"type": "ETCS-68", "start_m": start, "length_m": length})


@given(parsers.parse('列车已通过应答器组"{group}",其给出{at:g} m处的停车点'))
@given(parsers.parse('the train has passed balise group "{group}" giving a stop point at {at:g} m'))
@when(parsers.parse('列车通过应答器组"{group}",其给出{at:g} m处的停车点'), target_fixture="t_action")
@when(parsers.parse('the train passes balise group "{group}" giving a stop point at {at:g} m'),
      target_fixture="t_action")
def _(sut: TrainDriver, group: str, at: float) -> int:
    return _balise(sut, group, {"type": "stop point", "at_m": at, "psd": False})


@given(parsers.parse('列车已通过应答器组"{group}",其给出{at:g} m处的停车点,站台设有屏蔽门'))
@given(parsers.parse('the train has passed balise group "{group}" giving a stop point at {at:g} m '
                     'with platform screen doors'))
@when(parsers.parse('列车通过应答器组"{group}",其给出{at:g} m处的停车点,站台设有屏蔽门'), target_fixture="t_action")
@when(parsers.parse('the train passes balise group "{group}" giving a stop point at {at:g} m '
                    'with platform screen doors'), target_fixture="t_action")
def _(sut: TrainDriver, group: str, at: float) -> int:
    return _balise(sut, group, {"type": "stop point", "at_m": at, "psd": True})


@given(parsers.parse('列车已通过应答器组"{group}",其链接{at:g} m处的应答器组"{nxt}"'))
@given(parsers.parse('the train has passed balise group "{group}" linking to group "{nxt}" at {at:g} m'))
def _(sut: TrainDriver, group: str, nxt: str, at: float) -> None:
    _balise(sut, group, {"type": "linking", "next": [(nxt, at)]})


@when(parsers.parse('列车通过应答器组"{group}",收到{packet}信息包'), target_fixture="t_action")
@when(parsers.parse('the train passes balise group "{group}" with an {packet} packet'), target_fixture="t_action")
def _(sut: TrainDriver, group: str, packet: str) -> int:
    return _balise(sut, group, {"type": packet})


@when(parsers.parse("列车以{kmh:g} km/h从{a:g} m运行到{b:g} m"), target_fixture="t_action")
@when(parsers.parse("the train runs from {a:g} m to {b:g} m at {kmh:g} km/h"), target_fixture="t_action")
def _(sut: TrainDriver, a: float, b: float, kmh: float) -> int:
    sut.set_input("position", a)
    sut.set_input("speed", kmh)
    start = sut.now_us
    sut.advance(us((b - a) / (kmh / 3.6) * 1000))
    return start


# -- what the ATP decides ---------------------------------------------------------------------------------
@then(parsers.parse("ATP处于{mode:w}模式"), converters={"mode": zh.atp_mode})
@then(parsers.parse("the ATP is in mode {mode:w}"))
def _(sut: TrainDriver, mode: str) -> None:
    assert sut.output("ATP mode") == mode, f"the ATP is in mode {sut.output('ATP mode')}, not {mode}"


@then(parsers.re(r"ATP(?:输出(?P<brake>.+?)制动|不输出制动)"), converters={"brake": zh.atp_brake})
@then(parsers.parse("the ATP commands {brake} brake"))
def _(sut: TrainDriver, brake: str) -> None:
    want = "none" if brake == "no" else brake
    assert sut.output("ATP brake") == want, f"the ATP commands {sut.output('ATP brake')} brake, not {want}"


@then(parsers.parse("ATP给出{permission}"), converters={"permission": zh.atp_permission})
@then(parsers.parse("the ATP grants {permission}"))
def _(sut: TrainDriver, permission: str) -> None:
    assert sut.output(permission) == "granted", f"{permission} is {sut.output(permission)}, not granted"


@then(parsers.parse("ATP不给出{permission}"), converters={"permission": zh.atp_permission})
@then(parsers.parse("the ATP withholds {permission}"))
def _(sut: TrainDriver, permission: str) -> None:
    assert sut.output(permission) == "withheld", f"{permission} is {sut.output(permission)}, not withheld"


@then(parsers.parse('DMI显示"{text}"'), converters={"text": zh.atp_dmi_text})
@then(parsers.parse('the DMI shows "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, text: str) -> None:
    # The feature names a message; the SUT's declaration says how its DMI words it (any language).
    words = declaration.text(text)
    shown = sut.monitor(1)["faults"]
    assert any(words in m for m in shown), f"the DMI does not show {text!r} (declared as {words!r}): {shown}"


@then(parsers.parse('DMI不显示"{text}"'), converters={"text": zh.atp_dmi_text})
@then(parsers.parse('the DMI does not show "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, text: str) -> None:
    words = declaration.text(text)
    shown = sut.monitor(1)["faults"]
    assert not any(words in m for m in shown), f"the DMI shows {text!r} (declared as {words!r}): {shown}"


@then("线路数据被删除")
@then("the line data is deleted")
def _(sut: TrainDriver, t_action: int) -> None:
    assert sut.trace.first(kind="linedata.delete", since=t_action) is not None, "the line data was kept"


@then("线路数据被保留")
@then("the line data is kept")
def _(sut: TrainDriver, t_action: int) -> None:
    deleted = sut.trace.select(kind="linedata.delete", since=t_action)
    assert not deleted, f"the line data was deleted: {describe(deleted)}"


# -- CFSK ----------------------------------------------------------------------------------------------------
@then(parsers.parse("CFSK经{n:d}次比较一致后将载频{carrier:d} Hz与低频码{code:w}一起上报"))
@then(parsers.parse("the CFSK reports {carrier:d} Hz with code {code:w} together, after {n:d} agreeing comparisons"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, carrier: int, code: str, n: int) -> None:
    report = sut.trace.first(kind="cfsk.report", since=t_action, carrier=carrier)
    assert report is not None, f"the CFSK never reported {carrier} Hz"
    assert report["code"] == code, f"the CFSK reported {carrier} Hz with code {report['code']}, not {code}"
    period = us(declaration.parameter("cfsk_period_ms"))
    tick = declaration.parameter("timing_resolution_us")
    lag = report.t - t_action
    # ATP-03: not before n comparisons can have agreed (the first may come at once, so n - 1 periods). The
    # report follows the confirming comparison; how soon the requirement does not say: the project allows it
    # one more comparison period to travel (docs/decisions.md, "CFSK report travel").
    earliest, latest = (n - 1) * period - tick, (n + 1) * period + tick
    assert earliest <= lag <= latest, \
        f"{carrier} Hz reported {ms(lag)} after it appeared: {n} agreeing comparisons {period / 1000:g} ms apart " \
        f"and the report's travel take {earliest / 1000:g}..{latest / 1000:g} ms"


@then(parsers.parse("CFSK不上报载频{carrier:d} Hz"))
@then(parsers.parse("the CFSK does not report {carrier:d} Hz"))
def _(sut: TrainDriver, t_action: int, carrier: int) -> None:
    reports = sut.trace.select(kind="cfsk.report", since=t_action, carrier=carrier)
    assert not reports, f"the CFSK reported {carrier} Hz: {describe(reports)}"


@then("安全计算机收到CFSK故障信息,未收到译码结果")
@then("the safety computer gets the CFSK fault and no decoded result")
def _(sut: TrainDriver, t_action: int) -> None:
    fault = sut.trace.first(kind="cfsk.fault", since=t_action)
    assert fault is not None, "no CFSK fault information reached the safety computer"
    decoded = sut.trace.select(kind="cfsk.report", since=fault.t)
    assert not decoded, f"decoded results after the CFSK fault: {describe(decoded)}"


@then(parsers.parse("CFSK使用{which:w}载频"), converters={"which": zh.atp_line})
@then(parsers.parse("the CFSK uses the {which:w}-line carrier set"))
def _(sut: TrainDriver, which: str) -> None:
    assert sut.output("CFSK carrier set") == which, f"the CFSK uses the {sut.output('CFSK carrier set')} set"


@then(parsers.parse("ATP为CFSK记录{fields}"), converters={"fields": zh.atp_record_fields})
@then(parsers.parse("the ATP records for the CFSK {fields}"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, fields: str) -> None:
    _cfsk_record(sut, declaration, fields)


@then(parsers.parse("{after:g} ms起ATP为CFSK记录{fields}"), converters={"fields": zh.atp_record_fields})
@then(parsers.parse("from {after:g} ms on the ATP records for the CFSK {fields}"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, fields: str) -> None:
    """A record of the action itself, not one an earlier action left: a second fault soon after a first one is
    recorded too (ATP-05 records the CFSK state, not its first change). A stamp may be whole milliseconds (the
    contract's `records`), so one stamped in the millisecond the window opens in counts."""
    _cfsk_record(sut, declaration, fields, since_ms=(t_action + us(after)) // 1000)


def _cfsk_record(sut: TrainDriver, declaration: ProfileDeclaration, fields: str, since_ms: float | None = None) -> None:
    """ATP-05 lists the fields of a CFSK record, not their wording: the documented shape (contract `records`: a
    stamp, then one whitespace-separated word per field) with each field worded as the SUT declares it (form
    texts `CFSK`, `code=<code>`, ...), in any order, all the fields asked in one record; with `since_ms`, among the
    records stamped from then on."""
    marker = declaration.text("CFSK")
    records = [r for r in sut.records("ATP") if marker in r]
    assert records, f"no CFSK record (a line with {marker!r}): {sut.records('ATP')}"
    # Each record is stamped with the train time it was made (TrainDriver.records: `t_ms ...`): a time the
    # train has reached, not one from the future or in other units.
    for record in records:
        stamp = record.split(" ", 1)[0]
        assert re.fullmatch(r"\d+(\.\d+)?", stamp) and float(stamp) <= sut.now_us / 1000, (
            f"a CFSK record stamped {stamp!r} at {sut.now_us / 1000:.3f} ms: {record}")
    if since_ms is not None:
        earlier = records
        records = [r for r in records if float(r.split(" ", 1)[0]) >= since_ms]
        assert records, f"no CFSK record stamped from {since_ms} ms on: {earlier}"
    wanted = {}
    for field in re.split(r",\s*|\s+and\s+", fields):
        key, _, value = field.strip().partition(" ")
        wanted[field.strip()] = _record_word(declaration, key, value.replace(" ", ""))
    # Every field in one record (ATP-05: a record holds them together), each a word of it, not the value anywhere
    # in it.
    if not any(all(word in r.split() for word in wanted.values()) for r in records):
        best = max(records, key=lambda r: sum(word in r.split() for word in wanted.values()))
        missing = [f"{field!r} (declared as {word!r})" for field, word in wanted.items() if word not in best.split()]
        raise AssertionError(f"no CFSK record with {fields!r}; the closest lacks {', '.join(missing)}: {records}")


# The CFSK record's fields (ATP-05) by the feature's key: the form's text identifier, and the unit the feature
# may write after the value (`carrier 2300 Hz`, `amplitude 420mV`), which the identifier places itself.
RECORD_FIELDS = {"code": ("code=<code>", ""), "carrier": ("carrier=<carrier>", "Hz"),
                 "amplitude": ("amplitude=<amplitude>mV", "mV"), "type": ("type=<type>", "")}


def _record_word(declaration: ProfileDeclaration, key: str, value: str) -> str:
    """The word a CFSK record holds for the feature's field `key value`, in the SUT's declared wording."""
    if key == "state":                        # ok or fault: a word of its own each (`state=ok`, `状态=正常`)
        return declaration.text(f"state={value}")
    assert key in RECORD_FIELDS, f"no CFSK record field {key!r} (ATP-05: {', '.join([*RECORD_FIELDS, 'state'])})"
    identifier, unit = RECORD_FIELDS[key]
    return declaration.text(identifier).replace(f"<{key}>", value.removesuffix(unit) if unit else value)


# -- carrier consistency (ATP-02) ------------------------------------------------------------------------------
def _inconsistency(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, boundary: float, kmh: float):
    """The ATP's declaration of the inconsistency, where the formula puts the rear edge, and how far a position
    stamp may be off it: rounding (1 cm) and the travel of one declared timing resolution."""
    event = sut.trace.first(kind="carrier.inconsistent", since=t_action)
    assert event is not None, "the ATP never declared the carrier inconsistent"
    tick_m = kmh / 3.6 * declaration.parameter("timing_resolution_us") / 1e6
    return event, _rear_edge(declaration, boundary, kmh), 0.01 + tick_m


@then(parsers.parse("速度为{kmh:g} km/h时,ATP判定载频不一致,但不早于接收范围后端越过{boundary:g} m处"))
@then(parsers.parse("the ATP declares the carrier inconsistent, not before the rear of the receiver range passes "
                    "{boundary:g} m at {kmh:g} km/h"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, boundary: float, kmh: float) -> None:
    """ATP-02: while the range [Dmin, Dmax] still overlaps the old section its carrier is consistent, so not
    before the edge; when after it the requirement does not say (the run gives one comparison period and a
    second more past the edge)."""
    event, edge, slack = _inconsistency(sut, declaration, t_action, boundary, kmh)
    assert event["at_m"] >= edge - slack, \
        f"declared at {event['at_m']} m, before the rear of the range passed {boundary:g} m (the formula: {edge:.2f} m)"


@then(parsers.parse("速度为{kmh:g} km/h时,ATP在接收范围后端越过{boundary:g} m处判定载频不一致"))
@then(parsers.parse("the ATP declares the carrier inconsistent as the rear of the receiver range passes "
                    "{boundary:g} m at {kmh:g} km/h"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, boundary: float, kmh: float) -> None:
    """Not before the edge (ATP-02), and within one comparison period's travel past it: the project's reading
    that the ATP checks the moving range at least once per comparison period (docs/decisions.md, "Carrier
    consistency while the train moves")."""
    event, edge, slack = _inconsistency(sut, declaration, t_action, boundary, kmh)
    period_m = kmh / 3.6 * declaration.parameter("cfsk_period_ms") / 1000     # one comparison's travel
    assert edge - slack <= event["at_m"] <= edge + period_m + slack, \
        f"declared at {event['at_m']} m; the formula puts the edge at {edge:.2f} m (+{period_m:.2f} m, +-{slack:.2f} m)"


@then(parsers.parse("载频不一致判定{after:g} ms后没有CI收到高于0的牵引级位"))
@then(parsers.parse("no CI receives a traction notch above 0 from {after:g} ms after the carrier inconsistency on"))
def _(sut: TrainDriver, t_action: int, after: float) -> None:
    """ILK-08 from the ATP's own decision on: when the ATP finds the inconsistency depends on what it declares
    (its receiver range), so the window starts there, not at a fixed time after the train was set running."""
    found = sut.trace.first(kind="carrier.inconsistent", since=t_action)
    assert found is not None, "the ATP never declared the carrier inconsistent"
    takes = sut.trace.select(kind="cmd.in", source="*.CI", since=found.t + us(after))
    assert takes, "no CI received any command"
    odd = [ev for ev in takes if (ev["traction"] or 0) > 0 or ev["traction_step"] in ("A", "B")]
    assert not odd, f"traction reached a CI {after:g} ms and more after the inconsistency: {describe(odd)}"


@then("ATP判定载频一致")
@then("the ATP finds the carrier consistent")
def _(sut: TrainDriver, t_action: int) -> None:
    bad = sut.trace.select(kind="carrier.inconsistent", since=t_action)
    assert not bad, f"the ATP declared the carrier inconsistent: {describe(bad)}"


@then("ATP判定载频不一致")
@then("the ATP declares the carrier inconsistent")
def _(sut: TrainDriver, t_action: int) -> None:
    assert sut.trace.first(kind="carrier.inconsistent", since=t_action) is not None, \
        "the ATP accepted a carrier outside the receiver range"


# -- DEF self-test (ATP-08) ---------------------------------------------------------------------------------------
@then(parsers.parse("DEF自检按{step:g} s间隔执行{n:d}个检测步骤,并在{total:g} s内完成"))
@then(parsers.parse("the DEF self-test ran {n:d} steps {step:g} s apart and finished within {total:g} s"))
def _(sut: TrainDriver, declaration: ProfileDeclaration, n: int, step: float, total: float) -> None:
    """ATP-08: n steps of `step` s, the whole test within `total` s, counted from its first step (the test's own
    length: how long the ATP boots before it the requirement does not bound). A product on a task tick puts
    each step up to one tick off its slot, so each gap and the total are checked within the declared timing
    resolution (docs/decisions.md, "DEF timing")."""
    steps = sut.trace.select(kind="def.step")
    done = sut.trace.first(kind="def.done")
    assert len(steps) == n, f"{len(steps)} DEF steps, not {n}"
    tick = declaration.parameter("timing_resolution_us")
    gaps = intervals([s.t for s in steps])
    off = [g for g in gaps if abs(g - us(step * 1000)) > tick]
    assert not off, f"DEF steps {sorted(g / 1e6 for g in set(gaps))} s apart, not {step:g} s (+-{tick} us)"
    assert all(s["readback"] == "ok" for s in steps), describe(steps)
    assert done is not None and done.t - steps[0].t <= us(total * 1000) + tick, \
        f"the DEF self-test took {ms(done.t - steps[0].t) if done else 'forever'} (bound {total:g} s +{tick} us)"


@then("DEF自检在回读错误的输出处判定失败")
@then("the DEF self-test fails on the output that does not read back")
def _(sut: TrainDriver) -> None:
    """ATP-08: each step reads back the output it changed; a self-test that passed an output which does not
    read back would test nothing. What the ATP does then the requirement does not say (F-ATP-10's @tentative
    scenario: docs/decisions.md, "A failed DEF self-test")."""
    wrong = sut.trace.first(kind="def.step", readback="wrong")
    assert wrong is not None, "no DEF step found the wrong read-back"
    assert sut.trace.first(kind="def.done") is None, "the DEF self-test finished despite a wrong read-back"


@then("ATP保持列车制动")
@then("the ATP holds the train braked")
def _(sut: TrainDriver) -> None:
    # Any brake the ATP commands (maximum service or emergency): which one is the product's.
    assert sut.output("ATP brake") != "none", "the ATP commands no brake"


@then(parsers.parse("{after:g} ms起列车按ATP的制动施加制动"))
@then(parsers.parse("from {after:g} ms on the train brakes as the ATP commands"))
@budgets.budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float) -> None:
    """ILK-08 on the fitted train (atp-crh2 contract): whichever brake the ATP chose, the train takes it. An
    emergency brake applies the train's emergency brake; a maximum service brake raises every BCU's brake
    command to full service (step 7), as in F-ATP-13."""
    brake = sut.output("ATP brake")
    assert brake != "none", "the ATP commands no brake"
    if brake == "emergency":
        assert sut.output("emergency brake") == "applied", \
            f"the ATP brakes in emergency, and the train's emergency brake is {sut.output('emergency brake')}"
        return
    analysis.expect_brake_step(sut, t_action + budgets.window_us(declaration, after), 7,
                               why=f"the ATP commands {brake}, and ")


# -- neutral section, linking (ATP-11, ATP-12) ------------------------------------------------------------------
def _passing(sut: TrainDriver, t_action: int) -> tuple[list, list]:
    changes = sut.trace.select(kind="neutral.command", since=t_action)
    return [c for c in changes if c["state"] == "passing"], [c for c in changes if c["state"] == "none"]


@then(parsers.parse("ATP的过分相命令覆盖{a:g} m至{b:g} m,误差不超过{tol:g} m"))
@then(parsers.parse("the ATP's neutral-section passing command covers {a:g} m to {b:g} m, to within {tol:g} m"))
def _(sut: TrainDriver, t_action: int, a: float, b: float, tol: float) -> None:
    """ATP-11: the ATP passes the announced section by itself, so its command holds while the front is in it:
    on by the section's start (`tol`: the position stamps' granularity), not off before its end, once. How early
    it begins and how long it holds after (for the pantographs behind the front) ATP-11 leaves to the product."""
    on, off = _passing(sut, t_action)
    assert len(on) == 1 and len(off) <= 1, f"neutral-section commands: {describe(on + off)}"
    assert on[0]["at_m"] <= a + tol, f"passing commanded at {on[0]['at_m']} m, after the section began at {a:g} m"
    assert not off or off[0]["at_m"] >= b, f"passing ended at {off[0]['at_m']} m, inside the section (to {b:g} m)"


@then(parsers.parse("ATP自{a:g} m至{b:g} m输出过分相命令,误差不超过{tol:g} m"))
@then(parsers.parse("the ATP commands neutral-section passing from {a:g} m to {b:g} m, to within {tol:g} m"))
def _(sut: TrainDriver, t_action: int, a: float, b: float, tol: float) -> None:
    # The section's own start and end, each within `tol` after: the reference's reading, checked informatively.
    on, off = _passing(sut, t_action)
    assert len(on) == 1 and len(off) == 1, f"neutral-section commands: {describe(on + off)}"
    assert a <= on[0]["at_m"] <= a + tol, f"passing commanded at {on[0]['at_m']} m, section from {a} m"
    assert b <= off[0]["at_m"] <= b + tol, f"passing ended at {off[0]['at_m']} m, section to {b} m"


@then("ATP正在输出过分相命令")
@then("the ATP is commanding neutral-section passing")
def _(sut: TrainDriver) -> None:
    # The command line to the train itself, not its log: what the vehicle acts on.
    assert sut.output("neutral section") == "passing", f"the ATP's neutral-section output is {sut.output('neutral section')!r}"


@then("ATP未输出过分相命令")
@then("the ATP is not commanding neutral-section passing")
def _(sut: TrainDriver) -> None:
    assert sut.output("neutral section") == "none", f"the ATP's neutral-section output is {sut.output('neutral section')!r}"


@then(parsers.parse('丢失应答器组"{group}"时的链接反应为{reaction}'), converters={"reaction": zh.atp_reaction})
@then(parsers.parse('the linking reaction to the missing group "{group}" is {reaction}'))
def _(sut: TrainDriver, t_action: int, group: str, reaction: str) -> None:
    event = sut.trace.first(kind="linking.missing", since=t_action, group=group)
    assert event is not None, f"the ATP did not notice group {group} missing"
    assert event["reaction"] == reaction, f"linking reaction {event['reaction']!r}, not {reaction!r}"
