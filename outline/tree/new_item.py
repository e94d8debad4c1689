"""`python -m outline new`: add a test item: its feature-file skeleton, written with steps the library already
has, and its registry entry. The new item runs at once: its first scenario is `@pending` (reported as
pending, never as a pass) until the engineer writes the real steps and removes the tag.
"""
from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

from outline.tree.paths import Tree
from outline.tree.registry import load_registry
from outline.tree.requirements import REQ_ID, load_requirements

# The opening of a scenario of each train profile, in sentences of the step library.
PROFILE_BACKGROUND = {
    "crh2": ["Given an 8-car CRH2 train set", "And the driver has inserted the key in cab 1",
             "And the train has been powered up for 1000 ms"],
    "metro-tcn": ["Given a 6-car metro train with its train control and diagnosis system",
                  "And the driver has inserted the key in cab 1", "And the train has been powered up for 1000 ms"],
    "atp": ["Given a CTCS-2 200C on-board ATP on the test rig", "And the ATP has completed its start-up self-test"],
    "vdx": ["Given a CTCS3-300T ATP with its VDX emergency-brake interface",
            "And the train has been powered up for 1000 ms", "And the ATP has released the emergency brake"],
    "atp-crh2": ["Given a CTCS-2 200C on-board ATP fitted to an 8-car CRH2 train set",
                 "And the ATP has completed its start-up self-test"],
}
# A first check that already runs (the engineer replaces it), per profile.
PROFILE_FIRST_CHECK = {
    "crh2": "Then every car has an LCU on the ring and every cab car a CCU with systems 1 and 2",
    "metro-tcn": 'Then the cab 1 display shows the mode "normal"',
    "atp": "Then the ATP is in mode SB",
    "vdx": "Then the emergency-brake loop stays closed",
    "atp-crh2": "Then the ATP is in mode SB",
}


class NewItemError(ValueError):
    """Input the scaffold cannot use; the message says what would be allowed."""


@dataclass(frozen=True)
class NewItem:
    id: str
    feature: Path
    registry_line: int


def next_item_id(tree: Tree, cls: str, category: str) -> str:
    registry = load_registry(tree.registry, tree.rel(tree.features))
    if cls not in registry.classes:
        raise NewItemError(f"no class {cls!r}; the registry has {', '.join(registry.classes)}")
    categories = registry.classes[cls].categories
    if category not in categories:
        raise NewItemError(f"no category {category!r} in class {cls}; it has {', '.join(categories)}")
    prefix = f"{registry.classes[cls].code}-{categories[category].code}-"
    numbers = [int(i[len(prefix):]) for i in registry.items if i.startswith(prefix) and i[len(prefix):].isdigit()]
    return f"{prefix}{max(numbers, default=0) + 1:02d}"


def _feature_text(item_id: str, title: str, reqs: list[str], profile: str, texts: dict) -> str:
    lines = [f"@item:{item_id} @profile:{profile}", f"Feature: {item_id} {title}",
             f"  Requirements: {reqs[0]} (primary){''.join(', ' + r for r in reqs[1:])}."]
    for req in reqs:
        lines.append(f"  {req}: {texts[req]}")
    lines += ["", "  Background:"]
    lines += [f"    {step}" for step in PROFILE_BACKGROUND[profile]]
    lines += ["", f"  @req:{' @req:'.join(reqs)} @pending",
              f"  Scenario: {item_id} {title}",
              "    # Written by python -m outline new: replace the When/Then below with what this item checks",
              "    # (sentences the step library has: steps/*.py), then remove @pending.",
              "    When 500 ms pass",
              f"    {PROFILE_FIRST_CHECK[profile]}", ""]
    return "\n".join(lines)


def _registry_entry(item_id: str, cls: str, category: str, title: str, reqs: list[str], feature: str) -> str:
    quoted = title.replace("\\", "\\\\").replace('"', '\\"')
    return (f"  - id: {item_id}\n    class: {cls}\n    category: {category}\n    title: \"{quoted}\"\n"
            f"    requirements: [{', '.join(reqs)}]\n    feature: {feature}\n\n")


