"""The conformance run against its floor: the same scenarios through pytest-bdd with steps that do nothing.

    PYTHONPATH=. .venv/bin/python bench/suite_bench.py [--item F-NET-03] [-k EXPR] [--profile crh2]
                                                       [--sut SPEC] [--profile-run] [--repeat N] [-- PYTEST ARGS]

What it runs, each a fresh `python -m pytest` subprocess in one process (`-p no:xdist`, no --alluredir, `-q`,
`-p no:cacheprovider`), one after the other:
  conformance   `pytest features` from the repository root: the real step library driving the SUT (--sut);
  floor         the SAME feature files bound by `scenarios()` in a generated temporary folder whose conftest
                loads the outline plugin (tags -> marks, --item/--req selection, collection-time step check:
                everything the conformance run does before a step runs) and registers one catch-all step
                for each of given/when/then (`parsers.re("(?s).*")`, no arguments, no target fixture) that
                does nothing. Same scenarios, same steps, same skips (@pending); no step module, no SUT.
Both load bench/_bench_plugin.py (`-p _bench_plugin`), which records collection time, per-test seconds,
steps run and the peak-RSS scenario, and in the conformance run the wall time inside the reference's
Kernel.run (internal: the simulation proper; the rest of the run is what the harness, the steps and the
driver cost, compared with the floor too); the scenario counts of the two runs must be equal (asserted).

Printed: wall seconds (whole process, and the test phase after collection), CPU seconds (user + sys of the
child, from os.wait4: steadier than wall on a shared machine), scenarios and steps, the ratio conformance /
floor against the target (<= 1.5x, issue 9), peak RSS of each process (ru_maxrss from os.wait4, i.e. the
child's own getrusage(RUSAGE_CHILDREN) figure) with its ratio, the heaviest scenario (the one during which the
conformance process reached its peak RSS), the 10 slowest scenarios (setup + call + teardown, what pytest's
--durations lists per phase), and the machine load (1-minute load average) before and after each run.
With --profile-run, a third pass of the conformance run under cProfile, summarised: self time per package
(sut/, steps/, outline/, pytest_bdd, _pytest + pluggy, allure; the stdlib, builtins and other libraries
charged to their callers), the hottest modules of the project, and the top functions by self and by
cumulative time.

Measured on this machine (2-core VM, Python 3.11.7, pytest 9.2.0, pytest-bdd 9.0.1, full suite: 528
scenarios, 5 035 steps, all passed; 535 and 5 122 since issue 15):
  2026-11-25 17:45, load 1.5 -> 1.2 (metronomes and a 120 ms period, the monitor watch as one driver call,
    traces out of the GC's way): conformance 59.5 s wall (59.5 s CPU; collection 1.1 s), floor 1.66 s -> 36x;
    40.4 s (68 %) inside Kernel.run; the rest 19.1 s. Peak RSS 786 MB (a ten-minute scenario's trace).
  2026-11-25 04:40, load 1.0, side by side with 760111a (issue 14, second session: bulk advance in plain
    advances of every profile, replayed soak samples, cheaper frames): conformance 58.9 s wall (58.9 s CPU;
    collection 1.4 s), floor 1.50 s -> 39x; 42.1 s (72 %) inside Kernel.run; the rest 16.8 s. 760111a in the
    same sitting: 80.4 s, 54x, 65.2 s inside Kernel.run (the machine was slower than the day before).
  2026-11-24 23:23, load 0.2 -> 0.7 (issue 14: snapshots, step index, hot paths): conformance 65.1 s wall
    (65.1 s CPU; collection 1.1 s), floor 1.22 s -> 53x (the floor fell too: it shares the step index and
    no longer loads hypothesis's pytest plugin; against the old floor, 36x). 52.8 s (81 %) inside Kernel.run;
    the rest, 12.3 s, is 10x the floor. Peak RSS 303 MB (the snapshot cache) vs 58 MB.
  2026-11-24 21:43, load 0.2 -> 0.8 (before issue 14): conformance 88.2 s, floor 1.80 s -> 49x; 71.8 s inside
    Kernel.run; peak RSS 210 MB.
  2026-11-23 (issue 9): 150.4 s vs 2.9 s, 51x; what-if stand-ins for the step index and for no attachments
    without --alluredir were measured then (both done since).
  --profile-run: the simulation dominates (sut/ ~75 % of the self time); the 10 slowest scenarios (the 72 h
    soaks, the rated withstand tests, mileage ramps) are a third of the test phase.

In-process vs remote: bench/remote_bench.py (or --sut tcp://HOST:PORT here, against a running server).
Options --item, -k, --profile and anything after `--` go to both runs; --sut and --conf-arg to the
conformance run only.
"""
from __future__ import annotations

