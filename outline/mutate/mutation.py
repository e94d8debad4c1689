"""Mutation testing of the references: `make mutate` (`python -m outline.mutate.mutation --mutants 200 --seed 1`).

A conformance suite is worth the faulty implementations it rejects; the hand-written variants in
tests/variants.py are the ones somebody thought of. This breaks the references in ways nobody chose:
mutmut (3.8, pinned in the `mutate` extra) writes one small change per mutant (a constant, a comparison, an
operator, a dropped call) into every function of sut/reference/ ([tool.mutmut] in pyproject.toml), and the
conformance run (`pytest features`) is the test. Why mutmut rather than cosmic-ray, from a trial on the ATP
reference (2026-11-25): mutmut learns once which scenarios reach which function and runs only those, in a
forked child of an already started pytest, stopping at the first failure: ~0.6 s per mutant on two cores;
cosmic-ray starts the test command afresh per mutant (~2-3 s before the first scenario) and would run the
whole suite for every survivor. mutmut also works with pytest-bdd's generated tests as they are.

Phases:
1. `mutmut run <no such mutant>`: mutmut copies the project to mutants/, writes every mutant and runs the
   suite once to learn who reaches what (kept for the next run; when features or steps change, only the tests
   made of what changed are mapped again: MAPPED_FROM), then stops, finding no mutant by that name.
2. A seeded sample, the same share from each part (crh2, metro, atp, and the shared kernel/bulk), leaving out
   the mutants marked equivalent in sut/reference/EQUIVALENT_MUTANTS.txt, those inside a `raise` of the
   driver's usage errors (USAGE_ERRORS below), those of a backend's self-description (SELF_DESCRIPTION,
   BACKEND_PASSED_OVER), those inside the emit of a trace event no check reads (EMIT_CALLS) or inside one of
   its fields that no check reads (in_unread_field) or no contract lists for its kind (in_unlisted_field),
   those in a branch only faulty variants take
   (in_variant_only_branch) and those in other code the switches leave unrun (never_run: an operand they
   decide, a function only a variant calls); how many were passed over is printed and kept.
3. `mutmut run <sample>`; outline/mutate/mutation_plugin.py notes which scenario failed for each mutant.
4. The table: file:line, the change, killed by which scenario or survived; three kill rates per part
   (killed + timed out; "no tests" means no scenario reaches the function, which counts as a survivor):
   of everything drawn (the mutants passed over while drawing count as not killed: they were not run),
   after the rules (without those a rule passes over, while drawing or since), and after proven
   equivalents (also without those a mark names that the differential checker confirmed: make
   equivalence, reports/equivalence.json; a mark without that evidence leaves its mutant a survivor).
   Printed, and written to reports/mutation.md and reports/mutation.json, which `make report` turns into
   an entry of the Allure report (`--to-allure`).
"""
from __future__ import annotations

import argparse
import ast
import fnmatch
import hashlib
import json
import os
import random
import re
import subprocess
import sys
import tomllib
import time
import uuid
from dataclasses import asdict, dataclass
from pathlib import Path

# What a step module is made of lives with the plugin that notes it (one way: mutation -> scenario_inputs).
from outline.mutate.scenario_inputs import sha as _sha, step_definitions
# A mark counts as equivalent in the last rate only with the checker's evidence (reports/equivalence.json).
from outline.sequences import equivalence

ROOT = Path(__file__).resolve().parents[2]
MUTANTS_DIR = ROOT / "mutants"
EQUIVALENTS = ROOT / "sut" / "reference" / "EQUIVALENT_MUTANTS.txt"
KILLS = MUTANTS_DIR / "kills.tsv"
NAME = re.compile(r"^(?P<module>[\w.]+?)\.(?P<function>x[ǁ_].*)__mutmut_(?P<n>\d+)$")
DETECTED = {"killed", "timeout", "segfault"}
TARGET = 0.90               # issue 15, issue 31: the kill rate after proven equivalents, per reference
RATES = ("of everything drawn", "after the rules", "after proven equivalents")
# The driver interface's answers to a stimulus the test itself got wrong (an unknown name, a value out of
# range, a call out of order: sut/errors.py). They are the harness's contract, checked by the project's own
# tests (tests/test_bad_input.py), not train behaviour the articles specify, and a conforming
# rig words them as it likes: a mutant inside such a `raise` is left out of the sample, and counted.
USAGE_ERRORS = frozenset({"SutError", "UnknownName", "OutOfRange", "NotPoweredUp", "NotSupported"})
# A backend's description of itself (`describe`: backend, class, profile, timing, parameters) is what the
# report's environment names the run against (tests/test_allure_env.py), not train behaviour: no article
# specifies it and no scenario reads it, so its mutants are passed over too, and counted.
SELF_DESCRIPTION = "describe"
# Two more of the driver interface that no article specifies and no scenario reads, on a backend only: the
# names of its vehicle inputs and outputs, listed for a user (`vehicle_names`), and an input read back as the
# rig last set it (`input`: the stimulus's echo, not the train's answer; a model's own `input`, such as the
# metro I/O port's, is behaviour and stays in).
BACKEND_PASSED_OVER = {"vehicle_names": "self-description", "input": "stimulus read-back"}
# A trace event of a kind no conformance check reads (the step modules but those that build the reviewer's
# report: the timing diagram and the key events) is a diagnostic: no requirement makes a conforming
# implementation emit it as the reference does, so a mutant inside its emit call is passed over, and counted.
# What decides "read" is every string in the step modules that names a kind or a kind prefix ("fault." /
# "fault.*"): a step that reads a kind through a variable still names it somewhere, and a literal that merely
# looks like a kind only keeps more mutants in. Seed 3 (2026-11-26) marked 26 mutants equivalent by hand, 13
# of them events of this sort.
EMIT_CALLS = frozenset({"emit", "_emit", "_mark", "emit_free"})
REPORT_MODULES = ("diagram.py", "report.py")
_KIND = re.compile(r"^[a-z][a-z0-9_]*(\.[A-Za-z0-9_]+)+$")


@dataclass
class Mutant:
    name: str
    part: str               # crh2, metro, atp or shared
    path: str               # sut/reference/...
    line: int
    before: str
    after: str
    status: str = "not checked"
    killed_by: str = ""


