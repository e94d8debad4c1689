"""pytest plugin for `make mutate` (outline/mutate/mutation.py): what may judge a mutant, and what killed it.

mutmut runs the tests that reach a mutant's function in a forked child with MUTANT_UNDER_TEST naming
the mutant, and stops at the first failure (-x); it keeps only the exit code.

- What may judge it: a train reference (crh2, metro, atp) is judged by the conformance scenarios and by the
  driver's answers to bad input (tests/test_bad_input.py: an unknown name raises UnknownName, a value out of
  range OutOfRange, as docs/implementing-a-sut.md asks of any SUT; no scenario gives bad input, and seeds 9
  and 10 left 4 mutants that raise a TypeError there instead). The
  simulation engine they share (kernel.py, bulk.py) is no train: its specification is that a bulk advance
  gives the same state and trace as frame by frame (tests/test_bulk.py; the trace held as patterns reads as
  the one made event by event, tests/test_eventlog.py) and the kernel's own contract
  (tests/test_kernel.py), so its mutants also meet those tests, and first: they compare bulk with frame by
  frame directly, where a scenario notices a bulk mistake only in its one long advance, after hundreds of
  short ones (an engine mutant took minutes to reach it). mutmut collects all of them (pyproject.toml); this
  leaves each mutant only its own judges.
- What killed it: the failing test, one line per mutant, in the file named by $CRH2_MUTATION_KILLS.
- Nothing a process worked out before the fork: mutmut forks each mutant's run from a process that has
  already run the references (its clean run), so a table they fill once per process (bulk's per-class
  readings, the CRH2 packet templates and CRC tables, an lru_cache) would come into the child filled in by
  the original code, and a mutant of the code that fills it would never run (seeds 3-6 marked 9 such mutants
  as if they were equivalent). The child empties every such cache of sut/reference/ first: module-level
  names bound to an empty dict or set, and functions with cache_clear (reference_caches). The map of who
  reaches what is learnt in one process too, so there the caches are emptied before every test: else only
  the first test to read a class or build a template was mapped to the code that does it, and a mutant of
  that code met only those (seed 7: bulk's per-class reading met none of the tests with a damaged frame in
  flight, which kill it).
- Snapshots only where they cannot hide a scenario: mutmut learns who reaches what in one run of every test
  (MUTANT_UNDER_TEST=stats), and a scenario restored from a stored state never calls the functions that built
  it, so that run simulates every scenario in full (--no-snapshots). A mutant's own run (a fresh pytest
  session in a forked child, so a fresh cache) keeps them: every scenario it restores was built earlier in
  that same child, under the same mutant, by a scenario sharing its Background, which reaches the same
  functions and is in the mutant's list too; verdicts with and without snapshots are the same
  (tests/test_snapshot.py). A survivor of a busy function runs hundreds of scenarios, most of them restored
  instead of simulating their Background again.
- mutmut's trampoline made cheap for the session (outline/mutate/quick_trampoline.py): what it reads on every
  call of a reference function is read once; the map of who reaches what costs less than half as much.
- Fewer frames per call once a session has collected its tests: in the map every trampoline becomes a
  recorder made for its function (quick_trampoline.install_recorders), and in a mutant's own run and the
  clean run every reference function that cannot reach the mutant is called directly
  (outline/mutate/direct_calls.py).
"""
from __future__ import annotations

import ast
import os
import sys
from pathlib import Path

import pytest

from outline.mutate import direct_calls, quick_trampoline


ENGINE = ("sut.reference.kernel.", "sut.reference.bulk.")
BAD_INPUT = "tests/test_bad_input.py::"
MAPPING_RUN = quick_trampoline.MAPPING_RUN


def pytest_configure(config: pytest.Config) -> None:
    mutant = os.environ.get("MUTANT_UNDER_TEST", "")
    if mutant == MAPPING_RUN and hasattr(config.option, "no_snapshots"):
        config.option.no_snapshots = True
    if "__mutmut_" in mutant:
        _empty(reference_caches())
    if "mutmut.mutation.trampoline" in sys.modules:      # a run of mutmut's, not a user's pytest
        quick_trampoline.install()


def pytest_unconfigure(config: pytest.Config) -> None:
    direct_calls.uninstall()
    quick_trampoline.uninstall()


def pytest_runtest_setup(item: pytest.Item) -> None:
    if os.environ.get("MUTANT_UNDER_TEST", "") == MAPPING_RUN:
        _empty(reference_caches())