import argparse
import json
import os
import pstats
import shlex
import subprocess
import sys
import sysconfig
import tempfile
import time
import tomllib
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

BENCH = Path(__file__).resolve().parent
ROOT = BENCH.parent
sys.path.insert(0, str(BENCH))

from _table import table, text  # noqa: E402

TARGET_FLOOR = 1.5      # issue 9: the conformance run <= 1.5x the floor
TARGET_REMOTE = 2.0     # issue 9: remote <= 2x in-process (not measured here yet)

# -- the floor ------------------------------------------------------------------------------------------
FLOOR_CONFTEST = '''\
"""Generated by bench/suite_bench.py: the floor. The outline plugin (what the conformance run does around the
steps: tags -> marks, --item/--req, the collection-time step check) and one catch-all step per keyword that
does nothing; no step module, no SUT."""
import pytest
from pytest_bdd import given, parsers, then, when

pytest_plugins = ["outline.pytest_plugin"]

_ANY = parsers.re(r"(?s).*")      # no named group: no step argument; no target_fixture


@given(_ANY)
def _floor_given():
    pass


@when(_ANY)
def _floor_when():
    pass


@then(_ANY)
def _floor_then():
    pass


def pytest_addoption(parser):
    # steps.fixtures' --profile, so --profile passes through to both runs; the same selection rule.
    parser.getgroup("crh2").addoption("--profile", action="append", default=[])


def pytest_collection_modifyitems(config, items):
    wanted = {p.strip() for v in config.getoption("--profile") for p in v.split(",") if p.strip()}
    if not wanted:
        return
    keep, drop = [], []
    for item in items:
        profiles = {str(a) for m in item.iter_markers("profile") for a in m.args}
        (keep if not profiles or profiles & wanted else drop).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep
'''

FLOOR_TEST = '''\
"""Generated by bench/suite_bench.py: binds the repository's feature files exactly as features/test_outline.py."""
from pytest_bdd import scenarios

from outline.binding import feature_paths

_FEATURES = {features!r}
scenarios(*feature_paths(_FEATURES), features_base_dir=_FEATURES)
'''


def make_floor(folder: Path) -> Path:
    """Write the floor into `folder`: pytest.ini (the project's markers and options), conftest.py,
    test_floor.py, and docs/ linked to the project's (the outline plugin links requirements to it)."""
    ini = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["pytest"]["ini_options"]
    markers = "\n".join(f"    {m}" for m in ini.get("markers", []))
    (folder / "pytest.ini").write_text(
        "[pytest]\n"
        f"pythonpath = {ROOT}\n"
        f"bdd_features_base_dir = {ROOT / 'features'}\n"
        f"addopts = {ini.get('addopts', '')}\n"
        f"markers =\n{markers}\n", encoding="utf-8")
    (folder / "conftest.py").write_text(FLOOR_CONFTEST, encoding="utf-8")
    (folder / "test_floor.py").write_text(FLOOR_TEST.format(features=str(ROOT / "features")), encoding="utf-8")
    (folder / "docs").symlink_to(ROOT / "docs")
    return folder


# -- running pytest -------------------------------------------------------------------------------------
@dataclass
class Run:
    label: str
    argv: list[str]
    cwd: Path
    wall: float = 0.0
    cpu: float = 0.0
    maxrss_kb: int = 0
    exit: int = 0
    load: tuple[float, float] = (0.0, 0.0)
    data: dict = field(default_factory=dict)
    log: Path | None = None
    env: dict = field(default_factory=dict)
    started: float = 0.0         # time.time() at start, to line up with the plugin's marks

    @property
    def collected(self) -> int:
        return self.data.get("collected", 0)

    @property
    def steps(self) -> int:
        return self.data.get("steps", 0)

    @property
    def collect_s(self) -> float:
        m = self.data.get("marks", {})
        return m["collected"] - self.started if "collected" in m else float("nan")

    @property
    def tests_s(self) -> float:
        return sum(t["seconds"] for t in self.data.get("tests", {}).values())

    def outcomes(self) -> dict[str, int]:
        out: dict[str, int] = defaultdict(int)
        for t in self.data.get("tests", {}).values():
            out[t["outcome"]] += 1
        return dict(out)


