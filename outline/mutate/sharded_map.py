"""mutmut with its map of who reaches what learnt by several pytest processes at once (issue 33: the first
map took 71 min in one process on a 2-core machine).

`python -m outline.mutate.sharded_map ARGS` is `python -m mutmut ARGS` with two changes: where mutmut runs
the tests it maps in its own process (ForkRunner.collect_stats), they run in one pytest process with mutmut's
own arguments and outline/mutate/map_shard.py, spread over $MUTMUT_MAP_JOBS xdist workers (default: the
machine's cores) that each take the next test as they free up, and the workers' maps are merged into mutmut's
state before mutmut saves it; and its clean run (the tests of the drawn mutants, unmutated, must pass before
any mutant runs) is spread the same way. (Dealt out beforehand, round-robin, one process finished 5 minutes
before the other: a few tests cost minutes, and where they land decides.) Every mapped test is simulated whole
and the references' caches are emptied before it (mutation_plugin.py), so which process runs a test does not
change what it reaches. tests/test_sharded_map.py compares a sharded map with mutmut's own of the same tests.
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


def merge(state: object, shard: dict) -> None:
    """One shard's map added to mutmut's state, as mutmut's StatsCollector would have added it."""
    for function, tests in shard["tests_by_mangled_function_name"].items():
        state.tests_by_mangled_function_name[function] |= set(tests)
    state.duration_by_test.update(shard["duration_by_test"])
    for function, callers in shard["function_dependencies"].items():
        state.function_dependencies[function] |= set(callers)


def _in_shards(tests: list[str], plugin: list[str], what: str) -> tuple[int, list[dict]]:
    """`tests` run in mutants/ by one pytest process with mutmut's own arguments (and `plugin`, which writes
    each worker's result to $MUTMUT_MAP_SHARD.<worker> as JSON), spread over one xdist worker per job, which
    take the next test as they free up: 0 and those results, or the run's exit code (its output printed). A
    line of how long it took goes to mutants/map.log."""
    from mutmut.configuration import config

    jobs = min(int(os.environ.get("MUTMUT_MAP_JOBS") or os.cpu_count() or 1), len(tests)) or 1
    own = list(config().pytest_add_cli_args)
    for at in reversed([i for i in range(len(own) - 1) if own[i:i + 2] == ["-p", "no:xdist"]]):
        del own[at:at + 2]
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="mutmut-shards-") as tmp:
        out, log = Path(tmp) / "shard.json", Path(tmp) / "shard.log"
        args = [sys.executable, "-m", "pytest", "--rootdir=.", "--tb=native", "-x", "-q",
                "-p", "no:randomly", "-p", "no:random-order", *own, *plugin]
        # One test at a time to whichever worker is free: the costliest are collected first (tests/conftest.py),
        # and xdist's first batches would otherwise give them all to one worker.
        args += ["-n", str(jobs), "--dist", "load", "--maxschedchunk", "1"] if jobs > 1 else ["-p", "no:xdist"]
        # The test ids go through a file: a map names every test of the suite.
        ids = Path(tmp) / "tests.txt"
        ids.write_text("\n".join(tests) + "\n", encoding="utf-8")
        with open(log, "w", encoding="utf-8") as fh:
            # Not an xdist worker's environment of its own (make test runs mutmut's tests under xdist).
            env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_XDIST_")}
            code = subprocess.run([*args, f"@{ids}"], cwd="mutants", stdout=fh, stderr=subprocess.STDOUT,
                                  env=dict(env, MUTMUT_MAP_SHARD=str(out))).returncode
        if code != 0:
            print(log.read_text(encoding="utf-8")[-5000:], flush=True)
            return code, []
        results = [json.loads(part.read_text(encoding="utf-8")) for part in sorted(Path(tmp).glob("shard.json*"))]
    with open(LOG, "a", encoding="utf-8") as fh:          # mutmut holds its own output back: a line of ours
        fh.write(f"{what} {len(tests)} tests in {jobs} processes in {time.monotonic() - start:.0f} s\n")
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
