"""How many `Then` assertions the features make, by what backs them: a requirement (docs/requirements.md), a
requirement timed by a reaction-time budget (a step marked `@budgeted`: what happens is the requirement's, how
fast is the project's budget plus the SUT's declared margin, steps/budgets.py), a project decision (a
`@tentative` scenario: docs/decisions.md), or informative (an `@informative` scenario: what no requirement
states, reported and never failing conformance), per profile (`python -m outline assertions`).

Counted per run of a scenario (an outline row is a run), `Then` and the `And`/`But` after it alike: what a
reviewer signs off. The README's table is this output (tests/test_contract.py keeps it current)."""
from __future__ import annotations

from collections import Counter
from pathlib import Path

from outline.plugin.binding import feature_paths
from outline.tree.gherkin import parse_feature
from outline.plugin.stepdefs import definitions_in_modules, matching

KINDS = ("requirement", "requirement, budget-timed", "project decision", "informative")


def _budgeted_definitions() -> list:
    import steps                     # the step library, read as `outline check` reads it
    from steps.budgets import is_budgeted
    return [d for d in definitions_in_modules(steps.STEP_MODULES) if is_budgeted(d.context.step_func)]


def count(features_dir: str | Path) -> dict[str, Counter]:
    """profile -> Counter(kind -> Then assertions)."""
    out: dict[str, Counter] = {}
    budgeted = _budgeted_definitions()
    timed: dict[str, bool] = {}

    def kind_of(scenario_kind: str, text: str) -> str:
        if scenario_kind != "requirement":
            return scenario_kind
        if text not in timed:
            timed[text] = bool(matching("then", text, budgeted))
        return KINDS[1] if timed[text] else scenario_kind

    for path in feature_paths(features_dir, asked=set()):
        feature = parse_feature(Path(features_dir) / path)
        for scenario in feature.scenarios:
            kind = ("informative" if "informative" in scenario.tag_names
                    else "project decision" if "tentative" in scenario.tag_names else "requirement")
            for profile in scenario.tag_values("profile") or ["-"]:
                for _, steps in scenario.instances():
                    counter = out.setdefault(profile, Counter())
                    for step in steps:
                        if step.type == "then":
                            counter[kind_of(kind, step.text)] += 1
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
