"""Every step of the library has a Chinese phrasing (issue 8): the same function under a second pattern of the same
step type, taking the same arguments, so a `# language: zh-CN` feature can say anything an English one can.
The Chinese sentences must not collide: a sample sentence built from each one matches that definition only."""
from __future__ import annotations

import re
from collections import defaultdict

import pytest

from outline.plugin.stepdefs import StepDef, definitions_in_modules, matching
from steps import STEP_MODULES

CJK = re.compile(r"[\u3000-\u303f\u4e00-\u9fff\uff00-\uffef]")
FIELD = re.compile(r"\{(\w*)(?::([^{}]*))?\}")
# A value of each parse type used in the library, for a sample sentence (only matching is tried, not conversion).
SAMPLE = {"d": "7", "g": "1.5", "f": "1.5", "w": "甲"}

DEFS = [d for d in definitions_in_modules(STEP_MODULES) if d.module.startswith("steps.")]


def _fields(d: StepDef) -> frozenset[str]:
    parser = d.context.parser
    if hasattr(parser, "regex"):
        return frozenset(parser.regex.groupindex)
    if hasattr(parser, "parser"):
        return frozenset(parser.parser.named_fields)
    return frozenset()


def _sample(d: StepDef) -> str | None:
    """A sentence the pattern matches, or None for a regex pattern (no general way to invert it)."""
    parser = d.context.parser
    if hasattr(parser, "regex"):
        return None
    if not hasattr(parser, "parser"):
        return d.pattern
    text = FIELD.sub(lambda m: SAMPLE.get(m.group(2) or "", "x1"), d.pattern)
    return text.replace("{{", "{").replace("}}", "}")


def _by_function() -> dict[object, list[StepDef]]:
    grouped: dict[object, list[StepDef]] = defaultdict(list)
    for d in DEFS:
        grouped[d.context.step_func].append(d)
    return grouped


def test_the_library_has_definitions() -> None:
    assert len(_by_function()) > 150


def test_every_step_has_a_chinese_phrasing() -> None:
    missing = []
    for defs in _by_function().values():
        for step_type in {d.type for d in defs}:
            typed = [d for d in defs if d.type == step_type]
            english = [d for d in typed if not CJK.search(d.pattern)]
            chinese = [d for d in typed if CJK.search(d.pattern)]
            if english and not chinese:
                missing.append(f"{english[0]} ({step_type})")
    assert not missing, f"{len(missing)} step definitions have no Chinese phrasing:\n" + "\n".join(sorted(missing))


def test_a_chinese_phrasing_takes_the_same_arguments() -> None:
    wrong = []
    for defs in _by_function().values():
        for d in defs:
            if CJK.search(d.pattern):
                english = {_fields(e) for e in defs if e.type == d.type and not CJK.search(e.pattern)}
                if english and _fields(d) not in english:
                    wrong.append(f"{d}: fields {sorted(_fields(d))}, English {[sorted(f) for f in english]}")
    assert not wrong, "\n".join(wrong)


CHINESE = [d for d in DEFS if CJK.search(d.pattern) and _sample(d) is not None]


@pytest.mark.parametrize("definition", CHINESE, ids=[f"{d.module}:{d.line}:{d.type}" for d in CHINESE])
def test_a_chinese_sentence_matches_one_definition(definition: StepDef) -> None:
    sample = _sample(definition)
    found = matching(definition.type or "given", sample, DEFS)
    assert definition.context in [f.context for f in found], f"{sample!r} does not match its own pattern"
    others = [f for f in found if f.context.step_func is not definition.context.step_func]
    assert not others, f"{sample!r} also matches {'; '.join(map(str, others))}"