def _mutmut(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    """mutmut's command line, its map learnt by one pytest process per core (outline/mutate/sharded_map.py)."""
    return subprocess.run([sys.executable, "-m", "outline.mutate.sharded_map", *args], cwd=ROOT,
                          capture_output=True, text=True, env=dict(os.environ, **(env or {})))


# What the map of scenarios to functions is made from besides the references. mutmut maps a test again only
# when its id is new: a scenario given new steps keeps the map of its old ones (seed 4, 2026-11-26, called
# the metro backend's remove_key "no tests" though F-NET-25 had come to remove the key). So the tests made of
# what changed since the map was made are taken out of mutmut's map and mapped again, and only they: what each
# test is made of (its feature file, and each step definition its steps bind to, by the source of that
# definition) is noted beside the map (outline/mutate/scenario_inputs.py). Mapping every test under mutmut's
# trampolines took 71 min in one process (2026-11-27); it is now one process per core with the trampoline's
# bookkeeping read once (sharded_map.py, quick_trampoline.py). A changed feature file costs its own
# scenarios, a changed step definition the scenarios that use it, a change elsewhere in a step module (a
# helper, an import) every scenario whose step modules reach that module, and a change the notes cannot place
# (a module no noted test uses, such as the fixtures, or no notes at all) every test.
# The plugins are among them: they decide how every test is mapped, so a change to one maps every test again.
MAPS_EVERY_TEST = ("outline/mutate/mutation_plugin.py", "outline/mutate/quick_trampoline.py",
                   "outline/mutate/map_shard.py")
MAPPED_TESTS = ("features/", "tests/test_bulk.py", "tests/test_kernel.py", "tests/test_bad_input.py",
                "tests/test_eventlog.py")
MAPPED_FROM = ("features/**/*.feature", "steps/*.py", *(t for t in MAPPED_TESTS if t.endswith(".py")),
               *MAPS_EVERY_TEST)
MAP_DIGEST = MUTANTS_DIR / "scenarios.sha256"          # what the map was made from (JSON; see map_sources)
INPUTS = MUTANTS_DIR / "scenario_inputs.json"         # what each mapped test is made of
MAP_LOG = MUTANTS_DIR / "map.log"                     # how the map was learnt (sharded_map.py)




def map_sources(root: Path | None = None) -> dict[str, str]:
    """What the map is made from, each with its digest: every feature file and test file whole, every step
    module as its step definitions (`steps/x.py@<digest>`) and the rest of it (`steps/x.py`)."""
    root = root or ROOT
    out = {}
    for path in sorted({p for pattern in MAPPED_FROM for p in root.glob(pattern)}):
        name = path.relative_to(root).as_posix()
        if name.startswith("steps/"):
            definitions, rest = step_definitions(path)
            out[name] = rest
            out.update({f"{name}@{digest}": digest for digest in definitions.values()})
        else:
            out[name] = hashlib.sha256(path.read_bytes()).hexdigest()[:16]
    return out


def scenarios_digest(root: Path | None = None) -> str:
    return _sha(json.dumps(map_sources(root), sort_keys=True))


def step_imports(root: Path | None = None) -> dict[str, set[str]]:
    """Each step module with the step modules it imports, transitively (itself included)."""
    root = root or ROOT
    direct: dict[str, set[str]] = {}
    for path in sorted((root / "steps").glob("*.py")):
        name, found = path.relative_to(root).as_posix(), set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module == "steps":
                found |= {f"steps/{alias.name}.py" for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("steps."):
                found.add(node.module.replace(".", "/") + ".py")
            elif isinstance(node, ast.Import):
                found |= {a.name.replace(".", "/") + ".py" for a in node.names if a.name.startswith("steps.")}
        direct[name] = found
    closure = {}
    for name in direct:
        seen, todo = {name}, [name]
        while todo:
            for other in direct.get(todo.pop(), ()):
                if other not in seen:
                    seen.add(other)
                    todo.append(other)
        closure[name] = seen
    return closure


def tests_to_map_again(old: dict[str, str], new: dict[str, str], inputs: dict[str, list[str]],
                       imports: dict[str, set[str]]) -> set[str] | None:
    """The tests made of what changed between two map_sources (None: every test, the change cannot be
    placed). `inputs`: each test's files and step definitions as the notes have them."""
    changed = {name for name in old.keys() | new.keys() if old.get(name) != new.get(name)}
    if not changed:
        return set()
    if changed & set(MAPS_EVERY_TEST):
        return None
    modules = {name for name in changed if name.startswith("steps/") and "@" not in name}
    used: set[str] = set()
    reach: dict[str, set[str]] = {}
    for test, made_of in inputs.items():
        mine = {f for f in made_of if "@" not in f}
        for module in [f for f in mine if f.startswith("steps/")]:
            mine |= imports.get(module, set())
        reach[test] = mine
        used |= mine
    if modules - used:
        return None               # a module no noted test is made of (the fixtures, a helper of theirs)
    return {test for test, mine in reach.items()
            if mine & changed or any(f in changed for f in inputs[test] if "@" in f)}


def note_inputs() -> None:
    """What each mapped test is made of now (outline/mutate/scenario_inputs.py, a collect-only run), beside the map."""
    from outline.mutate.scenario_inputs import OUT
    result = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:xdist",
                             "-p", "no:cacheprovider", "-p", "outline.mutate.scenario_inputs", *MAPPED_TESTS],
                            cwd=ROOT, capture_output=True, text=True, env=dict(os.environ, **{OUT: str(INPUTS)}))
    if result.returncode != 0 or not INPUTS.exists():
        INPUTS.unlink(missing_ok=True)                # no notes: the next change maps every test again
        print(f"mutmut: could not note what each test is made of:\n{result.stdout[-2000:]}", flush=True)


def _forget(stats: Path, tests: set[str]) -> None:
    """Take `tests` out of mutmut's map: it maps them again as new tests."""
    data = json.loads(stats.read_text(encoding="utf-8"))
    data["tests_by_mangled_function_name"] = {name: [t for t in mapped if t not in tests] for name, mapped
                                              in data["tests_by_mangled_function_name"].items()}
    for test in tests:
        data["duration_by_test"].pop(test, None)
    stats.write_text(json.dumps(data, indent=4), encoding="utf-8")


def _noted(path: Path) -> dict:
    try:
        value = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return value if isinstance(value, dict) else {}


def _print_map_log(what: str) -> None:
    """sharded_map.py's lines starting with `what` (how long the map or the clean run took), which mutmut,
    holding its own output back, does not print."""
    if MAP_LOG.exists():
        for line in MAP_LOG.read_text(encoding="utf-8").splitlines():
            if line.startswith(what):
                print(f"mutmut: {line}", flush=True)


def generate() -> None:
    """Phase 1: mutants written and scenarios mapped (mutmut refuses the name afterwards, as intended)."""
    sources = map_sources()
    stats = MUTANTS_DIR / "mutmut-stats.json"
    old, inputs = _noted(MAP_DIGEST), _noted(INPUTS)
    if stats.exists() and old != sources:
        again = tests_to_map_again(old, sources, inputs, step_imports()) if old and inputs else None
        if again is None:
            print("mutmut: the scenarios or steps changed since the last map: mapping them all again", flush=True)
            stats.unlink()
        else:
            print(f"mutmut: the scenarios or steps changed since the last map: mapping the {len(again)} tests "
                  "made of what changed again", flush=True)
            _forget(stats, again)
    MAP_LOG.unlink(missing_ok=True)
    result = _mutmut("run", "outline.mutate.mutation.generate-only")
    _print_map_log("mapped")
    if stats.exists():
        if old != sources or not INPUTS.exists():
            note_inputs()
        MAP_DIGEST.write_text(json.dumps(sources, indent=0, sort_keys=True), encoding="utf-8")
    if not list(MUTANTS_DIR.rglob("*.py.meta")):
        sys.exit(f"mutmut wrote no mutants:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}")


def all_names() -> list[str]:
    names: list[str] = []
    for meta in sorted(MUTANTS_DIR.rglob("*.py.meta")):
        names += sorted(json.loads(meta.read_text(encoding="utf-8"))["exit_code_by_key"])
    return names


def part_of(path: str) -> str:
    parts = Path(path).parts              # sut/reference/<part>/... or sut/reference/<module>.py
    return parts[2] if len(parts) > 3 else "shared"


def describe(name: str) -> Mutant:
    """Where a mutant is (file:line in the original source) and what it changes, from mutmut's diff."""
    from mutmut.mutation.diff_apply import get_diff_for_mutant
    match = NAME.match(name)
    if not match:
        raise ValueError(f"not a mutmut mutant name: {name}")
    path = match["module"].replace(".", "/") + ".py"
    diff = get_diff_for_mutant(name, path=MUTANTS_DIR / path).splitlines()
    before = next((l[1:] for l in diff if l.startswith("-") and not l.startswith("---")), "")
    after = next((l[1:] for l in diff if l.startswith("+") and not l.startswith("+++")), "")
    return Mutant(name, part_of(path), path, _line_of(ROOT / path, match["function"], before, _offset(diff)),
                  before.strip(), after.strip())


def _offset(diff: list[str]) -> int | None:
    """The changed line's place in its function (1: the `def` line), from the diff's first hunk."""
    line = None
    for text in diff:
        hunk = re.match(r"^@@ -(\d+)", text)
        if hunk:
            line = int(hunk[1])
        elif line is not None and not text.startswith(("---", "+++", "+")):
            if text.startswith("-"):
                return line
            line += 1
    return None


