"""Step sentences added for the extra_control features (see steps/__init__.py).

The function-class control items (F-CTL-xx) check whole commands at CI and BCU (full resolution over path 1,
direction), the order in which two vehicle outputs followed each other, and monitor messages going away.
"""
from __future__ import annotations

from pytest_bdd import parsers, then

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, budgets, messages, zh
from steps.budgets import budgeted
from steps.analysis import ms, us
# the output-value grammar of vehicle.py: "open no later than" is never read as one longer value
from steps.vehicle import NUMBER, OUTPUT_VALUE, ZH_OUTPUT_VALUE


@then(parsers.parse("{after:g} ms起每个CI和BCU经路径1只收到牵引级位{notch:d}和制动级位{step:d}"))
@then(parsers.parse("from {after:g} ms on every CI and BCU receives only traction notch {notch:d} and brake step "
                    "{step:d} over path 1"))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, notch: int, step: int) -> None:
    """Full resolution (CMD-02): the exact notch and step, not merely the A/B band they fall in."""
    window = budgets.window_us(declaration, after)
    since = t_action + window
    assert sut.now_us > since, f"only {ms(sut.now_us - t_action)} passed, nothing to examine after {after} ms"
    devices = analysis.command_devices(sut)
    assert devices, "no CI or BCU to check"
    for device in devices:
        takes = sut.trace.select(kind="cmd.in", source=device, since=since)
        assert takes, f"{device} received nothing from {ms(since)} on"
        odd = [ev for ev in takes if ev["path"] != 1 or ev["traction"] != notch or ev["brake"] != step]
        assert not odd, f"{device} received other than notch {notch} / step {step} over path 1: {analysis.describe(odd)}"


@then(parsers.parse('{after:g} ms起没有CI或BCU收到"{direction}"方向指令'), converters={"direction": zh.direction})
@then(parsers.parse('from {after:g} ms on no CI or BCU receives direction "{direction}"'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, after: float, direction: str) -> None:
    window = budgets.window_us(declaration, after)
    since = t_action + window
    devices = analysis.command_devices(sut)
    assert devices, "no CI or BCU to check"
    for device in devices:
        takes = sut.trace.select(kind="cmd.in", source=device, since=since, path=1)
        assert takes, f"{device} received no command over path 1 from {ms(since)} on"
        odd = [ev for ev in takes if ev["direction"] == direction]
        assert not odd, f"{device} received direction {direction}: {analysis.describe(odd)}"


@then(parsers.re(rf'"(?P<a>[^"]+)"变为(?P<va>{ZH_OUTPUT_VALUE})的时刻不晚于"(?P<b>[^"]+)"变为(?P<vb>{ZH_OUTPUT_VALUE})后'
                 rf'(?P<bound>{NUMBER}) ms'), converters={"bound": float, "va": zh.core_state, "vb": zh.core_state})
@then(parsers.re(rf'the "(?P<a>[^"]+)" became (?P<va>{OUTPUT_VALUE}) no later than (?P<bound>{NUMBER}) ms after the '
                 rf'"(?P<b>[^"]+)" became (?P<vb>{OUTPUT_VALUE})'), converters={"bound": float})
def _(sut: TrainDriver, t_action: int, a: str, va: str, bound: float, b: str, vb: str) -> None:
    """Both changes after the last action; `a` may come first, but never more than `bound` after `b`."""
    first_b = next((ev for ev in sut.trace.select(kind="out.change", source=b, since=t_action)
                    if ev["value"] == vb), None)
    assert first_b is not None, f"the {b} never became {vb} after {ms(t_action)}"
    first_a = next((ev for ev in sut.trace.select(kind="out.change", source=a, since=t_action)
                    if ev["value"] == va), None)
    assert first_a is not None, f"the {a} never became {va} after {ms(t_action)}"
    lag = first_a.t - first_b.t
    assert lag <= us(bound), (f"the {a} became {va} {ms(lag)} after the {b} became {vb}, "
                               f"limit {bound} ms")
    assert sut.output(a) == va, f"the {a} is {sut.output(a)} now, not {va}"


@then(parsers.parse('{cab:d}号司机室监视器不再显示"{text}"'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor no longer shows "{text}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = messages.message(declaration, text, "faults")     # in the SUT's declared words
    faults = sut.monitor(cab)["faults"]
    assert not any(pattern.fullmatch(f) for f in faults), f"the cab {cab} monitor still shows {said}: {faults}"
