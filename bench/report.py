"""docs/performance.md and docs/performance.svg from the benchmark history (bench/history.jsonl).

    .venv/bin/python -m bench.report [--history FILE] [--md FILE] [--svg FILE] [--no-plot]    (or: make performance)

The page is text made from the rows alone (no clock, no machine state), so tests/test_performance_page.py can
check that the committed page is this module's output for the committed history without matplotlib. The plot
needs matplotlib (the project's `bench` extra, installed by `make performance`); the SVG carries the digest of
the series it was drawn from, which the test compares with the history's.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import sys
from datetime import datetime
from pathlib import Path

from bench._history import HISTORY, ROOT, read

PAGE = ROOT / "docs" / "performance.md"
PLOT = ROOT / "docs" / "performance.svg"
NOTES = ROOT / "bench" / "performance-notes.md"     # the page's hand-written part: what was done and why

# Issue 33's targets, each with the bench row that measures it (the latest row that qualifies).
FLOOR_TARGET, FLOOR_GOAL = 10.0, 1.5
TEST_TARGET_S, REPORT_TARGET_S, MAP_TARGET_S = 300.0, 25.0, 900.0


# -- reading rows -----------------------------------------------------------------------------------------
def _time(row: dict) -> datetime:
    when = row["when"].replace("Z", "")
    return datetime.fromisoformat(when if "T" in when else when + "T12:00")


def _full_suite(row: dict) -> bool:
    """A suite_bench row of the whole suite against the reference (no selection, no other SUT)."""
    return row["bench"] == "suite_bench" and not row.get("args")


def _rows(rows: list[dict], bench: str, need: str | None = None, where=None) -> list[dict]:
    out = [r for r in rows if r["bench"] == bench and (need is None or need in r["figures"])
           and (where is None or where(r))]
    return sorted(out, key=_time)


def _latest(rows: list[dict], bench: str, need: str | None = None, where=None) -> dict | None:
    found = _rows(rows, bench, need, where)
    return found[-1] if found else None


# -- formatting ------------------------------------------------------------------------------------------
def _when(row: dict) -> str:
    when = row["when"].replace("Z", "")
    return when.replace("T", " ")[:16] if "T" in when else when


def _load(row: dict) -> str:
    before, after = (list(row.get("load") or []) + [None, None])[:2]
    if before is None and after is None:
        return "-"
    if after is None:
        return f"{before:.1f}"
    return f"{'?' if before is None else f'{before:.1f}'} -> {after:.1f}"


def _commit(row: dict) -> str:
    commit = row.get("commit") or "-"
    return commit + ("+" if row.get("dirty") else "")


def _dur(seconds: float) -> str:
    if seconds < 90:
        return f"{seconds:.1f} s"
    m, s = divmod(round(seconds), 60)
    return f"{m} min {s} s" if s else f"{m} min"


def _n(x: float) -> str:
    if abs(x) >= 1e6:
        return f"{x / 1e6:.2f} M"
    if abs(x) >= 100:
        return f"{x:,.0f}"
    return f"{x:.3g}" if isinstance(x, float) else str(x)


def _measured(row: dict | None) -> str:
    return "-" if row is None else f"{_when(row)}, {_commit(row)}, load {_load(row)}"


def _verdict(value: float | None, target: float) -> str:
    return "-" if value is None else ("met" if value <= target else "missed")


def _table(headers: list[str], rows: list[list[str]]) -> list[str]:
    out = ["| " + " | ".join(headers) + " |", "| " + " | ".join("---" for _ in headers) + " |"]
    out += ["| " + " | ".join(c.replace("|", "/") for c in row) + " |" for row in rows]
    return out


def headline(row: dict) -> str:
    """A bench row's figures in a sentence (the ones its bench prints first)."""
    f, bench = row["figures"], row["bench"]
    if bench == "suite_bench":
        parts = [f"conformance {f['conformance_wall_s']:.1f} s, floor {f['floor_wall_s']:.2f} s: "
                 f"{f['ratio_wall']:.1f}x"]
        if "kernel_run_s" in f:
            parts.append(f"{f['kernel_run_s']:.1f} s inside Kernel.run")
        if "conformance_rss_mb" in f:
            parts.append(f"peak RSS {f['conformance_rss_mb']:.0f} MB")
        if "scenarios" in f:
            parts.append(f"{f['scenarios']} scenarios")
        return "; ".join(parts)
    if bench == "events_bench":
        profiles = [k.split(".")[0] for k in f if k.endswith(".events") and not k.startswith("all.")]
        return (f"{f['all.events'] / 1e6:.2f} M kernel events: "
                + ", ".join(f"{p} {f[p + '.events'] / 1e6:.2f} M" for p in profiles))
    if bench == "advances_bench":
        nothing = sum(v for k, v in f.items() if k.endswith(".1 s or more, nothing skipped.wall_s"))
        inside = sum(v for k, v in f.items() if k.endswith(".in_advances_s"))
        return (f"{inside:.1f} s in advances, {nothing:.1f} s of them in advances of 1 s or more that bulk advance "
                "could not shorten")
    if bench == "kernel_bench":
        parts = []
        if "kernel-callback_events_per_s" in f:
            parts.append(f"kernel callbacks {_n(f['kernel-callback_events_per_s'])} events/s")
        if "kernel_over_simpy_callbacks" in f:
            parts.append(f"{f['kernel_over_simpy_callbacks']:.2f}x SimPy's")
        if "ref_wall_s_per_sim_h" in f:
            parts.append(f"reference model {f['ref_wall_s_per_sim_h']:.0f} s wall per simulated hour (frame by frame)")
        return "; ".join(parts)
    if bench == "cars_bench":
        return (f"16 cars / 8 cars {f['ratio_wall_per_sim_s']:.2f}x wall per simulated second (target 2.2x); "
                f"8 cars {f.get('cars8_wall_s_per_sim_s', float('nan')):.3f} s per simulated second")
    if bench == "crc_bench":
        return (f"508 bytes: table {_n(f['table_us_508b'])} us, crc package {_n(f['crc_opt_us_508b'])} us "
                f"({f['crc_opt_us_508b'] / f['table_us_508b']:.0f}x)") if "table_us_508b" in f else ""
    if bench == "bulk_bench":
        line = (f"72 h powered on in {f.get('bulk_sample_1h_wall_s', float('nan')):.1f} s (target 10 s); frame by "
                f"frame {f['fbf_wall_s_per_sim_h']:.0f} s per simulated hour")
        if "fbf_peak_rss_mib_per_sim_h" in f:
            line += f", its peak RSS +{f['fbf_peak_rss_mib_per_sim_h']:,.0f} MiB per simulated hour"
        return line
    if bench == "instructions_bench":
        loads = [k[:-len("_minstr")] for k in f if k.endswith("_minstr") and k != "imports_minstr"]
        return ", ".join(f"{w} {f[w + '_minstr']:,.0f} M instructions" for w in loads) + " (callgrind, net of imports)"
    if bench == "remote_bench":
        return f"remote / in process {f['ratio_wall']:.2f}x wall (target 2x), {f['in_process_wall_s']:.1f} s in process"
    if bench == "shard_bench":
        shards = sorted((int(k.split("_")[1]), v) for k, v in f.items() if k.startswith("shards_"))
        return ", ".join(f"{n} shards {v:.0f} s" for n, v in shards)
    if bench == "make_mutate":
        return f"map {_dur(f['map_s'])}" + (f", whole run {_dur(f['wall_s'])}" if "wall_s" in f else "")
    if bench.startswith("make_"):
        parts = [_dur(f["wall_s"])]
        if "own_tests_s" in f:
            parts.append(f"own tests {_dur(f['own_tests_s'])}")
        if "conformance_s" in f:
            parts.append(f"conformance run {_dur(f['conformance_s'])}")
        return ", ".join(parts)
    return ", ".join(f"{k} {_n(v)}" for k, v in list(f.items())[:4])


