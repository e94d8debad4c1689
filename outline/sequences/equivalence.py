"""Equivalent mutants only with machine evidence (issue 31): `make equivalence`
(`python -m outline.sequences.equivalence`).

A mutant left out of `make mutate` as equivalent (a mark in sut/reference/EQUIVALENT_MUTANTS.txt) must be
one that no implementation's behaviour at the driver interface can tell apart from the reference. Reading
the code is how the marks were made, and it was wrong often enough (issue 31: 24 of 154 marks changed
behaviour a test can see). So each mark is built and driven side by side with the reference by the
differential checker (differential.py: hypothesis stimulus sequences, every observable compared after
every stimulus) in a fixed budget (BUDGET below): no difference found is a mark confirmed; a difference is
the mark overturned, recorded with the shortest sequence that shows it, the observable, and both values.

What a mark names: the mutants of mutmut (3.8, the `mutate` extra) that outline/mutate/mutation.py leaves out by
it, found the way mutmut writes them (`create_mutations`, which parses and mutates a file without running
anything): each is built exactly as mutmut would. Without mutmut, the mark's line is replaced in every
function where the file says it (or in the function a `path::Class.method` mark names). Each mutant is the
reference package loaded again under the same names with one module's source changed, beside the
unchanged reference in the same process (sys.modules swapped while it is imported: a copy's modules only
see each other).

Which profiles: a train's own modules by the profiles that train serves (crh2 -> crh2; metro -> metro-tcn;
the ATP rig's onboard.py -> atp and atp-crh2, vdx.py -> vdx and atp-crh2, its backend and config -> all
three); the shared kernel and bulk by every profile but atp-crh2 (SHARED_PROFILES). A mark stops at its
first difference.

The evidence, reports/equivalence.json (and a short .md), is keyed by the mark's mutant (path, original
line, mutated line) and the budget: a mark whose text changed, or a budget changed since, is not yet
checked (tests/test_equivalence.py fails until it is). By default only such marks run; `--all` runs every
mark again. The rule-based exclusions of outline/mutate/mutation.py are sampled through the same checker by
outline/sequences/rule_check.py, into the same report.
"""
from __future__ import annotations

import argparse
import datetime
import difflib
import hashlib
import importlib
import importlib.abc
import importlib.util
import json
import multiprocessing
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Iterator

ROOT = Path(__file__).resolve().parents[2]
EQUIVALENTS = ROOT / "sut" / "reference" / "EQUIVALENT_MUTANTS.txt"
OVERTURNED = ROOT / "sut" / "reference" / "OVERTURNED_MUTANTS.txt"
REPORT = ROOT / "reports" / "equivalence.json"
PACKAGE = "sut.reference"
PROFILES = ("crh2", "metro-tcn", "atp", "vdx", "atp-crh2")

# The budget, per profile: a list of (composition, how sequences are drawn, how many), each sequence up to
# ACTIONS stimuli, each followed by time and watched (_watched, below), and SHRINK_S seconds of shrinking once
# a difference is found (the shortest sequence found by then is the answer). Three ways to draw: "sentences",
# the step library's own stimuli as the random-sequence invariants draw them (sentences.py: openings at rest
# or driving, swarms of a few kinds; for the profiles it has), "paced", every stimulus the contract lists
# (stimuli.py; any composition: the names come from the SUT), and "cold", boards failed before power-up and
# repaired after it, then paced (a node dead from the start holds no state a later fault would have left;
# seed 12 found the crh2 monitor's defaults for it, which only such a start reaches). Measured on this machine (2026-11-26, CPU
# time per sequence, the reference against itself): crh2 ~0.9 s as sentences, ~0.5 s paced (a coupled train
# ~0.9 s; every ring node's counters are looked at after every step), metro ~0.5 s as sentences, ~1.1 s
# paced (its buses poll every few ms, every frame an event), the ATP and VDX rig ~0.01-0.02 s, the fitted
# ATP ~0.2 s. The crh2 budget also tries a coupled train and the shortest and longest set (configure sizes
# its range check accepts); the fitted ATP drives an 8-car CRH2 set. A mutant then costs ~15 s of CPU in
# crh2 or the metro, ~7-14 s in the ATP rig, ~40 s in the shared kernel and bulk: the 207 marks of
# 2026-11-26, ~60 CPU-minutes, ~30 min on two free cores (`make equivalence`, JOBS=2).
ACTIONS = 8
# A record with another verdict (an error of the checker, a mark not checked) is run again next time.
VERDICTS = ("confirmed", "overturned", "unreached", "names no mutant")
# What the checker's evidence is (part of the budget's identity: a record made under another is checked again):
# since 2026-11-28 a mark is confirmed only where the stimuli ran its mutated statement at least once.
EVIDENCE = "reached"          # then, for what the budget never reached, the scenarios replayed (REPLAY_*)
SHRINK_S = 20.0
SEED = 0
BUDGET: dict[str, list[tuple[dict[str, int], str, int]]] = {
    "crh2": [({}, "sentences", 10), ({}, "paced", 6), ({}, "cold", 10), ({"sets": 2, "cars_per_set": 8}, "paced", 2),
             ({"cars_per_set": 2}, "paced", 2), ({"cars_per_set": 16}, "paced", 2)],
    "metro-tcn": [({}, "sentences", 24), ({}, "paced", 2)],
    "atp": [({}, "sentences", 300), ({}, "paced", 100)],
    "vdx": [({}, "sentences", 300), ({}, "paced", 100)],
    "atp-crh2": [({"cars_per_set": 8}, "paced", 16)],
}
# The shared kernel and bulk run every train: each profile but the fitted ATP, which is the crh2 train and
# the ATP rig on one clock.
SHARED_PROFILES = ("crh2", "metro-tcn", "atp", "vdx")


