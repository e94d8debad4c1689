"""mutmut's trampoline, made cheap for one pytest session (issue 33: the map of who reaches what took 71 min).

Every call of a function of sut/reference/ under mutmut goes through a trampoline that asks which mutant is
active: two reads of os.environ per call (encode the key, look it up, decode the value). While mutmut maps
tests to functions (MUTANT_UNDER_TEST=stats) it also reads MUTMUT_DEPENDENCY_DEPTH from os.environ, builds
the function's name, re-reads its configuration and state, and keeps the caller in a ContextVar. A scenario
makes millions of such calls: the 44 scenarios of F-ILK-01..09 took 178 s to map against 21 s run plainly.

The trampoline finds all of these as globals of its module when it is called, so for the length of one
pytest session (mutmut runs each of the map, the clean run and every mutant's run as one) they are swapped
for ones that answer the same from what cannot change inside it: the mutant named when the session started
(mutmut sets it before, never during), the environment as it was then, the name of each function worked out
once, and a plain variable for the caller (the references run on one thread and every set is undone in
order, in a `finally`, which is all a ContextVar gives them). What is recorded is what mutmut records: the
map of those 44 scenarios came out byte-identical, functions and callers (tests/test_quick_trampoline.py
checks the same on a mutated module of its own). Left as mutmut has it where its configuration asks for
more (a stack-depth limit walks the frames).
"""
from __future__ import annotations

import functools
import inspect
import os
import types
from pathlib import Path

from outline.mutate import direct_calls

MAPPING_RUN = "stats"            # mutmut's MUTANT_UNDER_TEST while it learns which tests reach which function
_SWAPPED = ("os", "get_mutant_under_test", "mangled_name_from_mutant_name", "record_trampoline_hit",
            "MutmutCallStack")
_saved: dict[str, object] = {}


class _CallStack:
    """MutmutCallStack's answers without a ContextVar: the token handed back is the value it replaced."""
    top: tuple[str | None, int] = (None, 0)

    @classmethod
    def get(cls) -> tuple[str | None, int]:
        return cls.top

    @classmethod
    def set(cls, value: tuple[str, int]) -> tuple[str | None, int]:
        token, cls.top = cls.top, value
        return token

    @classmethod
    def reset(cls, token: tuple[str | None, int]) -> None:
        cls.top = token


def install() -> bool:
    """Swap the trampoline's globals for this session; False (nothing done) outside mutmut's runs."""
    try:
        from mutmut.configuration import config
        from mutmut.mutation import trampoline
        from mutmut.state import state
    except ImportError:
        return False
    if _saved or config().max_stack_depth != -1:
        return False
    mutant = trampoline.get_mutant_under_test()
    _saved.update({name: getattr(trampoline, name) for name in _SWAPPED})
    trampoline.get_mutant_under_test = lambda: mutant
    if mutant == MAPPING_RUN:
        track = config().track_dependencies

        def record_trampoline_hit(name: str, caller: str | None = None) -> None:
            now = state()
            now._stats.add(name)
            if caller is not None and track:
                now.function_dependencies[name].add(caller)

        _CallStack.top = _saved["MutmutCallStack"].get()
        trampoline.os = types.SimpleNamespace(environ=dict(os.environ))
        trampoline.mangled_name_from_mutant_name = functools.lru_cache(maxsize=None)(
            _saved["mangled_name_from_mutant_name"])
        trampoline.record_trampoline_hit = record_trampoline_hit
        trampoline.MutmutCallStack = _CallStack
    return True


def install_recorders(root: Path) -> int:
    """In the map run, after install(): every trampoline of a module loaded from under `root` (or a class of
    one) rebound to a recorder made for its function alone, which records and routes as mutmut's does, in one
    frame instead of nine; how many names were rebound (0 outside the map run or where install() left
    mutmut as it is). The call stack is the one mutmut's own trampolines use here (_CallStack), so a
    trampoline held elsewhere (a table of handlers built at import time) records its callers alike."""
    from mutmut.mutation.trampoline import get_mutant_under_test
    from mutmut.configuration import config
    from mutmut.state import state
    if not _saved or get_mutant_under_test() != MAPPING_RUN or \
            int(trampoline_environ().get("MUTMUT_DEPENDENCY_DEPTH", "-1")) != -1:
        return 0
    _Map.now, _Map.track = state(), config().track_dependencies
    return direct_calls.rebind(root, _recorder)


def trampoline_environ() -> dict:
    from mutmut.mutation import trampoline
    return trampoline.os.environ


class _Map:
    """What the recorders record into, set by install_recorders: module globals, not closure cells, because
    bulk.py reads the closure of a function a train holds (a callback) and refuses what it cannot carry over a
    jump (mutmut's state): a recorder may hold only its function's name and original in its cells, or the map
    run would simulate those trains frame by frame and map other functions than a plain run reaches."""
    now: object = None
    track = True


def _enter(name: str) -> tuple[str | None, int]:
    caller, depth = token = _CallStack.top
    _Map.now._stats.add(name)
    if caller is not None and _Map.track:
        _Map.now.function_dependencies[name].add(caller)
    _CallStack.top = (name, depth + 1)
    return token


def _recorder(wrapper: types.FunctionType, table: dict) -> object | None:
    """mutmut's map-run branch of the trampoline for one function, with its name worked out once; None for
    a classmethod's or a coroutine's trampoline (left to mutmut's, which records the same)."""
    from mutmut.utils.format_utils import mangled_name_from_mutant_name

    wrapped, orig = wrapper.__wrapped__, table["_mutmut_orig"]
    if direct_calls.closure(direct_calls.closure(wrapper)["trampoline"]).get("is_classmethod") or \
            inspect.iscoroutinefunction(wrapped) or inspect.isasyncgenfunction(wrapped):
        return None
    name = f"{orig.__module__}.{mangled_name_from_mutant_name(orig.__name__)}"

    if inspect.isgeneratorfunction(wrapped):
        def recorder(*args, **kwargs):
            # mutmut's trampoline runs at the first next(): it records then and hands back the generator.
            token = _enter(name)
            try:
                body = orig(*args, **kwargs)
            finally:
                _CallStack.top = token
            return (yield from body)
    else:
        def recorder(*args, **kwargs):
            # _enter written out: a call of it is a frame more on every call of every reference function
            caller, depth = token = _CallStack.top
            _Map.now._stats.add(name)
            if caller is not None and _Map.track:
                _Map.now.function_dependencies[name].add(caller)
            _CallStack.top = (name, depth + 1)
            try:
                return orig(*args, **kwargs)
            finally:
                _CallStack.top = token
    return functools.update_wrapper(recorder, wrapped)


def uninstall() -> None:
    """mutmut's own trampoline globals back: the same process goes on to its next session."""
    direct_calls.uninstall()
    if not _saved:
        return
    from mutmut.mutation import trampoline
    for name, value in _saved.items():
        setattr(trampoline, name, value)
    _saved.clear()