def _line_of(source: Path, mangled: str, text: str, offset: int | None = None) -> int:
    """The line of `text` inside the function mutmut calls `mangled` (xǁClassǁmethod or x_function): `offset`
    lines into it where the diff says so (a line said twice in one function, such as `continue`, is then the
    right one), else the first line that reads `text`."""
    names = mangled[2:].split("ǁ") if mangled.startswith("xǁ") else [mangled[2:]]
    nodes: list[ast.AST] = ast.parse(source.read_text(encoding="utf-8")).body
    found = None
    for name in (n for n in names if n):
        found = next((n for n in nodes if isinstance(n, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                      and n.name == name), None)
        if found is None:
            return 0
        nodes = found.body
    lines = source.read_text(encoding="utf-8").splitlines()
    start, end = found.lineno, found.end_lineno or found.lineno
    if offset is not None and start + offset - 1 <= end and lines[start + offset - 2].strip() == text.strip():
        return start + offset - 1
    return next((i for i in range(start, end + 1) if lines[i - 1].strip() == text.strip()), start)


def function_of(name: str) -> str:
    """The function a mutmut mutant name is in, as Python names it: `Relay.__init__`, `_one_check_encode`."""
    match = NAME.match(name)
    if not match:
        return ""
    mangled = match["function"]
    return ".".join(p for p in mangled[2:].split("ǁ") if p) if mangled.startswith("xǁ") else mangled[2:]


def is_marked(mutant: "Mutant", marked: set[tuple[str, str, str]]) -> bool:
    """Whether a mark names the mutant: by file, or where the same line text is said in several places of a
    file that are not all equivalent, by file and function (`path::Class.method`)."""
    return (mutant.path, mutant.before, mutant.after) in marked or \
        (f"{mutant.path}::{function_of(mutant.name)}", mutant.before, mutant.after) in marked


def equivalents() -> list[tuple[str, str, str]]:
    """(path, line before, line after) of each mutant marked equivalent (path may be `path::function`)."""
    return [(mark.where, mark.before, mark.after) for mark in equivalence.read_marks(EQUIVALENTS)]


_STEP_NAMES: dict[Path, tuple[frozenset[str], frozenset[str]]] = {}      # by ROOT (tests point it elsewhere)
_EMITS: dict[tuple[Path, str], tuple[str, list[ast.Call]]] = {}
_TREES: dict[tuple[Path, str], ast.AST] = {}                          # the trees _EMITS' calls are nodes of


def _step_names() -> tuple[frozenset[str], frozenset[str]]:
    """(every string, every keyword name) in the step modules a conformance check is made of (not the
    report's: REPORT_MODULES), each module parsed once."""
    if ROOT not in _STEP_NAMES:
        strings: set[str] = set()
        keywords: set[str] = set()
        for module in sorted((ROOT / "steps").glob("*.py")):
            if module.name in REPORT_MODULES:
                continue
            for node in ast.walk(ast.parse(module.read_text(encoding="utf-8"))):
                if isinstance(node, ast.Constant) and isinstance(node.value, str):
                    strings.add(node.value)
                elif isinstance(node, ast.keyword) and node.arg:
                    keywords.add(node.arg)
        _STEP_NAMES[ROOT] = (frozenset(strings), frozenset(keywords))
    return _STEP_NAMES[ROOT]


def _emits(path: str) -> tuple[str, list[ast.Call]]:
    """The source of `path` and its emit calls (EMIT_CALLS), parsed once per file."""
    if (ROOT, path) not in _EMITS:
        source = (ROOT / path).read_text(encoding="utf-8")
        tree = _TREES[ROOT, path] = ast.parse(source)
        calls = [node for node in ast.walk(tree) if isinstance(node, ast.Call)
                 and (node.func.attr if isinstance(node.func, ast.Attribute)
                      else getattr(node.func, "id", None)) in EMIT_CALLS]
        _EMITS[ROOT, path] = (source, calls)
    return _EMITS[ROOT, path]


def read_kinds() -> tuple[frozenset[str], tuple[str, ...], frozenset[str]]:
    """(kinds, kind prefixes, every string) the conformance checks name in the step modules (EMIT_CALLS'
    note). A kind without a dot ("balise") is read if some step names that very string."""
    literals = _step_names()[0]
    kinds = frozenset(v for v in literals if _KIND.match(v))
    prefixes = tuple(sorted(v.rstrip("*") for v in literals
                            if v.endswith((".", ".*")) and _KIND.match(v.rstrip("*") + "x")))
    return kinds, prefixes, literals


def _literal_kind(call: ast.Call) -> str | None:
    """The kind an emit call names, its last positional argument, if that is a string literal."""
    kind = call.args[-1] if call.args else None
    return kind.value if isinstance(kind, ast.Constant) and isinstance(kind.value, str) else None


def in_unread_event(path: str, line: int) -> bool:
    """Whether `line` of `path` is inside an emit call (EMIT_CALLS) whose kind, a literal, no check reads.
    Every emit of the references takes the kind as its last positional argument (`emit(kind)` on a node,
    `emit(source, kind)` on a train)."""
    _kinds, prefixes, literals = read_kinds()

    def unread(call: ast.Call) -> bool:
        kind = _literal_kind(call)
        return kind is not None and kind not in literals and not ("." in kind and kind.startswith(prefixes))

    _source, calls = _emits(path)
    if any(call.lineno <= line <= (call.end_lineno or call.lineno) for call in calls if unread(call)):
        return True
    # The test of an `if` that does nothing but emit events no check reads: a mutant there changes only when
    # they are emitted (the metro's train.stop at standstill, seed 6).
    emits = {id(call) for call in calls}
    for node in ast.walk(_TREES[ROOT, path]):
        if isinstance(node, ast.If) and node.test.lineno <= line <= (node.test.end_lineno or node.test.lineno):
            done = node.body + node.orelse
            if all(isinstance(st, ast.Expr) and id(st.value) in emits and unread(st.value) for st in done):
                return True
    return False


def read_fields() -> frozenset[str]:
    """Every name a conformance check could read an event's field by: the step modules' strings
    (`ev["state"]`) and their calls' keyword names (`select(kind=..., state="open")`)."""
    strings, keywords = _step_names()
    return strings | keywords


def changed_columns(line_text: str, before: str, after: str) -> tuple[int, int] | None:
    """The columns of `line_text` (the source line, `before` stripped) that the mutation changes."""
    indent = line_text.find(before)
    if indent < 0:
        return None
    prefix = 0
    while prefix < min(len(before), len(after)) and before[prefix] == after[prefix]:
        prefix += 1
    suffix = 0
    while suffix < min(len(before), len(after)) - prefix and before[-1 - suffix] == after[-1 - suffix]:
        suffix += 1
    return indent + prefix, indent + max(prefix, len(before) - suffix)


def _emit_change(path: str, line: int, before: str, after: str
                 ) -> tuple[list[ast.Call], str, tuple[int, int]] | None:
    """The emit calls of `path`, the source line and the columns of it the change covers; None if not found."""
    source, calls = _emits(path)
    lines = source.splitlines()
    if not 0 < line <= len(lines):
        return None
    text = lines[line - 1]
    columns = changed_columns(text, before, after)
    return None if columns is None else (calls, text, columns)


def _changed_field(path: str, line: int, before: str, after: str
                   ) -> tuple[ast.Call, ast.keyword, str, tuple[int, int]] | None:
    """The emit call (EMIT_CALLS) and its one-line keyword argument the change lies inside, with the source line
    and the changed columns; None if the change is not inside one."""
    found = _emit_change(path, line, before, after)
    if found is None:
        return None
    calls, text, columns = found
    start, end = columns
    def reach(kw: ast.keyword) -> int:
        # A keyword dropped from the middle of a call goes with the ", " after it (seed 9: `to=to, ` of the
        # metro's line.switch, which the rule did not see as inside the keyword).
        stop = kw.end_col_offset or 0
        return stop + 2 if text[stop:stop + 2] == ", " else stop

    return next(((call, kw, text, columns) for call in calls for kw in call.keywords
                 if kw.arg is not None and kw.lineno == line == kw.end_lineno
                 and kw.col_offset <= start and end <= reach(kw)), None)


def in_unread_field(path: str, line: int, before: str, after: str) -> bool:
    """Whether the change is inside one keyword argument of an emit call (EMIT_CALLS) that names a field no
    check reads (read_fields): a diagnostic field of an event whose other fields may well be read."""
    found = _changed_field(path, line, before, after)
    if found is None:
        return False
    _call, kw, text, columns = found
    return kw.arg not in read_fields() and field_change_cannot_raise(kw, text, before, after, columns)


_CONTRACT_FIELDS: dict[Path, dict[str, frozenset[str]]] = {}


def contract_fields() -> dict[str, frozenset[str]]:
    """Every event kind the implementer's contracts list (sut/contract/<profile>.yaml, every profile) with the
    fields any of them lists for it; a pattern (`loop.*`) stands as written."""
    if ROOT not in _CONTRACT_FIELDS:
        import yaml
        fields: dict[str, set[str]] = {}
        for path in sorted((ROOT / "sut" / "contract").glob("*.yaml")):
            events = (yaml.safe_load(path.read_text(encoding="utf-8")) or {}).get("events") or {}
            for kind, entry in events.items():
                fields.setdefault(kind, set()).update((entry or {}).get("fields") or {})
        _CONTRACT_FIELDS[ROOT] = {kind: frozenset(names) for kind, names in fields.items()}
    return _CONTRACT_FIELDS[ROOT]


def _listed_fields(kind: str) -> frozenset[str] | None:
    """The fields the contracts list for `kind` (None: no contract lists the kind)."""
    found = [names for pattern, names in contract_fields().items()
             if pattern == kind or any(ch in pattern for ch in "*?[") and fnmatch.fnmatchcase(kind, pattern)]
    return frozenset().union(*found) if found else None


def _squeezed(text: str) -> str:
    return re.sub(r"\s+", "", text).replace(",)", ")")


def in_unlisted_field(path: str, line: int, before: str, after: str) -> bool:
    """Whether the change is inside one keyword argument of an emit call whose kind (a literal, its last
    positional argument) no contract lists, or whose entries do not list that field, and the change cannot
    raise (field_change_cannot_raise). A step can read no such field (the contract guard refuses it:
    ContractGap), the differential checker compares none, and a conforming implementation need not write it."""
    found = _changed_field(path, line, before, after)
    if found is None:
        return False
    call, kw, text, columns = found
    kind = _literal_kind(call)
    if kind is None:
        return False
    listed = _listed_fields(kind)
    return (listed is None or kw.arg not in listed) and field_change_cannot_raise(kw, text, before, after, columns)


def in_unlisted_source(path: str, line: int, before: str, after: str) -> bool:
    """Whether the change is inside the source argument of an emit call (`emit(source, kind, ...)`, the first
    of two positional arguments) whose kind, a literal, no contract lists, and cannot raise: the whole source
    made None, or a change inside it that field_change_cannot_raise would allow in a field. Every emit stores
    its source as it is (TraceEvent), and an event of a kind no contract lists is read by no step (the guard
    refuses it: ContractGap) and compared by no checker; a listed kind's source is checked (check_event)."""
    found = _emit_change(path, line, before, after)
    if found is None:
        return False
    calls, text, columns = found
    start, end = columns
    for call in calls:
        kind = _literal_kind(call)
        if len(call.args) != 2 or kind is None:
            continue
        arg = call.args[0]
        if not (arg.lineno == line == arg.end_lineno and arg.col_offset <= start and end <= (arg.end_col_offset or 0)):
            continue
        if _listed_fields(kind) is not None:
            return False
        return _made_none(arg, text, after) or field_change_cannot_raise(None, text, before, after, columns, arg)
    return False


def _made_none(arg: ast.expr, text: str, after: str) -> bool:
    """Whether `after` is the source line `text` with the whole argument `arg` (on that line) written None."""
    whole = text[arg.col_offset:arg.end_col_offset]
    return whole != "None" and _squeezed(after) == _squeezed(text.strip().replace(whole, "None", 1))


def field_change_cannot_raise(kw: ast.keyword | None, text: str, before: str, after: str,
                              columns: tuple[int, int], value: ast.expr | None = None) -> bool:
    """Whether a change (at `columns` of the source line `text`) inside the keyword argument `kw` of a call (or,
    with `kw` None, inside the expression `value`) cannot raise before the call: the keyword's whole value made
    None, or the keyword dropped; otherwise no argument made None or dropped inside it (may_raise_otherwise), no
    subscript's key changed
    (`fields["XXcabXX"]` is a KeyError: the checker overturned it, 2026-11-27) and no arithmetic operator
    swapped (`"a" - b`, `x / 0`)."""
    if kw is not None:
        whole = text[kw.col_offset:kw.end_col_offset]
        stripped = text.strip()
        squeezed = _squeezed(after)
        if squeezed in (_squeezed(stripped.replace(whole, f"{kw.arg}=None", 1)),
                        _squeezed(re.sub(r",?\s*" + re.escape(whole), "", stripped, count=1)),
                        _squeezed(stripped.replace(whole, "", 1))):
            return True
        value = kw.value
    if may_raise_otherwise(before, after):
        return False
    start, end = columns

    def touched(lo: int, hi: int) -> bool:
        return start < hi and lo < max(end, start + 1)

    for node in ast.walk(value):
        if isinstance(node, ast.Subscript) and touched(node.slice.col_offset, node.slice.end_col_offset or 0):
            return False
        if isinstance(node, ast.BinOp) and touched(node.left.end_col_offset or 0, node.right.col_offset):
            return False
    return True


_RAISES: dict[str, list[tuple[int, int]]] = {}


def in_usage_error(path: str, line: int) -> bool:
    """Whether `line` of `path` is inside a `raise` of one of the driver's USAGE_ERRORS, or in an assignment of
    what its message lists inside an `if` that does nothing but raise one (the words of the answer). Not the
    `if`'s test: a change there changes which stimuli are refused, and one that refuses a good stimulus is
    seen by every scenario that gives it (seed 8 drew `if car in range(1, 7)`, which refuses every car)."""
    if path not in _RAISES:
        def usage(node: ast.AST) -> bool:
            return isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call) \
                and isinstance(node.exc.func, ast.Name) and node.exc.func.id in USAGE_ERRORS
        tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
        spans = [(node.lineno, node.end_lineno or node.lineno) for node in ast.walk(tree) if usage(node)]
        # An `if` that only raises one, maybe after naming what it lists as known: those assignments are the
        # message's words too.
        guards = [node for node in ast.walk(tree) if isinstance(node, ast.If) and not node.orelse
                  and usage(node.body[-1])
                  and all(isinstance(st, (ast.Assign, ast.AnnAssign)) for st in node.body[:-1])]
        spans += [(st.lineno, st.end_lineno or st.lineno) for node in guards for st in node.body[:-1]]
        _RAISES[path] = spans
    return any(start <= line <= end for start, end in _RAISES[path])


