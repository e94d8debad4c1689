"""outline/mutate/quick_trampoline.py: mutmut's trampoline with its globals swapped records and routes exactly
as mutmut's own, on functions wrapped by mutmut's real trampoline (installed with make test and make mutate)."""
from __future__ import annotations

import os
from collections import defaultdict
from pathlib import Path

import pytest

trampoline = pytest.importorskip("mutmut.mutation.trampoline")
from mutmut.state import state  # noqa: E402

from outline.mutate import quick_trampoline  # noqa: E402

MODULE = __name__


def _orig_inner(x: int) -> int:
    return x + 1


def _mutant_inner(x: int) -> int:
    return x - 1


def _orig_outer(x: int) -> int:
    return inner(inner(x)) * 2


def _orig_gen(n: int):
    for i in range(n):
        yield inner(i)
    return "done"


# What mutmut writes into a mutated module: a table per function, the function wrapped by the trampoline.
_inner_table = {"_mutmut_orig": _orig_inner, "x_inner__mutmut_1": _mutant_inner}
_outer_table = {"_mutmut_orig": _orig_outer}
_gen_table = {"_mutmut_orig": _orig_gen}
_orig_inner.__name__, _mutant_inner.__name__ = "x_inner__mutmut_orig", "x_inner__mutmut_1"
_orig_outer.__name__, _orig_gen.__name__ = "x_outer__mutmut_orig", "x_gen__mutmut_orig"


@trampoline.wrap_in_trampoline(_inner_table)
def inner(x: int) -> int:
    return _orig_inner(x)


@trampoline.wrap_in_trampoline(_outer_table)
def outer(x: int) -> int:
    return _orig_outer(x)


@trampoline.wrap_in_trampoline(_gen_table)
def gen(n: int):
    return (yield from _orig_gen(n))


def _drive() -> tuple:
    values = [outer(3), inner(5), list(gen(3))]
    g = gen(2)
    values.append([next(g), next(g)])
    with pytest.raises(StopIteration) as stop:
        next(g)
    values.append(stop.value.value)
    return tuple(map(repr, values))


def _run(mutant: str, quick: bool, monkeypatch: pytest.MonkeyPatch, recorders: bool = False) -> tuple:
    """What the functions return under `mutant`, with what mutmut recorded (the map run); with `recorders`,
    the trampolines of this module rebound to quick_trampoline's recorders after the swap."""
    monkeypatch.setenv("MUTANT_UNDER_TEST", mutant)
    monkeypatch.setattr(state(), "_stats", set())
    monkeypatch.setattr(state(), "function_dependencies", defaultdict(set))
    installed = quick_trampoline.install() if quick else False
    try:
        rebound = quick_trampoline.install_recorders(Path(__file__)) if recorders else 0
        assert rebound == (3 if recorders and mutant == "stats" else 0)
        values = _drive()
    finally:
        quick_trampoline.uninstall()
    assert installed == quick
    assert outer.__code__.co_name == "_trampoline_wrapper"             # every trampoline back
    deps = {k: sorted(v) for k, v in state().function_dependencies.items()}
    return values, sorted(state()._stats), deps


@pytest.mark.parametrize("mutant", ["stats", "", f"{MODULE}.x_inner__mutmut_1", "other.module.x_f__mutmut_1"])
def test_the_swapped_trampoline_returns_and_records_what_mutmut_own_does(mutant: str,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    assert _run(mutant, True, monkeypatch) == _run(mutant, False, monkeypatch)


def test_the_map_run_s_recorders_record_what_mutmut_own_trampolines_do(monkeypatch: pytest.MonkeyPatch) -> None:
    assert _run("stats", True, monkeypatch, recorders=True) == _run("stats", False, monkeypatch)


def test_a_recorder_and_a_trampoline_held_elsewhere_share_one_call_stack(monkeypatch: pytest.MonkeyPatch) -> None:
    held = {"outer": outer}                  # a table built at import time keeps mutmut's trampoline
    monkeypatch.setenv("MUTANT_UNDER_TEST", "stats")
    monkeypatch.setattr(state(), "_stats", set())
    monkeypatch.setattr(state(), "function_dependencies", defaultdict(set))
    quick_trampoline.install()
    try:
        quick_trampoline.install_recorders(Path(__file__))
        assert held["outer"] is not outer and held["outer"](3) == 10
    finally:
        quick_trampoline.uninstall()
    assert dict(state().function_dependencies) == {f"{MODULE}.x_inner": {f"{MODULE}.x_outer"}}


def test_the_map_run_records_each_function_with_its_callers(monkeypatch: pytest.MonkeyPatch) -> None:
    values, hits, deps = _run("stats", True, monkeypatch)
    assert hits == [f"{MODULE}.x_gen", f"{MODULE}.x_inner", f"{MODULE}.x_outer"]
    # A generator's body runs after its trampoline has returned: mutmut records no caller there either.
    assert deps == {f"{MODULE}.x_inner": [f"{MODULE}.x_outer"]}
    assert values[0] == repr(10)


def test_a_mutant_is_routed_to_and_everything_goes_back_after_the_session(monkeypatch: pytest.MonkeyPatch) -> None:
    saved = {name: getattr(trampoline, name) for name in quick_trampoline._SWAPPED}
    values, _, _ = _run(f"{MODULE}.x_inner__mutmut_1", True, monkeypatch)
    assert values[:2] == (repr(2), repr(4))                  # ((3-1)-1)*2 and 5-1: the mutant ran
    assert {name: getattr(trampoline, name) for name in quick_trampoline._SWAPPED} == saved
    assert trampoline.os is os


def test_a_stack_depth_limit_leaves_mutmut_as_it_is(monkeypatch: pytest.MonkeyPatch) -> None:
    from mutmut.configuration import config
    mutmut_own = trampoline.get_mutant_under_test
    monkeypatch.setattr(config(), "max_stack_depth", 3)
    assert quick_trampoline.install() is False
    assert trampoline.get_mutant_under_test is mutmut_own


def test_a_recorder_holds_only_its_function_s_name_and_original(monkeypatch: pytest.MonkeyPatch) -> None:
    # bulk.py reads the closure of a function a train holds (a callback) and refuses mutmut's state: a recorder
    # holding it made the map run simulate such trains frame by frame (H-EMC-02 never reached bulk.slope).
    monkeypatch.setenv("MUTANT_UNDER_TEST", "stats")
    quick_trampoline.install()
    try:
        quick_trampoline.install_recorders(Path(__file__))
        cells = [cell.cell_contents for cell in outer.__closure__]
    finally:
        quick_trampoline.uninstall()
    assert sorted(type(c).__name__ for c in cells) == ["function", "str"]
