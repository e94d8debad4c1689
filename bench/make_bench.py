"""The make targets a user waits for, timed: `make test`, `make report`, and `make mutate`'s first map.

    .venv/bin/python bench/make_bench.py test --clone [--record]       # a clean clone of HEAD, installs included
    .venv/bin/python bench/make_bench.py report [--record]             # this working tree, as it is
    .venv/bin/python bench/make_bench.py mutate --clone --map-only     # until the map is made, then stopped
    (--keep-map FILE keeps the map made, mutants/mutmut-stats.json, to compare with another)

One `make TARGET` (arguments after `--` go to make, e.g. `-- JOBS=2`), in this working tree or, with --clone, in
a fresh `git clone` of HEAD in a temporary folder (what issue 33's targets are measured on: the venv, npm and
the mutation extra installed by make itself; uncommitted changes are not in it). Printed and recorded: the wall
seconds of the whole target and, read from pytest's summary lines in its output, the seconds and counts of each
pytest run in it (make test: the own tests, then the conformance run; make report: the conformance run). For
mutate, map_s is the time until mutmut starts on the mutants ("mutmut: running ..."): the mutants written and
every scenario mapped to the functions it reaches, from scratch in a clean clone; --map-only stops there.
For make test also the own tests' seconds by test function (own_cpu_s and the largest few), from the JUnit XML
make test writes (reports/own-tests.xml).
Targets (issue 33, 2-core machine, clean clone): make test <= 5 min, make report <= 25 s, first map <= 15 min.
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

BENCH = Path(__file__).resolve().parent
ROOT = BENCH.parent
sys.path.insert(0, str(BENCH))

import _history  # noqa: E402

TARGETS = {"test": 300.0, "report": 25.0, "mutate": 900.0}        # issue 33, seconds (mutate: the first map)
_SUMMARY = re.compile(r"^=*\s*(?P<counts>\d+ [a-z]+(?:, \d+ [a-z]+)*) in (?P<seconds>[\d.]+)s\b")
_COUNT = re.compile(r"(\d+) (passed|failed|skipped|error|errors|deselected|xfailed|xpassed)")
_MAPPED = "mutmut: running "
OWN_TESTS_XML = Path("reports") / "own-tests.xml"      # make test's --junitxml of the own tests
TOP_TESTS = 8


def own_tests_by_function(xml: Path, top: int = TOP_TESTS) -> dict[str, float]:
    """The own tests' seconds (each test's own duration, summed over both workers) by test function, its
    parameters merged: `own_cpu_s` for all of them and `own_<function>_s` for the `top` largest. What a
    make test row needs to say where its minutes went (issue 33)."""
    sums: dict[str, float] = {}
    for case in ET.parse(xml).getroot().iter("testcase"):
        name = case.get("name", "?").split("[", 1)[0]
        sums[name] = sums.get(name, 0.0) + float(case.get("time") or 0.0)
    figures = {"own_cpu_s": round(sum(sums.values()), 1)}
    for name, seconds in sorted(sums.items(), key=lambda kv: -kv[1])[:top]:
        figures[f"own_{name.removeprefix('test_')}_s"] = round(seconds, 1)
    return figures


def run(target: str, cwd: Path, make_args: list[str], map_only: bool, log: Path) -> dict[str, float]:
    """`make TARGET` in cwd, its output to `log`; the figures of the history's row."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTEST_ADDOPTS", "VIRTUAL_ENV")}
    figures: dict[str, float] = {}
    runs: list[tuple[float, dict[str, int]]] = []
    started = time.perf_counter()
    with open(log, "w", encoding="utf-8") as out:
        proc = subprocess.Popen(["make", target, *make_args], cwd=cwd, env=env, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, start_new_session=True)
        for line in proc.stdout:
            out.write(line)
            if (m := _SUMMARY.match(line.strip())):
                runs.append((float(m["seconds"]), {k: int(n) for n, k in _COUNT.findall(m["counts"])}))
            if target == "mutate" and line.startswith(_MAPPED) and "map_s" not in figures:
                figures["map_s"] = time.perf_counter() - started
                if map_only:
                    os.killpg(proc.pid, signal.SIGTERM)      # the group this script started: make and its children
                    break
        proc.wait()
    figures["wall_s"] = time.perf_counter() - started
    figures["exit"] = proc.returncode
    names = {"test": ["own_tests", "conformance"], "report": ["conformance"]}.get(target, [])
    for name, (seconds, counts) in zip(names, runs):
        figures[f"{name}_s"] = seconds
        figures |= {f"{name}_{k}": n for k, n in counts.items()}
    return figures


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    make_args: list[str] = []
    if "--" in argv:
        i = argv.index("--")
        argv, make_args = argv[:i], argv[i + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], epilog="Arguments after `--` go to make.")
    ap.add_argument("target", choices=sorted(TARGETS))
    ap.add_argument("--clone", action="store_true", help="in a fresh git clone of HEAD (a temporary folder)")
    ap.add_argument("--map-only", action="store_true", help="mutate: stop once the map is made")
    ap.add_argument("--keep-log", type=Path, default=None, metavar="FILE", help="keep make's output here")
    ap.add_argument("--keep-map", type=Path, default=None, metavar="FILE",
                    help="mutate: keep the map made (mutants/mutmut-stats.json) here, to compare with another")
    _history.add_argument(ap)
    args = ap.parse_args(argv)
    load_before = _history.load()
    with tempfile.TemporaryDirectory(prefix="crh2-make-bench-") as tmp:
        cwd = ROOT
        if args.clone:
            cwd = Path(tmp) / "clone"
            subprocess.run(["git", "clone", "--quiet", str(ROOT), str(cwd)], check=True)
        log = args.keep_log or Path(tmp) / "make.log"
        figures = run(args.target, cwd, make_args, args.map_only, log)
        if args.target == "test" and (cwd / OWN_TESTS_XML).exists():
            figures |= own_tests_by_function(cwd / OWN_TESTS_XML)
        made = cwd / "mutants" / "mutmut-stats.json"
        if args.keep_map and made.exists():
            shutil.copyfile(made, args.keep_map)
    load_after = _history.load()
    shown = figures.get("map_s", figures["wall_s"]) if args.target == "mutate" else figures["wall_s"]
    goal = TARGETS[args.target]
    print(f"make {args.target}{' (clean clone)' if args.clone else ''}: {figures['wall_s']:.1f} s wall, exit "
          f"{figures['exit']}" + (f"; map {figures['map_s']:.1f} s" if "map_s" in figures else "")
          + f"; target {goal:g} s: {'met' if shown <= goal else 'missed'}; load {load_before:.2f} -> {load_after:.2f}")
    for key in sorted(k for k in figures if k.endswith("_s") and k not in ("wall_s", "map_s")):
        print(f"  {key}: {figures[key]:.1f}")
    _history.record(args, f"make_{args.target}", figures, load_before=load_before, load_after=load_after,
                    selection=[*(["--clone"] if args.clone else []), *(["--map-only"] if args.map_only else []),
                               *(["--", *make_args] if make_args else [])])
    return 0 if figures["exit"] == 0 or args.map_only else 1


if __name__ == "__main__":
    raise SystemExit(main())