def run_pytest(run: Run, logdir: Path, *, prefix: list[str] | None = None) -> Run:
    """Run `python [prefix] -m pytest <argv>` in run.cwd; wall, CPU and peak RSS of that child alone."""
    slug = "".join(c if c.isalnum() or c in "-_" else "_" for c in run.label)
    out_json = logdir / f"{slug}.json"
    run.log = logdir / f"{slug}.log"
    env = dict(os.environ, **run.env, BENCH_PLUGIN_OUT=str(out_json),
               PYTHONPATH=os.pathsep.join([str(BENCH), str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]))
    env.pop("PYTEST_ADDOPTS", None)
    cmd = [sys.executable, *(prefix or []), "-m", "pytest", *run.argv, "-p", "_bench_plugin"]
    load0 = os.getloadavg()[0]
    with open(run.log, "w", encoding="utf-8") as log:
        log.write("$ " + shlex.join(cmd) + f"\n# cwd {run.cwd}\n")
        log.flush()
        run.started = time.time()
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=run.cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        # wait4: this child's own rusage (RUSAGE_CHILDREN would fold in the earlier runs' peak)
        _pid, status, usage = os.wait4(proc.pid, 0)
        run.wall = time.perf_counter() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
    run.exit = proc.returncode
    run.cpu = usage.ru_utime + usage.ru_stime
    run.maxrss_kb = usage.ru_maxrss
    run.load = (load0, os.getloadavg()[0])
    run.data = json.loads(out_json.read_text(encoding="utf-8")) if out_json.exists() else {}
    return run


def passes(args: argparse.Namespace, floor_dir: Path) -> list[Run]:
    """The pytest passes to time, in order. In-process vs remote will be one more conformance pass here
    with `--sut tcp://...` (and its ratio against the in-process one, target TARGET_REMOTE)."""
    common = ["-p", "no:xdist", "-p", "no:cacheprovider", "-q", "--durations=10"]
    select = [*(f"--item={i}" for i in args.item), *(["-k", args.k] if args.k else []),
              *(f"--profile={p}" for p in args.profile), *args.pytest_args]
    conformance = ["features", *common, *select, *(["--sut", args.sut] if args.sut else []), *args.conf_arg]
    floor = [str(floor_dir), *common, *select]
    runs = [Run("conformance", conformance, ROOT), Run("floor", floor, floor_dir)]
    if args.what_if:
        patches = sorted(set(args.what_if))
        extra = ["-p", "_whatif_plugin"]
        runs.append(Run("what-if: " + "+".join(sorted(set(args.what_if))), [*conformance, *extra], ROOT,
                        env={"BENCH_WHATIF": ",".join(patches)}))
    return runs


# -- the profile ----------------------------------------------------------------------------------------
_SITE = sysconfig.get_paths()["purelib"].rstrip("/") + "/"
_STDLIB = sysconfig.get_paths()["stdlib"].rstrip("/") + "/"
OWNERS = ("sut", "steps", "outline", "features", "bench", "pytest_bdd", "pytest+pluggy", "allure")
_SITE_GROUPS = {"pytest_bdd": "pytest_bdd", "_pytest": "pytest+pluggy", "pytest": "pytest+pluggy",
                "pluggy": "pytest+pluggy", "allure": "allure", "allure_commons": "allure",
                "allure_pytest_bdd": "allure"}


