"""Feature files as the outline tools see them, parsed with pytest-bdd's own Gherkin front end.

pytest-bdd's `Feature.scenarios` is a dict keyed by title, so a duplicated title silently replaces the first
scenario. We read the raw Gherkin document instead (same parser, same errors) and keep every scenario, with
tag and step line numbers, so checks can name file:line.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from pytest_bdd.exceptions import GherkinParseError
from pytest_bdd.gherkin_parser import get_gherkin_document
from pytest_bdd.parser import render_string
from pytest_bdd.types import STEP_TYPE_BY_PARSER_KEYWORD


@dataclass(frozen=True)
class Tag:
    name: str  # without the leading @
    line: int


@dataclass(frozen=True)
class Step:
    keyword: str  # as written: Given, When, Then, And, But, *
    type: str  # given/when/then, And/But resolved to the step before, as pytest-bdd does
    text: str
    line: int

    def render(self, example: dict[str, str]) -> Step:
        return Step(self.keyword, self.type, render_string(self.text, example), self.line)


@dataclass(frozen=True)
class Examples:
    line: int
    tags: tuple[Tag, ...]
    rows: tuple[tuple[int, dict[str, str]], ...]  # (line, {param: value})


@dataclass
class Scenario:
    title: str
    line: int
    tags: tuple[Tag, ...]  # own tags plus those inherited from the rule and the feature
    steps: list[Step]  # background steps first
    examples: list[Examples] = field(default_factory=list)
    rule: str | None = None

    @property
    def tag_names(self) -> set[str]:
        return {tag.name for tag in self.tags}

    def tag_values(self, kind: str) -> list[str]:
        prefix = f"{kind}:"
        return sorted({t.name[len(prefix) :] for t in self.tags if t.name.startswith(prefix)})

    def instances(self) -> list[tuple[int, list[Step]]]:
        """(line, steps) per run: one per Examples row for an outline, else one at the scenario line."""
        rows = [row for ex in self.examples for row in ex.rows]
        if not rows:
            return [(self.line, self.steps)]
        return [(line, [step.render(example) for step in self.steps]) for line, example in rows]


@dataclass
class Feature:
    path: Path
    name: str
    line: int
    tags: tuple[Tag, ...]
    scenarios: list[Scenario]


class FeatureParseError(Exception):
    def __init__(self, path: Path, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path, self.line, self.message = path, line, message


def _tags(raw) -> tuple[Tag, ...]:
    return tuple(Tag(t.name.lstrip("@"), t.location.line) for t in raw)


def _steps(path: Path, raw) -> list[Step]:
    steps: list[Step] = []
    current = None
    for step in raw:
        current = STEP_TYPE_BY_PARSER_KEYWORD.get(step.keyword_type, current)
        if current is None:
            # Same rule as pytest-bdd, which would refuse the file at import with a less precise message.
            raise FeatureParseError(
                path, step.location.line, f"first step must start with Given, When or Then, not {step.keyword}"
            )
        steps.append(Step(step.keyword.strip(), current, step.text, step.location.line))
    return steps


def _scenario(path: Path, raw, inherited: tuple[Tag, ...], background: list[Step], rule: str | None) -> Scenario:
    examples = []
    for ex in raw.examples:
        header = [cell.value for cell in ex.table_header.cells] if ex.table_header else []
        rows = tuple(
            (row.location.line, dict(zip(header, (cell.value or "" for cell in row.cells), strict=True)))
            for row in ex.table_body or []
        )
        examples.append(Examples(ex.location.line, _tags(ex.tags), rows))
    return Scenario(
        title=raw.name,
        line=raw.location.line,
        tags=_tags(raw.tags) + inherited,
        steps=background + _steps(path, raw.steps),
        examples=examples,
        rule=rule,
    )


def parse_feature(path: str | Path) -> Feature:
    path = Path(path)
    try:
        doc = get_gherkin_document(str(path))
    except GherkinParseError as exc:
        raise FeatureParseError(path, exc.line, exc.message) from None
    except OSError as exc:
        raise FeatureParseError(path, 0, str(exc)) from None
    except KeyError:
        # gherkin yields no "feature" key for a file without `Feature:`; pytest-bdd then dies on a KeyError.
        raise FeatureParseError(path, 1, "no Feature: in file") from None
    raw = doc.feature
    feature_tags = _tags(raw.tags)
    feature = Feature(path, raw.name, raw.location.line, feature_tags, [])
    background: list[Step] = []
    for child in raw.children:
        if child.background:
            background = _steps(path, child.background.steps)
        elif child.scenario:
            feature.scenarios.append(_scenario(path, child.scenario, feature_tags, background, None))
        elif child.rule:
            rule = child.rule
            rule_tags = _tags(rule.tags) + feature_tags
            rule_background = list(background)
            for rule_child in rule.children:
                if rule_child.background:
                    rule_background = background + _steps(path, rule_child.background.steps)
                elif rule_child.scenario:
                    feature.scenarios.append(
                        _scenario(path, rule_child.scenario, rule_tags, rule_background, rule.name)
                    )
    return feature