def _insert_entry(registry_text: str, entry: str, cls: str, category: str) -> tuple[str, int]:
    """After the last item of the same class and category, else at the end; returns (text, line of entry)."""
    blocks = list(re.finditer(r"^  - id: .*?(?=^  - id: |\Z)", registry_text, re.S | re.M))
    same = [b for b in blocks if f"\n    class: {cls}\n" in b.group(0) and f"\n    category: {category}\n" in b.group(0)]
    if same:
        at = same[-1].end()
    else:
        at = len(registry_text)
        if not registry_text.endswith("\n\n"):
            entry = ("\n" if registry_text.endswith("\n") else "\n\n") + entry
    text = registry_text[:at] + entry + registry_text[at:]
    return text, text[:at].count("\n") + 1 + (1 if entry.startswith("\n") else 0)


def add_item(tree: Tree, cls: str, category: str, title: str, reqs: list[str], profile: str) -> NewItem:
    title = " ".join(title.split())
    if not title:
        raise NewItemError("the item needs a title")
    if profile not in PROFILE_BACKGROUND:
        raise NewItemError(f"no profile {profile!r}; known: {', '.join(PROFILE_BACKGROUND)}")
    known = load_requirements(tree.requirements)
    reqs = [r.strip() for r in reqs if r.strip()]
    bad = [r for r in reqs if not REQ_ID.match(r) or r not in known]
    if not reqs or bad:
        raise NewItemError(f"requirement IDs {', '.join(bad) or '(none given)'} not in "
                           f"{tree.rel(tree.requirements)}; e.g. {', '.join(list(known)[:4])}")
    item_id = next_item_id(tree, cls, category)
    feature = tree.features / cls / category / f"{item_id}.feature"
    if feature.exists():
        raise NewItemError(f"{tree.rel(feature)} exists already")
    feature.parent.mkdir(parents=True, exist_ok=True)
    feature.write_text(_feature_text(item_id, title, reqs, profile, {r: known[r].text for r in reqs}),
                       encoding="utf-8")
    text, line = _insert_entry(tree.registry.read_text(encoding="utf-8"),
                               _registry_entry(item_id, cls, category, title, reqs, tree.rel(feature)), cls, category)
    tree.registry.write_text(text, encoding="utf-8")
    return NewItem(item_id, feature, line)


def _ask(prompt: str, choices: list[str] | None = None) -> str:
    shown = f" [{', '.join(choices)}]" if choices else ""
    answer = input(f"{prompt}{shown}: ").strip()
    if choices and answer not in choices:
        raise NewItemError(f"{answer!r} is not one of {', '.join(choices)}")
    return answer


def run(tree: Tree, cls: str | None, category: str | None, title: str | None, reqs: str | None,
        profile: str, out=sys.stdout) -> int:
    try:
        registry = load_registry(tree.registry, tree.rel(tree.features))
        interactive = sys.stdin.isatty()
        if cls is None:
            if not interactive:
                raise NewItemError("--class is required (or run it in a terminal to be asked)")
            cls = _ask("class", list(registry.classes))
        if category is None:
            if not interactive:
                raise NewItemError("--category is required")
            cls_def = registry.classes.get(cls)
            category = _ask("category", list(cls_def.categories) if cls_def else None)
        if title is None:
            if not interactive:
                raise NewItemError("--title is required")
            title = _ask("title")
        if reqs is None:
            if not interactive:
                raise NewItemError("--req is required (comma-separated requirement IDs, the primary first)")
            reqs = _ask("requirement IDs, primary first, comma-separated")
        item = add_item(tree, cls, category, title, reqs.split(","), profile)
    except NewItemError as exc:
        print(f"python -m outline new: {exc}", file=sys.stderr)
        return 2
    print(f"{item.id}: wrote {tree.rel(item.feature)} and {tree.rel(tree.registry)}:{item.registry_line}", file=out)
    print(f"run it:  .venv/bin/pytest features --item {item.id}   (reported as pending until you remove @pending)",
          file=out)
    return 0
