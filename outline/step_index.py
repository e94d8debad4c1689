"""Step definitions indexed once per scope, instead of pytest-bdd 9.0.1's scan of every fixture per step.

For each step it runs, pytest-bdd (`scenario.find_fixturedefs_for_step`) asks pytest for the definitions of
every fixture name visible to the item (about 700 step definitions here, English and zh-CN, plus the
ordinary fixtures) and tries each step parser on the step's text: ~1,500 lookups per step, 5,000 steps a
run. Which step definitions an item sees depends only on where it lives (its module, the conftests and
plugins above it), and step definitions are all registered by the end of collection, so the index reads
the candidates once per module and remembers the matches per (module, step type, step text). It yields
the same fixture definitions in the same order as pytest-bdd's scan (`tests/test_step_index.py` checks
every step of every feature against it); pytest-bdd then does the rest (scope ordering, injection).
"""
from __future__ import annotations

import importlib
from collections.abc import Iterator
from typing import Any

from pytest_bdd.compat import get_fixture_names, getfixturedefs
from pytest_bdd.steps import step_function_context_registry
from pytest_bdd.utils import registry_get_safe

# The module, not the function `pytest_bdd.scenario` that the package exports under the same name.
_SCENARIO = importlib.import_module("pytest_bdd.scenario")
# pytest-bdd's own scan, kept for the equality test and as the fallback for items outside a module.
SCAN = _SCENARIO.find_fixturedefs_for_step


class StepIndex:
    def __init__(self, fixturemanager: Any):
        self._fixturemanager = fixturemanager
        self._candidates: dict[str, list[tuple[Any, Any]]] = {}     # module node id -> (fixturedef, context)
        self._matches: dict[tuple[str, str | None, str], list[Any]] = {}

    def _scope(self, node: Any) -> str | None:
        return getattr(node.parent, "nodeid", None)

    def _candidates_for(self, scope: str, node: Any) -> list[tuple[Any, Any]]:
        found = self._candidates.get(scope)
        if found is None:
            found = []
            for name in get_fixture_names(fixturemanager=self._fixturemanager):
                for fixturedef in getfixturedefs(self._fixturemanager, name, node) or []:
                    context = step_function_context_registry.get(fixturedef.func)
                    if context is not None:
                        found.append((fixturedef, context))
            self._candidates[scope] = found
        return found

    def find(self, step: Any, node: Any) -> list[Any]:
        scope = self._scope(node)
        if scope is None:
            return list(SCAN(step, self._fixturemanager, node))
        key = (scope, step.type, step.name)
        matched = self._matches.get(key)
        if matched is None:
            matched = [fixturedef for fixturedef, context in self._candidates_for(scope, node)
                       if (context.type is None or context.type == step.type)
                       and context.parser.is_matching(step.name)]
            self._matches[key] = matched
        return matched


def _template(function: Any) -> Any:
    return registry_get_safe(_SCENARIO.scenario_wrapper_template_registry, function)


def template_of(item: Any) -> Any:
    """The pytest-bdd scenario template behind a test item (None for an item that is not a scenario)."""
    return _template(getattr(item, "obj", None))


def is_scenario(function: Any) -> bool:
    """Whether a test function is a pytest-bdd scenario."""
    return _template(function) is not None


def index_of(fixturemanager: Any) -> StepIndex:
    index = getattr(fixturemanager, "_crh2_step_index", None)
    if index is None:
        index = fixturemanager._crh2_step_index = StepIndex(fixturemanager)
    return index


def find_fixturedefs_for_step(step: Any, fixturemanager: Any, node: Any) -> Iterator[Any]:
    """Drop-in for pytest-bdd's function of the same name (same arguments, same results)."""
    return iter(index_of(fixturemanager).find(step, node))


def install() -> None:
    _SCENARIO.find_fixturedefs_for_step = find_fixturedefs_for_step