def group_of(filename: str) -> str:
    """Which package a profiled function belongs to; 'lib:<name>', 'stdlib' and 'builtin' are charged to
    their callers by `attribute`."""
    if filename == "~" or filename.startswith("<built-in"):
        return "builtin"
    if "/site-packages/" in filename:             # first: the venv may live inside the repository
        top = filename.split("/site-packages/", 1)[1].split("/", 1)[0].removesuffix(".py")
        return _SITE_GROUPS.get(top, f"lib:{top}")
    root = str(ROOT) + "/"
    if filename.startswith(root):
        top = filename[len(root):].split("/", 1)[0]
        return top if top in OWNERS else f"lib:{top}"
    if filename.startswith(_STDLIB) or filename.startswith("<frozen") or filename.startswith("<"):
        return "stdlib"
    return f"lib:{Path(filename).name}"


def attribute(stats: dict) -> dict[str, float]:
    """Self time per owning package: a function of the project, pytest, pytest-bdd or allure keeps its own
    self time; the self time of the stdlib, builtins and other libraries (construct, svgwrite, wavedrom,
    gherkin, parse, yaml, ...) is split over their callers in proportion to the cumulative time of each call
    edge, up to the first owner. Calls inside one library (construct's nested _build, svgwrite's tostring)
    are followed to where the library was entered from outside, as a whole; recursion follows the other
    callers. Approximate: proportional splitting assumes every call of a function costs alike."""
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 20_000))
    group = {f: group_of(f[0]) for f in stats}
    entries: dict[str, dict[tuple, float]] = defaultdict(lambda: defaultdict(float))
    for f, v in stats.items():
        if group[f] not in OWNERS:
            for c, cv in v[4].items():
                if group.get(c, group_of(c[0])) != group[f] and cv[3] > 0:
                    entries[group[f]][c] += cv[3]
    memo: dict[object, dict[str, float]] = {}
    on_stack: set[object] = set()

    def mix(pairs, fallback: str) -> dict[str, float]:
        total = sum(w for _k, w in pairs)
        out: dict[str, float] = defaultdict(float)
        if total <= 0:
            return {fallback: 1.0}
        for resolve, w in pairs:
            for k, v in resolve().items():
                out[k] += v * w / total
        return dict(out)

    def entry_shares(g: str) -> dict[str, float]:
        key = ("group", g)
        if key in memo:
            return memo[key]
        if key in on_stack:
            return {f"unattributed {g}": 1.0}
        on_stack.add(key)
        memo[key] = mix([((lambda c=c: shares(c)), w) for c, w in entries[g].items() if c not in on_stack],
                        f"unattributed {g}")
        on_stack.discard(key)
        return memo[key]

    def shares(func: tuple) -> dict[str, float]:
        g = group.get(func) or group_of(func[0])
        if g in OWNERS:
            return {g: 1.0}
        if func in memo:
            return memo[func]
        if func in on_stack:
            return {f"unattributed {g}": 1.0}
        on_stack.add(func)
        callers = stats[func][4] if func in stats else {}
        pairs = []
        for c, cv in callers.items():
            if c == func or c in on_stack or cv[3] <= 0:        # recursion: follow the other callers
                continue
            # inside one third-party library: from where it was entered; the stdlib and builtins are too
            # mixed for that (ElementTree for svgwrite, weakref for pytest-bdd): caller by caller
            inside = g.startswith("lib:") and (group.get(c) or group_of(c[0])) == g
            pairs.append(((lambda: entry_shares(g)) if inside else (lambda c=c: shares(c)), cv[3]))
        memo[func] = mix(pairs, f"unattributed {g}")
        on_stack.discard(func)
        return memo[func]

    out: dict[str, float] = defaultdict(float)
    for func, (_cc, _nc, tt, _ct, _callers) in stats.items():
        for k, v in shares(func).items():
            out[k] += tt * v
    return dict(out)


def _fname(func: tuple) -> str:
    filename, line, name = func
    if filename == "~":
        return name
    for prefix in (_SITE, str(ROOT) + "/", _STDLIB):
        if filename.startswith(prefix):
            filename = filename[len(prefix):]
            break
    return f"{filename}:{line}({name})"


