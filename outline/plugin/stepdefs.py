"""Step definitions as pytest-bdd 9.0.1 registers them, and the 0-or-2+ match rule both checks share.

How pytest-bdd stores a step: `@given(...)` builds a `StepFunctionContext` (type, parser, step_func,
target_fixture), records it in `pytest_bdd.steps.step_function_context_registry` keyed by a tiny marker
function, and injects `pytest.fixture(name="pytestbdd_stepdef_<type>_<pattern>")(marker)` into the module that
ran the decorator. At run time pytest-bdd scans all fixtures for such markers whose parser `is_matching` the
step text; with several at the same scope the last one registered wins silently (issue #449).

`outline check` loads the modules in `steps.STEP_MODULES` and reads those fixtures from the module globals;
the pytest plugin gets the same contexts from pytest's fixture manager. Both then call `step_problem`.
"""

from __future__ import annotations

import importlib
from collections.abc import Iterable
from dataclasses import dataclass, field

from pytest_bdd.steps import StepFunctionContext, step_function_context_registry
from pytest_bdd.utils import registry_get_safe

# pytest-bdd's own plugin defines given/when/then "trace" (drop into pdb); every run sees it.
BUILTIN_STEP_MODULES = ("pytest_bdd.plugin",)


@dataclass(frozen=True)
class StepDef:
    type: str | None  # None: @step(...) without a type matches Given, When and Then
    pattern: str
    module: str
    line: int
    context: StepFunctionContext = field(compare=False, repr=False)

    @classmethod
    def from_context(cls, context: StepFunctionContext) -> StepDef:
        func = context.step_func
        code = getattr(func, "__code__", None)
        return cls(
            type=context.type,
            pattern=context.parser.name,
            module=getattr(func, "__module__", "?"),
            line=code.co_firstlineno if code else 0,
            context=context,
        )

    def matches(self, step_type: str, text: str) -> bool:
        return (self.type is None or self.type == step_type) and bool(self.context.parser.is_matching(text))

    def __str__(self) -> str:
        return f"{self.module}:{self.line} ({self.pattern!r})"


def context_of(obj: object) -> StepFunctionContext | None:
    """The StepFunctionContext behind a module global or a FixtureDef.func, if it is a step definition."""
    unwrap = getattr(obj, "_get_wrapped_function", None)  # pytest >= 8.4 wraps fixture functions
    raw = unwrap() if callable(unwrap) else obj
    return registry_get_safe(step_function_context_registry, raw)


def definitions_in_modules(module_names: Iterable[str]) -> list[StepDef]:
    """Import each module (as pytest would load it as a plugin) and collect its step definitions, once each."""
    seen: set[int] = set()
    found: list[StepDef] = []
    for name in [*BUILTIN_STEP_MODULES, *module_names]:
        module = importlib.import_module(name)
        for value in vars(module).values():
            context = context_of(value)
            # A module re-exporting another's steps (from x import *) must not look like an ambiguity.
            if context is not None and id(context) not in seen:
                seen.add(id(context))
                found.append(StepDef.from_context(context))
    return found


def matching(step_type: str, text: str, candidates: Iterable[StepDef]) -> list[StepDef]:
    seen: set[int] = set()
    out = []
    for d in candidates:
        if id(d.context) not in seen and d.matches(step_type, text):
            seen.add(id(d.context))
            out.append(d)
    return out


def step_problem(step_type: str, text: str, candidates: Iterable[StepDef]) -> str | None:
    """None if exactly one definition matches; otherwise the message for `<file>:<line>: <message>`."""
    shown = f"{step_type.capitalize()} {text}"
    matched = matching(step_type, text, candidates)
    if not matched:
        return f'unknown step "{shown}"'
    if len(matched) > 1:
        return f'ambiguous step "{shown}" matches {len(matched)} definitions: ' + "; ".join(map(str, matched))
    return None
