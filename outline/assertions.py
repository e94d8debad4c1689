"""How many `Then` assertions the features make, by what backs them: a requirement (docs/requirements.md), a
project decision (a `@tentative` scenario: docs/decisions.md), or informative (an `@informative` scenario: what
no requirement states, reported and never failing conformance), per profile (`python -m outline assertions`).

Counted per run of a scenario (an outline row is a run), `Then` and the `And`/`But` after it alike: what a
reviewer signs off. The README's table is this output (tests/test_contract.py keeps it current)."""
from __future__ import annotations

from collections import Counter
from pathlib import Path

from .binding import feature_paths
from .gherkin import parse_feature

KINDS = ("requirement", "project decision", "informative")


def count(features_dir: str | Path) -> dict[str, Counter]:
    """profile -> Counter(kind -> Then assertions)."""
    out: dict[str, Counter] = {}
    for path in feature_paths(features_dir, asked=set()):
        feature = parse_feature(Path(features_dir) / path)
        for scenario in feature.scenarios:
            kind = ("informative" if "informative" in scenario.tag_names
                    else "project decision" if "tentative" in scenario.tag_names else "requirement")
            for profile in scenario.tag_values("profile") or ["-"]:
                for _, steps in scenario.instances():
                    out.setdefault(profile, Counter())[kind] += sum(1 for s in steps if s.type == "then")
    return out


def table(features_dir: str | Path) -> str:
    counts = count(features_dir)
    lines = ["| profile | " + " | ".join(KINDS) + " | all |", "| --- |" + " --- |" * (len(KINDS) + 1)]
    total = Counter()
    for profile, c in sorted(counts.items()):
        total.update(c)
        lines.append(f"| {profile} | " + " | ".join(str(c[k]) for k in KINDS) + f" | {sum(c.values())} |")
    lines.append("| all | " + " | ".join(str(total[k]) for k in KINDS) + f" | {sum(total.values())} |")
    return "\n".join(lines)