# -- the plot's data -----------------------------------------------------------------------------------------
PANELS = (  # (title, bench, figure, scale, unit, target, where)
    ("conformance run / floor", "suite_bench", "ratio_wall", 1.0, "x", FLOOR_TARGET, _full_suite),
    ("make test, clean clone", "make_test", "wall_s", 1 / 60, "min", TEST_TARGET_S / 60, None),
    ("make report", "make_report", "wall_s", 1.0, "s", REPORT_TARGET_S, None),
    ("make mutate, first map", "make_mutate", "map_s", 1 / 60, "min", MAP_TARGET_S / 60, None),
    ("peak RSS, conformance run", "suite_bench", "conformance_rss_mb", 1.0, "MB", None, _full_suite),
    ("kernel events, all profiles", "events_bench", "all.events", 1e-6, "M", None, None),
)


def series(rows: list[dict]) -> list[dict]:
    """What the plot draws, panel by panel: the points (UTC time, value) and the target line."""
    out = []
    for title, bench, figure, scale, unit, target, where in PANELS:
        points = [[r["when"], round(r["figures"][figure] * scale, 4)] for r in _rows(rows, bench, figure, where)]
        out.append({"title": title, "unit": unit, "target": target, "points": points})
    return out


def digest(rows: list[dict]) -> str:
    return hashlib.sha256(json.dumps(series(rows), sort_keys=True).encode()).hexdigest()[:16]


