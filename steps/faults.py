"""Faults injected at named points: ring spans, boards, power supplies, frames; and traffic loads."""
from __future__ import annotations

from pytest_bdd import given, parsers, when

from sut.driver import TrainDriver
from steps import analysis, zh


@given(parsers.parse('"{a}"与"{b}"之间的环网链路已断开'))
@given(parsers.parse('the ring link between "{a}" and "{b}" is cut'))
@when(parsers.parse('"{a}"与"{b}"之间的环网链路断开'), target_fixture="t_action")
@when(parsers.parse('the ring link between "{a}" and "{b}" is cut'), target_fixture="t_action")
def _(sut: TrainDriver, a: str, b: str) -> int:
    sut.cut_link(a, b)
    return sut.now_us


@when(parsers.parse('"{a}"与"{b}"之间的环网链路恢复'), target_fixture="t_action")
@when(parsers.parse('the ring link between "{a}" and "{b}" is restored'), target_fixture="t_action")
def _(sut: TrainDriver, a: str, b: str) -> int:
    sut.restore_link(a, b)
    return sut.now_us


@given("所有环网链路已断开")
@given("every ring link is cut")
@when("所有环网链路断开", target_fixture="t_action")
@when("every ring link is cut", target_fixture="t_action")
def _(sut: TrainDriver) -> int:
    sut.cut_ring()
    return sut.now_us


@when(parsers.parse('下一个由"{a}"发往"{b}"的{kind}帧被损坏'), converters={"kind": zh.frame},
      target_fixture="t_action")
@when(parsers.parse('the next {kind} frame from "{a}" to "{b}" is corrupted'),
      target_fixture="t_action")
def _(sut: TrainDriver, kind: str, a: str, b: str) -> int:
    sut.corrupt_frames(a, b, kind, 1)
    return sut.now_us


# A board, or a whole unit, module or device ("car1.CCU", "car1.IO1", "car2.VVVF", the "CFSK" of an ATP).
@given(parsers.parse('板卡"{board}"已故障'))
@given(parsers.parse('board "{board}" has failed'))
@given(parsers.parse('"{board}"已故障'))
@given(parsers.parse('"{board}" has failed'))
@when(parsers.parse('板卡"{board}"故障'), target_fixture="t_action")
@when(parsers.parse('board "{board}" fails'), target_fixture="t_action")
@when(parsers.parse('"{board}"故障'), target_fixture="t_action")
@when(parsers.parse('"{board}" fails'), target_fixture="t_action")
def _(sut: TrainDriver, board: str) -> int:
    sut.fail(board)
    return sut.now_us


@when(parsers.parse('板卡"{board}"修复'), target_fixture="t_action")
@when(parsers.parse('board "{board}" is repaired'), target_fixture="t_action")
@when(parsers.parse('"{board}"修复'), target_fixture="t_action")
@when(parsers.parse('"{board}" is repaired'), target_fixture="t_action")
def _(sut: TrainDriver, board: str) -> int:
    sut.repair(board)
    return sut.now_us


@given(parsers.parse("每个LCU的{board:w}板卡已故障"))
@given(parsers.parse("the {board:w} board of every LCU has failed"))
@when(parsers.parse("每个LCU的{board:w}板卡故障"), target_fixture="t_action")
@when(parsers.parse("the {board:w} board of every LCU fails"), target_fixture="t_action")
def _(sut: TrainDriver, board: str) -> int:
    for lcu in analysis.lcus(sut):
        sut.fail(f"{lcu}.{board}")
    return sut.now_us


@given(parsers.parse('电源"{supply}"已关断'))
@given(parsers.parse('the supply "{supply}" is off'))
@when(parsers.parse('电源"{supply}"被关断'), target_fixture="t_action")
@when(parsers.parse('the supply "{supply}" is switched off'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str) -> int:
    sut.power_off(supply)
    return sut.now_us


@when(parsers.parse('电源"{supply}"重新接通'), target_fixture="t_action")
@when(parsers.parse('the supply "{supply}" is switched on again'), target_fixture="t_action")
def _(sut: TrainDriver, supply: str) -> int:
    sut.restore_power(supply)
    return sut.now_us


@when(parsers.parse('"{node}"请求以数据块方式发送一条{size:d}字节的记录'), target_fixture="t_action")
@when(parsers.parse('"{node}" asks to send a {size:d}-byte record as block data'), target_fixture="t_action")
def _(sut: TrainDriver, node: str, size: int) -> int:
    sut.request_block_transfer(node, analysis.record(size))
    return sut.now_us


@given(parsers.parse('在"{a}"与"{b}"之间的环网链路上接入分析仪'))
@given(parsers.parse('an analyser is attached to the ring link between "{a}" and "{b}"'))
def _(sut: TrainDriver, a: str, b: str) -> None:
    sut.tap_link(a, b)
