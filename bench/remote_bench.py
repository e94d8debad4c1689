"""The conformance run in process against the same run through the wire protocol (issue 9: remote <= 2x).

    PYTHONPATH=. .venv/bin/python bench/remote_bench.py [--item R-CTL-01,...] [--profile crh2] [--repeat 1]

One script run measures both, alternating (in-process first), each a fresh `python -m pytest features -q
-p no:xdist -p no:cacheprovider` subprocess, the remote one with `--sut tcp://127.0.0.1:N` against a
`python -m sut serve` started for it (one forked server process per connection, as in use). Printed: wall
seconds, CPU seconds (user + sys from os.wait4, the server's including the trains it forked), the scenario
outcome counts (must be equal), the ratios remote / in-process of wall and of total CPU, against the 2x target, and
the machine load before and after. Serial on purpose: with `-n 2` the two sides share the two cores.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

BENCH = Path(__file__).resolve().parent
ROOT = BENCH.parent
sys.path.insert(0, str(BENCH))

import _history  # noqa: E402
from _table import table, text  # noqa: E402
from suite_bench import Run, run_pytest  # noqa: E402  the same runner: wall, CPU from os.wait4, outcomes

TARGET = 2.0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--item", default=None, help="comma-separated item IDs (default: every item)")
    ap.add_argument("--profile", default=None, help="train profile(s) to run (default: all)")
    ap.add_argument("--repeat", type=int, default=1, help="pairs of runs; the best of each side is kept")
    ap.add_argument("--plain", action="store_true", help="plain text output even if rich is installed")
    _history.add_argument(ap)
    args = ap.parse_args(argv)
    select = [f"--item={args.item}"] if args.item else []
    select += [f"--profile={args.profile}"] if args.profile else []
    argv = ["features", "-q", "-p", "no:xdist", "-p", "no:cacheprovider", *select]
    logdir = Path(tempfile.mkdtemp(prefix="crh2-remote-bench-"))

    server = subprocess.Popen([sys.executable, "-m", "sut", "serve", "--port", "0"], cwd=ROOT,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    url = re.search(r"tcp://\S+", server.stdout.readline()).group(0)
    load_before = os.getloadavg()[0]
    local, remote = [], []
    try:
        for _ in range(args.repeat):
            local.append(run_pytest(Run("in process", argv, ROOT), logdir))
            remote.append(run_pytest(Run("remote", [*argv, f"--sut={url}"], ROOT), logdir))
    finally:
        server.terminate()
        _, _, server_usage = os.wait4(server.pid, 0)
    load_after = os.getloadavg()[0]
    for run in local + remote:
        if run.exit != 0:
            raise SystemExit(f"{run.label}: pytest exit {run.exit}, see {run.log}")
    best_local, best_remote = (min(runs, key=lambda r: r.wall) for runs in (local, remote))
    if best_local.outcomes() != best_remote.outcomes() or not best_local.collected:
        raise SystemExit(f"outcomes differ: in process {best_local.outcomes()}, remote {best_remote.outcomes()}")
    server_cpu = server_usage.ru_utime + server_usage.ru_stime       # all runs, the forked trains included
    remote_cpu = best_remote.cpu + server_cpu / args.repeat
    passed = lambda run: str(run.outcomes().get("passed", 0))          # noqa: E731
    rows = [("in process", f"{best_local.wall:.1f}", f"{best_local.cpu:.1f}", "", passed(best_local)),
            ("remote", f"{best_remote.wall:.1f}", f"{best_remote.cpu:.1f}", f"{server_cpu / args.repeat:.1f}",
             passed(best_remote))]
    table("in process vs remote (serial, best of %d)" % args.repeat,
          ["run", "wall s", "client CPU s", "server CPU s", "passed"], rows, plain=args.plain)
    wall_ratio = best_remote.wall / best_local.wall
    text(f"remote / in process: wall {wall_ratio:.2f}x, total CPU {remote_cpu / best_local.cpu:.2f}x "
         f"(target <= {TARGET:g}x: {'met' if wall_ratio <= TARGET else 'MISSED'}); "
         f"load {load_before:.2f} -> {load_after:.2f}", plain=args.plain)
    _history.record(args, "remote_bench",
                    {"scenarios": best_local.collected, "in_process_wall_s": best_local.wall,
                     "in_process_cpu_s": best_local.cpu, "remote_wall_s": best_remote.wall,
                     "remote_client_cpu_s": best_remote.cpu, "remote_server_cpu_s": server_cpu / args.repeat,
                     "ratio_wall": wall_ratio, "ratio_cpu": remote_cpu / best_local.cpu},
                    load_before=load_before, load_after=load_after,
                    selection=[*([f"--item={args.item}"] if args.item else []),
                               *([f"--profile={args.profile}"] if args.profile else []),
                               *([f"--repeat={args.repeat}"] if args.repeat > 1 else [])])
    return 0


if __name__ == "__main__":
    sys.exit(main())
