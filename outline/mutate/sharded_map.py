"""mutmut with its map of who reaches what learnt by several pytest processes at once (issue 33: the first
map took 71 min in one process on a 2-core machine).

`python -m outline.mutate.sharded_map ARGS` is `python -m mutmut ARGS` with two changes: where mutmut runs
the tests it maps in its own process (ForkRunner.collect_stats), the tests are dealt round-robin to
$MUTMUT_MAP_JOBS pytest processes (default: the machine's cores), each with mutmut's own arguments and
outline/mutate/map_shard.py, and their maps are merged into mutmut's state before mutmut saves it; and its
clean run (the tests of the drawn mutants, unmutated, must pass before any mutant runs) is dealt out the same
way. Every mapped test is simulated whole and the references' caches are emptied before it
(mutation_plugin.py), so which process runs a test does not change what it reaches. tests/test_sharded_map.py
compares a sharded map with mutmut's own of the same tests.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Iterable


LOG = Path("mutants") / "map.log"


def shards(tests: list[str], jobs: int) -> list[list[str]]:
    """The tests dealt round-robin in their sorted order: a feature's scenarios, which cost alike, spread over
    every process."""
    ordered = sorted(tests)
    return [ordered[k::jobs] for k in range(min(jobs, len(ordered)))]


def merge(state: object, shard: dict) -> None:
    """One shard's map added to mutmut's state, as mutmut's StatsCollector would have added it."""
    for function, tests in shard["tests_by_mangled_function_name"].items():
        state.tests_by_mangled_function_name[function] |= set(tests)
    state.duration_by_test.update(shard["duration_by_test"])
    for function, callers in shard["function_dependencies"].items():
        state.function_dependencies[function] |= set(callers)


def _in_shards(tests: list[str], plugin: list[str], what: str) -> tuple[int, list[dict]]:
    """`tests` run by one pytest process per job in mutants/, each with mutmut's own arguments (and `plugin`,
    which writes its shard's result to $MUTMUT_MAP_SHARD as JSON): 0 and those results, or the first failing
    shard's exit code (its output printed). A line of how long it took goes to mutants/map.log."""
    from mutmut.configuration import config

    jobs = int(os.environ.get("MUTMUT_MAP_JOBS") or os.cpu_count() or 1)
    parts = shards(tests, jobs)
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="mutmut-shards-") as tmp:
        running = []
        for index, part in enumerate(parts):
            out, log = Path(tmp) / f"shard{index}.json", Path(tmp) / f"shard{index}.log"
            args = [sys.executable, "-m", "pytest", "--rootdir=.", "--tb=native", "-x", "-q",
                    "-p", "no:randomly", "-p", "no:random-order", *part, *config().pytest_add_cli_args, *plugin]
            with open(log, "w", encoding="utf-8") as fh:
                running.append((subprocess.Popen(args, cwd="mutants", stdout=fh, stderr=subprocess.STDOUT,
                                                 env=dict(os.environ, MUTMUT_MAP_SHARD=str(out))), out, log))
        codes = [(process.wait(), out, log) for process, out, log in running]
        for code, _out, log in codes:
            if code != 0:
                print(log.read_text(encoding="utf-8")[-5000:], flush=True)
                return code, []
        results = [json.loads(out.read_text(encoding="utf-8")) for _code, out, _log in codes if out.exists()]
    with open(LOG, "a", encoding="utf-8") as fh:          # mutmut holds its own output back: a line of ours
        fh.write(f"{what} {len(tests)} tests in {len(parts)} processes in {time.monotonic() - start:.0f} s\n")
    return 0, results


def collect_stats(self: object, tests: Iterable[str] | None) -> int:
    """ForkRunner.collect_stats, sharded: 0, or the first failing shard's pytest exit code."""
    from mutmut.state import state

    wanted = list(tests or []) or sorted(self.test_runner.list_all_tests().ids)
    code, results = _in_shards(wanted, ["-p", "outline.mutate.map_shard"], "mapped")
    for result in results:
        merge(state(), result)
    return code


def run_clean_tests(self: object, tests: Iterable[str]) -> int:
    """ForkRunner.run_clean_tests, sharded: the tests that reach the drawn mutants, unmutated, must pass. Every
    test is judged alone (snapshots give the same verdicts as a run without them: tests/test_snapshot.py), so
    which process runs it does not matter; with no tests named, mutmut's own run of them all."""
    wanted = list(tests)
    if not wanted:
        return _MUTMUT_CLEAN(self, wanted)
    return _in_shards(wanted, [], "clean run of")[0]


_MUTMUT_CLEAN = None


def main() -> None:
    from mutmut.__main__ import cli
    from mutmut.workers.isolation import ForkRunner

    global _MUTMUT_CLEAN
    _MUTMUT_CLEAN = ForkRunner.run_clean_tests
    ForkRunner.collect_stats = collect_stats
    ForkRunner.run_clean_tests = run_clean_tests
    sys.argv[0] = "mutmut"
    cli()


if __name__ == "__main__":
    main()
