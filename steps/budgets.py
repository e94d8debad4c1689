"""Reaction-time budgets: the time a `Then` allows where no requirement gives one.

The interlocks (ILK-01..08), the cab monitor and the command paths (CMD-02..04) state what happens, not how
fast; the features still bound each reaction, or a product that never reacts would pass. The figure written
in the feature is the project's budget, composed of the requirements' own figures where they give some
(docs/decisions.md, "Reaction-time budgets"); a product adds its own delays on the way (task cycles, loops,
a slower display), so it declares `reaction_margin_ms` (IXIT, sut/contract/form.yaml) and every budget grows
by it and by the declared timing resolution. What the step checks besides the time (which device, which path,
which value) is the requirement's and is held as strictly as ever.

A budgeted step is marked (`@budgeted`) so that `python -m outline assertions` counts its assertion apart
("requirement, timed by a budget"), and the first budget a scenario uses is noted in its Allure report.
"""
from __future__ import annotations

import os
from collections.abc import Callable
from typing import TypeVar

import allure

from sut.contract.declaration import ProfileDeclaration
from sut.driver import TrainDriver

F = TypeVar("F", bound=Callable)

DECISION = "docs/decisions.md#reaction-time-budgets"
MARGIN = "reaction_margin_ms"

_noted: set[str] = set()


def budgeted(func: F) -> F:
    """Mark a step definition whose time bound is a reaction-time budget (put it below the @then lines)."""
    func.reaction_budget = True   # type: ignore[attr-defined]
    return func


def is_budgeted(func: Callable) -> bool:
    return getattr(func, "reaction_budget", False)


def margin_ms(declaration: ProfileDeclaration) -> float:
    """The declared margin; a profile whose form has none (the ATP fitted to a CRH2: its train side is the
    reference's CRH2) allows the budget alone."""
    return declaration.parameters.get(MARGIN, 0)


def margin_us(declaration: ProfileDeclaration) -> int:
    """The declared margin alone, in us: how long a product may still act on what it had before a cause."""
    return round(margin_ms(declaration) * 1000)


def window_us(declaration: ProfileDeclaration, budget_ms: float) -> int:
    """The time, in us, a reaction with this budget may take from its cause: the project's budget, the SUT's
    declared margin and one declared time step."""
    margin = margin_ms(declaration)
    test = os.environ.get("PYTEST_CURRENT_TEST", "")
    if test not in _noted:
        _noted.add(test)
        allure.attach(f"{budget_ms:g} ms (the project's budget, {DECISION}) + reaction_margin_ms {margin:g} ms "
                      f"declared by the SUT + timing_resolution_us {declaration.parameter('timing_resolution_us')}",
                      name="reaction-time budget (a project decision)", attachment_type=allure.attachment_type.TEXT)
    return round((budget_ms + margin) * 1000) + declaration.parameter("timing_resolution_us")


def within(sut: TrainDriver, start: int, window: int, check: Callable[[], None]) -> None:
    """`check()` as the SUT stands; if it fails while the window after `start` is not yet all simulated (the
    scenario waited for the written budget, a product declared a margin), the SUT runs to the window's end and
    `check()` decides. A SUT that passes at once is never advanced, so the reference's runs are unchanged."""
    try:
        check()
        return
    except AssertionError:
        if sut.now_us >= start + window:
            raise
    sut.advance(start + window - sut.now_us)
    check()


def band_on_ramp(declaration: ProfileDeclaration, rate: float | None, lo: float, hi: float) -> tuple[float, float]:
    """A band an output must switch in while its input ramps at `rate` per second (signed; None: no ramp): the
    side the ramp moves towards grows by the ground covered in the declared margin and time step, because the
    output is read where it acts, that much after the input crossed (the reference: one microsecond's worth)."""
    if not rate:
        return lo, hi
    slack = abs(rate) * (margin_us(declaration) + declaration.parameter("timing_resolution_us")) / 1e6
    return (lo, hi + slack) if rate > 0 else (lo - slack, hi)