_WORDS_ONLY: dict[Path, dict[str, tuple[str, ...]]] = {}


def words_only_parameters() -> dict[str, tuple[str, ...]]:
    """For each of the driver's USAGE_ERRORS (sut/errors.py), the parameters of its __init__ in order, each
    named if the constructor only puts it into its message (an f-string's value) or keeps it as an attribute,
    "" if it computes with it (UnknownName sorts `known` and looks `name` up among them: None there raises)."""
    if ROOT not in _WORDS_ONLY:
        tree = ast.parse((ROOT / "sut" / "errors.py").read_text(encoding="utf-8"))
        found: dict[str, tuple[str, ...]] = {}
        for cls in (n for n in tree.body if isinstance(n, ast.ClassDef) and n.name in USAGE_ERRORS):
            init = next((f for f in cls.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"), None)
            if init is None:
                continue
            params = [a.arg for a in init.args.args[1:]]
            harmless: set[int] = set()
            for node in ast.walk(init):
                if isinstance(node, ast.FormattedValue) and isinstance(node.value, ast.Name):
                    harmless.add(id(node.value))
                if isinstance(node, ast.Assign) and all(isinstance(t, (ast.Attribute, ast.Tuple)) for t in node.targets):
                    values = node.value.elts if isinstance(node.value, ast.Tuple) else [node.value]
                    harmless.update(id(v) for v in values if isinstance(v, ast.Name))
            loads = [n for n in ast.walk(init) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)]
            found[cls.name] = tuple(p if all(id(n) in harmless for n in loads if n.id == p) else "" for p in params)
        _WORDS_ONLY[ROOT] = found
    return _WORDS_ONLY[ROOT]


def words_made_none(path: str, line: int, before: str, after: str) -> bool:
    """Whether the change makes one whole argument of a usage error's constructor None where that constructor
    only words it (words_only_parameters): the same error, raised by the same test, only its message reads
    "None" (seed 9: `OutOfRange(name, value, None)`, `UnknownName(None, name, lamps)`)."""
    source, _calls = _emits(path)                  # parsed once per file (_TREES)
    lines = source.splitlines()
    text = lines[line - 1] if 0 < line <= len(lines) else ""
    for node in ast.walk(_TREES[ROOT, path]):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                and node.func.id in USAGE_ERRORS and node.lineno <= line <= (node.end_lineno or node.lineno)):
            continue
        params = words_only_parameters().get(node.func.id, ())
        for index, arg in enumerate(node.args):
            if index < len(params) and params[index] and arg.lineno == line == arg.end_lineno \
                    and _made_none(arg, text, after):
                return True
    return False