def _empty(caches: list) -> None:
    for cache in caches:
        cache.cache_clear() if hasattr(cache, "cache_clear") else cache.clear()


def pytest_collection_finish(session: pytest.Session) -> None:
    reference_caches()        # read once here, where mutmut's warm-up collects: the forked runs inherit it
    if "mutmut.mutation.trampoline" in sys.modules:
        from mutmut.mutation.trampoline import get_mutant_under_test
        quick_trampoline.install_recorders(Path.cwd()) or direct_calls.install(get_mutant_under_test(), Path.cwd())


# What each module's caches are, worked out once per module: a mutated module is large (reading them all
# took 6 s), and the map of who reaches what asks before every test.
_FOUND: dict[str, tuple[object, list]] = {}


def reference_caches() -> list:
    """The per-process caches of the references that are loaded: every module-level name of sut/reference/
    bound to an empty dict or set in its source (a table filled as it is needed), and every function of
    theirs with `cache_clear` (functools' caches)."""
    found = []
    for name, module in sorted(sys.modules.items()):
        if not name.startswith("sut.reference.") or module is None or not getattr(module, "__file__", None):
            continue
        known = _FOUND.get(name)
        if known is None or known[0] is not module:
            known = _FOUND[name] = (module, _module_caches(name, module))
        found += known[1]
    return found


def _module_caches(name: str, module: object) -> list:
    found = []
    tree = ast.parse(Path(module.__file__).read_text(encoding="utf-8"))
    for node in tree.body:
        target = node.targets[0] if isinstance(node, ast.Assign) and len(node.targets) == 1 else \
            node.target if isinstance(node, ast.AnnAssign) else None
        value = getattr(node, "value", None)
        empty = (isinstance(value, ast.Dict) and not value.keys) or \
            (isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id in ("set", "dict")
             and not value.args and not value.keywords)
        if isinstance(target, ast.Name) and empty and not _trampoline_table(node) \
                and isinstance(getattr(module, target.id, None), (dict, set)):
            found.append(getattr(module, target.id))
    return found + [value for value in vars(module).values() if callable(value) and hasattr(value, "cache_clear")
                    and getattr(value, "__module__", None) == name]


def _trampoline_table(node: ast.stmt) -> bool:
    """mutmut's own table of a function's mutants (`mutants_<function>: MutantDict = {}`, filled when the
    module has been read): in a mutated module it looks like a cache, and emptying it leaves every call of
    that function without its original (KeyError '_mutmut_orig'), so every test fails and every mutant
    looks killed (seed 7's first run, 2026-11-26: 99 % "killed", almost all by the first scenario run)."""
    annotation = getattr(node, "annotation", None)
    target = node.target if isinstance(node, ast.AnnAssign) else node.targets[0]
    return (isinstance(annotation, ast.Name) and annotation.id == "MutantDict") or \
        (isinstance(target, ast.Name) and target.id.startswith("mutants_"))


def judges(mutant: str, nodeids: list[str]) -> list[str]:
    """The tests that may judge `mutant`: for a train reference the driver's answers to bad input
    (BAD_INPUT: milliseconds each, so first) and the scenarios; for the engine its own tests first, then the
    scenarios."""
    scenarios = [n for n in nodeids if n.startswith("features/")]
    bad_input = [n for n in nodeids if n.startswith(BAD_INPUT)]
    if mutant.startswith(ENGINE):
        return [n for n in nodeids if not n.startswith(("features/", BAD_INPUT))] + scenarios
    return bad_input + scenarios


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    mutant = os.environ.get("MUTANT_UNDER_TEST", "")
    if "__mutmut_" not in mutant:
        return                        # mutmut's own runs (the map of who reaches what, the clean run): all
    by_id = {item.nodeid: item for item in items}
    kept = [by_id[n] for n in judges(mutant, list(by_id))]
    config.hook.pytest_deselected(items=[item for item in items if item not in kept])
    items[:] = kept


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    mutant, kills = os.environ.get("MUTANT_UNDER_TEST", ""), os.environ.get("CRH2_MUTATION_KILLS")
    if report.failed and kills and "__mutmut_" in mutant:
        with open(kills, "a", encoding="utf-8") as fh:            # one short line: appends do not interleave
            fh.write(f"{mutant}\t{report.nodeid}\n")
