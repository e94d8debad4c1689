"""`python -m outline trace`: requirement -> items -> scenarios, item -> requirements, and what nothing covers.

Requirement -> scenario links come from the scenarios' own @req tags (what actually runs); `partly` notes come
from the registry. `--results DIR` adds each scenario's last status from an allure results directory.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from pytest_bdd.parser import render_string

from outline.tree.check import check_tree
from outline.tree.gherkin import Scenario
from outline.tree.paths import Tree
from outline.report.summary import WORST_FIRST, load_results, statuses_by_name


@dataclass
class Trace:
    # requirement ID -> item ID -> scenario titles
    by_requirement: dict[str, dict[str, list[str]]] = field(default_factory=dict)
    # item ID -> (title, requirement IDs, partly)
    by_item: dict[str, tuple[str, tuple[str, ...], dict[str, str]]] = field(default_factory=dict)
    uncovered: list[str] = field(default_factory=list)
    status: dict[str, str] = field(default_factory=dict)  # scenario title as written -> last status
    requirements: dict = field(default_factory=dict)  # the baseline the tables follow (ID -> Requirement)
    out_of_scope: dict[str, str] | None = None  # the registry's, None without the key


def _run_names(scenario: Scenario) -> list[str]:
    """Names the runs of a scenario get in the results: an outline's title rendered per Examples row."""
    rows = [example for ex in scenario.examples for _, example in ex.rows]
    return [render_string(scenario.title, row) for row in rows] or [scenario.title]


def _last_status(scenario: Scenario, by_name: dict[str, str]) -> str:
    found = [by_name[name] for name in _run_names(scenario) if name in by_name]
    return min(found, key=WORST_FIRST.index) if found else "not run"


def build_trace(tree: Tree, results_dir: str | None = None) -> Trace:
    result = check_tree(tree, definitions=None)
    registry = result.registry
    trace = Trace(requirements=result.requirements, out_of_scope=registry.out_of_scope if registry else None)
    by_name = statuses_by_name(load_results(results_dir)) if results_dir else None
    for feature in result.features.values():
        for scenario in feature.scenarios:
            if by_name is not None:
                trace.status[scenario.title] = _last_status(scenario, by_name)
            for item_id in scenario.tag_values("item") or ["(no item)"]:
                for req in scenario.tag_values("req"):
                    trace.by_requirement.setdefault(req, {}).setdefault(item_id, []).append(scenario.title)
    if registry:
        for item in registry.items.values():
            trace.by_item[item.id] = (item.title, item.requirements, item.partly)
            for req in item.requirements:  # a registry claim with no scenario yet still shows up
                trace.by_requirement.setdefault(req, {}).setdefault(item.id, [])
    order = list(result.requirements)
    trace.by_requirement = dict(
        sorted(trace.by_requirement.items(), key=lambda kv: order.index(kv[0]) if kv[0] in order else len(order))
    )
    trace.uncovered = [req for req in order if not any(trace.by_requirement.get(req, {}).values())]
    return trace


def _partly(trace: Trace, item_id: str, req: str) -> str:
    note = trace.by_item.get(item_id, ("", (), {}))[2].get(req)
    return f" (partly: {note})" if note else ""


def _scenario(trace: Trace, title: str) -> str:
    return f"{title} [{trace.status.get(title, 'not run')}]" if trace.status else title


def render_plain(trace: Trace, out) -> None:
    print("Requirement -> items -> scenarios", file=out)
    for req, items in trace.by_requirement.items():
        for item_id, titles in items.items():
            print(f"{req}\t{item_id}{_partly(trace, item_id, req)}", file=out)
            for title in titles or ["(no scenario yet)"]:
                print(f"\t\t{_scenario(trace, title)}", file=out)
    print("\nItem -> requirements", file=out)
    for item_id, (title, reqs, partly) in sorted(trace.by_item.items()):
        shown = ", ".join(req + (f" (partly: {partly[req]})" if req in partly else "") for req in reqs)
        print(f"{item_id}\t{title}: {shown}", file=out)
    print(f"\nCovered by nothing ({len(trace.uncovered)}): {' '.join(trace.uncovered) or '-'}", file=out)


def render_rich(trace: Trace, out) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console(file=out)
    table = Table(title="Requirement -> items -> scenarios")
    for name in ("Requirement", "Item", "Scenarios"):
        table.add_column(name)
    for req, items in trace.by_requirement.items():
        for item_id, titles in items.items():
            table.add_row(
                req, item_id + _partly(trace, item_id, req), "\n".join(_scenario(trace, t) for t in titles) or "-"
            )
    console.print(table)
    table = Table(title="Item -> requirements")
    for name in ("Item", "Title", "Requirements"):
        table.add_column(name)
    for item_id, (title, reqs, partly) in sorted(trace.by_item.items()):
        table.add_row(item_id, title, ", ".join(r + (f" (partly: {partly[r]})" if r in partly else "") for r in reqs))
    console.print(table)
    console.print(f"Covered by nothing ({len(trace.uncovered)}): {' '.join(trace.uncovered) or '-'}")