# A branch only faulty variants take: an `if` whose test the reference's behaviour switches decide (each
# config's *Behaviour dataclass: "switches that only faulty variants turn off"), read at their defaults. A
# mutant in the branch the reference never takes changes a faulty variant, not the reference, and no run
# against the reference can tell (seeds 3 and 4 marked 6 and 5 of these by hand).
_UNTAKEN: dict[tuple[Path, str], list[tuple[int, int]]] = {}
_UNKNOWN = object()


def behaviour_defaults(path: str) -> dict[str, object]:
    """The default of every behaviour switch of the reference `path` belongs to (its part's config)."""
    import dataclasses
    import importlib

    parts = Path(path).parts
    if len(parts) < 4:
        return {}
    try:
        config = importlib.import_module(f"sut.reference.{parts[2]}.config")
    except ImportError:
        return {}
    return {field.name: field.default for klass in vars(config).values()
            if isinstance(klass, type) and klass.__name__.endswith("Behaviour") and dataclasses.is_dataclass(klass)
            for field in dataclasses.fields(klass)}


def _switch(node: ast.AST, aliases: dict[str, str]) -> str | None:
    """The behaviour switch `node` reads: `<...>.behaviour.NAME`, `behaviour.NAME`, or `self.X` that this file
    only ever sets from one switch."""
    if isinstance(node, ast.Attribute):
        owner = node.value
        if (isinstance(owner, ast.Name) and owner.id == "behaviour") or \
                (isinstance(owner, ast.Attribute) and owner.attr == "behaviour"):
            return node.attr
        if isinstance(owner, ast.Name) and owner.id == "self":
            return aliases.get(node.attr)
    return None


def _decides(op: ast.boolop, value: object) -> bool:
    """Whether an operand of `and`/`or` that is `value` decides the whole (the rest is never read)."""
    return value is not _UNKNOWN and (not value if isinstance(op, ast.And) else bool(value))


def _untaken(node: ast.If, value: object) -> tuple[int, int] | None:
    """The lines of the branch of `node` that a test of `value` never takes, if it has its own lines."""
    branch = node.orelse if value else node.body
    if branch and branch[0].lineno > (node.test.end_lineno or node.test.lineno):
        return branch[0].lineno, branch[-1].end_lineno or branch[-1].lineno
    return None


def _value(node: ast.AST, aliases: dict[str, str], defaults: dict[str, object],
           names: dict[str, object] | None = None) -> object:
    """What `node` is when every behaviour switch has its default, or _UNKNOWN. `names`: local variables
    the function sets once, with what they are."""
    switch = _switch(node, aliases)
    if switch is not None:
        return defaults.get(switch, _UNKNOWN)
    if isinstance(node, ast.Name):
        return (names or {}).get(node.id, _UNKNOWN)
    if isinstance(node, ast.Constant):
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
        value = _value(node.operand, aliases, defaults, names)
        return _UNKNOWN if value is _UNKNOWN else not value
    if isinstance(node, ast.BoolOp):
        values = [_value(v, aliases, defaults, names) for v in node.values]
        if any(_decides(node.op, v) for v in values):
            return isinstance(node.op, ast.Or)
        return _UNKNOWN if _UNKNOWN in values else isinstance(node.op, ast.And)
    if isinstance(node, ast.Compare) and len(node.ops) == 1:
        left = _value(node.left, aliases, defaults, names)
        right = _value(node.comparators[0], aliases, defaults, names)
        if left is _UNKNOWN or right is _UNKNOWN:
            return _UNKNOWN
        compare = {ast.Is: lambda a, b: a is b, ast.IsNot: lambda a, b: a is not b, ast.Eq: lambda a, b: a == b,
                   ast.NotEq: lambda a, b: a != b}.get(type(node.ops[0]))
        return _UNKNOWN if compare is None else compare(left, right)
    return _UNKNOWN


def _switch_aliases(tree: ast.AST) -> dict[str, str]:
    """`self.X` that this file only ever sets from one behaviour switch: X -> the switch."""
    set_from: dict[str, set[str | None]] = {}
    for node in ast.walk(tree):
        targets = [node.target] if isinstance(node, ast.AnnAssign) else getattr(node, "targets", [])
        if not isinstance(node, (ast.Assign, ast.AnnAssign)) or node.value is None:
            continue
        pairs = [(t, node.value) for t in targets]
        if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Tuple) and \
                isinstance(node.value, ast.Tuple) and len(node.targets[0].elts) == len(node.value.elts):
            pairs = list(zip(node.targets[0].elts, node.value.elts))
        for target, value in pairs:
            if isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name) and \
                    target.value.id == "self":
                set_from.setdefault(target.attr, set()).add(_switch(value, {}))
    return {attr: next(iter(switches)) for attr, switches in set_from.items()
            if len(switches) == 1 and None not in switches}


def in_variant_only_branch(path: str, line: int) -> bool:
    """Whether `line` of `path` is in a branch of an `if` that the reference's behaviour switches, at their
    defaults, never take (the note above)."""
    if (ROOT, path) not in _UNTAKEN:
        tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
        defaults = behaviour_defaults(path)
        aliases = _switch_aliases(tree)
        spans = []
        for node in ast.walk(tree):
            if not isinstance(node, ast.If):
                continue
            value = _value(node.test, aliases, defaults)
            span = None if value is _UNKNOWN else _untaken(node, value)
            if span is not None:
                spans.append(span)
        _UNTAKEN[ROOT, path] = spans
    return any(start <= line <= end for start, end in _UNTAKEN[ROOT, path])


# Code the reference never runs although no `if` of a variant's says so: an operand of `and`/`or` after one
# that the switches already decide (`not behaviour.on and <never read>`), the branch of a conditional
# expression that they decide, and a function whose every use is in such code, in a variant's branch or in
# another such function (the self-diagnostic line's status data, the one-check-sequence codec). Seeds 3-5
# marked 10 mutants of these kinds by hand. A use is any name, attribute or string that spells the function's
# name in sut/, steps/ or outline/ (a method of the same name elsewhere, or a getattr by string, keeps it in).
Extent = tuple[int, int, int, int]                  # (first line, column) .. (last line, end column)
_NEVER_RUN: dict[Path, dict[str, list[tuple[Extent, str]]]] = {}
_WHOLE = 1 << 30


def _extent(node: ast.AST) -> Extent:
    return (node.lineno, node.col_offset, node.end_lineno or node.lineno,
            node.end_col_offset if node.end_col_offset is not None else _WHOLE)


