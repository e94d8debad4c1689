"""The step catalogue: every sentence of the step library, for the test engineer who writes a feature file
(`python -m outline steps [WORDS] [--lang zh-CN]`; docs/steps.md is the same data, kept current by a test).

One entry per step definition (a function), with its English sentence(s) and their Chinese twins (the other
decorators of the same function), each parameter's type (or the words it takes), what it does to the SUT (the
driver calls it makes, through the helpers it uses) or what it reads (trace event kinds of the implementer's
contract, declared parameters), whether its time is a reaction-time budget (steps/budgets.py), and one line of
a feature that uses it. Read from the code, never written by hand: the source is the step modules themselves.
"""
from __future__ import annotations

import ast
import importlib
import inspect
import re
import textwrap
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from outline.tree.gherkin import parse_feature
from outline.plugin.stepdefs import StepDef, definitions_in_modules
from outline.plugin.step_index import literal_prefix

_CJK = re.compile(r"[\u3400-\u9fff]")
_PARSE_FIELD = re.compile(r"\{(?P<name>\w+)(?::(?P<format>[^}]*))?\}")
_RE_GROUP = re.compile(r"\(\?P<(?P<name>\w+)>")
_FORMATS = {"g": "number", "f": "number", "d": "integer", "w": "word", "": "text"}
# The helper modules whose functions a step may call on its behalf: their driver calls count as the step's.
_HELPERS = ("steps.analysis", "steps.budgets", "steps.messages")


@dataclass
class Entry:
    types: list[str]                    # given / when / then
    english: list[str]
    chinese: list[str]
    params: dict[str, str]
    calls: list[str]                    # TrainDriver methods
    kinds: list[str]                    # trace event kinds read
    declared: list[str]                 # declaration parameters read
    budgeted: bool
    module: str
    line: int
    examples: list[str] = field(default_factory=list)   # "path:line: Keyword text"

    @property
    def sentences(self) -> list[str]:
        return self.english + self.chinese

    def matches(self, words: Iterable[str]) -> bool:
        hay = " ".join([*self.sentences, self.module, *self.calls, *self.kinds]).lower()
        return all(w.lower() in hay for w in words)


def _params(patterns: list[str], converters: dict) -> dict[str, str]:
    out: dict[str, str] = {}
    for pattern in patterns:
        for m in _PARSE_FIELD.finditer(pattern):
            out.setdefault(m["name"], _FORMATS.get((m["format"] or "")[-1:], "text"))
        for m in _RE_GROUP.finditer(pattern):
            body = _group_body(pattern, m.end())
            if re.fullmatch(r"[\w \-]+(\|[\w \-]+)+", body):
                out.setdefault(m["name"], "one of " + ", ".join(body.split("|")))
            elif body.startswith(r"\d"):
                out.setdefault(m["name"], "number")
            else:
                out.setdefault(m["name"], "text")
    for name, conv in converters.items():
        if name in out and getattr(conv, "__module__", "").startswith("steps"):
            out[name] += f" (read by {conv.__module__.split('.')[-1]}.{conv.__name__})"
    return out


def _group_body(pattern: str, start: int) -> str:
    depth, i = 1, start
    while i < len(pattern) and depth:
        depth += {"(": 1, ")": -1}.get(pattern[i], 0) if pattern[i - 1] != "\\" else 0
        i += 1
    return pattern[start:i - 1]


class _Reader(ast.NodeVisitor):
    """What a function's body does to the SUT: `sut.<method>(...)`, `kind="..."`, `declaration.parameter("...")`,
    and which helper functions it calls (followed once, by name)."""

    def __init__(self) -> None:
        self.calls: set[str] = set()
        self.kinds: set[str] = set()
        self.declared: set[str] = set()
        self.helpers: set[tuple[str | None, str]] = set()

    def visit_Call(self, node: ast.Call) -> None:
        f = node.func
        if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Attribute) and f.value.attr == "trace":
            self.calls.add(f"trace.{f.attr}")
        elif isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name):
            if f.value.id == "sut":
                self.calls.add(f.attr)
            elif f.value.id == "declaration" and f.attr == "parameter" and node.args \
                    and isinstance(node.args[0], ast.Constant):
                self.declared.add(str(node.args[0].value))
            else:
                self.helpers.add((f.value.id, f.attr))
        elif isinstance(f, ast.Name):
            self.helpers.add((None, f.id))
        for kw in node.keywords:
            if kw.arg == "kind" and isinstance(kw.value, ast.Constant) and isinstance(kw.value.value, str):
                self.kinds.add(kw.value.value)
        self.generic_visit(node)


def _read(func, depth: int = 2, seen: set | None = None) -> _Reader:
    seen = seen if seen is not None else set()
    reader = _Reader()
    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(func)))
    except (OSError, TypeError, SyntaxError):
        return reader
    reader.visit(tree)
    if depth:
        module = inspect.getmodule(func)
        for owner, name in sorted(reader.helpers, key=str):
            target = None
            if owner is None:
                target = getattr(module, name, None)
            elif owner in {h.rsplit(".", 1)[-1] for h in _HELPERS}:
                target = getattr(importlib.import_module(f"steps.{owner}"), name, None)
            if inspect.isfunction(target) and target not in seen:
                seen.add(target)
                inner = _read(target, depth - 1, seen)
                reader.calls |= inner.calls
                reader.kinds |= inner.kinds
                reader.declared |= inner.declared
    return reader