def summarise_profile(path: Path, plain: bool, top: int) -> dict:
    st = pstats.Stats(str(path))
    stats = st.stats        # {(file, line, name): (cc, nc, tt, ct, callers)}
    total = sum(v[2] for v in stats.values())
    raw: dict[str, float] = defaultdict(float)
    for func, v in stats.items():
        raw[group_of(func[0])] += v[2]
    charged = attribute(stats)
    groups = sorted((g for g in set(charged) | {g for g in raw if g in OWNERS}
                     if g in OWNERS or charged.get(g, 0.0) >= 0.0005 * total), key=lambda g: -charged.get(g, 0.0))
    rows = [[g, f"{raw.get(g, 0.0):.2f}", f"{100 * raw.get(g, 0.0) / total:.1f}%",
             f"{charged.get(g, 0.0):.2f}", f"{100 * charged.get(g, 0.0) / total:.1f}%"] for g in groups]
    others = sorted(((g, t) for g, t in raw.items() if g not in OWNERS), key=lambda x: -x[1])[:8]
    table(f"cProfile of the conformance run: self time by package (total {total:.1f} s profiled)",
          ["package", "own self s", "share", "charged s", "share"], rows, plain=plain,
          notes=["own = functions defined in the package; charged = own + the stdlib/builtin/library time they "
                 "call (split by call-edge cumulative time)",
                 "largest non-owner self times (charged above to their callers): "
                 + ", ".join(f"{g} {t:.1f} s" for g, t in others)])
    # phases and notable subtrees (cumulative time; nested rows are part of the row above)
    def cum(suffix: str, name: str) -> float | None:
        hits = [v[3] for f, v in stats.items() if f[2] == name and f[0].endswith(suffix)]
        return max(hits) if hits else None

    def inclusive(group: str) -> float:
        """Time inside `group`'s frames entered from outside it (its own calls to others included; imports
        of its modules left out: they belong to collection)."""
        return sum(cv[3] for f, v in stats.items() if group_of(f[0]) == group and f[2] != "<module>"
                   for c, cv in v[4].items() if group_of(c[0]) != group)

    sut_in, steps_in = inclusive("sut"), inclusive("steps")
    phases = [
        ("collection (pytest perform_collect)", cum("_pytest/main.py", "perform_collect")),
        ("  outline.binding.feature_paths: parse + lint every feature", cum("outline/binding.py", "feature_paths")),
        ("  pytest_bdd scenarios(): parse + generate the tests", cum("pytest_bdd/scenario.py", "scenarios")),
        ("  outline plugin collection-time step check (_step_problems)",
         cum("outline/pytest_plugin.py", "_step_problems")),
        ("test run (pytest_runtestloop)", cum("_pytest/main.py", "pytest_runtestloop")),
        ("  pytest-bdd: scenarios run (_execute_scenario, steps incl.)",
         cum("pytest_bdd/scenario.py", "_execute_scenario")),
        ("    pytest-bdd step lookup per step (get_step_function)", cum("pytest_bdd/scenario.py", "get_step_function")),
        ("  steps/ inclusive (step functions, fixtures, report; SUT incl.)", steps_in),
        ("    sut/ inclusive (every call into the driver and the model)", sut_in),
        ("      reference kernel run (Kernel.run: the simulation proper)", cum("sut/reference/kernel.py", "run")),
        ("    steps/ without the SUT", steps_in - sut_in),
        ("    report attachments after each scenario (steps/report.attach_run)", cum("steps/report.py", "attach_run")),
        ("      timing diagram SVG (steps/diagram.render_svg)", cum("steps/diagram.py", "render_svg")),
        ("terminal summary (pytest_sessionfinish of the terminal reporter)",
         cum("_pytest/terminal.py", "pytest_sessionfinish")),
    ]
    table("Where the profiled time goes (cumulative; indented rows are part of the row above)",
          ["part", "cum s", "share"],
          [[label, f"{t:.2f}", f"{100 * t / total:.1f}%"] for label, t in phases if t is not None], plain=plain)
    result_phases = {label.strip(): t for label, t in phases if t is not None}
    # hottest project modules
    mods: dict[str, float] = defaultdict(float)
    for func, v in stats.items():
        if group_of(func[0]) in ("sut", "steps", "outline"):
            mods[func[0][len(str(ROOT)) + 1:]] += v[2]
    mod_rows = [[m, f"{t:.2f}", f"{100 * t / total:.1f}%"] for m, t in sorted(mods.items(), key=lambda x: -x[1])[:top]]
    table("Project modules by own self time", ["module", "self s", "share of total"], mod_rows, plain=plain)
    # top functions by self time and by cumulative time
    by_tt = sorted(stats.items(), key=lambda kv: -kv[1][2])[:top]
    table(f"Top {top} functions by self time",
          ["function", "calls", "self s", "self share", "cum s", "cum share"],
          [[_fname(f), f"{v[1]:,}", f"{v[2]:.2f}", f"{100 * v[2] / total:.1f}%", f"{v[3]:.2f}",
            f"{100 * v[3] / total:.1f}%"] for f, v in by_tt], plain=plain)
    proj = [(f, v) for f, v in stats.items() if group_of(f[0]) in ("sut", "steps")]
    by_ct = sorted(proj, key=lambda kv: -kv[1][3])[:top]
    table(f"Top {top} sut/ and steps/ functions by cumulative time",
          ["function", "calls", "self s", "cum s", "cum share", "s per call"],
          [[_fname(f), f"{v[1]:,}", f"{v[2]:.2f}", f"{v[3]:.2f}", f"{100 * v[3] / total:.1f}%",
            f"{v[3] / max(v[1], 1):.2e}"] for f, v in by_ct], plain=plain)
    return {"total_s": total, "own": dict(raw), "charged": charged, "phases": result_phases,
            "top_self": [[_fname(f), v[1], v[2], v[3]] for f, v in by_tt],
            "top_cum": [[_fname(f), v[1], v[2], v[3]] for f, v in by_ct]}