def _inside(extent: Extent, line: int, start: int, end: int) -> bool:
    first, col, last, end_col = extent
    return (first, col) <= (line, start) and (line, end) <= (last, end_col)


def _set_once(function: ast.AST, aliases: dict[str, str], defaults: dict[str, object]) -> dict[str, object]:
    """The local variables `function` sets exactly once, by a plain `name = ...`, that the switches decide."""
    stores: dict[str, list[ast.AST]] = {}
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, (ast.Store, ast.Del)):
            stores.setdefault(node.id, []).append(node)
        elif isinstance(node, ast.arg):
            stores.setdefault(node.arg, []).extend([node, node])        # a parameter is never decided
    names: dict[str, object] = {}
    for node in ast.walk(function):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name) \
                and len(stores[node.targets[0].id]) == 1:
            value = _value(node.value, aliases, defaults, names)
            if value is not _UNKNOWN:
                names[node.targets[0].id] = value
    return names


def _terminates(block: list[ast.stmt]) -> bool:
    return bool(block) and isinstance(block[-1], (ast.Return, ast.Raise, ast.Continue, ast.Break))


def _decided(path: str, tree: ast.AST) -> list[Extent]:
    """The extents in `path` the switches at their defaults leave unread: operands after a deciding one, a
    conditional expression's untaken branch, an `if`'s untaken branch (in_variant_only_branch), and what
    follows an `if` they decide that always returns."""
    defaults = behaviour_defaults(path)
    aliases = _switch_aliases(tree)
    extents: list[Extent] = []

    def after_early_return(node: ast.AST, names: dict[str, object]) -> None:
        for field in ("body", "orelse", "finalbody"):
            block = getattr(node, field, None)
            if not isinstance(block, list):
                continue
            for i, st in enumerate(block[:-1]):
                if isinstance(st, ast.If) and not st.orelse and _terminates(st.body) and \
                        _value(st.test, aliases, defaults, names) not in (_UNKNOWN, False, None, 0, ""):
                    extents.append((block[i + 1].lineno, 0, block[-1].end_lineno or block[-1].lineno, _WHOLE))
                    break

    def visit(scope: ast.AST, names: dict[str, object]) -> None:
        after_early_return(scope, names)
        todo = list(ast.iter_child_nodes(scope))
        while todo:
            node = todo.pop()
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                visit(node, _set_once(node, aliases, defaults) if not isinstance(node, ast.Lambda) else names)
                continue
            todo.extend(ast.iter_child_nodes(node))
            after_early_return(node, names)
            if isinstance(node, ast.BoolOp):
                for i, operand in enumerate(node.values[:-1]):
                    if _decides(node.op, _value(operand, aliases, defaults, names)):
                        extents.extend(_extent(rest) for rest in node.values[i + 1:])
                        break
            elif isinstance(node, (ast.IfExp, ast.If)):
                value = _value(node.test, aliases, defaults, names)
                if value is _UNKNOWN:
                    continue
                if isinstance(node, ast.IfExp):
                    extents.append(_extent(node.orelse if value else node.body))
                elif (span := _untaken(node, value)) is not None:
                    extents.append((span[0], 0, span[1], _WHOLE))

    visit(tree, {})
    return extents


def never_run() -> dict[str, list[tuple[Extent, str]]]:
    """Per reference file: the extents the reference never runs (the note above), each with its reason."""
    if ROOT in _NEVER_RUN:
        return _NEVER_RUN[ROOT]
    # Uses are looked for wherever the conformance run has code (a driver call a step makes keeps the method
    # in), not in the project's own tests: a function only tests/variants.py calls is a variant's.
    files = [p for folder in ("sut", "steps", "outline") for p in sorted((ROOT / folder).rglob("*.py"))]
    trees = {path.relative_to(ROOT).as_posix(): ast.parse(path.read_text(encoding="utf-8"))
             for path in files + [ROOT / "conftest.py"] if path.exists()}
    dead = {path: [(extent, "decided by the switches") for extent in _decided(path, tree)]
            for path, tree in trees.items() if path.startswith("sut/reference/")}
    functions: dict[str, list[tuple[str, ast.AST]]] = {}
    uses: dict[str, list[tuple[str, int, int, int]]] = {}
    for path, tree in trees.items():
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and path in dead \
                    and not node.name.startswith("__"):
                functions.setdefault(node.name, []).append((path, node))
            name = node.id if isinstance(node, ast.Name) else node.attr if isinstance(node, ast.Attribute) else \
                node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None
            if name is not None:
                uses.setdefault(name, []).append((path, node.lineno, node.col_offset,
                                                  node.end_col_offset or node.col_offset))
    marked: set[str] = set()
    found = True
    while found:                          # a function only dead code calls makes its own calls dead too
        found = False
        for name, defs in functions.items():
            if name in marked:
                continue
            own = [(path, _extent(node)) for path, node in defs]
            calls = [(path, line, start, end) for path, line, start, end in uses.get(name, [])
                     if not any(p == path and _inside(e, line, start, end) for p, e in own)]
            if calls and all(any(_inside(extent, line, start, end) for extent, _ in dead.get(path, []))
                             for path, line, start, end in calls):
                for path, node in defs:
                    dead[path].append((_extent(node), "only a faulty variant calls it"))
                marked.add(name)
                found = True
    _NEVER_RUN[ROOT] = dead
    return dead


def never_run_reason(path: str, line: int, before: str, after: str) -> str | None:
    """Why the reference never runs what the mutation changes (never_run), or None."""
    lines = (ROOT / path).read_text(encoding="utf-8").splitlines()
    if not 0 < line <= len(lines):
        return None
    columns = changed_columns(lines[line - 1], before, after)
    if columns is None:
        return None
    return next((reason for extent, reason in never_run().get(path, []) if _inside(extent, line, *columns)),
                None)


def may_raise_otherwise(before: str, after: str) -> bool:
    """Whether a one-token change may raise where the original line does not: an argument made None
    (`round(None, 3)`, `UnknownName("reading", None, known)`, `emit("VDX", None)`) or dropped (`f(a, )`, a
    keyword gone), mutmut's argument mutations. The differential checker overturned one mutant of the
    "unread field" rule and one of the "usage error" rule this way (2026-11-27, reports/equivalence.md): what
    a rule says is not read (a diagnostic field, an error's wording, a diagnostic event) is not read, but a
    TypeError in computing it is seen by everyone."""
    dropped = after.count(",") < before.count(",") or ", )" in after and ", )" not in before
    return after.count("None") > before.count("None") or dropped


def rule_reason(path: str, line: int, before: str, after: str) -> str | None:
    """The rule (the module's note) that passes a mutant of `line` over, or None: the draw's and the reading's.
    The rules about what nobody reads (a usage error's words, an unread event or field) hold only for a change
    that cannot raise instead (may_raise_otherwise)."""
    unread = not may_raise_otherwise(before, after)
    if in_usage_error(path, line):
        if unread:
            return "usage error"
        if words_made_none(path, line, before, after):
            return "usage error worded None"
    if unread and in_unread_event(path, line):
        return "unread event"
    if in_variant_only_branch(path, line):
        return "faulty-variant branch"
    if unread and in_unread_field(path, line, before, after):
        return "unread field"
    if in_unlisted_field(path, line, before, after):
        return "unlisted field"
    if in_unlisted_source(path, line, before, after):
        return "unlisted source"
    return never_run_reason(path, line, before, after)


