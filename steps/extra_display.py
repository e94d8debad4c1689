"""Step sentences added for the extra_display features (see steps/__init__.py).

The display categories of the function class (F-DSP, F-RSD, F-VSD, F-EAD): what the cab monitor shows,
when it changes, and that it follows the train. Every "within" is measured on the `display.change` events
the monitor recorded, so a value that was already displayed before the action never satisfies a sentence
that asks for a change.
"""
from __future__ import annotations

from pytest_bdd import parsers, then

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver
from steps import analysis, budgets, messages, zh
from steps.budgets import budgeted
from steps.analysis import ms, same_value, us


def _display_changes(sut: TrainDriver, cab: int, name: str, since: int):
    return sut.trace.select(kind="display.change", source=f"car{cab}.monitor", since=since, name=name)


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"在{bound:g} ms内变为"{value}"'),
      converters={"value": zh.core_state})
@then(parsers.parse('the cab {cab:d} monitor changes "{name}" to "{value}" within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, cab: int, name: str, value: str, bound: float) -> None:
    """A change, not a state: the first value the monitor displays after the action is the wanted one,
    it comes within the bound, and it is still displayed now."""
    window = budgets.window_us(declaration, bound)

    def check() -> None:
        changes = _display_changes(sut, cab, name, t_action)
        assert changes, f"the cab {cab} monitor did not change {name} after {ms(t_action)}"
        first = changes[0]
        assert same_value(first["value"], value), (f"the cab {cab} monitor first displayed {name} as "
                                                   f"{first['value']!r}, not {value!r}: {analysis.describe(changes)}")
        delay = first.t - t_action
        assert delay <= window, f"{name} was displayed as {value} after {ms(delay)}, limit {ms(window)}"
        shown = sut.monitor(cab)["display"].get(name)
        assert same_value(shown, value), f"the cab {cab} monitor now displays {name} as {shown!r}, not {value!r}"

    budgets.within(sut, t_action, window, check)


@then(parsers.parse('{cab:d}号司机室监视器上"{name}"从未显示为"{value}"'), converters={"value": zh.core_state})
@then(parsers.parse('the cab {cab:d} monitor never displayed "{name}" as "{value}"'))
def _(sut: TrainDriver, t_action: int, cab: int, name: str, value: str) -> None:
    shown = sut.monitor(cab)["display"].get(name)
    assert shown is not None, f"the cab {cab} monitor does not display {name} at all"
    wrong = [ev for ev in _display_changes(sut, cab, name, t_action) if same_value(ev["value"], value)]
    assert not wrong, f"the cab {cab} monitor displayed {name} as {value}: {analysis.describe(wrong)}"
    assert not same_value(shown, value), f"the cab {cab} monitor displays {name} as {value}"


@then(parsers.parse('{after:g} ms起{cab:d}号司机室监视器上"{name}"保持不变'))
@then(parsers.parse('the cab {cab:d} monitor kept "{name}" unchanged from {after:g} ms on'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration, t_action: int, cab: int, name: str, after: float) -> None:
    window = budgets.window_us(declaration, after)
    shown = sut.monitor(cab)["display"].get(name)
    assert shown is not None, f"the cab {cab} monitor does not display {name} at all"
    assert sut.now_us > t_action + window, f"no time has passed {after} ms after the action"
    changes = _display_changes(sut, cab, name, t_action + window)
    assert not changes, f"the cab {cab} monitor changed {name}: {analysis.describe(changes)}"


@then(parsers.parse('"{name}"变为"{value}"后{cab:d}号司机室监视器在{bound:g} ms内随之显示'),
      converters={"value": zh.core_state})
@then(parsers.parse('the cab {cab:d} monitor follows "{name}" to "{value}" within {bound:g} ms'))
@budgeted
def _(sut: TrainDriver, declaration: ProfileDeclaration,
      t_action: int, cab: int, name: str, value: str, bound: float) -> None:
    """The train's output changed after the action, and the monitor displayed the new state within the
    bound of that change (not of the action: the output may change long after it, e.g. inside a ramp)."""
    window = budgets.window_us(declaration, bound)
    outs = [ev for ev in sut.trace.select(kind="out.change", source=name, since=t_action) if ev["value"] == value]
    assert outs, f"the {name} never became {value} after {ms(t_action)}"
    changed = outs[0].t

    def check() -> None:
        shown = [ev for ev in _display_changes(sut, cab, name, changed) if same_value(ev["value"], value)]
        assert shown, f"the {name} became {value} at {ms(changed)}, the cab {cab} monitor never displayed it"
        delay = shown[0].t - changed
        assert delay <= window, (f"the {name} became {value} at {ms(changed)}, the cab {cab} monitor displayed "
                                 f"it {ms(delay)} later, limit {ms(window)}")
        now = sut.monitor(cab)["display"].get(name)
        assert same_value(now, value), f"the cab {cab} monitor now displays {name} as {now!r}, not {value!r}"

    budgets.within(sut, changed, window, check)


@then(parsers.parse("{a:d}号与{b:d}号司机室监视器显示的数值一致"))
@then(parsers.parse("the cab {a:d} and cab {b:d} monitors display the same values"))
def _(sut: TrainDriver, a: int, b: int) -> None:
    shown_a, shown_b = sut.monitor(a)["display"], sut.monitor(b)["display"]
    assert shown_a, f"the cab {a} monitor displays nothing"
    assert shown_b, f"the cab {b} monitor displays nothing"
    differ = {name: (shown_a.get(name), shown_b.get(name)) for name in sorted(set(shown_a) | set(shown_b))
              if not same_value(shown_a.get(name), str(shown_b.get(name)))}
    assert not differ, f"cab {a} / cab {b} monitors differ: {differ}"


@then(parsers.parse('{cab:d}号司机室监视器的数据来自"{node}"'))
@then(parsers.parse('the cab {cab:d} monitor is fed by "{node}"'))
def _(sut: TrainDriver, cab: int, node: str) -> None:
    fed_by = sut.monitor(cab)["fed_by"]
    assert fed_by == node, f"the cab {cab} monitor is fed by {fed_by}, not {node}"


@then(parsers.parse('{cab:d}号司机室监视器显示"{text}"且无其他故障'), converters={"text": zh.crh2_fault})
@then(parsers.parse('the cab {cab:d} monitor shows "{text}" and no other fault'))
def _(sut: TrainDriver, declaration: ProfileDeclaration, cab: int, text: str) -> None:
    pattern, said = messages.message(declaration, text, "faults")     # in the SUT's declared words
    faults = sut.monitor(cab)["faults"]
    assert len(faults) == 1 and pattern.fullmatch(faults[0]), \
        f"the cab {cab} monitor shows {faults or 'no faults'}, expected only {said}"
