"""Load and validate features/registry.yaml: test classes, categories, items and required coverage.

The registry is the one place that says which test items exist, where their feature files live and which
requirements each claims. Collection hooks (report labels) and `outline check`/`trace` read it; nothing else.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from outline.tree.requirements import REQ_ID

ITEM_ID = re.compile(r"^(?P<cls>[A-Z]+)-(?P<cat>[A-Z]+)-(?P<nn>\d{2})$")
KEBAB = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")
CODE = re.compile(r"^[A-Z]+$")
ITEM_KEYS = {"id", "class", "category", "title", "requirements", "partly", "why", "feature", "translations"}


@dataclass(frozen=True)
class Category:
    key: str
    code: str
    title: str


@dataclass(frozen=True)
class TestClass:
    key: str
    code: str
    title: str
    categories: dict[str, Category]


@dataclass(frozen=True)
class Item:
    id: str
    cls: str
    category: str
    title: str
    requirements: tuple[str, ...]
    feature: str
    partly: dict[str, str] = field(default_factory=dict)
    why: str = ""               # why the item is in the outline, where the source does not name it
    line: int = 0
    translations: tuple[str, ...] = ()   # the same item in other languages: <ID>.<language>.feature beside it


@dataclass(frozen=True)
class Registry:
    path: Path
    classes: dict[str, TestClass]
    items: dict[str, Item]
    required_coverage: tuple[str, ...]
    required_coverage_line: int = 0
    # Requirement ID -> why no item claims it. None: the registry has no out_of_scope key, and requirements
    # nothing claims are only reported; a mapping (even empty): each must be claimed or listed here.
    out_of_scope: dict[str, str] | None = None
    out_of_scope_line: int = 0

    def item_for_feature(self, rel_path: str) -> Item | None:
        return next((item for item in self.items.values() if item.feature == rel_path), None)


class RegistryError(Exception):
    """All problems found in one registry file; `problems` holds (line, message) pairs."""

    def __init__(self, path: Path, problems: list[tuple[int, str]]) -> None:
        self.path = path
        self.problems = problems
        super().__init__("\n".join(f"{path}:{line}: {msg}" for line, msg in problems))


class _LineDict(dict):
    line = 0


class _Loader(yaml.SafeLoader):
    """SafeLoader that remembers the line of every mapping, so problems can name registry.yaml:line."""


def _construct_mapping(loader: _Loader, node: yaml.MappingNode) -> _LineDict:
    mapping = _LineDict(loader.construct_mapping(node, deep=True))
    mapping.line = node.start_mark.line + 1
    return mapping


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def expected_feature_path(item_id: str, cls: str, category: str, features_prefix: str = "features") -> str:
    return f"{features_prefix}/{cls}/{category}/{item_id}.feature"


def load_registry(path: str | Path, features_prefix: str = "features") -> Registry:
    """Parse and validate; raises RegistryError listing every problem found (not just the first)."""
    path = Path(path)
    try:
        data = yaml.load(path.read_text(encoding="utf-8"), Loader=_Loader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        raise RegistryError(path, [(mark.line + 1 if mark else 0, f"invalid YAML: {exc}")]) from None
    problems: list[tuple[int, str]] = []
    if not isinstance(data, dict):
        raise RegistryError(path, [(1, "registry must be a mapping with classes, required_coverage, items")])
    for key in sorted(set(data) - {"classes", "required_coverage", "items", "out_of_scope"}):
        problems.append((data.line, f"unknown top-level key {key!r}"))

    classes = _load_classes(data.get("classes"), data.line, problems)
    coverage = data.get("required_coverage") or []
    if not isinstance(coverage, list) or not all(isinstance(c, str) for c in coverage):
        problems.append((data.line, "required_coverage must be a list of requirement IDs"))
        coverage = []
    for req in coverage:
        if not REQ_ID.match(req):
            problems.append((data.line, f"required_coverage: {req!r} is not a requirement ID like NET-03"))
    items = _load_items(data.get("items"), classes, features_prefix, data.line, problems)
    out_of_scope = None
    if "out_of_scope" in data:
        raw = data.get("out_of_scope") or {}
        out_of_scope = {}
        if not isinstance(raw, dict):
            problems.append((data.line, "out_of_scope must map requirement ID -> why no item claims it"))
            raw = {}
        for req, why in raw.items():
            if not REQ_ID.match(str(req)):
                problems.append((raw.line, f"out_of_scope: {req!r} is not a requirement ID like NET-03"))
            elif not isinstance(why, str) or not why.strip():
                problems.append((raw.line, f"out_of_scope: {req} needs a reason"))
            else:
                out_of_scope[str(req)] = why.strip()
    if problems:
        raise RegistryError(path, problems)
    return Registry(path, classes, items, tuple(coverage), _key_line(path, "required_coverage"),
                    out_of_scope, _key_line(path, "out_of_scope"))


def _key_line(path: Path, key: str) -> int:
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if line.startswith(f"{key}:"):
            return number
    return 0


def _load_classes(raw, line: int, problems: list) -> dict[str, TestClass]:
    if not isinstance(raw, dict) or not raw:
        problems.append((line, "classes must be a non-empty mapping"))
        return {}
    classes: dict[str, TestClass] = {}
    codes: dict[str, str] = {}
    for key, spec in raw.items():
        where = getattr(spec, "line", line)
        if not KEBAB.match(str(key)):
            problems.append((where, f"class key {key!r} must be kebab-case (it is a folder name)"))
        if not isinstance(spec, dict) or not {"code", "title", "categories"} <= set(spec):
            problems.append((where, f"class {key!r} needs code, title and categories"))
            continue
        code = str(spec["code"])
        if not CODE.match(code):
            problems.append((where, f"class {key!r}: code {code!r} must be upper-case letters"))
        if code in codes:
            problems.append((where, f"class {key!r}: code {code!r} already used by {codes[code]!r}"))
        codes[code] = key
        categories: dict[str, Category] = {}
        cat_codes: dict[str, str] = {}
        for cat_key, cat in (spec["categories"] or {}).items():
            cat_where = getattr(cat, "line", where)
            if not KEBAB.match(str(cat_key)):
                problems.append((cat_where, f"category key {cat_key!r} must be kebab-case (it is a folder name)"))
            if not isinstance(cat, dict) or not {"code", "title"} <= set(cat):
                problems.append((cat_where, f"category {key}/{cat_key} needs code and title"))
                continue
            cat_code = str(cat["code"])
            if not CODE.match(cat_code):
                problems.append((cat_where, f"category {key}/{cat_key}: code {cat_code!r} must be upper-case letters"))
            if cat_code in cat_codes:
                problems.append(
                    (cat_where, f"category {key}/{cat_key}: code {cat_code!r} already used by {cat_codes[cat_code]!r}")
                )
            cat_codes[cat_code] = cat_key
            categories[cat_key] = Category(cat_key, cat_code, str(cat["title"]))
        classes[key] = TestClass(key, code, str(spec["title"]), categories)
    return classes


def _load_items(raw, classes: dict[str, TestClass], prefix: str, line: int, problems: list) -> dict[str, Item]:
    if raw is None:
        raw = []
    if not isinstance(raw, list):
        problems.append((line, "items must be a list"))
        return {}
    items: dict[str, Item] = {}
    for entry in raw:
        where = getattr(entry, "line", line)
        if not isinstance(entry, dict):
            problems.append((where, "each item must be a mapping"))
            continue
        missing = {"id", "class", "category", "title", "requirements", "feature"} - set(entry)
        if missing:
            problems.append((where, f"item {entry.get('id', '?')}: missing {', '.join(sorted(missing))}"))
            continue
        for key in sorted(set(entry) - ITEM_KEYS):
            problems.append((where, f"item {entry['id']}: unknown key {key!r}"))
        item_id, cls_key, cat_key = str(entry["id"]), str(entry["class"]), str(entry["category"])
        if item_id in items:
            problems.append((where, f"item {item_id}: duplicate id (first at line {items[item_id].line})"))
        match = ITEM_ID.match(item_id)
        cls = classes.get(cls_key)
        cat = cls.categories.get(cat_key) if cls else None
        if not match:
            problems.append((where, f"item {item_id}: id must be <class code>-<category code>-<nn>, e.g. R-CTL-01"))
        if cls is None:
            problems.append((where, f"item {item_id}: unknown class {cls_key!r}"))
        elif cat is None:
            problems.append((where, f"item {item_id}: class {cls_key!r} has no category {cat_key!r}"))
        elif match and (match["cls"], match["cat"]) != (cls.code, cat.code):
            problems.append(
                (where, f"item {item_id}: id prefix must be {cls.code}-{cat.code}- for {cls_key}/{cat_key}")
            )
        reqs = entry["requirements"]
        if not isinstance(reqs, list) or not reqs or not all(isinstance(r, str) for r in reqs):
            problems.append((where, f"item {item_id}: requirements must be a non-empty list of IDs"))
            reqs = []
        partly = entry.get("partly") or {}
        if not isinstance(partly, dict):
            problems.append((where, f"item {item_id}: partly must map requirement ID -> which part"))
            partly = {}
        for req in sorted(set(partly) - set(reqs)):
            problems.append((where, f"item {item_id}: partly names {req}, which is not in its requirements"))
        expected = expected_feature_path(item_id, cls_key, cat_key, prefix)
        if str(entry["feature"]) != expected:
            problems.append((where, f"item {item_id}: feature must be {expected}, not {entry['feature']}"))
        translations = entry.get("translations") or []
        if not isinstance(translations, list):
            problems.append((where, f"item {item_id}: translations must be a list of feature files"))
            translations = []
        for path in translations:
            if not re.fullmatch(re.escape(expected[:-len(".feature")]) + r"\.[a-z]{2}(-[A-Z]{2})?\.feature", str(path)):
                problems.append((where, f"item {item_id}: a translation is {expected[:-len('.feature')]}.<language>"
                                        f".feature (e.g. .zh-CN.feature), not {path}"))
        items[item_id] = Item(
            id=item_id,
            cls=cls_key,
            category=cat_key,
            title=str(entry["title"]),
            requirements=tuple(reqs),
            feature=str(entry["feature"]),
            partly={str(k): str(v) for k, v in partly.items()},
            why=str(entry.get("why") or ""),
            line=where,
            translations=tuple(str(p) for p in translations),
        )
    return items