def _random_budget(profiles: Iterable[str] | None) -> list:
    budget = BUDGET if profiles is None else {p: BUDGET[p] for p in sorted(set(profiles))}
    return [budget, ACTIONS, SEED, EVIDENCE]


def budget_id(profiles: Iterable[str] | None = None) -> str:
    """What a record was checked in: the budget of the profiles given (None: all of it, for the report's heading
    and the rule samples), the seed, the sequence length and the replay's counts. A record of another is not
    evidence for this one."""
    return hashlib.sha256(json.dumps([*_random_budget(profiles), REPLAY_PROBES, REPLAY_REACHING],
                                     sort_keys=True).encode()).hexdigest()[:12]


def random_budget_id(profiles: Iterable[str] | None = None) -> str:
    """The random sequences' part of budget_id (the identity records had before the replay stage): a record
    confirmed or overturned by them alone is the same evidence under any replay counts."""
    return hashlib.sha256(json.dumps(_random_budget(profiles), sort_keys=True).encode()).hexdigest()[:12]


def mark_budget(mark: "Mark") -> str:
    """The budget a mark is checked in: that of the profiles its file runs in, so that a change to one
    profile's budget checks again only the marks that profile runs."""
    return budget_id(profiles_of(mark.path))


def mark_random_budget(mark: "Mark") -> str:
    return random_budget_id(profiles_of(mark.path))


def carry_over(report: dict[str, Any], marks: list["Mark"]) -> list["Mark"]:
    """Records made under the current random sequences but other replay counts: those the sequences decided
    (confirmed, reached; overturned; names no mutant) are the same evidence now and take the current budget;
    the unreached ones are returned, for the replay alone."""
    replay_only = []
    for mark in marks:
        record = report.get("marks", {}).get(mark.key)
        if not record or record.get("budget") == mark_budget(mark) \
                or record.get("random_budget", record.get("budget")) != mark_random_budget(mark):
            continue
        if record["verdict"] == "unreached":
            replay_only.append(mark)
        elif record["verdict"] in ("confirmed", "overturned", "names no mutant") and "replay" not in record:
            record["budget"], record["random_budget"] = mark_budget(mark), mark_random_budget(mark)
    return replay_only


def profiles_of(path: str) -> tuple[str, ...]:
    parts = Path(path).parts
    part = parts[2] if len(parts) > 3 else "shared"
    if part == "crh2":
        return ("crh2",)
    if part == "metro":
        return ("metro-tcn",)
    if part == "atp":
        return {"onboard.py": ("atp", "atp-crh2"), "vdx.py": ("vdx", "atp-crh2")}.get(
            parts[-1], ("atp", "vdx", "atp-crh2"))
    return SHARED_PROFILES


# -- marks -------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Mark:
    where: str               # path, or path::Class.method
    before: str
    after: str
    reason: str

    @property
    def path(self) -> str:
        return self.where.split("::", 1)[0]

    @property
    def function(self) -> str | None:
        return self.where.split("::", 1)[1] if "::" in self.where else None

    @property
    def key(self) -> str:
        """The mark's mutant, as its text says it: another text is another mark."""
        return hashlib.sha256(f"{self.where} | {self.before} | {self.after}".encode()).hexdigest()[:16]

    def line(self) -> str:
        return " | ".join([*(_escape(text) for text in (self.where, self.before, self.after)), self.reason])


# A line of code may hold the fields' own separator (`a | b`): written ` \| ` inside a field, which
# `split(" | ")` leaves whole.
def _escape(text: str) -> str:
    return text.replace(" | ", " \\| ")


def parse_mark(raw: str, path: Path) -> Mark | None:
    """One line of a marks file as a Mark (None for a comment or a blank line); the reason is the rest of the
    line, separators and all."""
    if not raw.strip() or raw.startswith("#"):
        return None
    fields = [f.strip().replace(" \\| ", " | ") for f in raw.split(" | ")]
    if len(fields) < 4 or not fields[3]:
        raise ValueError(f"{path}: want 'path | before | after | reason', got {raw!r}")
    return Mark(fields[0], fields[1], fields[2], " | ".join(fields[3:]))


def read_marks(path: Path | None = None) -> list[Mark]:
    path = path or EQUIVALENTS
    lines = path.read_text(encoding="utf-8").splitlines() if path.exists() else []
    return [mark for mark in (parse_mark(raw, path) for raw in lines) if mark is not None]


# -- mutants -----------------------------------------------------------------------------------------------

@dataclass
class Site:
    """One mutant: where, what it changes, and how the module's source reads with the change (the original
    with `text` in place of its characters start..end: thousands of mutants share one original)."""
    path: str
    line: int
    function: str            # as Python names it: Relay.__init__, _one_check_encode
    before: str
    after: str
    original: str = field(repr=False, default="")
    start: int = 0
    end: int = 0
    text: str = field(repr=False, default="")
    name: str = ""           # mutmut's name, where it came from mutmut

    @property
    def source(self) -> str:
        return self.original[:self.start] + self.text + self.original[self.end:]


def _functions(tree: Any) -> Iterator[tuple[str, Any]]:
    """The functions mutmut mutates: each top-level function and each method of a top-level class."""
    import ast
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node.name, node
        elif isinstance(node, ast.ClassDef):
            for child in node.body:
                if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    yield f"{node.name}.{child.name}", child


def replaced_sites(mark: Mark, root: Path = ROOT) -> list[Site]:
    """The mark's mutants by its line replaced: every line inside a function (of the one it names) that
    reads the original line, with the mutated line in its place."""
    import ast
    source = (root / mark.path).read_text(encoding="utf-8")
    lines = source.splitlines(keepends=True)
    sites = []
    for name, node in _functions(ast.parse(source)):
        if mark.function is not None and name != mark.function:
            continue
        for number in range(node.lineno, (node.end_lineno or node.lineno) + 1):
            text = lines[number - 1]
            if text.strip() == mark.before:
                start = sum(map(len, lines[:number - 1])) + len(text) - len(text.lstrip())
                sites.append(Site(mark.path, number, name, mark.before, mark.after, source, start,
                                  start + len(text.strip()), mark.after))
    return sites


