"""The vehicle around the network (ILK-01..08): speed, main air pipe, doors, couplers, main circuit,
neutral section, ATP brake; and what the train's valves, relays and breakers do.

Outputs are read from the trace (`out.change` events carry the speed and pressure at that instant), so a
band test asks *where* a valve dropped, not only whether it did.
"""
from __future__ import annotations

from pytest_bdd import given, parsers, then, when

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, budgets, zh
from steps.budgets import budgeted
from steps.analysis import ms, us


# An output value is words of lower-case letters and hyphens ("de-energised", "not commanded"), so a
# sentence that goes on with "within 200 ms" can never be read as a longer value.
OUTPUT_VALUE = r"[a-z][a-z -]*[a-z]"
NUMBER = r"\d+(?:\.\d+)?"
# The same in a Chinese sentence: a Chinese state word (zh.CORE_STATES, converted to the English value) or the
# English value itself.
ZH_OUTPUT_VALUE = rf"{zh.CORE_STATE_RE}|{OUTPUT_VALUE}"
VALUE = rf"(?P<value>{OUTPUT_VALUE})"
ZH_VALUE = rf"(?P<value>{ZH_OUTPUT_VALUE})"

# The edges where a valve, a relay or the compressor must switch, by the vehicle input it acts on, and the side
# of each edge its own value lies on (-1: the lower side, +1: the upper): ILK-02's band (tripped by 580 kPa,
# allowed to trip at 600 and to stay tripped up to it), the hysteresis rule's 640 kPa (released by), the
# compressor governor's (started by 770, never at 780; stopped from 870 and by 880); ILK-05's press-seal valve
# (never at 30 km/h, by 32) and door-open relay (by 4 km/h, never at 5). A train measures its speed and pressure
# itself, so a switching point off by its declared accuracy conforms (docs/decisions.md, "Measurement accuracy at
# the interlocks' edges"): a stimulus written at an edge or nearer it than that is fed that far clear of it on
# its own side, and each band grows by that much on both sides.
EDGES: dict[str, dict[float, int]] = {
    "main pipe pressure": {580: -1, 600: -1, 640: +1, 770: -1, 780: +1, 870: +1, 880: +1},
    "speed": {4: -1, 5: +1, 30: -1, 32: +1},
}


def clear_of_edges(name: str, value: float, accuracy: dict[str, float], shifts: dict[str, float]) -> float:
    """The value to feed for a `value` written for vehicle input `name`: the SUT's declared accuracy clear of
    every edge (the form's ranges keep the edges at least twice that apart); what it moved is noted in `shifts`."""
    margin = accuracy.get(name, 0)
    fed = value
    for edge, side in EDGES.get(name, {}).items():
        if margin and abs(value - edge) < margin:
            fed = edge + (side if value == edge else (1 if value > edge else -1)) * margin
    shifts[name] = fed - value
    return fed


def band(name: str, lo: float, hi: float, accuracy: dict[str, float]) -> tuple[float, float]:
    """A band the SUT must switch in, wider by the accuracy it declares for the input it acts on."""
    margin = accuracy.get(name, 0)
    return lo - margin, hi + margin


# -- inputs -----------------------------------------------------------------------------------------
@given(parsers.parse("列车以{kmh:g} km/h运行"))
@given(parsers.parse("the train runs at {kmh:g} km/h"))
@when(parsers.parse("列车速度变为{kmh:g} km/h"), target_fixture="t_action")
@when(parsers.parse("the train speed changes to {kmh:g} km/h"), target_fixture="t_action")
def _(sut: TrainDriver, accuracy: dict[str, float], edge_shifts: dict[str, float], kmh: float) -> int:
    sut.set_input("speed", clear_of_edges("speed", kmh, accuracy, edge_shifts))
    return sut.now_us


@when(parsers.parse("列车速度以每秒{rate:g} km/h从{a:g} km/h变化到{b:g} km/h"), target_fixture="t_action")
@when(parsers.parse("the train speed goes from {a:g} km/h to {b:g} km/h at {rate:g} km/h per second"),
      target_fixture="t_action")
def _(sut: TrainDriver, ramps: dict[str, float], accuracy: dict[str, float], edge_shifts: dict[str, float],
      a: float, b: float, rate: float) -> int:
    sut.set_input("speed", clear_of_edges("speed", a, accuracy, edge_shifts))
    sut.ramp_input("speed", clear_of_edges("speed", b, accuracy, edge_shifts), rate)
    ramps["speed"] = rate if b >= a else -rate
    return sut.now_us