def sample(names: list[str], count: int, seed: int, left_out: dict[str, int] | None = None,
           passed: list[tuple[Mutant, str]] | None = None) -> list[Mutant]:
    """`count` mutants, the same share from each part, none of those the module's note lists as passed over
    (marked equivalent, usage errors, self-description, unread events and fields, faulty-variant branches,
    code the switches leave unrun);
    seeded. `left_out` counts the ones passed over, by reason; `passed` gets each of them with its reason."""
    rng = random.Random(seed)
    left_out = {} if left_out is None else left_out
    marked = set(equivalents())
    by_part: dict[str, list[str]] = {}
    for name in names:
        match = NAME.match(name)
        if match:
            by_part.setdefault(part_of(match["module"].replace(".", "/") + ".py"), []).append(name)
    chosen: list[Mutant] = []
    parts = sorted(by_part)
    for index, part in enumerate(parts):
        want = count // len(parts) + (1 if index < count % len(parts) else 0)
        pool = by_part[part][:]
        rng.shuffle(pool)
        taken = 0
        for name in pool:
            if taken == want:
                break
            mutant = describe(name)
            reason = passed_over(mutant, marked)
            if reason is not None:
                left_out[reason] = left_out.get(reason, 0) + 1
                if passed is not None:
                    passed.append((mutant, reason))
            else:
                chosen.append(mutant)
                taken += 1
    return chosen


def passed_over(mutant: Mutant, marked: set[tuple[str, str, str]]) -> str | None:
    """Why the draw passes a mutant over (the module's note), or None: a backend's self-description, a mark
    (EQUIVALENT_MUTANTS.txt), or a rule (rule_reason)."""
    function = NAME.match(mutant.name)["function"] if NAME.match(mutant.name) else ""
    method = function.rsplit("ǁ", 1)[-1].removeprefix("x_")
    backend_only = BACKEND_PASSED_OVER.get(method) if mutant.path.endswith("/backend.py") else None
    if method == SELF_DESCRIPTION or backend_only:
        return backend_only or "self-description"
    if is_marked(mutant, marked):
        return "marked equivalent"
    return rule_reason(mutant.path, mutant.line, mutant.before, mutant.after)


def _codes() -> dict[str, int | None]:
    codes: dict[str, int | None] = {}
    for meta in MUTANTS_DIR.rglob("*.py.meta"):
        codes.update(json.loads(meta.read_text(encoding="utf-8"))["exit_code_by_key"])
    return codes


# One scenario of each train and the kernel's tests: a few seconds.
PROBE = ("features", "--item", "R-CTL-03,F-NET-21,F-ATP-04", "tests/test_kernel.py")


def probe_mutant_mode() -> None:
    """Run a few tests the way a mutant's run runs them (mutmut's trampolines, outline/mutate/mutation_plugin.py in
    a mutant's mode) under a mutant that does not exist, so every call takes the original code: they must
    pass. If they fail, the harness itself breaks the tests, and every mutant would look killed (seed 7's
    first run, 2026-11-26: the plugin emptied mutmut's own tables and 99 % were "killed")."""
    mutmut_args = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["mutmut"]
    # as mutmut's harness starts a mutant's pytest: its own options, the tests, then pyproject's options
    cmd = [sys.executable, "-m", "pytest", "--rootdir=.", "-x", "-q", *PROBE, *mutmut_args["pytest_add_cli_args"]]
    result = subprocess.run(cmd, cwd=MUTANTS_DIR, capture_output=True, text=True,
                            env=dict(os.environ, MUTANT_UNDER_TEST="sut.reference.kernel.x_no_such_function__mutmut_1"))
    if result.returncode != 0:
        raise SystemExit("mutmut: the tests fail in a mutant's run with no mutant active, so every mutant would "
                         f"look killed; nothing was run. The probe ({' '.join(PROBE)}) said:\n"
                         + (result.stdout[-3000:] + result.stderr[-2000:]).strip())


def run(mutants: list[Mutant], jobs: int, resume: bool = False) -> None:
    """Phase 3: mutmut runs the sample; statuses from its records, the killing scenario from the plugin.
    With `resume`, a mutant the last run already rejected keeps its verdict (and its killer) and only the
    rest run: survivors again (scenarios may have been added since), and those never checked."""
    from mutmut.stats import status_by_exit_code
    todo = mutants
    if resume:
        codes = _codes()
        todo = [m for m in mutants if status_by_exit_code[codes.get(m.name)] not in DETECTED]
    else:
        KILLS.unlink(missing_ok=True)
    print(f"mutmut: running {len(todo)} of the {len(mutants)} drawn mutants", flush=True)
    if todo:
        probe_mutant_mode()
        _mutmut("run", "--max-children", str(jobs), *[m.name for m in todo], env={"CRH2_MUTATION_KILLS": str(KILLS)})
        _print_map_log("clean run")
    codes = _codes()
    killers = dict(line.split("\t", 1) for line in KILLS.read_text(encoding="utf-8").splitlines()) \
        if KILLS.exists() else {}
    for mutant in mutants:
        mutant.status = status_by_exit_code[codes.get(mutant.name)]
        killer = killers.get(mutant.name, "")          # a scenario by its title, a test of the engine in full
        mutant.killed_by = killer.split("::")[-1] if killer.startswith("features/") else killer


def explained(mutant: Mutant, marked: set[tuple[str, str, str]] | None = None) -> str | None:
    """Why a survivor is no break the suite missed: marked equivalent since (the reading of its survivors), or
    under a rule made after its draw; None for a mutant detected, not checked, or surviving unexplained. The
    line is found again by its text if the source moved since the run."""
    if mutant.status in DETECTED or mutant.status == "not checked":
        return None
    if is_marked(mutant, set(equivalents()) if marked is None else marked):
        return "marked equivalent"
    source = ROOT / mutant.path
    if not source.exists():
        return None
    lines = source.read_text(encoding="utf-8").splitlines()
    line = mutant.line
    if not (0 < line <= len(lines) and lines[line - 1].strip() == mutant.before):
        line = next((i for i, text in enumerate(lines, start=1) if text.strip() == mutant.before), 0)
        if not line:
            return None
    return rule_reason(mutant.path, line, mutant.before, mutant.after)


def explanations(mutants: list[Mutant]) -> dict[str, str | None]:
    """explained() of every mutant, the marks read once."""
    marked = set(equivalents())
    return {m.name: explained(m, marked) for m in mutants}


def rates(mutants: list[Mutant], reviewed: bool = False,
          why: dict[str, str | None] | None = None) -> dict[str, tuple[int, int]]:
    """(detected, checked) per part and over all; a mutant a stopped run never got to is in neither. Reviewed:
    the survivors explained() as equivalent are left out too (issue 15's target: the kill rate excluding
    marked equivalents); `why`: their explanations, if the caller has them already."""
    why = (explanations(mutants) if why is None else why) if reviewed else {}
    out: dict[str, tuple[int, int]] = {}
    for part in sorted({m.part for m in mutants}) + ["all"]:
        mine = [m for m in mutants if part in ("all", m.part) and m.status != "not checked" and not why.get(m.name)]
        out[part] = (sum(m.status in DETECTED for m in mine), len(mine))
    return out


def proven(mutant: Mutant, report: dict) -> bool:
    """Whether the differential checker confirmed the mark that names the mutant (by file, or by function)."""
    return any(equivalence.confirmed(report, equivalence.Mark(where, mutant.before, mutant.after, ""))
               for where in (mutant.path, f"{mutant.path}::{function_of(mutant.name)}"))


def three_rates(mutants: list[Mutant], passed: list[tuple[Mutant, str]] | None = None,
                why: dict[str, str | None] | None = None,
                report: dict | None = None) -> dict[str, list[tuple[int, int]]]:
    """Per part and over all, (detected, counted) for each of RATES: of everything drawn (`passed`: the
    mutants passed over while drawing, with the reason, counted as not killed); without what a rule passes
    over (while drawing, or a survivor under a rule made since: `why`, explanations()); and also without
    the mutants of marks the checker confirmed (`report`: reports/equivalence.json). A survivor marked
    equivalent without that evidence stays a survivor."""
    why = explanations(mutants) if why is None else why
    report = equivalence.load_report() if report is None else report

    def kind(mutant: Mutant, reason: str | None) -> str | None:
        if not reason:
            return None
        if reason != "marked equivalent":
            return "rule"
        return "proven" if proven(mutant, report) else None

    rows = [(m.part, m.status in DETECTED, kind(m, why.get(m.name))) for m in mutants if m.status != "not checked"]
    rows += [(m.part, False, kind(m, reason)) for m, reason in passed or []]
    out: dict[str, list[tuple[int, int]]] = {}
    for part in sorted({part for part, _, _ in rows}) + ["all"]:
        mine = [(done, k) for p, done, k in rows if part in ("all", p)]
        out[part] = [(sum(done for done, _ in kept), len(kept)) for kept in
                     (mine, [r for r in mine if r[1] != "rule"], [r for r in mine if r[1] is None])]
    return out