_MUTMUT: dict[str, list[Site]] = {}


def mutmut_sites(path: str, root: Path = ROOT) -> list[Site]:
    """Every mutant mutmut writes for `path`, named as mutmut names it, each with its module's source."""
    key = str(root / path)
    if key in _MUTMUT:
        return _MUTMUT[key]
    import libcst as cst
    from libcst.metadata import MetadataWrapper, WhitespaceInclusivePositionProvider
    from mutmut.mutation.file_mutation import create_mutations

    source = (root / path).read_text(encoding="utf-8")
    module, mutations, _classes, _functions_ignored = create_mutations(path, source)
    owner: dict[int, tuple[str | None, str]] = {}
    for node in module.body:
        if isinstance(node, cst.FunctionDef):
            owner[id(node)] = (None, node.name.value)
        elif isinstance(node, cst.ClassDef) and isinstance(node.body, cst.IndentedBlock):
            for child in node.body.body:
                if isinstance(child, cst.FunctionDef):
                    owner[id(child)] = (node.name.value, child.name.value)
    spans = MetadataWrapper(module, unsafe_skip_copy=True).resolve(WhitespaceInclusivePositionProvider)
    offsets = [0]
    for text in source.splitlines(keepends=True):
        offsets.append(offsets[-1] + len(text))
    module_name = path.removesuffix(".py").replace("/", ".")
    counts: dict[int, int] = {}
    sites = []
    for mutation in mutations:
        function = mutation.contained_by_top_level_function
        if function is None or id(function) not in owner:
            continue                      # mutmut writes no mutant for it
        counts[id(function)] = counts.get(id(function), 0) + 1
        klass, name = owner[id(function)]
        mangled = f"xǁ{klass}ǁ{name}" if klass else f"x_{name}"
        # The mutated node's code in place of the original's characters (a whole module rendered again per
        # mutant takes minutes over the references). libcst renders a node without the indentation of its
        # block, which the lines after its first get back; where that does not give the original text
        # again, the whole module is rendered.
        span = spans[mutation.original_node]
        start = offsets[span.start.line - 1] + span.start.column
        end = offsets[span.end.line - 1] + span.end.column
        indent = _block_indent(source[start:end], module.code_for_node(mutation.original_node))
        if indent is not None:
            text = _indented(module.code_for_node(mutation.mutated_node), indent)
        else:
            start, end, text = 0, len(source), module.deep_replace(mutation.original_node, mutation.mutated_node).code
        line, before, after = _first_change(source, start, end, text)
        if line:
            sites.append(Site(path, line, f"{klass}.{name}" if klass else name, before, after, source, start, end,
                              text, f"{module_name}.{mangled}__mutmut_{counts[id(function)]}"))
    _MUTMUT[key] = sites
    return sites


def _block_indent(original: str, rendered: str) -> str | None:
    """The indentation libcst left out of `rendered` (a node's code) against `original` (its text in the
    file), or None if indenting its lines after the first does not give the original."""
    old, new = original.split("\n"), rendered.split("\n")
    if len(old) != len(new):
        return None
    indent = next((o[:len(o) - len(n)] for o, n in zip(old[1:], new[1:]) if n.strip() and o.endswith(n)), "")
    return indent if _indented(rendered, indent) == original else None


def _indented(text: str, indent: str) -> str:
    first, *rest = text.split("\n")
    return "\n".join([first] + [indent + line if line else line for line in rest])


def _first_change(source: str, start: int, end: int, text: str) -> tuple[int, str, str]:
    """(line, original, mutated) of the first line the change makes differ, stripped, as `mutmut show`
    prints them; (0, "", "") if it changes nothing."""
    first = source.count("\n", 0, start)
    line_start = source.rfind("\n", 0, start) + 1
    line_end = source.find("\n", end)
    line_end = len(source) if line_end < 0 else line_end
    old = source[line_start:line_end].split("\n")
    new = (source[line_start:start] + text + source[end:line_end]).split("\n")
    before = after = None
    line = 0
    for hunk in difflib.unified_diff(old, new, lineterm="", n=0):
        if hunk.startswith("@@") and not line:
            line = first + int(hunk.split()[1].lstrip("-").split(",")[0]) or first + 1
        elif hunk.startswith("-") and not hunk.startswith("---") and before is None:
            before = hunk[1:].strip()
        elif hunk.startswith("+") and not hunk.startswith("+++") and after is None:
            after = hunk[1:].strip()
    return line, before or "", after or ""


def have_mutmut() -> bool:
    return importlib.util.find_spec("mutmut") is not None


def sites_of(mark: Mark, root: Path = ROOT, exact: bool | None = None) -> list[Site]:
    """The mutants a mark leaves out: mutmut's (exact, where mutmut is installed), else its line replaced."""
    if not (have_mutmut() if exact is None else exact):
        return replaced_sites(mark, root)
    return [s for s in mutmut_sites(mark.path, root) if (s.before, s.after) == (mark.before, mark.after)
            and mark.function in (None, s.function)]


# -- a mutant beside the reference ------------------------------------------------------------------------

class Reach:
    """How often the mutated statement ran: a mark is evidence only where the stimuli reached its change
    (a branch no sequence takes shows no difference whatever it does)."""

    def __init__(self) -> None:
        self.count = 0

    def __call__(self) -> None:
        self.count += 1


REACH_NAME = "__checker_reached__"      # dunder at both ends: not mangled inside a class body


