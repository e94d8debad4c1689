"""`python -m outline check`: the test outline, the feature files, the steps and the requirements agree.

Every function takes its paths and step definitions as arguments so the tests can run them on fixture trees.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from outline.tree import tags as tagvocab
from outline.tree.gherkin import Feature, FeatureParseError, parse_feature
from outline.tree.paths import REPO, Tree
from outline.tree.registry import ITEM_ID, Registry, RegistryError, load_registry
from outline.tree.requirements import Requirement, load_requirements
from outline.plugin.stepdefs import StepDef, definitions_in_modules, step_problem


@dataclass(frozen=True, order=True)
class Problem:
    path: str
    line: int
    message: str

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: {self.message}" if self.line else f"{self.path}: {self.message}"


@dataclass
class CheckResult:
    problems: list[Problem] = field(default_factory=list)
    warnings: list[Problem] = field(default_factory=list)
    features: dict[str, Feature] = field(default_factory=dict)  # tree-relative path -> parsed feature
    registry: Registry | None = None
    requirements: dict[str, Requirement] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.problems


def _unique(problems: Iterable[Problem]) -> list[Problem]:
    # Feature-level tags and background steps repeat in every scenario; say each thing once.
    return list(dict.fromkeys(problems))


def feature_files(features_dir: Path) -> list[Path]:
    return sorted(Path(features_dir).rglob("*.feature"))


def lint_feature(feature: Feature, rel: str) -> tuple[list[Problem], list[Problem]]:
    """File-local problems that need neither registry nor steps: tags and duplicate titles.

    Shared with the feature binder, which refuses to hand such a file to pytest-bdd.
    """
    problems: list[Problem] = []
    warnings: list[Problem] = []
    seen_titles: dict[str, int] = {}
    for scenario in feature.scenarios:
        if scenario.title in seen_titles:
            problems.append(
                Problem(
                    rel,
                    scenario.line,
                    f'duplicate scenario title "{scenario.title}" (first at line {seen_titles[scenario.title]}); '
                    "pytest-bdd would silently run only one of them",
                )
            )
        seen_titles.setdefault(scenario.title, scenario.line)
        for tag in scenario.tags:
            try:
                kind, _ = tagvocab.classify(tag.name)
            except tagvocab.TagError as exc:
                problems.append(Problem(rel, tag.line, str(exc)))
                continue
            if kind is None and tag.name not in tagvocab.PLAIN:
                warnings.append(
                    Problem(rel, tag.line, f"@{tag.name} is not a project tag ({', '.join(tagvocab.PLAIN)})")
                )
        for examples in scenario.examples:
            for tag in examples.tags:
                if ":" in tag.name:
                    # pytest-bdd turns Examples tags straight into marks, bypassing pytest_bdd_apply_tag.
                    problems.append(Problem(rel, tag.line, f"@{tag.name}: kind:value tags cannot go on Examples"))
    return _unique(problems), _unique(warnings)


# A feature tagged @on_request is a generated campaign of thousands of rows written from a few sentences: its
# first rows per outline are checked here; every row is checked where it runs (the collection-time step check
# of outline/plugin/pytest_plugin.py, file:line as here). All of them took `outline check` from 1 s to 20 s.
ON_REQUEST_ROWS = 64


def step_problems(feature: Feature, rel: str, definitions: Sequence[StepDef]) -> list[Problem]:
    out = []
    sampled = any(tag.name == "on_request" for tag in feature.tags)
    for scenario in feature.scenarios:
        instances = scenario.instances()
        for _, steps in instances[:ON_REQUEST_ROWS] if sampled else instances:
            for step in steps:
                message = step_problem(step.type, step.text, definitions)
                if message:
                    out.append(Problem(rel, step.line, message))
    return _unique(out)


def _scenario_problems(feature: Feature, rel: str, item_id: str, known: dict[str, Requirement]) -> list[Problem]:
    out = []
    for sc in feature.scenarios:
        items = sc.tag_values("item")
        if not items:
            out.append(Problem(rel, sc.line, f'scenario "{sc.title}" has no @item:{item_id} tag'))
        elif items != [item_id]:
            shown = ", ".join(f"@item:{i}" for i in items)
            out.append(Problem(rel, sc.line, f'scenario "{sc.title}" is tagged {shown}; the file is item {item_id}'))
        if not sc.tag_values("req"):
            out.append(Problem(rel, sc.line, f'scenario "{sc.title}" has no @req: tag'))
        for tag in sc.tags:
            if tag.name.startswith("req:") and tag.name[4:] not in known:
                message = f"@{tag.name}: {tag.name[4:]} is not defined in docs/requirements.md"
                out.append(Problem(rel, tag.line, message))
        head = sc.title[: len(item_id) + 1]
        if not (head == item_id or head == f"{item_id} "):
            out.append(Problem(rel, sc.line, f'scenario title "{sc.title}" must start with "{item_id} "'))
    return out


def carried_requirements(feature: Feature) -> set[str]:
    return {req for sc in feature.scenarios for req in sc.tag_values("req")}


def shared_copies(tree: Tree) -> list[Path]:
    """Where the project's shared baseline may sit beside this checkout (only the real repo knows /work)."""
    copies = [tree.root.parent / "shared" / "requirements.md"]
    if tree.root == REPO.root:
        copies.insert(0, Path("/work/shared/requirements.md"))
    return copies