@given(parsers.parse("总风管压力为{kpa:g} kPa"))
@given(parsers.parse("the main air pipe pressure is {kpa:g} kPa"))
@when(parsers.parse("总风管压力变为{kpa:g} kPa"), target_fixture="t_action")
@when(parsers.parse("the main air pipe pressure changes to {kpa:g} kPa"), target_fixture="t_action")
def _(sut: TrainDriver, accuracy: dict[str, float], edge_shifts: dict[str, float], kpa: float) -> int:
    sut.set_input("main pipe pressure", clear_of_edges("main pipe pressure", kpa, accuracy, edge_shifts))
    return sut.now_us


@when(parsers.parse("总风管压力以每秒{rate:g} kPa从{a:g} kPa变化到{b:g} kPa"), target_fixture="t_action")
@when(parsers.parse("the main air pipe pressure goes from {a:g} kPa to {b:g} kPa at {rate:g} kPa per second"),
      target_fixture="t_action")
def _(sut: TrainDriver, ramps: dict[str, float], accuracy: dict[str, float], edge_shifts: dict[str, float],
      a: float, b: float, rate: float) -> int:
    sut.set_input("main pipe pressure", clear_of_edges("main pipe pressure", a, accuracy, edge_shifts))
    sut.ramp_input("main pipe pressure", clear_of_edges("main pipe pressure", b, accuracy, edge_shifts), rate)
    ramps["main pipe pressure"] = rate if b >= a else -rate
    return sut.now_us


@when(parsers.parse("列车在{a:d}号车与{b:d}号车之间分离"), target_fixture="t_action")
@when(parsers.parse("the train separates between car {a:d} and car {b:d}"), target_fixture="t_action")
def _(sut: TrainDriver, a: int, b: int) -> int:
    sut.set_input(f"coupler car{a}~car{b}", "separated")
    return sut.now_us


@given(parsers.parse("{car:d}号车的制动力为需求值的{pct:g} %"))
@given(parsers.parse("the brake force of car {car:d} is {pct:g} % of the demand"))
@when(parsers.parse("{car:d}号车的制动力变为需求值的{pct:g} %"), target_fixture="t_action")
@when(parsers.parse("the brake force of car {car:d} becomes {pct:g} % of the demand"), target_fixture="t_action")
def _(sut: TrainDriver, car: int, pct: float) -> int:
    sut.set_input(f"car{car}.brake force", pct)
    return sut.now_us


@given(parsers.parse("车门处于{state:w}状态"), converters={"state": zh.core_state})
@given(parsers.parse("the doors are {state:w}"))
@when(parsers.parse("司机发出车门{state:w}指令"), converters={"state": zh.core_state}, target_fixture="t_action")
@when(parsers.parse("the driver commands the doors {state:w}"), target_fixture="t_action")
def _(sut: TrainDriver, state: str) -> int:
    sut.set_input("doors", state)
    return sut.now_us


@given(parsers.parse("关门联锁旁路开关在{state:w}位"), converters={"state": zh.core_switch})
@given(parsers.parse("the door-interlock bypass switch is {state:w}"))
@when(parsers.parse("司机将关门联锁旁路开关置于{state:w}位"), converters={"state": zh.core_switch},
      target_fixture="t_action")
@when(parsers.parse("the driver turns the door-interlock bypass switch {state:w}"), target_fixture="t_action")
def _(sut: TrainDriver, state: str) -> int:
    sut.set_input("door bypass", state)
    return sut.now_us


@when(parsers.parse("ATP发出{kind:w}制动指令"), converters={"kind": zh.core_brake}, target_fixture="t_action")
@when(parsers.parse("the ATP commands a {kind:w} brake"), target_fixture="t_action")
def _(sut: TrainDriver, kind: str) -> int:
    sut.set_input("ATP brake", kind)
    return sut.now_us


@when("ATP解除制动", target_fixture="t_action")
@when("the ATP releases its brake", target_fixture="t_action")
def _(sut: TrainDriver) -> int:
    sut.set_input("ATP brake", "none")
    return sut.now_us


