"""The driver desk (CMD-05): key and master control, direction, traction notch, brake step."""
from __future__ import annotations

from pytest_bdd import given, parsers, when

from sut.driver import TrainDriver
from steps import zh


@given(parsers.parse("司机已在{cab:d}号司机室插入钥匙"))
@given(parsers.parse("the driver has inserted the key in cab {cab:d}"))
@when(parsers.parse("司机在{cab:d}号司机室插入钥匙"), target_fixture="t_action")
@when(parsers.parse("the driver inserts the key in cab {cab:d}"), target_fixture="t_action")
def _(sut: TrainDriver, cab: int) -> int:
    sut.insert_key(cab)
    return sut.now_us


@when(parsers.parse("司机从{cab:d}号司机室拔出钥匙"), target_fixture="t_action")
@when(parsers.parse("the driver removes the key from cab {cab:d}"), target_fixture="t_action")
def _(sut: TrainDriver, cab: int) -> int:
    sut.remove_key(cab)
    return sut.now_us


@given(parsers.parse("{cab:d}号司机室的方向开关在{direction:w}位"), converters={"direction": zh.direction})
@given(parsers.parse("the direction switch of cab {cab:d} is at {direction:w}"))
@when(parsers.parse("司机将{cab:d}号司机室的方向开关置于{direction:w}位"), converters={"direction": zh.direction},
      target_fixture="t_action")
@when(parsers.parse("the driver sets the direction switch of cab {cab:d} to {direction:w}"),
      target_fixture="t_action")
def _(sut: TrainDriver, cab: int, direction: str) -> int:
    sut.set_direction(cab, direction)
    return sut.now_us


@given(parsers.parse("{cab:d}号司机室的牵引手柄在{notch:d}级"))
@given(parsers.parse("the traction notch of cab {cab:d} is at {notch:d}"))
@when(parsers.parse("司机将{cab:d}号司机室的牵引手柄移到{notch:d}级"), target_fixture="t_action")
@when(parsers.parse("the driver moves the traction notch of cab {cab:d} to {notch:d}"), target_fixture="t_action")
def _(sut: TrainDriver, cab: int, notch: int) -> int:
    sut.set_traction(cab, notch)
    return sut.now_us


@given(parsers.parse("{cab:d}号司机室的制动手柄在{step:d}级"))
@given(parsers.parse("the brake handle of cab {cab:d} is at step {step:d}"))
@when(parsers.parse("司机将{cab:d}号司机室的制动手柄移到{step:d}级"), target_fixture="t_action")
@when(parsers.parse("the driver moves the brake handle of cab {cab:d} to step {step:d}"),
      target_fixture="t_action")
def _(sut: TrainDriver, cab: int, step: int) -> int:
    sut.set_brake(cab, step)
    return sut.now_us