def _span(node: Any) -> tuple[tuple[int, int], tuple[int, int]]:
    """Where a statement (with its decorators), an except clause or a match case starts and ends."""
    import ast
    if isinstance(node, ast.match_case):
        start, last = node.pattern, node.body[-1]
    else:
        start, last = min([node, *getattr(node, "decorator_list", ())], key=lambda n: (n.lineno, n.col_offset)), node
    return (start.lineno, start.col_offset), (last.end_lineno, last.end_col_offset)


def _innermost_statement(tree: Any, line: int, column: int) -> tuple[Any, list] | None:
    """(statement, the block it is in) of the deepest statement whose span holds (line, column)."""
    import ast
    found, owners = None, [tree]
    while owners:
        owner, owners = owners[0], []
        for _name, value in ast.iter_fields(owner):
            for item in value if isinstance(value, list) else ():
                if isinstance(item, (ast.stmt, ast.excepthandler, ast.match_case)):
                    start, end = _span(item)
                    if start <= (line, column) <= end:
                        if isinstance(item, ast.stmt):
                            found = (item, value)
                        owners = [item]
    return found


def _counted(tree: Any, source: str, path: str, line: int, column: int) -> tuple[Any, list]:
    """(statement, its block): the statement REACH_NAME() goes before, for a change at (line, column): the one
    that holds it, or in a function's header (a default, a decorator) the first of its body after a
    docstring (a default is used when the function is called)."""
    import ast
    hit = _innermost_statement(tree, line, column) or _innermost_statement(
        tree, line, len(source.splitlines()[line - 1]) - len(source.splitlines()[line - 1].lstrip()))
    if hit is None:
        raise ValueError(f"{path}:{line}:{column}: no statement there to count the mutant's reach")
    statement, body = hit
    in_header = isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)) and statement.body \
        and (line, column) < (statement.body[0].lineno, statement.body[0].col_offset)
    if in_header:
        first = statement.body[0]
        docstring = isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) \
            and isinstance(first.value.value, str) and len(statement.body) > 1
        return statement.body[1 if docstring else 0], statement.body
    return statement, body


def instrumented(source: str, path: str, line: int, column: int) -> Any:
    """The module's code with a call of REACH_NAME() just before the statement that holds (line, column),
    the first changed character of a mutant (_counted). Line numbers stay as they are."""
    import ast
    tree = ast.parse(source, path)
    statement, body = _counted(tree, source, path, line, column)
    call = ast.Expr(ast.Call(ast.Name(REACH_NAME, ast.Load()), [], []))
    body.insert(body.index(statement), ast.copy_location(call, statement))
    return compile(ast.fix_missing_locations(tree), path, "exec")


def counted_line(site: "Site") -> int:
    """The line of the statement whose runs count as the mutant's reach (_counted): where a line coverage of
    the reference shows whether a scenario ran it."""
    import ast
    line, column = changed_at(site)
    return _counted(ast.parse(site.source, site.path), site.source, site.path, line, column)[0].lineno


def changed_at(site: "Site") -> tuple[int, int]:
    """(line, column) of the mutant's first changed character in its module's source."""
    original, source = site.original, site.source
    at, stop = site.start, min(len(original), len(source))
    while at < stop and original[at] == source[at]:
        at += 1
    return source.count("\n", 0, at) + 1, at - (source.rfind("\n", 0, at) + 1)