def check_tree(
    tree: Tree,
    definitions: Sequence[StepDef] | None = None,
    shared: Sequence[Path] | None = None,
) -> CheckResult:
    """Run every check on one tree. `definitions=None` skips step matching (`--no-steps`)."""
    result = CheckResult()
    P = result.problems.append
    reg_rel, req_rel = tree.rel(tree.registry), tree.rel(tree.requirements)

    if tree.requirements.is_file():
        result.requirements = load_requirements(tree.requirements)
    else:
        P(Problem(req_rel, 0, "requirement baseline not found"))
    known = result.requirements
    for copy in shared if shared is not None else shared_copies(tree):
        if copy.is_file() and tree.requirements.is_file() and copy.read_bytes() != tree.requirements.read_bytes():
            result.warnings.append(Problem(req_rel, 0, f"differs from {copy}; which one is the baseline?"))
            break

    try:
        result.registry = registry = load_registry(tree.registry, tree.rel(tree.features))
    except (RegistryError, OSError) as exc:
        for line, message in getattr(exc, "problems", [(0, str(exc))]):
            P(Problem(reg_rel, line, message))
        registry = None

    on_disk = {tree.rel(p): p for p in feature_files(tree.features)}
    listed = {item.feature: item for item in registry.items.values()} if registry else {}
    listed |= {path: item for item in registry.items.values() for path in item.translations} if registry else {}
    for item in registry.items.values() if registry else []:
        for path in (item.feature, *item.translations):
            if path not in on_disk:
                P(Problem(reg_rel, item.line, f"item {item.id}: feature file {path} does not exist"))
        for req in item.requirements:
            if known and req not in known:
                P(Problem(reg_rel, item.line, f"item {item.id}: {req} is not defined in docs/requirements.md"))
    if registry and known:
        for req in registry.required_coverage:
            if req not in known:
                P(Problem(reg_rel, registry.required_coverage_line, f"required_coverage: {req} is not defined"))

    carried: set[str] = set()
    for rel, path in on_disk.items():
        item = listed.get(rel)
        if item is None and registry is not None:
            P(Problem(rel, 0, f"not listed in {reg_rel}"))
            _placement_problems(rel, path, tree, registry, P)
        try:
            feature = parse_feature(path)
        except FeatureParseError as exc:
            P(Problem(rel, exc.line, exc.message))
            continue
        result.features[rel] = feature
        problems, warnings = lint_feature(feature, rel)
        result.problems += problems
        result.warnings += warnings
        item_id = item.id if item else path.stem
        result.problems += _unique(_scenario_problems(feature, rel, item_id, known))
        reqs = carried_requirements(feature)
        carried |= reqs
        if item is not None and reqs != set(item.requirements):
            diff = []
            if set(item.requirements) - reqs:
                diff.append("in registry only: " + ", ".join(sorted(set(item.requirements) - reqs)))
            if reqs - set(item.requirements):
                diff.append("in @req tags only: " + ", ".join(sorted(reqs - set(item.requirements))))
            P(Problem(rel, feature.line, f"@req tags differ from registry item {item.id} ({'; '.join(diff)})"))
        if definitions is not None:
            result.problems += step_problems(feature, rel, definitions)

    for req in registry.required_coverage if registry else ():
        if req not in carried:
            P(Problem(reg_rel, registry.required_coverage_line, f"required coverage: {req} is carried by no scenario"))
    if registry is not None and registry.out_of_scope is not None and known:
        claimed = {req: item.id for item in registry.items.values() for req in item.requirements}
        line = registry.out_of_scope_line
        for req in known:
            if req not in claimed and req not in registry.out_of_scope:
                P(Problem(reg_rel, line, f"{req} is claimed by no item and not listed in out_of_scope with a reason"))
        for req in registry.out_of_scope:
            if req not in known:
                P(Problem(reg_rel, line, f"out_of_scope: {req} is not defined in docs/requirements.md"))
            elif req in claimed:
                P(Problem(reg_rel, line, f"out_of_scope: {req} is claimed by item {claimed[req]}; take it out"))
    return result


def _placement_problems(rel: str, path: Path, tree: Tree, registry: Registry, P) -> None:
    parts = path.relative_to(tree.features).parts
    if len(parts) != 3 or parts[0] not in registry.classes or parts[1] not in registry.classes[parts[0]].categories:
        P(Problem(rel, 0, "a feature file belongs in features/<class>/<category>/ as named in the registry"))
        return
    cls = registry.classes[parts[0]]
    cat = cls.categories[parts[1]]
    match = ITEM_ID.match(path.stem)
    if not match or (match["cls"], match["cat"]) != (cls.code, cat.code):
        P(Problem(rel, 0, f"file name must be the item ID, {cls.code}-{cat.code}-<nn>.feature in this folder"))


def run(tree: Tree, step_modules: Sequence[str] | None, out=sys.stdout) -> int:
    """CLI body: print problems (one line each), warnings, a closing line; 0 when there are no problems."""
    definitions = None
    if step_modules is not None:
        sys.path.insert(0, str(tree.root))
        definitions = definitions_in_modules(step_modules)
    result = check_tree(tree, definitions)
    for problem in sorted(result.problems):
        print(problem, file=out)
    for warning in sorted(result.warnings):
        print(f"warning: {warning}", file=out)
    n_sc = sum(len(f.scenarios) for f in result.features.values())
    n_items = len(result.registry.items) if result.registry else 0
    counts = f"{len(result.features)} feature files, {n_sc} scenarios, {n_items} registry items"
    if result.problems:
        print(f"outline check: {len(result.problems)} problems ({counts})", file=out)
        return 1
    print(f"outline check: OK ({counts}, {len(result.warnings)} warnings)", file=out)
    return 0
