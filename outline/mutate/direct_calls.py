"""In a mutant's own run, every reference function but the mutated one called directly, not through mutmut.

mutmut wraps every function of sut/reference/ in a trampoline that asks, on every call, which mutant is
active and then calls the original or the mutant. In a mutant's run the answer cannot change: one function
runs its mutant, every other function its original. The trampolines cost a mutant's run more than a third of
its time (F-ILK-01..09's 44 scenarios: 33.4 s under the trampolines, 21 s run plainly), and `make mutate`
is mostly mutants' runs.

So once a session has collected its tests (every module it needs is loaded), each trampoline that cannot
reach the mutant under test is replaced, wherever a module or class of the project holds it, by the function
it wraps: mutmut keeps that as `__wrapped__`, the function as written in the source, with its own name,
qualified name and globals; its body is the body of the trampoline's `_mutmut_orig`. The mutated function
keeps its trampoline, and so does anything that holds a trampoline elsewhere (a table of handlers built at
import time): those still route exactly as mutmut routes. The clean run (no mutant) is served the same way.
mutmut's other runs (the map, the forced failure) need the trampoline and are left alone.

Everything is put back when the session ends. tests/test_direct_calls.py checks that a mutated project
gives mutmut's verdicts, mutant by mutant, with and without this; 82 of make mutate seed 10's mutants gave
the same verdicts both ways in 333 s of runs instead of 901 s (bench/performance-notes.md).
"""
from __future__ import annotations

import sys
import types
from pathlib import Path
from typing import Callable

_WRAPPER = "_trampoline_wrapper"           # the function mutmut's decorator returns
_replaced: list[tuple[object, str, object]] = []


def install(mutant: str, root: Path) -> int:
    """Unwrap the trampolines of the modules loaded from under `root` that cannot reach `mutant`
    ("" for the clean run); how many names were rebound."""
    if _replaced or not (mutant == "" or "__mutmut_" in mutant):
        return 0
    module_of, _, name = mutant.rpartition(".")

    def direct(wrapper: types.FunctionType, table: dict) -> object | None:
        return None if wrapper.__module__ == module_of and name in table else wrapper.__wrapped__
    return rebind(root, direct)


def rebind(root: Path, replace: Callable[[types.FunctionType, dict], object | None]) -> int:
    """Every trampoline that a module loaded from under `root` or a class defined there holds, rebound to what
    `replace(trampoline, its table of mutants)` gives (None: left); how many names were rebound. A trampoline
    found under several names gets one replacement; a staticmethod or classmethod stays one."""
    made: dict[int, object | None] = {}
    for holder in _holders(root.resolve()):
        for attr, value in list(vars(holder).items()):
            kind = type(value) if isinstance(value, (staticmethod, classmethod)) else None
            func = value.__func__ if kind else value
            if not isinstance(func, types.FunctionType) or func.__code__.co_name != _WRAPPER:
                continue
            if id(func) not in made:
                table = _table(func)
                made[id(func)] = None if table is None else replace(func, table)
            if made[id(func)] is not None:
                _replaced.append((holder, attr, value))
                setattr(holder, attr, kind(made[id(func)]) if kind else made[id(func)])
    return len(_replaced)


def uninstall() -> None:
    while _replaced:
        holder, attr, value = _replaced.pop()
        setattr(holder, attr, value)


def _holders(root: Path) -> list[object]:
    """The modules loaded from under `root`, and the classes defined in them."""
    found = []
    for module in list(sys.modules.values()):
        path = getattr(module, "__file__", None)
        if not path or not Path(path).resolve().is_relative_to(root):
            continue
        found.append(module)
        found += [v for v in vars(module).values()
                  if isinstance(v, type) and v.__module__ == module.__name__]
    return found


def closure(func: types.FunctionType) -> dict[str, object]:
    """The variables a function's closure holds, by name."""
    return {name: cell.cell_contents for name, cell in zip(func.__code__.co_freevars, func.__closure__ or ())}


def _table(wrapper: types.FunctionType) -> dict | None:
    """The trampoline's table of mutants (`mutants_<function>`), read from the closures mutmut built."""
    inner = closure(wrapper).get("trampoline")
    table = closure(inner).get("mutants_dict") if isinstance(inner, types.FunctionType) else None
    return table if isinstance(table, dict) and "_mutmut_orig" in table else None
