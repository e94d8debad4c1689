"""mutmut with its map of who reaches what learnt by several pytest processes at once (issue 33: the first
map took 71 min in one process on a 2-core machine).

`python -m outline.mutate.sharded_map ARGS` is `python -m mutmut ARGS` with one change: where mutmut runs
the tests it maps in its own process (ForkRunner.collect_stats), the tests are dealt round-robin to
$MUTMUT_MAP_JOBS pytest processes (default: the machine's cores), each with mutmut's own arguments and
outline/mutate/map_shard.py, and their maps are merged into mutmut's state before mutmut saves it. Every
mapped test is simulated whole and the references' caches are emptied before it (mutation_plugin.py), so
which process runs a test does not change what it reaches. tests/test_sharded_map.py compares a sharded map
with mutmut's own of the same tests.
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


def collect_stats(self: object, tests: Iterable[str] | None) -> int:
    """ForkRunner.collect_stats, sharded: 0, or the first failing shard's pytest exit code."""
    from mutmut.configuration import config
    from mutmut.state import state

    runner = self.test_runner
    wanted = list(tests or []) or sorted(runner.list_all_tests().ids)
    jobs = int(os.environ.get("MUTMUT_MAP_JOBS") or os.cpu_count() or 1)
    parts = shards(wanted, jobs)
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="mutmut-map-") as tmp:
        running = []
        for index, part in enumerate(parts):
            out, log = Path(tmp) / f"shard{index}.json", Path(tmp) / f"shard{index}.log"
            args = [sys.executable, "-m", "pytest", "--rootdir=.", "--tb=native", "-x", "-q",
                    "-p", "no:randomly", "-p", "no:random-order", *part, *config().pytest_add_cli_args,
                    "-p", "outline.mutate.map_shard"]
            with open(log, "w", encoding="utf-8") as fh:
                running.append((subprocess.Popen(args, cwd="mutants", stdout=fh, stderr=subprocess.STDOUT,
                                                 env=dict(os.environ, MUTMUT_MAP_SHARD=str(out))), out, log))
        codes = [(process.wait(), out, log) for process, out, log in running]
        for code, out, log in codes:
            if code != 0:
                print(log.read_text(encoding="utf-8")[-5000:], flush=True)
                return code
        for _, out, _ in codes:
            merge(state(), json.loads(out.read_text(encoding="utf-8")))
    with open(LOG, "a", encoding="utf-8") as fh:          # mutmut holds its own output back: a line of ours
        fh.write(f"mapped {len(wanted)} tests in {len(parts)} processes in {time.monotonic() - start:.0f} s\n")
    return 0


def main() -> None:
    from mutmut.__main__ import cli
    from mutmut.workers.isolation import ForkRunner

    ForkRunner.collect_stats = collect_stats
    sys.argv[0] = "mutmut"
    cli()


if __name__ == "__main__":
    main()