def _percent(done: int, total: int) -> str:
    return f"{done}/{total} = {100 * done / max(total, 1):.1f} %"


def table(mutants: list[Mutant], seed: int, left_out: dict[str, int] | None = None,
          passed: list[tuple[Mutant, str]] | None = None) -> str:
    lines = [f"# Mutation testing of the references ({len(mutants)} mutants, seed {seed})", ""]
    if left_out:
        lines += ["Passed over while drawing: " + ", ".join(f"{n} {why}" for why, n in sorted(left_out.items()))
                  + " (sut/reference/EQUIVALENT_MUTANTS.txt; usage errors: outline/mutate/mutation.py).", ""]
    unchecked = sum(m.status == "not checked" for m in mutants)
    if unchecked:
        lines += [f"{unchecked} sampled mutants were not checked (the run was stopped before them); the rates "
                  "are over the checked ones.", ""]
    lines += ["Of everything drawn: the mutants passed over while drawing count as not killed (they were not run). "
              "After the rules: without what a rule passes over, while drawing or a survivor under a rule made "
              "since (named below). After proven equivalents: also without the mutants of marks the differential "
              "checker confirmed (make equivalence, reports/equivalence.json); a mark without that evidence "
              "leaves its mutant a survivor. A survivor that is a real gap counts as one even once a new "
              "scenario closes it.", "",
              f"| part | {' | '.join(RATES)} |", "| --- | --- | --- | --- |"]
    why = explanations(mutants)
    report = equivalence.load_report()
    for part, values in three_rates(mutants, passed, why, report).items():
        lines.append(f"| {part} | " + " | ".join(_percent(*v) for v in values) + " |")
    lines += ["", "| file:line | change | result | killed by |", "| --- | --- | --- | --- |"]
    for m in sorted(mutants, key=lambda m: (m.path, m.line, m.name)):
        change = f"`{m.before}` -> `{m.after}`".replace("|", "\\|")
        equivalent = f"equivalent: {why[m.name]}" if why[m.name] else ""
        if why[m.name] == "marked equivalent" and not proven(m, report):
            equivalent = "marked equivalent, not confirmed by make equivalence: a survivor"
        lines.append(f"| {m.path}:{m.line} | {change} | {m.status} | {m.killed_by or equivalent} |")
    return "\n".join(lines) + "\n"


def _passed_over(data: dict) -> list[tuple[Mutant, str]]:
    """The mutants a kept run passed over while drawing, with the reason (none in a run before issue 31)."""
    return [(Mutant(**{k: v for k, v in m.items() if k != "reason"}), m["reason"]) for m in data.get("passed_over", [])]


def to_allure(results: Path, kept: Path) -> Path | None:
    """The last `make mutate` (reports/mutation.json) as one entry of an Allure results folder: the kill rate
    against the 90 % target in its name and status, the table attached. None if mutation testing never ran."""
    if not kept.exists():
        return None
    data = json.loads(kept.read_text(encoding="utf-8"))
    mutants = [Mutant(**m) for m in data["mutants"]]
    passed_over = _passed_over(data)
    three = three_rates(mutants, passed_over)
    (drawn_done, drawn_total), (rules_done, rules_total), (done, total) = three["all"]
    attachment = f"{uuid.uuid4()}-attachment.md"
    (results / attachment).write_text(table(mutants, data["seed"], data.get("left_out"), passed_over),
                                      encoding="utf-8")
    now = int(time.time() * 1000)
    per_part = ", ".join(f"{part} {v[2][0]}/{v[2][1]}" for part, v in three.items() if part != "all")
    passed = all(v[2][0] >= TARGET * v[2][1] for v in three.values())
    result = {
        "uuid": str(uuid.uuid4()), "historyId": "mutation-testing-of-the-references",
        "name": f"Mutation testing of the references: {100 * done / max(total, 1):.1f} % killed after proven "
                f"equivalents ({100 * drawn_done / max(drawn_total, 1):.1f} % of everything drawn, "
                f"{100 * rules_done / max(rules_total, 1):.1f} % after the rules; target 90 % per reference)",
        "fullName": "make mutate", "status": "passed" if passed else "failed",
        "statusDetails": {"message": f"{done} of {total} mutants rejected after proven equivalents; "
                                     f"{rules_done} of {rules_total} after the rules; {drawn_done} of "
                                     f"{drawn_total} of everything drawn (seed {data['seed']}): {per_part}"},
        "stage": "finished", "start": now, "stop": now,
        "labels": [{"name": "epic", "value": "Mutation testing"}, {"name": "suite", "value": "make mutate"},
                   {"name": "tag", "value": "mutation"}],           # outline.report.summary: not a scenario
        "attachments": [{"name": "mutants", "source": attachment, "type": "text/markdown"}],
    }
    out = results / f"{result['uuid']}-result.json"
    out.write_text(json.dumps(result), encoding="utf-8")
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m outline.mutate.mutation", description=__doc__.split("\n\n")[0])
    parser.add_argument("--mutants", type=int, default=200, help="how many mutants to sample (default 200)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the sample (default 1)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="mutants tested at once")
    parser.add_argument("--resume", action="store_true",
                        help="keep the verdicts of drawn mutants the last run rejected; run the others")
    parser.add_argument("--out", type=Path, default=ROOT / "reports", help="where mutation.md/.json go")
    parser.add_argument("--to-allure", type=Path, metavar="RESULTS",
                        help="run nothing: add the last run (--out/mutation.json) to this Allure results folder")
    parser.add_argument("--review", action="store_true",
                        help="run nothing: the last run's table again (--out/mutation.md), its survivors read "
                             "against the equivalents marked and the rules made since")
    args = parser.parse_args(argv)
    if args.review:
        kept = args.out / "mutation.json"
        if not kept.exists():
            print(f"mutation: no make mutate run to review ({kept})")
            return 1
        data = json.loads(kept.read_text(encoding="utf-8"))
        text = table([Mutant(**m) for m in data["mutants"]], data["seed"], data.get("left_out"), _passed_over(data))
        (args.out / "mutation.md").write_text(text, encoding="utf-8")
        print(text)
        return 0
    if args.to_allure:
        written = to_allure(args.to_allure, args.out / "mutation.json")
        print(f"mutation: {written or 'no make mutate run to add to the report'}")
        return 0
    print("mutmut: writing the mutants and mapping scenarios to functions (one conformance run) ...", flush=True)
    generate()
    names = all_names()
    left_out: dict[str, int] = {}
    passed: list[tuple[Mutant, str]] = []
    mutants = sample(names, args.mutants, args.seed, left_out, passed)
    passed_over = ", ".join(f"{n} {why}" for why, n in sorted(left_out.items())) or "none"
    print(f"mutmut: {len(names)} mutants of the references; testing {len(mutants)} (seed {args.seed}; "
          f"passed over while drawing: {passed_over}) ...", flush=True)
    run(mutants, args.jobs, resume=args.resume)
    text = table(mutants, args.seed, left_out, passed)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "mutation.md").write_text(text, encoding="utf-8")
    (args.out / "mutation.json").write_text(json.dumps(
        {"seed": args.seed, "left_out": left_out, "mutants": [asdict(m) for m in mutants],
         "passed_over": [dict(asdict(m), reason=reason) for m, reason in passed],
         "rates": {p: dict(zip(RATES, v)) for p, v in three_rates(mutants, passed).items()}}, indent=1),
        encoding="utf-8")
    print(text)
    print(f"mutation: {args.out / 'mutation.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