def entries(step_modules: Iterable[str], features_dir: Path | None = None, examples: int = 1) -> list[Entry]:
    """The catalogue, in the order the library defines the steps; `features_dir` fills each entry's example
    lines (the first `examples` uses found, features in path order)."""
    defs = [d for d in definitions_in_modules(step_modules) if d.module.startswith("steps.")]
    by_func: dict[int, list[StepDef]] = {}
    for d in defs:
        by_func.setdefault(id(d.context.step_func), []).append(d)
    out: list[Entry] = []
    index: list[tuple[StepDef, Entry]] = []
    for group in by_func.values():
        func = group[0].context.step_func
        patterns = [d.pattern for d in group]
        converters: dict = {}
        for d in group:
            converters.update(getattr(d.context, "converters", None) or {})
        reader = _read(func)
        entry = Entry(types=sorted({d.type or "step" for d in group}, key=["given", "when", "then", "step"].index),
                      english=[p for p in patterns if not _CJK.search(p)],
                      chinese=[p for p in patterns if _CJK.search(p)],
                      params=_params(patterns, converters), calls=sorted(reader.calls), kinds=sorted(reader.kinds),
                      declared=sorted(reader.declared), budgeted=getattr(func, "reaction_budget", False),
                      module=group[0].module, line=min(d.line for d in group))
        out.append(entry)
        index += [(d, entry) for d in group]
    if features_dir is not None:
        _examples(Path(features_dir), index, examples)
    return sorted(out, key=lambda e: (e.module, e.line))


def _examples(features_dir: Path, index: list[tuple[StepDef, Entry]], wanted: int) -> None:
    heads = [(literal_prefix(d.context.parser), d, e) for d, e in index]
    done: dict[tuple[str, str], Entry | None] = {}
    for path in sorted(features_dir.rglob("*.feature")):
        feature = parse_feature(path)
        rel = path.relative_to(features_dir.parent)
        for scenario in feature.scenarios:
            first = next(iter(scenario.instances()), None)      # an outline's first row: its steps as run
            for step in first[1] if first else []:
                key = (step.type, step.text)
                if key not in done:
                    done[key] = next((e for (head, fold), d, e in heads
                                      if (step.text.lower() if fold else step.text).startswith(head)
                                      and d.matches(step.type, step.text)), None)
                entry = done[key]
                if entry is not None and len(entry.examples) < wanted:
                    entry.examples.append(f"{rel}:{step.line}: {step.keyword.strip()} {step.text}")


def render_text(found: list[Entry], lang: str | None = None) -> str:
    lines = []
    for e in found:
        shown = e.chinese if lang == "zh-CN" else e.english or e.chinese
        lines.append(f"{'/'.join(e.types).upper():<10} {shown[0]}")
        for more in shown[1:]:
            lines.append(f"{'':<10} {more}")
        if lang != "zh-CN":
            for zh in e.chinese:
                lines.append(f"{'':<10} zh-CN: {zh}")
        for name, kind in e.params.items():
            lines.append(f"{'':<12}{{{name}}}: {kind}")
        does = _does(e)
        if does:
            lines.append(f"{'':<12}{does}")
        for ex in e.examples:
            lines.append(f"{'':<12}e.g. {ex}")
        lines.append(f"{'':<12}({e.module}:{e.line})")
    return "\n".join(lines)


def _does(e: Entry) -> str:
    parts = []
    if e.calls:
        parts.append("driver: " + ", ".join(e.calls))
    if e.kinds:
        parts.append("reads events: " + ", ".join(e.kinds))
    if e.declared:
        parts.append("declared: " + ", ".join(e.declared))
    if e.budgeted:
        parts.append("time: a reaction-time budget + the declared margin")
    return "; ".join(parts)


def render_markdown(found: list[Entry]) -> str:
    out = ["# The step catalogue", "",
           "Every sentence of the step library, generated from steps/ by `python -m outline steps --md docs/steps.md`",
           "(tests/test_catalogue.py fails when this page is stale). Search it on a terminal with",
           "`python -m outline steps WORDS` (`--lang zh-CN` for the Chinese sentences). `{name}` is a parameter; what",
           "each step does is read from its code: the driver calls it makes, the trace event kinds of the",
           "implementer's contract it reads (docs/implementing-a-sut.md), the declared parameters it uses.", ""]
    module = None
    for e in found:
        if e.module != module:
            module = e.module
            doc = " ".join((importlib.import_module(module).__doc__ or "").strip().split("\n\n")[0].split())
            out += [f"## {module}", "", doc, ""] if doc else [f"## {module}", ""]
        out.append(f"- **{'/'.join(e.types).capitalize()}** " + " / ".join(f"`{s}`" for s in e.english or e.chinese))
        for zh in e.chinese if e.english else []:
            out.append(f"  - zh-CN: `{zh}`")
        if e.params:
            out.append("  - " + "; ".join(f"`{{{n}}}` {k}" for n, k in e.params.items()))
        does = _does(e)
        if does:
            out.append(f"  - {does}")
        for ex in e.examples:
            out.append(f"  - e.g. `{ex}`")
    return "\n".join(out) + "\n"
