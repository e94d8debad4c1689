"""Hand every feature file to pytest-bdd, after refusing malformed ones with file:line messages.

pytest-bdd reports a malformed file as a bare exception during import, applies tags before anything
names the file, and silently keeps one of two scenarios sharing a title. Parsing each file here first
turns all three into one collection error listing `features/<file>.feature:<line>: <problem>`.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from pytest_bdd.utils import CONFIG_STACK

from outline.tree import tags as tagvocab
from outline.tree.check import Problem, feature_files, lint_feature
from outline.tree.gherkin import Feature, FeatureParseError, parse_feature


def _registered_markers() -> set[str] | None:
    """Marker names of the running pytest (pytest-bdd keeps the config on a stack); None outside pytest."""
    if not CONFIG_STACK:
        return None
    lines = CONFIG_STACK[-1].getini("markers")
    return {line.split(":", 1)[0].split("(", 1)[0].strip() for line in lines}


def _unregistered(feature: Feature, rel: str, registered: set[str]) -> list[Problem]:
    # pytest-bdd would turn such a tag into getattr(pytest.mark, tag), which --strict-markers rejects with a
    # message naming neither file nor line.
    return list(
        dict.fromkeys(
            Problem(rel, tag.line, f"@{tag.name} is neither a project tag ({', '.join(tagvocab.PLAIN)}) "
                    "nor a registered pytest marker")
            for scenario in feature.scenarios
            for tag in scenario.tags
            if ":" not in tag.name and tag.name not in tagvocab.PLAIN and tag.name not in registered
        )
    )


def _asked_items() -> set[str]:
    """The items the running pytest selects with --item (none outside pytest)."""
    if not CONFIG_STACK:
        return set()
    given = CONFIG_STACK[-1].getoption("item", default=None) or []
    return {i.strip() for value in given for i in value.split(",") if i.strip()}


def _tagged_on_request(path: Path) -> str | None:
    """The item of a feature whose tags, before `Feature:`, hold @on_request; read without parsing the file
    (a campaign's thousands of rows would cost every pytest process the parse)."""
    tags: list[str] = []
    with path.open(encoding="utf-8") as fh:
        for line in fh:
            text = line.strip()
            if text.startswith(("Feature:", "功能:", "功能：")):
                break
            if text.startswith("@"):
                tags += text.split()
    if "@on_request" not in tags:
        return None
    return next((t.partition(":")[2] for t in tags if t.startswith("@item:")), "")


def feature_paths(features_dir: str | Path, asked: set[str] | None = None) -> list[str]:
    """Every `*.feature` under features_dir (recursively), relative to it, sorted; raises CollectError.
    A feature tagged @on_request is left out unless its item is asked for (`asked`; by default the running
    pytest's --item): collecting its thousands of scenarios would cost every other run seconds."""
    features_dir = Path(features_dir).resolve()
    root = features_dir.parent
    problems: list[Problem] = []
    registered = _registered_markers()
    asked, skipped = (_asked_items() if asked is None else asked), set()
    for path in feature_files(features_dir):
        rel = path.relative_to(root).as_posix()
        unasked = _tagged_on_request(path)
        if unasked is not None and unasked not in asked:
            skipped.add(path)              # not parsed either: `outline check` lints it (tests/test_outline_repo.py)
            continue
        try:
            feature = parse_feature(path)
        except FeatureParseError as exc:
            problems.append(Problem(rel, exc.line, exc.message))
            continue
        problems += lint_feature(feature, rel)[0]
        if registered is not None:
            problems += _unregistered(feature, rel, registered)
    if problems:
        # CollectError is shown as its message alone, without a traceback through this module.
        raise pytest.Collector.CollectError("\n".join(map(str, problems)))
    return [path.relative_to(features_dir).as_posix() for path in feature_files(features_dir) if path not in skipped]
