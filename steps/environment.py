"""The hardware/software class (TST-02): the environment a rig would apply (supply voltage and
interruptions, climatic chamber, burst generator, vibration table, withstand-voltage tester) and what the
network does under it.

Voltages are given as % of Un, the SUT's declared nominal supply voltage (EN 50155 states its ranges that
way). Stimuli "outside the rated range" are placed relative to what the SUT itself declares, so a SUT
rated wider than the standard is tested beyond its own limits, not failed for being better.
"""
from __future__ import annotations

from pytest_bdd import given, parsers, then, when

from sut.driver import TrainDriver
from steps import analysis
from steps.analysis import ms, us


def _volts(sut: TrainDriver, pct: float) -> float:
    return sut.rated_limits()["nominal supply voltage V"] * pct / 100


# -- supply voltage and interruptions ---------------------------------------------------------------
@given(parsers.parse('电源"{supply}"的输入电压为{pct:g} % Un'))
@given(parsers.parse('the input of supply "{supply}" is at {pct:g} % of Un'))
@when(parsers.parse('电源"{supply}"的输入电压变为{pct:g} % Un'), target_fixture="t_action")
@when(parsers.parse('the input of supply "{supply}" changes to {pct:g} % of Un'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str, pct: float) -> int:
    sut.set_supply_voltage(supply, _volts(sut, pct))
    return sut.now_us


@when(parsers.parse('电源"{supply}"的输入电压变为{pct:g} % Un并持续{span:d} ms,然后恢复到100 % Un'),
      target_fixture="t_action")
@when(parsers.parse('the input of supply "{supply}" stays at {pct:g} % of Un for {span:d} ms, then returns to '
                    '100 % of Un'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str, pct: float, span: int) -> int:
    start = sut.now_us
    sut.set_supply_voltage(supply, _volts(sut, pct))
    sut.advance_ms(span)
    sut.set_supply_voltage(supply, _volts(sut, 100))
    return start


@when(parsers.parse('电源"{supply}"的输入电压跌落到额定连续范围以下,持续时间比其额定短时跌落长{extra:d} ms,'
                    '然后恢复到100 % Un'), target_fixture="t_action")
@when(parsers.parse('the input of supply "{supply}" dips below its rated continuous range for {extra:d} ms longer '
                    'than its rated short dip, then returns to 100 % of Un'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str, extra: int) -> int:
    """Halfway between the declared short dip's voltage and the continuous range's low end: a dip the SUT
    says it rides out for its declared time, held longer than that."""
    rated = sut.rated_limits()
    volts = (rated["short dip supply voltage V"] + rated["continuous supply voltage V"][0]) / 2
    start = sut.now_us
    sut.set_supply_voltage(supply, volts)
    sut.advance_ms(rated["short dip ms"] + extra)
    sut.set_supply_voltage(supply, _volts(sut, 100))
    return start


@when(parsers.parse('电源"{supply}"中断{span:g} ms'), target_fixture="t_action")
@when(parsers.parse('the supply "{supply}" is interrupted for {span:g} ms'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str, span: float) -> int:
    sut.interrupt_supply(supply, us(span))
    return sut.now_us


# -- temperature ------------------------------------------------------------------------------------
@given(parsers.parse('"{unit}"的温度为{celsius:g} °C'))
@given(parsers.parse('the temperature of "{unit}" is {celsius:g} °C'))
@when(parsers.parse('"{unit}"的温度变为{celsius:g} °C'), target_fixture="t_action")
@when(parsers.parse('the temperature of "{unit}" changes to {celsius:g} °C'), target_fixture="t_action")
def _(sut: TrainDriver, unit: str, celsius: float) -> int:
    sut.set_temperature(unit, celsius)
    return sut.now_us


@when(parsers.parse('"{unit}"的温度升至比其额定最高工作温度高{delta:g} °C'), target_fixture="t_action")
@when(parsers.parse('the temperature of "{unit}" rises to {delta:g} °C above its rated maximum'),
      target_fixture="t_action")
def _(sut: TrainDriver, unit: str, delta: float) -> int:
    sut.set_temperature(unit, sut.rated_limits()["operating temperature C"][1] + delta)
    return sut.now_us


@when(parsers.parse('"{unit}"的温度降至比其额定最低工作温度低{delta:g} °C'), target_fixture="t_action")
@when(parsers.parse('the temperature of "{unit}" falls to {delta:g} °C below its rated minimum'),
      target_fixture="t_action")
def _(sut: TrainDriver, unit: str, delta: float) -> int:
    sut.set_temperature(unit, sut.rated_limits()["operating temperature C"][0] - delta)
    return sut.now_us


# -- interference -----------------------------------------------------------------------------------
@when(parsers.parse('"{a}"与"{b}"之间的环网链路受到{kv:g} kV电快速瞬变脉冲群干扰{span:d} ms'),
      target_fixture="t_action")
@when(parsers.parse('bursts of {kv:g} kV hit the ring link between "{a}" and "{b}" for {span:d} ms'),
      target_fixture="t_action")
def _(sut: TrainDriver, kv: float, a: str, b: str, span: int) -> int:
    sut.interfere(f"{a}~{b}", kv, us(span))
    return sut.now_us


@when(parsers.parse('自诊断传输线受到{kv:g} kV电快速瞬变脉冲群干扰{span:d} ms'), target_fixture="t_action")
@when(parsers.parse('bursts of {kv:g} kV hit the self-diagnostic line for {span:d} ms'), target_fixture="t_action")
def _(sut: TrainDriver, kv: float, span: int) -> int:
    sut.interfere("selfdiag", kv, us(span))
    return sut.now_us


@when(parsers.parse('"{a}"与"{b}"之间的环网链路受到{factor:g}倍额定抗扰度等级的电快速瞬变脉冲群干扰'
                    '{span:d} ms'), target_fixture="t_action")
@when(parsers.parse('bursts of {factor:g} times the rated immunity level hit the ring link between "{a}" and "{b}" '
                    'for {span:d} ms'), target_fixture="t_action")
def _(sut: TrainDriver, factor: float, a: str, b: str, span: int) -> int:
    sut.interfere(f"{a}~{b}", factor * sut.rated_limits()["burst immunity kV"], us(span))
    return sut.now_us


@when(parsers.parse('自诊断传输线受到{factor:g}倍额定抗扰度等级的电快速瞬变脉冲群干扰{span:d} ms'),
      target_fixture="t_action")
@when(parsers.parse('bursts of {factor:g} times the rated immunity level hit the self-diagnostic line for {span:d} ms'),
      target_fixture="t_action")
def _(sut: TrainDriver, factor: float, span: int) -> int:
    sut.interfere("selfdiag", factor * sut.rated_limits()["burst immunity kV"], us(span))
    return sut.now_us


# -- vibration --------------------------------------------------------------------------------------
@when(parsers.parse('振动使电源"{supply}"的触点每{period:g} ms断开一次,每次{length:g} ms,共{count:d}次'),
      target_fixture="t_action")
@when(parsers.parse('vibration opens the contacts of supply "{supply}" {count:d} times for {length:g} ms every '
                    '{period:g} ms'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str, count: int, length: float, period: float) -> int:
    sut.vibrate(supply, us(length), count, us(period))
    return sut.now_us


@when(parsers.parse('振动使"{a}"与"{b}"之间环网链路的光信号每{period:g} ms中断一次,每次{length:g} ms,'
                    '共{count:d}次'), target_fixture="t_action")
@when(parsers.parse('vibration breaks the light on the ring link between "{a}" and "{b}" {count:d} times for '
                    '{length:g} ms every {period:g} ms'), target_fixture="t_action")
def _(sut: TrainDriver, a: str, b: str, count: int, length: float, period: float) -> int:
    sut.vibrate(f"{a}~{b}", us(length), count, us(period))
    return sut.now_us


# -- withstand voltage and insulation ---------------------------------------------------------------
@when(parsers.parse('对"{unit}"进行{volts:g} V rms、{s:g} s的耐压试验'), target_fixture="t_action")
@when(parsers.parse('"{unit}" is given a withstand-voltage test at {volts:g} V rms for {s:g} s'),
      target_fixture="t_action")
def _(sut: TrainDriver, unit: str, volts: float, s: float) -> int:
    sut.withstand_test(unit, volts, us(s * 1000))
    return sut.now_us


@when(parsers.parse('对"{unit}"以其额定试验电压的{factor:g}倍进行{s:g} s的耐压试验'), target_fixture="t_action")
@when(parsers.parse('"{unit}" is given a withstand-voltage test at {factor:g} times its rated test voltage for '
                    '{s:g} s'), target_fixture="t_action")
def _(sut: TrainDriver, unit: str, factor: float, s: float) -> int:
    sut.withstand_test(unit, factor * sut.rated_limits()["withstand voltage V rms"], us(s * 1000))
    return sut.now_us


@then(parsers.parse('"{unit}"的绝缘电阻不小于{mohm:g} MOhm'))
@then(parsers.parse('the insulation resistance of "{unit}" is at least {mohm:g} MOhm'))
def _(sut: TrainDriver, unit: str, mohm: float) -> None:
    got = sut.insulation_resistance(unit)
    assert got >= mohm, f"{unit} has {got:g} MOhm of insulation resistance, less than {mohm:g} MOhm"


@then(parsers.parse('"{unit}"的绝缘电阻低于{mohm:g} MOhm'))
@then(parsers.parse('the insulation resistance of "{unit}" is below {mohm:g} MOhm'))
def _(sut: TrainDriver, unit: str, mohm: float) -> None:
    got = sut.insulation_resistance(unit)
    assert got < mohm, f"{unit} still has {got:g} MOhm of insulation resistance after its insulation broke down"


# -- what the SUT declares --------------------------------------------------------------------------
def _rated(sut: TrainDriver, name: str):
    limits = sut.rated_limits()
    assert name in limits, f"the SUT declares no rated {name!r}; it declares {sorted(limits)}"
    return limits[name]


@then(parsers.parse('额定"{name}"覆盖{lo:g}至{hi:g}'))
@then(parsers.parse('the rated "{name}" covers {lo:g} to {hi:g}'))
def _(sut: TrainDriver, name: str, lo: float, hi: float) -> None:
    got_lo, got_hi = _rated(sut, name)
    assert got_lo <= lo and hi <= got_hi, f"the rated {name} is {got_lo:g} .. {got_hi:g}, not all of {lo:g} .. {hi:g}"


@then(parsers.parse('额定"{name}"不小于{value:g}'))
@then(parsers.parse('the rated "{name}" is at least {value:g}'))
def _(sut: TrainDriver, name: str, value: float) -> None:
    got = _rated(sut, name)
    assert got >= value, f"the rated {name} is {got:g}, less than {value:g}"


@then(parsers.parse('额定"{name}"不大于{value:g}'))
@then(parsers.parse('the rated "{name}" is at most {value:g}'))
def _(sut: TrainDriver, name: str, value: float) -> None:
    got = _rated(sut, name)
    assert got <= value, f"the rated {name} is {got:g}, more than {value:g}"


# -- what the network does --------------------------------------------------------------------------
_TALK = ("status.tx", "cmd.tx", "token.pass", "token.init", "token.form", "block.tx")


@then(parsers.parse('动作后{start:g} ms至{end:g} ms内"{node}"不在环网上发送任何数据'))
@then(parsers.parse('"{node}" sends nothing on the ring from {start:g} ms to {end:g} ms after the action'))
def _(sut: TrainDriver, t_action: int, node: str, start: float, end: float) -> None:
    """Fail-safe (FS-02): a board outside its rated environment stops talking rather than talk wrong."""
    assert sut.now_us >= t_action + us(end), f"the scenario ran only {ms(sut.now_us - t_action)} after the action"
    said = sorted((ev for kind in _TALK
                   for ev in sut.trace.select(kind=kind, source=node, since=t_action + us(start),
                                              until=t_action + us(end))), key=lambda ev: ev.t)
    assert not said, f"{node} kept talking: {analysis.describe(said)}"


@then(parsers.parse('"{node}"在{bound:g} ms内重新发送状态数据'))
@then(parsers.parse('"{node}" sends status data again within {bound:g} ms'))
def _(sut: TrainDriver, t_action: int, node: str, bound: float) -> None:
    first = sut.trace.first(kind="status.tx", source=f"{node}.CPU3", since=t_action)
    assert first is not None, f"{node} sent no status data in the {ms(sut.now_us - t_action)} after the action"
    assert first.t - t_action <= us(bound), f"{node} sent status data again {ms(first.t - t_action)} after the action"


@then(parsers.parse('"{a}"与"{b}"之间环网链路两端的节点丢弃被损坏的帧'))
@then(parsers.parse('the nodes beside the ring link between "{a}" and "{b}" discard the damaged frames'))
def _(sut: TrainDriver, t_action: int, a: str, b: str) -> None:
    for node, peer in ((a, b), (b, a)):
        found = sut.trace.select(kind="frame.discard", source=f"{node}.MDM8", since=t_action, frm=peer)
        assert found, f"{node} discarded no frame from {peer}"


@then("没有节点丢弃帧")
@then("no node discards a frame")
def _(sut: TrainDriver, t_action: int) -> None:
    found = sut.trace.select(kind="frame.discard", since=t_action)
    assert not found, f"frames were discarded: {analysis.describe(found)}"


@then("自诊断传输线上被损坏的帧被丢弃")
@then("the damaged frames on the self-diagnostic line are discarded")
def _(sut: TrainDriver, t_action: int) -> None:
    found = sut.trace.select(kind="sd.discard", since=t_action)
    assert found, "no self-diagnostic frame was discarded"


@then(parsers.parse('没有CI或BCU收到"{step}"以外的牵引级位'))
@then(parsers.parse('no CI or BCU receives a traction step other than "{step}"'))
def _(sut: TrainDriver, t_action: int, step: str) -> None:
    takes = [ev for ev in sut.trace.select(kind="cmd.in", since=t_action) if ev["traction_step"] is not None]
    odd = [ev for ev in takes if ev["traction_step"] != step]
    assert not odd, f"devices received other traction steps: {analysis.describe(odd)}"