@when(parsers.parse("收到过分相{signal:w}信号"), converters={"signal": zh.core_signal}, target_fixture="t_action")
@when(parsers.parse("the neutral-section {signal:w} signal arrives"), target_fixture="t_action")
def _(sut: TrainDriver, signal: str) -> int:
    sut.set_input("neutral section signal", signal)
    return sut.now_us


@given(parsers.parse('过分相装置报告"{state}"'), converters={"state": zh.core_state})
@given(parsers.parse('the neutral-section device reports "{state}"'))
@when(parsers.parse('过分相装置改为报告"{state}"'), converters={"state": zh.core_state}, target_fixture="t_action")
@when(parsers.parse('the neutral-section device comes to report "{state}"'), target_fixture="t_action")
def _(sut: TrainDriver, state: str) -> int:
    sut.set_input("neutral section device", state)
    return sut.now_us


@when("司机手动恢复过分相之前的状态", target_fixture="t_action")
@when("the driver restores the pre-section state manually", target_fixture="t_action")
def _(sut: TrainDriver) -> int:
    sut.set_input("neutral section restore", "manual restore")
    return sut.now_us


@when("司机复位主电路", target_fixture="t_action")
@when("the driver resets the main circuit", target_fixture="t_action")
def _(sut: TrainDriver) -> int:
    sut.set_input("main circuit reset", "reset")
    return sut.now_us


@given(parsers.parse('车辆输入"{name}"为"{value}"'), converters={"value": zh.core_state})
@given(parsers.parse('the vehicle input "{name}" is "{value}"'))
@when(parsers.parse('车辆输入"{name}"变为"{value}"'), converters={"value": zh.core_state}, target_fixture="t_action")
@when(parsers.parse('the vehicle input "{name}" becomes "{value}"'), target_fixture="t_action")
def _(sut: TrainDriver, name: str, value: str) -> int:
    """The catch-all: any input of the SUT's catalogue, so a new test item needs no new Python."""
    try:
        parsed: object = float(value)
    except ValueError:
        parsed = value
    sut.set_input(name, parsed)
    return sut.now_us


# -- outputs ----------------------------------------------------------------------------------------
def _changes(sut: TrainDriver, output: str, since: int, value: str | None = None):
    found = sut.trace.select(kind="out.change", source=output, since=since)
    return [ev for ev in found if value is None or ev["value"] == value]


