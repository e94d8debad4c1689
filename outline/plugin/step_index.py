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
import re
from collections.abc import Iterator
from typing import Any

from pytest_bdd import parsers
from pytest_bdd.compat import get_fixture_names, getfixturedefs
from pytest_bdd.steps import step_function_context_registry
from pytest_bdd.utils import registry_get_safe

# The module, not the function `pytest_bdd.scenario` that the package exports under the same name.
_SCENARIO = importlib.import_module("pytest_bdd.scenario")
# pytest-bdd's own scan, kept for the equality test and as the fallback for items outside a module.
SCAN = _SCENARIO.find_fixturedefs_for_step


_REGEX_SPECIAL = frozenset(".^$*+?{}[]\\|()")
_QUANTIFIERS = frozenset("*+?{")


def literal_prefix(parser: Any) -> tuple[str, bool]:
    """(text every step this parser matches starts with, whether to compare it ignoring case). Conservative:
    a shorter prefix only lets more candidates through to the parser itself, never fewer."""
    name = getattr(parser, "name", None)
    if not isinstance(name, str):
        return "", False
    if isinstance(parser, parsers.string):
        return name, False
    if isinstance(parser, parsers.parse):                 # cfparse too: case-insensitive by default
        head = name.split("{", 1)[0]
        return _ascii_head(head), True
    if isinstance(parser, parsers.re):
        if _top_level_alternation(name):
            return "", False                              # "the a|an b": no common start
        head: list[str] = []
        for ch in name:
            if ch in _REGEX_SPECIAL:
                if ch in _QUANTIFIERS and head:
                    head.pop()                            # "ab?" : the b is optional
                break
            head.append(ch)
        text = "".join(head)
        if parser.regex.flags & re.IGNORECASE:
            return _ascii_head(text), True
        return text, False
    return "", False


def literal_chunks(parser: Any) -> tuple[str, ...]:
    """For a parse format: its literal pieces between fields, lowercased, each of which a matching step's
    text contains (parse matches literals as written, ignoring case); () where that is not certain."""
    name = getattr(parser, "name", None)
    if not isinstance(parser, parsers.parse) or not isinstance(name, str) or "{{" in name or "}}" in name:
        return ()
    chunks = re.split(r"\{[^{}]*\}", name)
    return tuple(c.lower() for c in chunks if len(c) >= 3 and all(ch.isascii() or ch.lower() == ch == ch.upper()
                                                                    for ch in c))


def _top_level_alternation(pattern: str) -> bool:
    depth, escaped, in_class = 0, False, False
    for ch in pattern:
        if escaped:
            escaped = False
        elif ch == "\\":
            escaped = True
        elif in_class:
            in_class = ch != "]"
        elif ch == "[":
            in_class = True
        elif ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        elif ch == "|" and depth == 0:
            return True
    return False


def _ascii_head(text: str) -> str:
    """The ASCII start of text: compared lowercased, where Unicode case folding has no surprise."""
    for i, ch in enumerate(text):
        if not ch.isascii():
            return text[:i]
    return text


class StepIndex:
    """Per module: the step definitions it sees, by their literal prefix, so that a step is tried only
    against definitions whose prefix it starts with and whose literal pieces it contains (the collection-time
    step check tries every distinct step of the suite: 380,000 parser calls without these filters)."""

    def __init__(self, fixturemanager: Any):
        self._fixturemanager = fixturemanager
        self._candidates: dict[str, list[tuple[Any, Any]]] = {}     # module node id -> (fixturedef, context)
        self._prefixes: dict[str, tuple] = {}         # module node id -> definitions by literal prefix
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
            candidates = self._candidates_for(scope, node)
            exact, folded, longest, chunks = self._prefixes_for(scope, candidates)
            text = step.name
            lowered = text.lower()
            found: list[int] = []
            for n in range(min(len(text), longest) + 1):        # every prefix of the text that some definition has
                found += exact.get(text[:n], ())
                found += folded.get(lowered[:n], ())
            matched = []
            for i in sorted(found):                             # the scan's order
                fixturedef, context = candidates[i]
                if (context.type is None or context.type == step.type) \
                        and all(chunk in lowered for chunk in chunks[i]) and context.parser.is_matching(text):
                    matched.append(fixturedef)
            self._matches[key] = matched
        return matched

    def _prefixes_for(self, scope: str, candidates: list[tuple[Any, Any]]):
        found = self._prefixes.get(scope)
        if found is None:
            exact: dict[str, list[int]] = {}
            folded: dict[str, list[int]] = {}
            chunks: list[tuple[str, ...]] = []
            for i, (_fixturedef, context) in enumerate(candidates):
                prefix, fold = literal_prefix(context.parser)
                (folded if fold else exact).setdefault(prefix.lower() if fold else prefix, []).append(i)
                chunks.append(literal_chunks(context.parser))
            longest = max((len(p) for table in (exact, folded) for p in table), default=0)
            found = self._prefixes[scope] = (exact, folded, longest, chunks)
        return found


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


_PATTERNS: dict[tuple[Any, str], str] = {}


def pattern_of(step_func: Any, step_type: str) -> str:
    """`<type> <pattern>` of a step function, its English pattern where it has one (the first registered
    otherwise): how a step is named in the implementer's contract."""
    key = (step_func, step_type)
    if key not in _PATTERNS:
        found = [ctx.parser.name for ctx in list(step_function_context_registry.values())
                 if ctx.step_func is step_func and ctx.type in (None, step_type)]
        english = [p for p in found if p.isascii()]
        _PATTERNS[key] = f"{step_type} {(english or found or ['?'])[0]}"
    return _PATTERNS[key]
