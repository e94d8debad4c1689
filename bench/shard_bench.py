"""The fault campaign (or any selection) serial, on two workers, and what N shards would take.

    .venv/bin/python bench/shard_bench.py                      # F-NET-30,F-NET-31; shards from .test_durations
    .venv/bin/python bench/shard_bench.py --item R-CTL-01 --shards 2,4,8
    .venv/bin/python bench/shard_bench.py --no-run             # only the computed shard times

The two runs are measured (wall seconds of the whole pytest process). The shard times are computed: pytest-split's
own least-duration algorithm (what `make shard` uses) splits the selection by the durations recorded in
.test_durations (`make durations`), and a shard takes its group's sum plus one pytest start-up and collection
(measured here as the floor of an empty selection). Scenarios without a recorded duration count as the mean.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

from pytest_split.algorithms import Algorithms

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _history  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def _pytest(*args: str) -> tuple[float, list[str]]:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", *args]
    start = time.perf_counter()
    run = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if run.returncode not in (0, 5):
        sys.exit(f"pytest failed (exit {run.returncode}): {' '.join(cmd)}\n{run.stdout[-2000:]}")
    return wall, run.stdout.splitlines()


def _selected(items: str) -> list[str]:
    _wall, lines = _pytest("-p", "no:xdist", f"--item={items}", "--collect-only")
    return [line for line in lines if line.startswith("features/")]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="bench/shard_bench.py", description=__doc__.splitlines()[0])
    parser.add_argument("--item", default="F-NET-30,F-NET-31", help="test items (comma-separated)")
    parser.add_argument("--shards", default="1,2,4,8,16", help="shard counts to compute (comma-separated)")
    parser.add_argument("--durations", default=str(ROOT / ".test_durations"), help="recorded durations")
    parser.add_argument("--no-run", action="store_true", help="skip the serial and two-worker runs")
    _history.add_argument(parser)
    args = parser.parse_args(argv)
    load_before = _history.load()

    print(f"Python {sys.version.split()[0]}, {os.cpu_count()} cores, load {' '.join(f'{x:.2f}' for x in os.getloadavg())}"
          f" at start; selection --item {args.item}")
    nodeids = _selected(args.item)
    durations = json.loads(Path(args.durations).read_text(encoding="utf-8"))
    known = sum(1 for n in nodeids if n in durations)
    print(f"{len(nodeids)} scenarios, {known} with a recorded duration in {Path(args.durations).name}")
    floor, _ = _pytest("-p", "no:xdist", "--item", args.item, "-k", "no_scenario_has_this_name")
    figures: dict[str, float] = {"scenarios": len(nodeids), "with_duration": known, "start_up_s": floor}
    if not args.no_run:
        serial, _ = _pytest("-p", "no:xdist", f"--item={args.item}")
        two, _ = _pytest("-n", "2", f"--item={args.item}")
        figures |= {"serial_wall_s": serial, "two_workers_wall_s": two}
        print(f"measured: serial {serial:.1f} s, two workers {two:.1f} s (start-up and collection {floor:.1f} s)")
    items = [SimpleNamespace(nodeid=n) for n in nodeids]
    print(f"{'shards':>6}  {'largest group s':>15}  {'shard wall s':>12}  (least_duration split of the recorded durations)")
    for n in (int(x) for x in args.shards.split(",")):
        groups = Algorithms.least_duration.value(n, items, durations)
        largest = max(g.duration for g in groups)
        print(f"{n:>6}  {largest:>15.1f}  {largest + floor:>12.1f}")
        figures[f"shards_{n}_wall_s"] = largest + floor
    print(f"load at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    _history.record(args, "shard_bench", figures, load_before=load_before, load_after=_history.load(),
                    selection=None if argv is None else _history.measured_options(argv))
    return 0


if __name__ == "__main__":
    sys.exit(main())