class _Changed(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Imports one module of the copy from a changed source; where `reach` is given with the position of
    the change, the statement there counts its runs into it."""

    def __init__(self, name: str, path: Path, source: str, reach: Reach | None = None,
                 at: tuple[int, int] | None = None) -> None:
        self.name, self.path, self.source, self.loaded = name, path, source, False
        self.reach, self.at = reach, at

    def find_spec(self, fullname: str, path: Any = None, target: Any = None) -> Any:
        if fullname != self.name:
            return None
        return importlib.util.spec_from_loader(fullname, self, origin=str(self.path))

    def create_module(self, spec: Any) -> None:
        return None

    def exec_module(self, module: Any) -> None:
        module.__file__ = str(self.path)
        self.loaded = True
        if self.reach is not None and self.at is not None:
            module.__dict__[REACH_NAME] = self.reach
            code = instrumented(self.source, str(self.path), *self.at)
        else:
            code = compile(self.source, str(self.path), "exec")
        exec(code, module.__dict__)


def _ours(name: str) -> bool:
    return name == PACKAGE or name.startswith(PACKAGE + ".")


def trains_with(path: str, source: str, reach: Reach | None = None,
                at: tuple[int, int] | None = None) -> dict[str, type]:
    """The reference trains by profile (sut/reference/profiles.py's TRAINS) of a copy of the reference in
    which `path` reads `source` (its statement at `at` counting its runs into `reach`, where given). The
    reference already imported stays as it was."""
    import sut
    importlib.import_module(f"{PACKAGE}.profiles")            # the reference itself, before the swap
    saved = {name: sys.modules.pop(name) for name in list(sys.modules) if _ours(name)}
    attribute = getattr(sut, "reference")
    finder = _Changed(path.removesuffix(".py").replace("/", "."), ROOT / path, source, reach, at)
    sys.meta_path.insert(0, finder)
    try:
        trains = dict(importlib.import_module(f"{PACKAGE}.profiles").TRAINS)
    finally:
        sys.meta_path.remove(finder)
        for name in [n for n in sys.modules if _ours(n)]:
            del sys.modules[name]
        sys.modules.update(saved)
        sut.reference = attribute
    if not finder.loaded:
        raise ImportError(f"{path} is not part of the reference trains")
    return trains


# Time passing after every stimulus, and watched: drawn as the stimuli are, a sequence leaves most stimuli
# without time to act (one draw in five is time), and what the driver shows is looked at only after each
# call, so a mutant that reports a silent device one poll early, picks a relay up 3 ms late or runs a cycle
# at another phase shows only to a look inside that window. After each stimulus (not time itself) comes a
# pause (PAUSES_US) or a watch: a few to a few dozen short advances (WATCH_STEPS_US), each looked at.
PAUSES_US = (1_000, 3_000, 10_000, 50_000, 120_000, 500_000, 2_000_000)
WATCH_STEPS_US = (1_000, 2_000, 5_000, 16_000)
WATCH_LOOKS = (4, 40)
COLD_US = (1_000_000, 3_000_000)      # how long a board failed at power-up stays dead ("cold")


def _time_after(stimulus: Any) -> Any:
    """What follows one stimulus: nothing if it is time passing, else a pause or a watch."""
    from hypothesis import strategies as st

    from .stimuli import Action

    if stimulus.method in ("advance", "advance_ms", "soak"):
        return st.just([])
    pause = st.sampled_from(PAUSES_US).map(lambda us: [Action("advance", (us,))])
    watch = st.tuples(st.sampled_from(WATCH_STEPS_US), st.integers(*WATCH_LOOKS)).map(
        lambda a: [Action("advance", (a[0],))] * a[1])
    return st.one_of(pause, watch)


def _watched(sequences: Any) -> Any:
    from hypothesis import strategies as st
    return sequences.flatmap(lambda seq: st.tuples(*[_time_after(a) for a in seq]).map(
        lambda after: [x for stimulus, then in zip(seq, after) for x in (stimulus, *then)]))


def paced(profile: str, probe: Any, max_actions: int) -> Any:
    """Up to `max_actions` of every stimulus the contract lists (stimuli.py), each followed by time, watched."""
    from hypothesis import strategies as st

    from .stimuli import actions
    return _watched(st.lists(actions(profile, probe), max_size=max_actions))


def _sentences(profile: str, probe: Any, max_actions: int) -> Any:
    """The step library's stimuli (sentences.py, for a profile it has; else paced), each followed by time,
    watched."""
    from . import sentences
    if profile not in sentences.PROFILES:
        return paced(profile, probe, max_actions)
    return _watched(sentences.sequences(profile, probe, max_actions))


def cold(profile: str, probe: Any, max_actions: int) -> Any:
    """Boards failed before power-up (stimuli.failed_at_power_up), power-up, each repaired (watched), then
    paced stimuli: what a node dead from the start does when it comes back, where no state of it was ever
    held."""
    from hypothesis import strategies as st

    from .stimuli import Action, failed_at_power_up

    def after(before: list) -> Any:
        # Long enough dead for the rest of the train to be heard from: the ring forms its token and every node has
        # sent status data well within a second of power-up (at 300 ms the 8-car set was not yet heard from).
        dead = st.sampled_from(COLD_US).map(lambda us: [Action("advance", (us,))])
        repairs = _watched(st.just([Action("repair", a.args) for a in before]))
        return st.tuples(dead, repairs, paced(profile, probe, max(max_actions - len(before), 0))).map(
            lambda rest: [*before, Action("power_on", ()), *rest[0], *rest[1], *rest[2]])
    return failed_at_power_up(profile, probe).flatmap(after)


DRAWN = {"sentences": _sentences, "paced": paced, "cold": cold}


def _factory(cls: type, profile: str, composition: dict[str, int]) -> Callable[[], Any]:
    def make() -> Any:
        driver = cls.open(profile)
        if composition:
            driver.configure(**composition)
        return driver
    return make


def _runs(calls: list[str]) -> list[str]:
    """A watch's many equal advances as one line: `advance(2000) x 30`."""
    out: list[list] = []
    for call in calls:
        if out and out[-1][0] == call:
            out[-1][1] += 1
        else:
            out.append([call, 1])
    return [call if n == 1 else f"{call} x {n}" for call, n in out]


def _short(value: Any, limit: int = 600) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit] + " ..."


def check_site(site: Site, profiles: tuple[str, ...], budget: dict[str, list[tuple[dict[str, int], str, int]]],
               *, actions: int = ACTIONS, seed: int = SEED, shrink_s: float | None = SHRINK_S,
               replay_only: bool = False) -> dict[str, Any]:
    """Drive the reference and the mutant side by side in each profile and composition of the budget: the
    first difference, or none; where none of it ran the change, the scenarios replayed (replay_scenarios).
    `replay_only`: the budget's sequences already ran for this mutant and never reached it (a record that
    says so): the replay alone."""
    from .differential import search
    from sut.reference.profiles import TRAINS

    reach = Reach()
    try:
        mutant = trains_with(site.path, site.source, reach, changed_at(site))
    except Exception as error:                  # noqa: BLE001  (a mutant that does not import: seen at once)
        return {"verdict": "overturned", "difference": {"profile": None, "observable": "import",
                                                          "reference": "imports", "mutant": _short(error)}}
    tried = 0
    for profile in () if replay_only else profiles:
        for composition, drawn, examples in budget.get(profile, []):
            def against(other: type) -> Any:
                return search(_factory(TRAINS[profile], profile, composition), _factory(other, profile, composition),
                              profile, examples=examples, max_actions=actions, seed=seed, shrink_s=shrink_s,
                              sequences=DRAWN[drawn])
            try:
                difference = against(mutant[profile])
            except Exception as error:          # noqa: BLE001  (an error outside the driver calls: read it)
                # Raised outside a driver call (opening or configuring the train, or reading what it shows:
                # an event without a kind). If the reference driven alone the same way raises nothing, the
                # mutant's crash is what a user would see: a difference. Otherwise the checker is at fault.
                try:
                    against(TRAINS[profile])
                except Exception as own:        # noqa: BLE001
                    return {"verdict": "error", "sequences": tried, "difference": {
                        "profile": profile, "composition": composition, "drawn": drawn,
                        "observable": "the checker itself", "reference": _short(own), "mutant": _short(error)}}
                return {"verdict": "overturned", "sequences": tried + examples, "reached": reach.count, "difference": {
                    "profile": profile, "composition": composition, "drawn": drawn,
                    "observable": "an error raised where the reference raises none",
                    "reference": "none", "mutant": _short(error)}}
            tried += examples
            if difference is not None:
                return {"verdict": "overturned", "sequences": tried, "reached": reach.count, "difference": {
                    "profile": profile, "composition": composition, "drawn": drawn,
                    "after_stimuli": difference.step,
                    "observable": difference.what, "reference": _short(difference.a), "mutant": _short(difference.b),
                    "sequence": _runs(difference.calls())}}
    if reach.count:
        return {"verdict": "confirmed", "sequences": tried, "reached": reach.count}
    # No difference where the change never ran is no evidence of anything: the scenarios' own stimuli next,
    # and if they do not reach it either the mark stays unproven (its mutants count as survivors).
    replayed = replay_scenarios(mutant, profiles, reach, where=(site.path, counted_line(site)))
    return {**replayed, "sequences": tried}


# The replay stage (replay.py), only for a mark the random budget never reached: per profile, the recorded
# scenarios cheapest first (by the train time they ask for), each run on the mutant alone to see whether it
# reaches the change (at most REPLAY_PROBES of them), and the first REPLAY_REACHING that do replayed on the
# reference and the mutant side by side. Counts, not seconds: the same evidence on any machine.
REPLAY_PROBES = 80
REPLAY_REACHING = 3


def replay_scenarios(mutant: dict[str, type], profiles: tuple[str, ...], reach: Reach,
                     corpus: Path | None = None, where: tuple[str, int] | None = None) -> dict[str, Any]:
    """`where`: (path, line) of the statement that counts the reach (counted_line); the scenarios whose
    recording ran that line are probed first, then the rest, each lot cheapest first."""
    from .differential import first_difference
    from . import replay
    from sut.reference.profiles import TRAINS

    scenarios = replay.load(corpus or replay.CORPUS)
    if not scenarios:
        return {"verdict": "unreached", "reached": 0, "replay": {"corpus": "none recorded"}}
    probed, reaching = 0, []
    for profile in profiles:
        ordered = scenarios.get(profile, [])
        if where is not None:
            ordered = sorted(ordered, key=lambda scenario: not scenario.covers(*where))     # stable
        for scenario in ordered[:REPLAY_PROBES]:
            if len(reaching) >= REPLAY_REACHING:
                break
            probed += 1
            before = reach.count
            driver = mutant[profile].open(profile)
            try:
                for action in scenario.actions():
                    action.apply(driver)
            except Exception:                   # noqa: BLE001  (how far it got is what counts here)
                pass
            finally:
                driver.shutdown()
            if reach.count == before:
                continue
            reaching.append(scenario.nodeid)
            reference = _factory(TRAINS[profile], profile, {})
            try:
                difference = first_difference(reference, _factory(mutant[profile], profile, {}), profile,
                                              scenario.actions())
            except Exception as error:          # noqa: BLE001  (raised outside a driver call: as check_site)
                first_difference(reference, reference, profile, scenario.actions())   # the checker's own fault?
                return {"verdict": "overturned", "reached": reach.count, "difference": {
                    "profile": profile, "composition": {}, "drawn": f"replay of {scenario.nodeid}",
                    "observable": "an error raised where the reference raises none", "reference": "none",
                    "mutant": _short(error)}, "replay": {"probed": probed, "reaching": reaching}}
            if difference is not None:
                return {"verdict": "overturned", "reached": reach.count, "difference": {
                    "profile": profile, "composition": {}, "drawn": f"replay of {scenario.nodeid}",
                    "after_stimuli": difference.step, "observable": difference.what,
                    "reference": _short(difference.a), "mutant": _short(difference.b),
                    "sequence": _runs(difference.calls())},
                    "replay": {"probed": probed, "reaching": reaching}}
    return {"verdict": "confirmed" if reaching else "unreached", "reached": reach.count,
            "replay": {"probed": probed, "reaching": reaching}}


# A mark whose reason begins so claims that the reference never runs its line (a faulty variant's switch
# decides it): its evidence is that no stimulus of the budget, no replayed scenario and no line of the whole
# recorded conformance run (replay.ran_anywhere) ran it. A mutant differs from the reference only once its
# changed statement runs, and up to then both run alike, so a line the reference never runs under a stimulus
# the mutant does not run under it either. For any other mark, unreached stays no evidence.
NEVER_RUN = "never run:"


def replay_ran_anywhere(path: str, line: int) -> bool | None:
    from . import replay
    return replay.ran_anywhere(path, line)


def never_run(result: dict[str, Any], ran_anywhere: bool | None) -> dict[str, Any]:
    """An unreached result confirmed as never run where the recorded conformance run did not run the line
    either (ran_anywhere False; None: recorded without lines, no evidence); any other result as it is."""
    if result["verdict"] == "unreached" and ran_anywhere is False:
        return {**result, "verdict": "confirmed", "never_run": True}
    return result


def check_mark(mark: Mark, *, budget: dict | None = None, exact: bool | None = None,
               root: Path = ROOT, **options: Any) -> dict[str, Any]:
    """The record of one mark: confirmed (none of its mutants differs from the reference in the budget) or
    overturned (the first that does, and how), or that it names no mutant."""
    started = time.monotonic()
    record: dict[str, Any] = {"where": mark.where, "before": mark.before, "after": mark.after,
                              "reason": mark.reason, "budget": mark_budget(mark) if budget is None else "custom",
                              "checked": datetime.date.today().isoformat()}
    if budget is None:
        record["random_budget"] = mark_random_budget(mark)
    sites = sites_of(mark, root, exact)
    record["mutants"] = [{"line": s.line, "function": s.function, **({"name": s.name} if s.name else {})}
                         for s in sites]
    if not sites:
        record["verdict"] = "names no mutant"
    for site in sites:
        result = check_site(site, profiles_of(site.path), BUDGET if budget is None else budget, **options)
        if result["verdict"] == "unreached" and mark.reason.startswith(NEVER_RUN):
            result = never_run(result, replay_ran_anywhere(site.path, counted_line(site)))
            if result.get("never_run"):
                record["never_run"] = True
        record["verdict"] = result["verdict"]
        record["sequences"] = record.get("sequences", 0) + result.get("sequences", 0)
        record["reached"] = record.get("reached", 0) + result.get("reached", 0)
        if "replay" in result:
            record["replay"] = result["replay"]
        if result["verdict"] == "unreached":
            record["unreached"] = {"line": site.line, "function": site.function}
            break
        if result["verdict"] != "confirmed":
            record["difference"] = {"line": site.line, **result["difference"]}
            break
    record["seconds"] = round(time.monotonic() - started, 1)
    return record


def confirmed(report: dict[str, Any], mark: Mark) -> bool:
    """Whether the report holds the evidence for this mark, as it reads now, in the current budget."""
    record = report.get("marks", {}).get(mark.key)
    return bool(record) and record.get("verdict") == "confirmed" and record.get("budget") == mark_budget(mark)


def load_report(path: Path | None = None) -> dict[str, Any]:
    try:
        return json.loads((path or REPORT).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


# -- running them ------------------------------------------------------------------------------------------

def _mark_job(job: tuple[Mark, bool]) -> tuple[str, dict[str, Any]]:
    mark, replay_only = job
    try:
        return mark.key, check_mark(mark, replay_only=replay_only)
    except Exception as error:                  # noqa: BLE001  (one mark's trouble must not end the sweep)
        return mark.key, {"where": mark.where, "before": mark.before, "after": mark.after, "reason": mark.reason,
                          "budget": mark_budget(mark), "verdict": "not checked", "error": _short(error)}


# -- the marks made honest ---------------------------------------------------------------------------------

def move_overturned(report: dict[str, Any], marks_file: Path | None = None,
                    overturned: Path | None = None) -> tuple[int, int]:
    """Take each mark the report overturned, or found unreached (no sequence of the budget ran its changed
    statement: no evidence either way), out of the marks (one line each, the rest untouched) and note it in
    OVERTURNED_MUTANTS.txt with what the checker saw: outline/mutate/mutation.py no longer leaves its mutants
    out, so they count as survivors until a scenario kills them (or, unreached, until stimuli that reach it
    confirm a mark made again). A mark that names no mutant (its line is no longer in the code) goes too.
    (moved, dropped)."""
    marks_file, overturned = marks_file or EQUIVALENTS, overturned or OVERTURNED
    records = report.get("marks", {})
    kept, moved, dropped = [], [], 0
    for raw in marks_file.read_text(encoding="utf-8").splitlines(keepends=True):
        mark = parse_mark(raw, marks_file)
        if mark is not None:
            verdict = records.get(mark.key, {}).get("verdict")
            if verdict == "overturned":
                moved.append((mark, records[mark.key]["difference"]))
                continue
            if verdict == "unreached":
                where = records[mark.key].get("unreached", {})
                moved.append((mark, {"profile": "every profile of its budget", "observable": "unreached",
                                     "reference": f"no sequence ran the changed statement (line {where.get('line')} "
                                                  f"of {where.get('function')})", "mutant": "no evidence"}))
                continue
            if verdict == "names no mutant":
                dropped += 1
                continue
        kept.append(raw)
    if not moved and not dropped:
        return 0, 0
    marks_file.write_text("".join(kept), encoding="utf-8")
    header = ("# Marks of EQUIVALENT_MUTANTS.txt that the differential checker overturned (make equivalence,\n"
              "# reports/equivalence.json): a difference from the reference at the driver interface, so not\n"
              "# equivalent; or found unreached: no sequence of its budget ran the changed statement, so no evidence.\n"
              "# outline/mutate/mutation.py does not leave them out: they are survivors until a scenario\n"
              "# kills them. One per line:\n"
              "#   path | original line | mutated line | profile: observable, reference -> mutant\n")
    text = overturned.read_text(encoding="utf-8") if overturned.exists() else header
    for mark, seen in moved:
        said = f"{seen.get('profile')}: {seen.get('observable')}, {seen.get('reference')} -> {seen.get('mutant')}"
        text += Mark(mark.where, mark.before, mark.after, " ".join(said.split())).line() + "\n"
    overturned.write_text(text, encoding="utf-8")
    return len(moved), dropped


def summary(report: dict[str, Any], marks: list[Mark]) -> str:
    records = report.get("marks", {})
    verdicts: dict[str, int] = {}
    for record in records.values():
        verdicts[record["verdict"]] = verdicts.get(record["verdict"], 0) + 1
    lines = ["# Equivalent mutants, checked (make equivalence)", "",
             f"Budget {budget_id()}: per profile, (composition, how drawn, sequences) {json.dumps(BUDGET)}; up "
             f"to {ACTIONS} stimuli a sequence, seed {SEED}; for a mark they never reach, the conformance scenarios' "
             f"recorded stimuli replayed (the first {REPLAY_REACHING} of at most {REPLAY_PROBES} that reach it, "
             "outline/sequences/replay.py) (outline/sequences/equivalence.py).", "",
             "Marks checked: " + ", ".join(f"{n} {v}" for v, n in sorted(verdicts.items())) + f"; {len(marks)} "
             f"marks in sut/reference/EQUIVALENT_MUTANTS.txt now, "
             f"{sum(confirmed(report, m) for m in marks)} of them confirmed ("
             f"{sum(confirmed(report, m) and bool(records[m.key].get('replay')) for m in marks)} reached only by "
             "replaying the scenarios' stimuli). A confirmation needs the change reached: a mark no stimulus "
             "reached is unreached, no evidence.", ""]
    overturned = [r for r in records.values() if r["verdict"] == "overturned"]
    if overturned:
        lines += ["## Overturned marks", "", "| mark | profile | observable | reference | mutant | sequence |",
                  "| --- | --- | --- | --- | --- | --- |"]
        for r in sorted(overturned, key=lambda r: (r["where"], r["before"])):
            d = r["difference"]
            cells = [f"{r['where']}:{d.get('line')} `{r['before']}` -> `{r['after']}`", str(d.get("profile")),
                     str(d.get("observable")), f"`{str(d.get('reference'))[:120]}`", f"`{str(d.get('mutant'))[:120]}`",
                     "; ".join(d.get("sequence", [])[1:])[:300]]
            lines.append("| " + " | ".join(c.replace("|", "\\|").replace("\n", " ") for c in cells) + " |")
        lines.append("")
    unreached = [r for r in records.values() if r["verdict"] == "unreached"]
    if unreached:
        lines += ["## Unreached marks (no evidence: counted as survivors)", "",
                  "No sequence of the budget ran the changed statement, so finding no difference says nothing.", "",
                  "| mark | function | sequences |", "| --- | --- | --- |"]
        for r in sorted(unreached, key=lambda r: (r["where"], r["before"])):
            u = r.get("unreached", {})
            cells = [f"{r['where']}:{u.get('line')} `{r['before']}` -> `{r['after']}`", str(u.get("function")),
                     str(r.get("sequences"))]
            lines.append("| " + " | ".join(c.replace("|", "\\|").replace("\n", " ") for c in cells) + " |")
        lines.append("")
    rules = report.get("rules")
    if rules:
        lines += [f"## Rule-based exclusions (sample of {rules['asked']} a rule, seed {rules['seed']})", "",
                  "Of a rule that says the reference never runs the code (a switch's untaken side, a function only "
                  "such code calls), a mutant no stimulus, no replayed scenario and no line of the recorded conformance "
                  "run ran is confirmed: that is the rule's claim (\"never run\"). Of the others (run, but nobody "
                  "reads it: a self-description, a read-back, a usage error's words), unreached is no evidence.",
                  "",
                  "| rule | mutants it passes over | checked | confirmed | of them never run | overturned | unreached |",
                  "| --- | --- | --- | --- | --- | --- | --- |"]
        never = {}
        for r in rules["mutants"]:
            never[r["rule"]] = never.get(r["rule"], 0) + bool(r.get("never_run"))
        for reason, counts in sorted(rules["per_rule"].items()):
            lines.append(f"| {reason} | {counts['mutants']} | {counts['checked']} | {counts['confirmed']} | "
                         f"{never.get(reason, 0)} | {counts['overturned']} | {counts.get('unreached', 0)} |")
        lines.append("")
        for r in rules["mutants"]:
            if r["verdict"] == "overturned":
                d = r["difference"]
                lines.append(f"- {r['rule']}: {r['path']}:{r['line']} `{r['before']}` -> `{r['after']}`: "
                             f"{d.get('profile')}, {d.get('observable')}: {str(d.get('reference'))[:100]} -> "
                             f"{str(d.get('mutant'))[:100]}")
        lines.append("")
    return "\n".join(lines)


def write_report(report: dict[str, Any], out: Path | None = None) -> None:
    """The evidence (json) and its summary (.md beside it)."""
    out = out or REPORT
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(report, indent=1, ensure_ascii=False, sort_keys=True) + "\n", encoding="utf-8")
    out.with_suffix(".md").write_text(summary(report, read_marks()), encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m outline.sequences.equivalence",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("--all", action="store_true", help="check every mark again, not only those not yet checked")
    parser.add_argument("--mark", action="append", default=[], metavar="TEXT",
                        help="check only the marks whose line contains TEXT (repeatable)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--move", action="store_true",
                        help="move the marks the report overturned to sut/reference/OVERTURNED_MUTANTS.txt")
    parser.add_argument("--out", type=Path, default=REPORT)
    args = parser.parse_args(argv)
    if not have_mutmut():
        print("equivalence: mutmut is not installed (pip install -e '.[mutate]'): each mark's line is replaced "
              "instead of building mutmut's own mutants", flush=True)
    marks = read_marks()
    report = load_report(args.out)
    report.setdefault("marks", {})
    replay_only = set(m.key for m in carry_over(report, marks)) if not args.all else set()
    todo = [(m, m.key in replay_only) for m in marks if all(text in m.line() for text in args.mark)
            and (args.all or args.mark or report["marks"].get(m.key, {}).get("budget") != mark_budget(m)
                 or report["marks"][m.key].get("verdict") not in VERDICTS)]
    print(f"equivalence: {len(todo)} of {len(marks)} marks to check (budget {budget_id()}, {args.jobs} jobs)",
          flush=True)
    started = time.monotonic()
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        for done, (key, record) in enumerate(pool.imap_unordered(_mark_job, todo), start=1):
            report["marks"][key] = record
            write_report(report, args.out)
            seen = record.get("difference", {})
            print(f"[{done}/{len(todo)} {time.monotonic() - started:.0f}s] {record['verdict']}: {record['where']} "
                  f"| {record['before'][:60]} -> {record['after'][:60]}"
                  + (f"  ({seen.get('profile')}: {seen.get('observable')})" if seen else ""), flush=True)
    report["budget"] = {"id": budget_id(), "per_profile": BUDGET, "actions": ACTIONS, "seed": SEED,
                        "shrink_s": SHRINK_S}
    write_report(report, args.out)
    if args.move:
        moved, dropped = move_overturned(report)
        print(f"equivalence: {moved} overturned marks moved to {OVERTURNED.relative_to(ROOT)}, {dropped} marks that "
              "name no mutant taken out")
    print(f"equivalence: {args.out} ({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
