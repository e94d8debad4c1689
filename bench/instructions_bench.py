"""Instructions the reference spends on fixed workloads, counted by valgrind's callgrind: a count that repeats.

    PYTHONPATH=. .venv/bin/python bench/instructions_bench.py [--workload crh2-8 ...] [--sut reference] [--plain]
                                                              [--record [FILE]] [--note "..."]

Wall and CPU seconds on this shared 2-core VM move 7-20 % from one hour to the next (bench/performance-notes.md),
as much as a change to the model is worth; `perf stat` has no instruction counter here (no PMU in the VM). An
instruction count under callgrind is the same run after run (two runs of one 808 M workload differed by 128
instructions; a warm-up run first keeps bytecode compilation out of the count), so a change of a few per cent
shows, back to back with the commit before it. Not below ~1 %: a change that only moves objects in memory (a
few lines more in this script) moved crh2-8 by 0.3 % (807.6 -> 805.5 M, each repeated exactly; counted then with the backends' imports), as the order
of objects hashed by address follows the layout. It costs ~50x the run's own time, hence small workloads.

Each workload runs in its own `python` under `valgrind --tool=callgrind` (PYTHONHASHSEED=0), through the driver
only (`sut.backends.open_backend(SUT, profile)`), and is counted whole; the `imports` workload (the same start-up,
imports and a driver of each profile opened and shut, no train) is subtracted, so each figure is what the train's simulation and the driver calls cost:
  crh2-8    an 8-car set as the features' Background (key, forward, power on, 1000 ms), notch 5, 500 ms
  crh2-16   the same on two 8-car sets coupled (24 ring nodes)
  metro     a 6-car metro train powered up, 1000 ms, then traction 50 % and 500 ms
Printed: the instructions per workload (millions, net of imports) and the driver's trace length (a change that
alters the count of events has changed the model, not only its cost). With --record, one row in
bench/history.jsonl (`make performance`).
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parent
ROOT = BENCH.parent
sys.path.insert(0, str(BENCH))

import _history  # noqa: E402
from _table import table  # noqa: E402

_COLLECTED = re.compile(r"Collected : (\d+)")


def _crh2(driver, sets: int) -> None:
    driver.configure(sets=sets, cars_per_set=8)
    driver.insert_key(1)
    driver.set_direction(1, "forward")
    driver.power_on()
    driver.advance_ms(1000)
    driver.set_traction(1, 5)
    driver.advance_ms(500)


def _metro(driver) -> None:
    driver.configure(sets=1, cars_per_set=6)
    driver.power_on()
    driver.advance_ms(1000)
    driver.set_traction(1, 50)
    driver.advance_ms(500)


# name -> (profile, what it does to the driver); None: start-up and imports only
WORKLOADS = {
    "imports": ("crh2", None),
    "crh2-8": ("crh2", lambda d: _crh2(d, 1)),
    "crh2-16": ("crh2", lambda d: _crh2(d, 2)),
    "metro": ("metro-tcn", _metro),
}


def run_one(name: str, sut: str) -> dict:
    """In this process (the child valgrind counts): the workload through the driver; its trace length."""
    from sut.backends import open_backend
    # Every profile's backend opened and shut first, in every child: their imports are in the baseline too.
    for profile in sorted({p for p, _ in WORKLOADS.values()}):
        open_backend(sut, profile).shutdown()
    profile, work = WORKLOADS[name]
    if work is None:
        return {"trace": 0}
    driver = open_backend(sut, profile)
    try:
        work(driver)
        return {"trace": len(driver.trace)}
    finally:
        driver.shutdown()


def count(name: str, sut: str) -> tuple[int, int]:
    """(instructions, trace events) of one workload in a child process under callgrind."""
    child = [sys.executable, __file__, "--child", name, "--sut", sut]
    env = dict(os.environ, PYTHONHASHSEED="0", PYTHONPATH=str(ROOT))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    # Once without valgrind first: a module compiled during the counted run (a changed file's bytecode cache)
    # cost 4.5 M instructions more in one of two runs of crh2-8.
    subprocess.run(child, cwd=ROOT, capture_output=True, env=env, check=True)
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *child],
                          cwd=ROOT, capture_output=True, text=True, env=env)
    found = _COLLECTED.search(done.stderr)
    if done.returncode != 0 or not found:
        raise SystemExit(f"{name}: valgrind run failed (exit {done.returncode}):\n{done.stderr[-2000:]}")
    return int(found.group(1)), json.loads(done.stdout.strip().splitlines()[-1])["trace"]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--workload", action="append", choices=[w for w in WORKLOADS if w != "imports"],
                    help="a workload to count (repeatable; default: all)")
    ap.add_argument("--sut", default="reference", help="the backend (a name or package.module:Class)")
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("--plain", action="store_true", help="plain text output even if rich is installed")
    _history.add_argument(ap)
    args = ap.parse_args(argv)
    if args.child:
        print(json.dumps(run_one(args.child, args.sut)))
        return 0
    if shutil.which("valgrind") is None:
        raise SystemExit("valgrind is not installed (Debian's package valgrind)")
    load_before = _history.load()
    names = args.workload or [w for w in WORKLOADS if w != "imports"]
    base, _ = count("imports", args.sut)
    rows, figures = [], {"imports_minstr": base / 1e6}
    for name in names:
        instructions, trace = count(name, args.sut)
        net = instructions - base
        figures[f"{name}_minstr"] = net / 1e6
        figures[f"{name}_trace_events"] = trace
        rows.append([name, f"{net / 1e6:,.1f}", f"{trace:,}", f"{net / max(trace, 1):,.0f}"])
        print(f"{name}: {net / 1e6:,.1f} M instructions net of imports, {trace:,} trace events", file=sys.stderr)
    table(f"Instructions (callgrind), net of start-up and imports ({base / 1e6:,.1f} M); --sut {args.sut}",
          ["workload", "M instructions", "trace events", "instructions per event"], rows, plain=args.plain)
    _history.record(args, "instructions_bench", figures, load_before=load_before, load_after=_history.load())
    return 0


if __name__ == "__main__":
    sys.exit(main())