# -- output ---------------------------------------------------------------------------------------------
def _mb(kb: int) -> str:
    return f"{kb / 1024:,.0f}"


def _ratio(a: float, b: float) -> str:
    return f"{a / b:.2f}x" if b else "-"


def report(runs: list[Run], plain: bool, top: int) -> dict:
    conf, floor = runs[0], runs[1]
    rows = []
    for r in runs:
        oc = r.outcomes()
        rows.append([r.label, f"{r.collected}", "/".join(str(oc.get(k, 0)) for k in ("passed", "failed", "skipped")),
                     f"{r.steps:,}", f"{r.wall:.2f}", f"{r.collect_s:.2f}", f"{r.tests_s:.2f}", f"{r.cpu:.2f}",
                     _mb(r.maxrss_kb), f"{r.load[0]:.2f} -> {r.load[1]:.2f}", str(r.exit)])
    for r in [conf, *runs[2:]]:
        rows.append([f"ratio {r.label}/floor", "", "", "", _ratio(r.wall, floor.wall), _ratio(r.collect_s, floor.collect_s),
                     _ratio(r.tests_s, floor.tests_s), _ratio(r.cpu, floor.cpu),
                     _ratio(r.maxrss_kb, floor.maxrss_kb), "", ""])
    for r in runs[2:]:
        rows.append([f"ratio {r.label}/conformance", "", "", "", _ratio(r.wall, conf.wall),
                     _ratio(r.collect_s, conf.collect_s), _ratio(r.tests_s, conf.tests_s), _ratio(r.cpu, conf.cpu),
                     _ratio(r.maxrss_kb, conf.maxrss_kb), "", ""])
    verdict = "met" if conf.wall <= TARGET_FLOOR * floor.wall else "MISSED"
    table("Conformance run vs floor (one process each, -p no:xdist)",
          ["run", "scenarios", "pass/fail/skip", "steps run", "wall s", "collect s", "tests s", "CPU s",
           "peak RSS MB", "load 1m", "exit"], rows, plain=plain,
          notes=[f"target: conformance wall <= {TARGET_FLOOR}x floor -> {conf.wall / floor.wall:.2f}x, {verdict}"
                 f" (test phase {conf.tests_s / max(floor.tests_s, 1e-9):.1f}x, CPU {conf.cpu / max(floor.cpu, 1e-9):.2f}x)",
                 "wall = whole process (start-up, collection, tests); collect = start to end of collection; "
                 "tests = sum of setup+call+teardown; CPU = user+sys of the child; RSS = ru_maxrss (os.wait4)",
                 "logs: " + "  ".join(str(r.log) for r in runs)])
    for r in [conf, *runs[2:]]:
        k = r.data.get("kernel_run_s")
        if k:
            rest = r.wall - k
            text(f"{r.label}: {k:.1f} s of its {r.wall:.1f} s inside Kernel.run ({100 * k / r.wall:.0f}%, reference "
                 f"internals: the simulation proper, {r.data.get('kernel_run_calls', 0):,} advances); the rest, "
                 f"{rest:.1f} s, is {rest / floor.wall:.2f}x the floor", plain=plain)
    if conf.steps != floor.steps:
        text(f"note: steps run differ ({conf.steps} vs {floor.steps}): a failing scenario stops at its first "
             "failed step", plain=plain)
    tests = conf.data.get("tests", {})
    slow = sorted(tests.items(), key=lambda kv: -kv[1]["seconds"])[:10]
    tsum = max(conf.tests_s, 1e-9)
    table("10 slowest scenarios of the conformance run (setup + call + teardown)",
          ["scenario", "seconds", "share of tests s", "outcome"],
          [[nid.split("::")[-1], f"{t['seconds']:.2f}", f"{100 * t['seconds'] / tsum:.1f}%", t["outcome"]]
           for nid, t in slow], plain=plain,
          notes=[f"these 10: {sum(t['seconds'] for _n, t in slow):.1f} s of {conf.tests_s:.1f} s; the other "
                 f"{max(len(tests) - 10, 0)}: {conf.tests_s - sum(t['seconds'] for _n, t in slow):.1f} s "
                 f"({(conf.tests_s - sum(t['seconds'] for _n, t in slow)) / max(len(tests) - 10, 1) * 1000:.0f} ms "
                 "each on average)"])
    raised = conf.data.get("raised", [])
    mem_notes = []
    if raised:
        biggest = sorted(raised, key=lambda r: -r["rise_kb"])[:3]
        mem_notes.append("heaviest scenarios (largest rises of the process's peak RSS while they ran): " + "; ".join(
            f"{r['nodeid'].split('::')[-1][:70]} +{_mb(r['rise_kb'])} MB (to {_mb(r['hwm_kb'])} MB)"
            for r in biggest))
        last = raised[-1]
        mem_notes.append(f"the peak was last raised during {last['nodeid'].split('::')[-1][:70]}: "
                         f"{_mb(last['hwm_kb'])} MB, RSS at its setup {_mb(last['rss_at_start_kb'])} MB "
                         "(CPython keeps freed memory, so later scenarios start high)")
    table("Peak memory (RSS of the pytest process)", ["run", "peak RSS MB"],
          [[conf.label, _mb(conf.maxrss_kb)], [floor.label, _mb(floor.maxrss_kb)],
           ["ratio", _ratio(conf.maxrss_kb, floor.maxrss_kb)]], plain=plain, notes=mem_notes)
    return {"runs": [{"label": r.label, "argv": r.argv, "env": r.env, "wall_s": r.wall, "cpu_s": r.cpu, "collect_s": r.collect_s,
                      "tests_s": r.tests_s, "collected": r.collected, "steps": r.steps, "outcomes": r.outcomes(),
                      "maxrss_kb": r.maxrss_kb, "load": r.load, "exit": r.exit,
                      "kernel_run_s": r.data.get("kernel_run_s")} for r in runs],
            "ratio_wall": conf.wall / floor.wall, "ratio_cpu": conf.cpu / max(floor.cpu, 1e-9),
            "ratio_rss": conf.maxrss_kb / max(floor.maxrss_kb, 1), "target_floor": TARGET_FLOOR,
            "slowest": [[nid, t["seconds"]] for nid, t in slow], "heaviest": raised[-1] if raised else None}


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    rest: list[str] = []
    if "--" in argv:
        i = argv.index("--")
        argv, rest = argv[:i], argv[i + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 epilog="Arguments after `--` go to both pytest runs.")
    ap.add_argument("--item", action="append", default=[], metavar="ID",
                    help="only this test item (repeatable; both runs)")
    ap.add_argument("-k", default=None, metavar="EXPR", help="pytest -k expression (both runs)")
    ap.add_argument("--profile", action="append", default=[], metavar="NAME",
                    help="only scenarios of this train profile, e.g. crh2 (the suite's --profile; both runs)")
    ap.add_argument("--sut", default=None, metavar="SPEC",
                    help="SUT backend of the conformance run (reference, package.module:Class, tcp://host:port)")
    ap.add_argument("--conf-arg", action="append", default=[], metavar="ARG",
                    help="one more pytest argument for the conformance run only (repeatable)")
    ap.add_argument("--repeat", type=int, default=1,
                    help="run the pair N times, alternating, and keep each run's best wall time (default 1)")
    ap.add_argument("--what-if", type=lambda v: [w.strip() for w in v.split(",") if w.strip()], default=[],
                    metavar="LIST",
                    help="experimental: one more conformance pass with stand-ins for proposed fixes "
                         "(comma-separated: bddscan; see bench/_whatif_plugin.py)")
    ap.add_argument("--profile-run", action="store_true",
                    help="also run the conformance pass under cProfile and summarise it by package")
    ap.add_argument("--profile-out", type=Path, default=None, metavar="FILE",
                    help="where to keep the cProfile output (default: a temporary file, removed)")
    ap.add_argument("--from-profile", type=Path, default=None, metavar="FILE",
                    help="run nothing: summarise a profile kept earlier with --profile-out")
    ap.add_argument("--top", type=int, default=15, help="rows in the profile's function tables (default 15)")
    ap.add_argument("--json", type=Path, default=None, metavar="FILE", help="also write the figures as JSON")
    ap.add_argument("--logdir", type=Path, default=None,
                    help="keep the pytest logs (with --durations=10) here (default: a temporary folder)")
    ap.add_argument("--plain", action="store_true", help="plain text output even if rich is installed")
    args = ap.parse_args(argv)
    args.pytest_args = rest
    if args.repeat < 1:
        ap.error("--repeat must be >= 1")
    bad = set(args.what_if) - {"bddscan"}
    if bad:
        ap.error(f"--what-if: unknown {', '.join(sorted(bad))}")

    if args.from_profile:
        summarise_profile(args.from_profile, args.plain, args.top)
        return 0
    with tempfile.TemporaryDirectory(prefix="crh2-floor-") as tmp:
        tmp = Path(tmp)
        (tmp / "floor").mkdir()
        floor_dir = make_floor((tmp / "floor").resolve())
        logdir = args.logdir.resolve() if args.logdir else tmp / "logs"
        logdir.mkdir(parents=True, exist_ok=True)
        text(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.2f} "
             f"{os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f} (1/5/15 min) at start", plain=args.plain)
        best: dict[str, Run] = {}
        for rep in range(args.repeat):
            for run in passes(args, floor_dir):
                run_pytest(run, logdir)
                if run.exit not in (0, 1):
                    text(f"{run.label}: pytest exited {run.exit}; see {run.log}", plain=args.plain)
                    print(run.log.read_text(encoding="utf-8")[-3000:], file=sys.stderr)
                    return 2
                if run.label not in best or run.wall < best[run.label].wall:
                    best[run.label] = run
        runs = list(best.values())            # conformance, floor, [what-if]
        counts = {r.label: r.collected for r in runs}
        assert len(set(counts.values())) == 1, f"scenario counts differ: {counts}"
        result = report(runs, args.plain, args.top)
        if args.logdir is None:
            text("(logs are removed at exit: --logdir DIR keeps them with pytest's --durations=10)", plain=args.plain)

        if args.profile_run:
            prof = args.profile_out.resolve() if args.profile_out else tmp / "conformance.prof"
            prun = Run("profiled", passes(args, floor_dir)[0].argv, ROOT)
            run_pytest(prun, logdir, prefix=["-m", "cProfile", "-o", str(prof)])
            text(f"profiled conformance run: {prun.wall:.1f} s wall under cProfile ({prun.wall / runs[0].wall:.1f}x "
                 f"the plain run), load {prun.load[0]:.2f} -> {prun.load[1]:.2f}, exit {prun.exit}", plain=args.plain)
            if prof.exists():
                result["profile"] = summarise_profile(prof, args.plain, args.top)
                if args.profile_out:
                    text(f"profile kept: {prof} (python -m pstats {prof})", plain=args.plain)
        text(f"load at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())} (1/5/15 min)", plain=args.plain)
        if args.json:
            args.json.write_text(json.dumps(result, indent=1, default=str), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
