"""The cab monitor as the driver and the maintainer see it: displayed values, equipment orders, the fault
history; and the readings behind them (mileage).

What the monitor displays arrives in status data, so every "within" here is measured from the action to
the `display.change` the monitor recorded.
"""
from __future__ import annotations

from pytest_bdd import given, parsers, then, when

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, budgets, messages, zh
from steps.budgets import budgeted
from steps.analysis import ms, same_value, us


@given(parsers.parse('已在{cab:d}号司机室监视器上将"{name}"设为"{value}"'),
       converters={"value": zh.core_state})
@given(parsers.parse('"{name}" has been ordered to "{value}" on the cab {cab:d} monitor'))
@when(parsers.parse('司机在{cab:d}号司机室监视器上将"{name}"设为"{value}"'), converters={"value": zh.core_state},
      target_fixture="t_action")
@when(parsers.parse('the driver orders "{name}" to "{value}" on the cab {cab:d} monitor'), target_fixture="t_action")
def _(sut: TrainDriver, name: str, value: str, cab: int) -> int:
    sut.monitor_order(cab, name, value)
    return sut.now_us


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"显示为"{value}"'), converters={"value": zh.core_state})
@then(parsers.parse('the cab {cab:d} monitor displays "{name}" as "{value}"'))
def _(sut: TrainDriver, cab: int, name: str, value: str) -> None:
    shown = sut.monitor(cab)["display"].get(name)
    assert same_value(shown, value), f"the cab {cab} monitor displays {name} as {shown!r}, not {value!r}"


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"在{bound:g} ms内显示为"{value}"'),
      converters={"value": zh.core_state})
@then(parsers.parse('the cab {cab:d} monitor displays "{name}" as "{value}" within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, cab: int, name: str, value: str, bound: float) -> None:
    window = budgets.window_us(declaration, bound)

    def check() -> None:
        shown = sut.monitor(cab)["display"].get(name)
        assert same_value(shown, value), f"the cab {cab} monitor displays {name} as {shown!r}, not {value!r}"
        changes = [ev for ev in sut.trace.select(kind="display.change", source=f"car{cab}.monitor", since=t_action,
                                                 name=name) if same_value(ev["value"], value)]
        if changes:
            delay = changes[0].t - t_action
            assert delay <= window, f"{name} was displayed as {value} after {ms(delay)}, limit {ms(window)}"

    budgets.within(sut, t_action, window, check)


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"的显示值在{lo:g}至{hi:g}之间'))
@then(parsers.parse('the cab {cab:d} monitor displays "{name}" between {lo:g} and {hi:g}'))
def _(sut: TrainDriver, edge_shifts: dict[str, float], cab: int, name: str, lo: float, hi: float) -> None:
    lo, hi = lo + edge_shifts.get(name, 0), hi + edge_shifts.get(name, 0)      # a reading fed clear of an edge
    shown = sut.monitor(cab)["display"].get(name)
    assert shown is not None and lo <= float(shown) <= hi, f"the cab {cab} monitor displays {name} as {shown!r}"


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"的显示值在{bound:g} ms内进入{lo:g}至{hi:g}之间'))
@then(parsers.parse('the cab {cab:d} monitor displays "{name}" between {lo:g} and {hi:g} within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, edge_shifts: dict[str, float],
      t_action: int, cab: int, name: str, lo: float, hi: float, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    lo, hi = lo + edge_shifts.get(name, 0), hi + edge_shifts.get(name, 0)      # a reading fed clear of an edge

    def check() -> None:
        changes = sut.trace.select(kind="display.change", source=f"car{cab}.monitor", since=t_action, name=name)
        hit = next((ev for ev in changes if lo <= float(ev["value"]) <= hi), None)
        assert hit is not None, f"{name} was never displayed between {lo:g} and {hi:g}: {analysis.describe(changes)}"
        assert hit.t - t_action <= window, f"{name} reached the band after {ms(hit.t - t_action)}"

    budgets.within(sut, t_action, window, check)


@then(parsers.parse("里程在{lo:g}至{hi:g} km之间"))
@then(parsers.parse("the mileage is between {lo:g} and {hi:g} km"))
def _(sut: TrainDriver, lo: float, hi: float) -> None:
    km = sut.reading("mileage")
    assert lo <= km <= hi, f"the mileage is {km:.6f} km, outside {lo:g}..{hi:g} km"


# The maintenance view's lines are found in the SUT's own words: the feature names a message of the form
# (sut/contract/form.yaml, crh2 texts, view maintenance) and the SUT's declaration words it (steps/messages.py).
@then(parsers.re(r'(?P<cab>\d+)号司机室的检修画面列出"(?P<text>[^"]+)"'),
      converters={"cab": int, "text": zh.crh2_record})
@then(parsers.re(r'the maintenance view of cab (?P<cab>\d+) lists "(?P<text>[^"]+)"'), converters={"cab": int})
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = messages.message(declaration, text, "maintenance")
    history = sut.monitor(cab)["maintenance"]
    assert any(pattern.search(line) for line in history), \
        f"the maintenance view does not list {said}; it lists {history or 'nothing'}"
    garbled = [line for line in history if not line.isprintable()]
    assert not garbled, f"the maintenance view shows lines a driver cannot read: {garbled}"


@then(parsers.parse('{cab:d}号司机室的检修画面中"{first}"列在"{second}"之前'),
      converters={"first": zh.crh2_record, "second": zh.crh2_record})
@then(parsers.parse('the maintenance view of cab {cab:d} lists "{first}" before "{second}"'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, first: str, second: str) -> None:
    history = sut.monitor(cab)["maintenance"]
    found = {t: messages.message(declaration, t, "maintenance") for t in (first, second)}
    where = {t: next((i for i, line in enumerate(history) if pattern.search(line)), None)
             for t, (pattern, _) in found.items()}
    missing = [found[t][1] for t, i in where.items() if i is None]
    assert not missing, f"the maintenance view does not list {' nor '.join(missing)}; it lists {history or 'nothing'}"
    assert where[first] < where[second], f"{found[second][1]} is listed before {found[first][1]}: {history}"


@then(parsers.parse('"{master}"保存有"{node}"关于"{board}"{event:w}的故障记录'),
      converters={"event": zh.core_event})
@then(parsers.parse('"{master}" holds a fault record of "{node}" saying "{board}" {event:w}'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, master: str, node: str, board: str, event: str) -> None:
    records = [r.rstrip(b"\0").decode("ascii", "replace") for r in sut.block_store(master).get(node, [])]
    want = f"|{node}|{board}|{analysis.record_event(declaration, event)}"
    assert any(r.startswith("F|") and r.endswith(want) for r in records), f"{master} holds {records} from {node}"


@then(parsers.parse('每个CI在{bound:g} ms内收到"{direction}"方向指令'),
      converters={"direction": zh.direction})
@then(parsers.parse('every CI receives direction "{direction}" within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, direction: str, bound: float) -> None:
    window = budgets.window_us(declaration, bound)
    cis = [d for d in analysis.command_devices(sut) if d.endswith(".CI")]
    analysis.expect_taken(sut, cis, t_action, window, f"direction {direction}", direction=direction)
