"""Reaction-time budgets (steps/budgets.py): the figure a feature writes where no requirement gives one, plus
the SUT's declared margin; the steps that use one are marked and counted apart."""
from __future__ import annotations

import inspect
from pathlib import Path

import pytest

import steps
from outline.tree.assertions import KINDS, count
from outline.plugin.stepdefs import definitions_in_modules
from steps import budgets
from sut.backends import resolve
from sut.contract import declaration as declarations

ROOT = Path(__file__).resolve().parents[1]


def _crh2(path: str = "sut/reference/declaration.yaml") -> declarations.ProfileDeclaration:
    found = declarations.load(ROOT / path).of("crh2")
    assert found is not None
    return found


def test_a_budget_grows_by_the_declared_margin_and_time_step() -> None:
    reference = _crh2()
    slow = _crh2("tests/declarations/slow-reactions-crh2.yaml")
    assert budgets.window_us(reference, 40) == 40_000 + reference.parameter("timing_resolution_us")
    assert budgets.window_us(slow, 40) == 80_000 + slow.parameter("timing_resolution_us")
    assert budgets.margin_us(reference) == 0 and budgets.margin_us(slow) == 40_000


def test_every_budgeted_step_reads_the_declaration() -> None:
    marked = [d for d in definitions_in_modules(steps.STEP_MODULES) if budgets.is_budgeted(d.context.step_func)]
    assert len(marked) >= 20, f"only {len(marked)} budgeted step definitions"
    for d in marked:
        assert "declaration" in inspect.signature(d.context.step_func).parameters, f"{d} ignores the declaration"


def test_the_budget_timed_assertions_are_counted_apart() -> None:
    counts = count(ROOT / "features")
    assert counts["crh2"][KINDS[1]] > 0
    assert counts["metro-tcn"][KINDS[1]] == 0     # metro-tcn's bounds are the requirements' own (TCN-03..07)


def test_within_runs_the_sut_on_only_when_the_check_fails_early() -> None:
    sut = resolve("reference").open("crh2")
    sut.power_on()
    sut.advance(100_000)
    start = sut.now_us
    budgets.within(sut, start, 50_000, lambda: None)
    assert sut.now_us == start, "a check that passes at once must not move the simulation"

    def after_the_window() -> None:
        assert sut.now_us >= start + 50_000, "too early"

    budgets.within(sut, start, 50_000, after_the_window)
    assert sut.now_us == start + 50_000
    with pytest.raises(AssertionError):
        budgets.within(sut, start, 50_000, lambda: (_ for _ in ()).throw(AssertionError("never")))