def plot(rows: list[dict], path: Path) -> None:
    """The history as an SVG: one panel per target, its target as a dashed line. Deterministic output (a
    fixed hash salt, no date), so the same history gives the same file."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.dates as mdates
    import matplotlib.pyplot as plt

    plt.rcParams["svg.hashsalt"] = "bench-history"
    panels = series(rows)
    # one time axis for every panel, so a change shows at the same place in each
    fig, axes = plt.subplots(3, 2, figsize=(10, 9), constrained_layout=True, sharex=True)
    times = [_time(r) for r in rows]
    span = max(times) - min(times)
    axes[0, 0].set_xlim(min(times) - span * 0.03, max(times) + span * 0.03)
    for ax, panel in zip(axes.flat, panels):
        xs = [_time({"when": w}) for w, _v in panel["points"]]
        ys = [v for _w, v in panel["points"]]
        ax.plot(xs, ys, marker="o", markersize=3, linewidth=1)
        if panel["target"] is not None:
            ax.axhline(panel["target"], linestyle="--", color="tab:green", linewidth=1,
                       label=f"target {panel['target']:g} {panel['unit']}")
            ax.legend(loc="best", fontsize=8)
        ax.set_title(panel["title"], fontsize=10)
        ax.set_ylabel(panel["unit"])
        ax.set_ylim(bottom=0)
        locator = mdates.AutoDateLocator()
        ax.xaxis.set_major_locator(locator)
        ax.xaxis.set_major_formatter(mdates.ConciseDateFormatter(locator))
        ax.tick_params(labelsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Benchmark history (bench/history.jsonl), UTC", fontsize=11)
    fig.savefig(path, format="svg", metadata={"Date": None, "Creator": "bench/report.py",
                                              "Description": f"series sha256 {digest(rows)}"})
    plt.close(fig)


# -- the page ---------------------------------------------------------------------------------------------------
HOW_TO_MEASURE = """\
## How to measure

Every bench script prints its figures and, with `--record`, appends them as one row to `bench/history.jsonl`
(the UTC time, the commit, `+` after it when the working tree had changes, the machine's 1-minute load before and
after, the options that narrowed the run, the figures as named numbers; `--note "..."` says what changed). Then
`make performance` regenerates this page and its plot (`python -m bench.report`). The project's `bench` extra
(`.venv/bin/pip install -e '.[bench]'`, which the target runs) brings matplotlib for the plot and SimPy for
`bench/kernel_bench.py`. Commit the row, the page and the SVG together;
`tests/test_performance_page.py` fails when the page is not the generator's output for the history.

```
.venv/bin/python bench/suite_bench.py --record     # conformance run vs its floor (same scenarios, empty steps), ~4 min
.venv/bin/python bench/make_bench.py test --clone --record     # make test in a clean clone of HEAD
.venv/bin/python bench/make_bench.py report --record           # make report in this tree
.venv/bin/python bench/make_bench.py mutate --clone --map-only --record   # make mutate's first map, from scratch
.venv/bin/python bench/events_bench.py --record    # kernel events per profile and of which kind (the event budget)
.venv/bin/python bench/advances_bench.py --record  # the advances per profile, and why bulk advance left long ones whole
.venv/bin/python bench/kernel_bench.py --record    # SimPy vs our kernel on the ring load, then the full model
.venv/bin/python bench/cars_bench.py --record      # one workload on 8 cars and on 16 (two sets coupled)
.venv/bin/python bench/remote_bench.py --record    # the conformance run in process vs through python -m sut serve
.venv/bin/python bench/crc_bench.py --record       # our table CRC-16 vs the crc package
.venv/bin/python bench/instructions_bench.py --record   # instructions of fixed workloads (callgrind), ~35 s
.venv/bin/python bench/bulk_bench.py --record      # 72 h of continuous power-on: bulk advance vs frame by frame
.venv/bin/python bench/shard_bench.py --record     # a selection serial, on two workers, and on N shards
make performance                                   # this page and docs/performance.svg from the history
```

