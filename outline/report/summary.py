"""One-line verdict of a run from its allure results: `python -m outline.report.summary reports/allure-results`.

Reads the `*-result.json` files allure-pytest-bdd writes (one per scenario run), so `make report` can say
what happened without opening the HTML.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

# "not applicable" is ISO/IEC 9646's verdict for a scenario needing an option the SUT does not claim: a skip
# whose reason says so (steps/verdicts.py), counted apart from the other skips.
# An "informative deviation" is a failed Then of an @informative scenario: a check of what no requirement states
# (docs/decisions.md), shown to the reviewer and never failing conformance; an xfail to pytest.
STATUSES = ("passed", "failed", "broken", "informative deviation", "not applicable", "skipped")
WORST_FIRST = ("broken", "failed", "unknown", "skipped", "informative deviation", "not applicable", "passed")
NOT_APPLICABLE = "not applicable: "         # how such a skip's reason starts (steps/verdicts.py raises it)
INFORMATIVE = "informative deviation: "     # how an informative check's failure reads (steps/verdicts.py)


def verdict(result: dict) -> str:
    """A result's status, with "not applicable" told apart from the other skips."""
    status = result.get("status", "unknown")
    message = str((result.get("statusDetails") or {}).get("message", ""))
    if status == "skipped" and NOT_APPLICABLE in message:
        return "not applicable"
    if status == "skipped" and INFORMATIVE in message:
        return "informative deviation"
    return status


@dataclass
class Summary:
    counts: Counter = field(default_factory=Counter)
    covered: set[str] = field(default_factory=set)  # requirement IDs of passing scenarios
    touched: set[str] = field(default_factory=set)  # requirement IDs of every scenario that ran
    not_passed: list[tuple[str, str]] = field(default_factory=list)  # (status, scenario name)
    by_profile: dict[str, Counter] = field(default_factory=dict)     # train profile -> status counts
    mutation: str = ""                   # the name of `make mutate`'s entry (outline/mutate/mutation.py), if any

    @property
    def total(self) -> int:
        return sum(self.counts.values())


def load_results(*results_dirs: str | Path) -> list[dict]:
    """Latest result per test (historyId), so a rerun into the same directory does not count twice; several
    directories (the shards of one run, make merge) are read as one."""
    latest: dict[str, dict] = {}
    for path in sorted(p for d in results_dirs for p in Path(d).glob("*-result.json")):
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        key = data.get("historyId") or data.get("uuid") or path.name
        if key not in latest or data.get("stop", 0) >= latest[key].get("stop", 0):
            latest[key] = data
    return list(latest.values())


def labels(result: dict, name: str) -> list[str]:
    return [lab["value"] for lab in result.get("labels", []) if lab.get("name") == name]


def statuses_by_name(results: list[dict]) -> dict[str, str]:
    """Scenario name -> status; scenario outlines (one result per example) report their worst example."""
    out: dict[str, str] = {}
    for result in results:
        name, status = result.get("name", "?"), verdict(result)
        if name not in out or WORST_FIRST.index(status) < WORST_FIRST.index(out[name]):
            out[name] = status
    return out


def summarize(results: list[dict]) -> Summary:
    summary = Summary()
    for result in results:
        if "traceability" in labels(result, "tag"):
            continue                     # the matrix's own entry (outline.tracing.render) is not a scenario
        if "mutation" in labels(result, "tag"):
            summary.mutation = result.get("name", "?")       # nor is the last make mutate run
            continue
        status = verdict(result)
        summary.counts[status] += 1
        reqs = labels(result, "requirement")
        summary.touched.update(reqs)
        for tag in labels(result, "tag"):
            if tag.startswith("profile:"):
                summary.by_profile.setdefault(tag[len("profile:"):], Counter())[status] += 1
        if status == "passed":
            summary.covered.update(reqs)
        else:
            summary.not_passed.append((status, result.get("name", "?")))
    return summary


def format_summary(summary: Summary) -> str:
    # The verdicts besides ISO/IEC 9646's pass/fail show only where a run has any: the line stays as it was.
    rare = ("not applicable", "informative deviation")
    parts = [f"{summary.counts.get(s, 0)} {s}" for s in STATUSES if s not in rare or summary.counts.get(s)]
    extra = summary.total - sum(summary.counts.get(s, 0) for s in STATUSES)
    if extra:
        parts.append(f"{extra} unknown")
    lines = [
        f"{summary.total} scenarios: {', '.join(parts)}; "
        f"{len(summary.covered)} requirement IDs covered by passing scenarios"
        + (f" (of {len(summary.touched)} exercised)" if summary.touched != summary.covered else "")
    ]
    if summary.by_profile:
        lines.append("by profile: " + "; ".join(
            f"{name} {sum(c.values())} ({', '.join(f'{c[s]} {s}' for s in STATUSES if c[s])})"
            for name, c in sorted(summary.by_profile.items())))
    if summary.covered:
        lines.append("covered: " + " ".join(sorted(summary.covered)))
    for status, name in sorted(summary.not_passed):
        if status not in ("skipped", "not applicable"):
            lines.append(f"{status}: {name}")
    if summary.mutation:
        lines.append(summary.mutation)
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m outline.report.summary", description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="*", default=["reports/allure-results"],
                        help="allure results directories (several: the shards of one run)")
    args = parser.parse_args(argv)
    missing = [d for d in args.results if not Path(d).is_dir()]
    if missing:
        print(f"no allure results in {', '.join(missing)}", file=sys.stderr)
        return 1
    print(format_summary(summarize(load_results(*args.results))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