@then(parsers.re(rf'"(?P<output>[^"]+)"为{ZH_VALUE}'), converters={"value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" is {VALUE}'))
def _(sut: TrainDriver, output: str, value: str) -> None:
    got = sut.output(output)
    assert got == value, f"the {output} is {got}, expected {value}"


@then(parsers.re(rf'"(?P<output>[^"]+)"在(?P<bound>{NUMBER}) ms内变为{ZH_VALUE}'),
      converters={"bound": float, "value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" is {VALUE} within (?P<bound>{NUMBER}) ms'),
      converters={"bound": float})
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, output: str, value: str, bound: float) -> None:
    window = budgets.window_us(declaration, bound)

    def check() -> None:
        got = sut.output(output)
        assert got == value, f"the {output} is {got} at {ms(sut.now_us)}, expected {value}"
        change = sut.trace.last(kind="out.change", source=output, until=sut.now_us)
        if change is not None and change.t >= t_action:
            delay = change.t - t_action
            assert delay <= window, f"the {output} became {value} after {ms(delay)}, limit {ms(window)}"

    budgets.within(sut, t_action, window, check)


@then(parsers.re(rf'"(?P<output>[^"]+)"保持{ZH_VALUE}'), converters={"value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" stays {VALUE}'))
def _(sut: TrainDriver, t_action: int, output: str, value: str) -> None:
    changes = _changes(sut, output, t_action)
    assert not changes, f"the {output} changed: {analysis.describe(changes)}"
    got = sut.output(output)
    assert got == value, f"the {output} is {got}, expected {value}"


@then(parsers.re(rf'"(?P<output>[^"]+)"在总风管压力处于(?P<lo>{NUMBER})至(?P<hi>{NUMBER}) kPa之间时变为{ZH_VALUE}'),
      converters={"lo": float, "hi": float, "value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" became {VALUE} while the main air pipe pressure was between '
                 rf'(?P<lo>{NUMBER}) and (?P<hi>{NUMBER}) kPa'), converters={"lo": float, "hi": float})
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, ramps: dict[str, float], accuracy: dict[str, float],
      t_action: int, output: str, value: str, lo: float, hi: float) -> None:
    changes = _changes(sut, output, t_action, value)
    assert changes, f"the {output} never became {value} after {ms(t_action)}"
    p = changes[0]["pressure"]
    lo, hi = band("main pipe pressure", lo, hi, accuracy)
    lo, hi = budgets.band_on_ramp(declaration, ramps.get("main pipe pressure"), lo, hi)
    assert lo <= p <= hi, f"the {output} became {value} at {p:g} kPa, outside {lo:g}..{hi:g} kPa"


@then(parsers.re(rf'"(?P<output>[^"]+)"在速度处于(?P<lo>{NUMBER})至(?P<hi>{NUMBER}) km/h之间时变为{ZH_VALUE}'),
      converters={"lo": float, "hi": float, "value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" became {VALUE} while the speed was between (?P<lo>{NUMBER}) and '
                 rf'(?P<hi>{NUMBER}) km/h'), converters={"lo": float, "hi": float})
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, ramps: dict[str, float], accuracy: dict[str, float],
      t_action: int, output: str, value: str, lo: float, hi: float) -> None:
    changes = _changes(sut, output, t_action, value)
    assert changes, f"the {output} never became {value} after {ms(t_action)}"
    v = changes[0]["speed"]
    lo, hi = band("speed", lo, hi, accuracy)
    lo, hi = budgets.band_on_ramp(declaration, ramps.get("speed"), lo, hi)
    assert lo <= v <= hi, f"the {output} became {value} at {v:g} km/h, outside {lo:g}..{hi:g} km/h"


@then(parsers.re(rf'"(?P<output>[^"]+)"始终未变为{ZH_VALUE}'), converters={"value": zh.core_state})
@then(parsers.re(rf'the "(?P<output>[^"]+)" never became {VALUE}'))
def _(sut: TrainDriver, t_action: int, output: str, value: str) -> None:
    changes = _changes(sut, output, t_action, value)
    assert not changes, f"the {output} became {value}: {analysis.describe(changes)}"
    assert sut.output(output) != value, f"the {output} is {value}"


@then(parsers.parse('"{a}"与"{b}"在同一时刻变化'))
@then(parsers.parse('the "{a}" and the "{b}" changed at the same instant'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, a: str, b: str) -> None:
    """ILK-01's "together": the two first changes after the action lie within the SUT's declared timing
    resolution of each other (one instant of a product on a task tick); which of the two it logs first
    at that instant is its own business."""
    ca, cb = _changes(sut, a, t_action), _changes(sut, b, t_action)
    assert ca and cb, f"{a} changes: {len(ca)}, {b} changes: {len(cb)}"
    tick = declaration.parameter("timing_resolution_us")
    assert abs(ca[0].t - cb[0].t) <= tick, (f"the {a} changed at {ms(ca[0].t)}, the {b} at {ms(cb[0].t)}, more "
                                           f"than the declared {tick} us apart")


@then(parsers.parse("{after:g} ms起没有CI收到高于0级的牵引级位"))
@then(parsers.parse("no CI receives a traction notch above 0 from {after:g} ms on"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float) -> None:
    window = budgets.window_us(declaration, after)
    takes = [ev for ev in sut.trace.select(kind="cmd.in", source="*.CI", since=t_action + window)]
    assert takes, "no CI received any command"
    odd = [ev for ev in takes if (ev["traction"] or 0) > 0 or ev["traction_step"] in ("A", "B")]
    assert not odd, f"traction reached a CI: {analysis.describe(odd)}"


@then(parsers.parse("每个CI在{bound:g} ms内收到牵引级位{notch:d}"))
@then(parsers.parse("every CI receives traction notch {notch:d} within {bound:g} ms"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, notch: int, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    cis = [d for d in analysis.command_devices(sut) if d.endswith(".CI")]
    analysis.expect_taken(sut, cis, t_action, window, f"traction notch {notch}", traction=notch)


@then(parsers.parse("{after:g} ms起每个BCU收到制动级位{step:d}"))
@then(parsers.parse("from {after:g} ms on every BCU receives brake step {step:d}"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, step: int) -> None:
    analysis.expect_brake_step(sut, t_action + budgets.window_us(declaration, after), step)