The machine is a shared 2-core VM whose speed varies by ~20 % from one hour to the next: compare rows of one
sitting (their load is beside them), run a bench under `nice -n 10` when others work, and measure a change back to
back with the commit before it. `--help` lists each script's options; each prints its ratios with the load.

- `bench/suite_bench.py` runs `pytest features` in one process (`-p no:xdist`, no Allure) and the *floor*: the
  same feature files bound by `scenarios()` in a generated folder whose conftest loads the outline plugin and one
  catch-all step per keyword that does nothing. It asserts equal scenario counts and prints wall, collection, test
  and CPU seconds, the ratio, the seconds inside `Kernel.run` (the simulation proper; the rest is the harness, the
  steps and the driver), peak RSS of both (and the scenario during which the run peaked), and the 10 slowest
  scenarios. `--item`, `-k`, `--profile` and arguments after `--` shrink both runs (such rows are kept but not
  taken as the target's figure); `--sut` goes to the conformance run (`tcp://...` for the remote backend).
  `--profile-run` adds a cProfile pass summarised by package, by phase and by function; `--what-if bddscan` a pass
  with pytest-bdd's own step scan instead of the step index (`bench/_whatif_plugin.py`).
- `bench/make_bench.py` times a make target, in this tree or (`--clone`) in a fresh clone of HEAD with every install
  make does, and reads each pytest run's seconds and counts from its summary lines; of make test also the own
  tests' seconds by test function, from the JUnit XML it writes (reports/own-tests.xml).
- `bench/events_bench.py` counts every callback `Kernel.run` makes, per profile and by kind
  (`bench/_events_plugin.py`): what the simulation must still do once snapshots and bulk advance have taken out
  all they can.
- `bench/advances_bench.py` watches every `bulk.advance` of a run per profile (`bench/_advances_plugin.py`):
  the wall and simulated seconds of advances shorter than a second, of longer ones bulk advance shortened and
  of longer ones it could not, and for those what stopped it the last time it looked (where the state still
  changed, which integer moved unevenly, which trace did not repeat): what a remodel has to make steady or cheap.
- `bench/cars_bench.py` drives only `sut.backends.open_backend(SUT, "crh2")`: power-up as the features do, notch 7,
  then `--sim-seconds` of train time, frame by frame; wall and CPU seconds per simulated second, trace events,
  the 16/8 ratio (issue 9: <= 2.2x).
- `bench/kernel_bench.py`, `bench/crc_bench.py` and `bench/bulk_bench.py` measure one mechanism each: the event
  kernel against SimPy, the table CRC-16/ARC against the `crc` package, and bulk advance over 72 h of
  power-on against frame by frame (issue 5: <= 10 s).
- `bench/remote_bench.py` runs the conformance run in process and through `python -m sut serve` (issue 9: remote
  <= 2x); `bench/shard_bench.py` a selection serial, on two workers, and what N shards of `make shard` would take.
- `bench/instructions_bench.py` counts the instructions of fixed workloads through the driver (an 8-car set and
  two coupled, powered up as the features' Background, then a notch and 500 ms; a metro train likewise) under
  valgrind's callgrind, net of start-up and imports. The count repeats to a few hundred instructions in 800 M
  where seconds move 7-20 % by the hour (memory layout alone moves it ~0.3 %): the judge of a change to the
  model of a per cent or more, back to back with the commit before.
"""


def _budget(f: dict) -> str:
    """What the target leaves the simulation once the harness has taken its share."""
    budget = FLOOR_TARGET * f["floor_wall_s"]
    if f["rest_over_floor"] >= FLOOR_TARGET - 0.05:
        return (f"At {FLOOR_TARGET:g}x the floor the whole run may take {budget:.1f} s, and the rest alone takes "
                f"{f['rest_over_floor']:.1f}x: the target needs the harness cut as well as the simulation.")
    return (f"At {FLOOR_TARGET:g}x the floor the whole run may take {budget:.1f} s: with the rest as it is, "
            f"{budget - f['rest_s']:.1f} s are left for the simulation.")


def _advances_section(row: dict) -> list[str]:
    """Where the simulation goes, advance by advance (bench/advances_bench.py): per profile, the wall seconds in
    advances by kind, and what stopped bulk advance in the long ones it could not shorten."""
    f = row["figures"]
    profiles = [k[:-len(".wall_s")] for k in f if k.count(".") == 1 and k.endswith(".wall_s")]
    out = [f"Where the simulation goes, advance by advance (`bench/advances_bench.py`, {_when(row)}, {row['commit']}): "
           "per profile in one process, the wall seconds spent in advances shorter than a second (simulated as "
           "they are), in longer ones bulk advance shortened, and in longer ones it could not; then the largest "
           "reasons it gave up, as it last looked (the state still changing, and where).", ""]
    table_rows = []
    for p in profiles:
        kinds = []
        for kind in ("shorter than 1 s", "1 s or more, some skipped", "1 s or more, nothing skipped"):
            wall = sum(v for k, v in f.items() if k.startswith(p + ".") and k.endswith(f".{kind}.wall_s"))
            simulated = sum(v for k, v in f.items() if k.startswith(p + ".") and k.endswith(f".{kind}.simulated_s"))
            kinds.append(f"{wall:.1f} s ({simulated:,.0f} s simulated)")
        why = sorted(((k.split(".why.", 1)[1], v) for k, v in f.items() if k.startswith(p + ".why.")),
                     key=lambda kv: -kv[1])[:3]
        table_rows.append([p, f"{f[p + '.wall_s']:.1f} s", *kinds,
                           "; ".join(f"{reason} {v:.1f} s" for reason, v in why) or "-"])
    out += _table(["profile", "run", "advances < 1 s", ">= 1 s, some skipped", ">= 1 s, nothing skipped",
                   "what stopped bulk advance (wall)"], table_rows)
    return out + [""]


def render_markdown(rows: list[dict]) -> str:
    lines = ["# Performance: today's figures, the targets, the history", "",
             "Generated by `make performance` (`python -m bench.report`) from `bench/history.jsonl`, one row per",
             "measurement, and `bench/performance-notes.md`; edit those, not this page. Times are UTC; a commit",
             "followed by `+` was measured with uncommitted changes on top; load is the 1-minute load average before",
             "-> after the run (2 cores).", ""]
    suite = _latest(rows, "suite_bench", "ratio_wall", _full_suite)
    rss = _latest(rows, "suite_bench", "conformance_rss_mb", _full_suite)
    test = _latest(rows, "make_test", "wall_s")
    report = _latest(rows, "make_report", "wall_s")
    mapped = _latest(rows, "make_mutate", "map_s")
    fig = lambda row, key: None if row is None else row["figures"].get(key)          # noqa: E731

    lines += ["## Today against the targets (issue 33)", ""]
    target_rows = [
        ["conformance run / its floor, one process", f"<= {FLOOR_TARGET:g}x (the long-run goal {FLOOR_GOAL:g}x)",
         "-" if suite is None else f"{fig(suite, 'ratio_wall'):.1f}x ({fig(suite, 'conformance_wall_s'):.1f} s against "
                                   f"{fig(suite, 'floor_wall_s'):.2f} s"
                                   + (f"; CPU {fig(suite, 'ratio_cpu'):.1f}x" if fig(suite, "ratio_cpu") else "") + ")",
         _verdict(fig(suite, "ratio_wall"), FLOOR_TARGET), _measured(suite)],
        ["`make test`, clean clone, 2 cores", f"<= {_dur(TEST_TARGET_S)}",
         "-" if test is None else _dur(fig(test, "wall_s")), _verdict(fig(test, "wall_s"), TEST_TARGET_S),
         _measured(test)],
        ["`make report`", f"<= {_dur(REPORT_TARGET_S)}", "-" if report is None else _dur(fig(report, "wall_s")),
         _verdict(fig(report, "wall_s"), REPORT_TARGET_S), _measured(report)],
        ["`make mutate`, the first map", f"<= {_dur(MAP_TARGET_S)}",
         "-" if mapped is None else _dur(fig(mapped, "map_s")),
         _verdict(fig(mapped, "map_s"), MAP_TARGET_S), _measured(mapped)],
        ["peak RSS of the conformance run, one process", "bounded (issue 33, item 4; no figure set)",
         "-" if rss is None else f"{fig(rss, 'conformance_rss_mb'):.0f} MB"
                                 + (f" (floor {fig(rss, 'floor_rss_mb'):.0f} MB)" if fig(rss, "floor_rss_mb") else ""),
         "-", _measured(rss)],
    ]
    lines += _table(["what", "target", "latest", "status", "measured (UTC, commit, load)"], target_rows)
    lines += ["", "Each figure is the latest row of its kind: the whole suite against the reference for the ratio "
              "and the peak RSS; `make test` on a clean clone. Rows of one sitting compare; rows of different hours "
              "differ by the machine too.", ""]

    lines += ["## What the remaining gap is made of", ""]
    if suite is not None and "kernel_run_s" in suite["figures"]:
        f = suite["figures"]
        share = f["kernel_run_s"] / f["conformance_wall_s"]
        lines += [f"From the latest whole-suite `bench/suite_bench.py` row ({_when(suite)}): of the conformance run's "
                  f"{f['conformance_wall_s']:.1f} s, {f['kernel_run_s']:.1f} s ({share:.0%}) are inside `Kernel.run`, "
                  f"the simulation proper; the rest, {f['rest_s']:.1f} s, is {f['rest_over_floor']:.1f}x the floor's "
                  f"{f['floor_wall_s']:.2f} s: the steps, trace queries, the snapshot journal, bulk's state reads and "
                  "pytest-bdd itself. "
                  + _budget(f), ""]
    own = _latest(rows, "make_test", "own_cpu_s")
    if own is not None:
        f = own["figures"]
        largest = sorted(((k[4:-2].replace("_", " "), v) for k, v in f.items()
                          if k.startswith("own_") and k.endswith("_s") and k not in ("own_cpu_s", "own_tests_s")),
                         key=lambda kv: -kv[1])
        lines += [f"`make test` ({_when(own)}, clean clone): the own tests took {_dur(f['own_tests_s'])} on two "
                  f"workers, {f['own_cpu_s']:.0f} s of tests in all; the largest, by test function: "
                  + "; ".join(f"{name} {seconds:.0f} s ({seconds / f['own_cpu_s']:.0%})" for name, seconds in largest)
                  + f". Then the conformance run, {f.get('conformance_s', 0):.0f} s.", ""]
    events = _latest(rows, "events_bench", "all.events")
    if events is not None:
        f = events["figures"]
        profiles = [k[:-len(".events")] for k in f if k.endswith(".events") and not k.startswith("all.")]
        lines += [f"The simulation's work, from the latest `bench/events_bench.py` row ({_when(events)}): "
                  f"{f['all.events'] / 1e6:.2f} M kernel events in all, after snapshots and bulk advance have taken "
                  "out all they can.", ""]
        ev_rows = []
        for p in profiles:
            kinds = sorted(((k.split(".kind.", 1)[1], v) for k, v in f.items() if k.startswith(p + ".kind.")),
                           key=lambda kv: -kv[1])
            scen = f.get(f"{p}.scenarios")
            ev_rows.append([p + (f" ({scen} scenarios)" if scen else ""), f"{f[p + '.events'] / 1e6:.2f} M",
                            ", ".join(f"{k} {v / 1e6:.2f} M" for k, v in kinds)])
        lines += _table(["profile", "kernel events", "the largest kinds"], ev_rows)
        lines += [""]
        # a cost per event only from a suite_bench row of the same commit: the suite changes from one to the next
        same = _latest(rows, "suite_bench", "kernel_run_s",
                       lambda r: _full_suite(r) and r.get("commit") == events.get("commit") and events.get("commit"))
        per = "" if same is None else (
            f"At the {_when(same)} run's time inside `Kernel.run` (the same commit), that is "
            f"~{same['figures']['kernel_run_s'] / f['all.events'] * 1e6:.1f} us per event. ")
        lines += [per + "Of issue 33's remodel, a trace that holds repeated stretches as patterns and a cruising CRH2 "
                  "train that is steady (its mileage integrated exactly) are in; the events that are the same every "
                  "round in a steady state (a ring traversal, an HDLC round, an MVB basic period as one event each, "
                  "their trace computed) are not.", ""]

    advances = _latest(rows, "advances_bench", None, lambda r: not r.get("args"))
    if advances is not None:
        lines += _advances_section(advances)

    if NOTES.exists():
        lines += [NOTES.read_text(encoding="utf-8").rstrip(), ""]
    lines += ["## The history", "", "![The benchmark history: the targets' figures over time](performance.svg)", "",
              "The plot is `docs/performance.svg`, drawn by `make performance`; each panel's dashed line is its "
              "target.", ""]
    history = [
        ("Conformance run against its floor (`bench/suite_bench.py`, the whole suite, one process each)",
         _rows(rows, "suite_bench", "ratio_wall", _full_suite),
         ["when", "commit", "load", "scenarios", "conformance", "floor", "ratio", "inside Kernel.run", "the rest",
          "peak RSS", "what changed"],
         lambda r, f: [_when(r), _commit(r), _load(r), str(f.get("scenarios", "-")), f"{f['conformance_wall_s']:.1f} s",
                       f"{f['floor_wall_s']:.2f} s", f"{f['ratio_wall']:.1f}x",
                       f"{f['kernel_run_s']:.1f} s" if "kernel_run_s" in f else "-",
                       f"{f['rest_s']:.1f} s" if "rest_s" in f else "-",
                       f"{f['conformance_rss_mb']:.0f} MB" if "conformance_rss_mb" in f else "-", r.get("note", "")]),
        ("`make test` on a clean clone (`.ci/run`, or `bench/make_bench.py test --clone`)",
         _rows(rows, "make_test", "wall_s"),
         ["when", "commit", "load", "make test", "own tests", "conformance run", "what changed"],
         lambda r, f: [_when(r), _commit(r), _load(r), _dur(f["wall_s"]),
                       (_dur(f["own_tests_s"]) if "own_tests_s" in f else "-")
                       + (f" ({f['own_tests_passed']})" if "own_tests_passed" in f else ""),
                       (_dur(f["conformance_s"]) if "conformance_s" in f else "-")
                       + (f" ({f['conformance_passed']})" if "conformance_passed" in f else ""), r.get("note", "")]),
        ("`make report`", _rows(rows, "make_report", "wall_s"),
         ["when", "commit", "load", "make report", "scenarios passed", "what changed"],
         lambda r, f: [_when(r), _commit(r), _load(r), _dur(f["wall_s"]), str(f.get("conformance_passed", "-")),
                       r.get("note", "")]),
        ("`make mutate`: the map of who reaches what", _rows(rows, "make_mutate", "map_s"),
         ["when", "commit", "load", "map", "what"],
         lambda r, f: [_when(r), _commit(r), _load(r), _dur(f["map_s"]), r.get("note", "")]),
    ]
    for title, found, headers, cells in history:
        if found:
            lines += [f"### {title}", ""] + _table(headers, [cells(r, r["figures"]) for r in found]) + [""]

    lines += ["## The latest row of each bench", ""]
    latest = sorted({r["bench"] for r in rows})
    lines += _table(["bench", "measured (UTC, commit, load)", "options", "figures"],
                    [[b, _measured(r := _latest(rows, b)), " ".join(r.get("args") or []) or "defaults", headline(r)]
                     for b in latest])
    lines += ["", "A row read back from older prose says where in its `source` field (the bench docstrings and the "
              "README held these figures before the history did).", "", HOW_TO_MEASURE.rstrip(), ""]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--history", type=Path, default=HISTORY, help="the rows (default bench/history.jsonl)")
    ap.add_argument("--md", type=Path, default=PAGE, help="the page to write (default docs/performance.md)")
    ap.add_argument("--svg", type=Path, default=PLOT, help="the plot to write (default docs/performance.svg)")
    ap.add_argument("--no-plot", action="store_true", help="the page only (no matplotlib needed)")
    args = ap.parse_args(argv)
    rows = read(args.history)
    if not rows:
        print(f"no rows in {args.history}: run a bench script with --record first", file=sys.stderr)
        return 1
    args.md.write_text(render_markdown(rows), encoding="utf-8")
    print(f"{args.md}: {len(rows)} rows")
    if not args.no_plot:
        try:
            plot(rows, args.svg)
        except ImportError:
            print("matplotlib is not installed: .venv/bin/pip install -e '.[bench]' (make performance does), or "
                  "--no-plot", file=sys.stderr)
            return 1
        print(f"{args.svg}: series sha256 {digest(rows)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
