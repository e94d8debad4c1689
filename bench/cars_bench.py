"""One workload on an 8-car train and on a 16-car train (two 8-car sets coupled), through the driver only.

    PYTHONPATH=. .venv/bin/python bench/cars_bench.py [--sim-seconds 10] [--repeat 3] [--sut reference]
                                                      [--cars-per-set 8] [--mem-seconds 5] [--plain]

Workload, the same for both compositions, through `sut.backends.open_backend(SUT, "crh2")` and nothing else
(the power-up sequence of the features' Background, steps/train.py and steps/desk.py):
    configure(sets=1 or 2, cars_per_set=8); insert_key(1); set_direction(1, "forward"); power_on();
    advance_ms(1000); set_traction(1, 7); then the measured part: advance(--sim-seconds).
After one unmeasured power-up of each (imports, first-use caches), the two compositions run alternately,
--repeat times; each keeps its best wall time (and the CPU time of that run: process_time, steadier on a
shared machine).

Printed per composition: ring nodes, power-up cost (open to notch 7 after 1 s), wall seconds per simulated
second of the measured part, trace events per simulated second (`len(driver.trace)`: the driver's count of
observable events), trace events per wall second, and the ratios 16-car / 8-car against the target
(<= 2.2x wall per simulated second, issue 9). Also the trace kinds that grow the most, which tells whether a
ratio comes from more work (events) or from dearer events.
Labelled "internal" (reference only, read from `driver.train.kernel.events`, not the driver interface):
kernel callbacks per simulated second. With --mem-seconds N > 0, peak traced memory (tracemalloc, a
separate run of N simulated seconds, never the timed one) per composition.

With --record the figures go to bench/history.jsonl as one row (docs/performance.md, `make performance`).
"""
from __future__ import annotations

import argparse
import gc
import os
import sys
import time
import tracemalloc
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

BENCH = Path(__file__).resolve().parent
sys.path.insert(0, str(BENCH))
sys.path.insert(0, str(BENCH.parent))

import _history  # noqa: E402
from _table import table, text  # noqa: E402
from sut.backends import open_backend  # noqa: E402

TARGET = 2.2            # issue 9: 16 cars <= 2.2x 8 cars
S = 1_000_000


@dataclass
class Result:
    label: str
    sets: int
    nodes: int = 0
    setup_wall: float = float("inf")
    wall: float = float("inf")          # best wall of the measured advance
    cpu: float = 0.0                    # CPU of that best run
    sim_us: int = 0
    trace_events: int = 0               # during the measured advance
    kernel_events: int | None = None    # internal: driver.train.kernel.events during the measured advance
    kinds: Counter = field(default_factory=Counter)
    mem_base: int = 0
    mem_peak: int = 0

    @property
    def wall_per_sim_s(self) -> float:
        return self.wall / (self.sim_us / S)

    @property
    def cpu_per_sim_s(self) -> float:
        return self.cpu / (self.sim_us / S)

    @property
    def trace_per_sim_s(self) -> float:
        return self.trace_events / (self.sim_us / S)


def _kernel_events(driver) -> int | None:
    """Internal (reference only): kernel callbacks run so far."""
    try:
        return int(driver.train.kernel.events)
    except AttributeError:
        return None


def powered(sut: str, sets: int, cars_per_set: int):
    driver = open_backend(sut, "crh2")
    driver.configure(sets=sets, cars_per_set=cars_per_set)
    driver.insert_key(1)
    driver.set_direction(1, "forward")
    driver.power_on()
    driver.advance_ms(1000)
    driver.set_traction(1, 7)
    return driver


def run_once(res: Result, sut: str, cars_per_set: int, sim_us: int, kinds: bool) -> None:
    gc.collect()
    t0 = time.perf_counter()
    driver = powered(sut, res.sets, cars_per_set)
    setup = time.perf_counter() - t0
    try:
        res.nodes = len(driver.ring_nodes())
        n0, k0 = len(driver.trace), _kernel_events(driver)
        gc.collect()
        c0, t0 = time.process_time(), time.perf_counter()
        driver.advance(sim_us)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        res.setup_wall = min(res.setup_wall, setup)
        if wall < res.wall:
            res.wall, res.cpu, res.sim_us = wall, cpu, sim_us
            res.trace_events = len(driver.trace) - n0
            k1 = _kernel_events(driver)
            res.kernel_events = None if k0 is None or k1 is None else k1 - k0
            if kinds:
                res.kinds = Counter(ev.kind for ev in driver.trace[n0:])
    finally:
        driver.shutdown()


def mem_run(res: Result, sut: str, cars_per_set: int, sim_us: int) -> None:
    gc.collect()
    tracemalloc.start()
    try:
        driver = powered(sut, res.sets, cars_per_set)
        res.mem_base = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        driver.advance(sim_us)
        res.mem_peak = tracemalloc.get_traced_memory()[1]
        driver.shutdown()
    finally:
        tracemalloc.stop()


def main(argv: list[str] | None = None) -> int:
    # Simulation speed is measured frame by frame: a plain advance of the reference would skip steady
    # periods (sut/reference/bulk.py); the variable reaches a remote server started from here too.
    os.environ["CRH2_FRAME_BY_FRAME"] = "1"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sim-seconds", type=float, default=10.0,
                    help="simulated seconds of the measured advance (default 10)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per composition, alternating; best kept (default 3)")
    ap.add_argument("--sut", default="reference", help="backend spec for open_backend (default reference)")
    ap.add_argument("--cars-per-set", type=int, default=8, help="cars per set (default 8: 8 vs 16 cars)")
    ap.add_argument("--mem-seconds", type=float, default=5.0,
                    help="simulated seconds of the separate tracemalloc run per composition, 0 to skip (default 5)")
    ap.add_argument("--plain", action="store_true", help="plain text output even if rich is installed")
    _history.add_argument(ap)
    args = ap.parse_args(argv)
    if args.repeat < 1 or args.sim_seconds <= 0:
        ap.error("--repeat must be >= 1 and --sim-seconds > 0")
    sim_us = round(args.sim_seconds * S)
    n = args.cars_per_set
    one, two = Result(f"{n} cars (1 set)", 1), Result(f"{2 * n} cars (2 sets coupled)", 2)
    load0 = os.getloadavg()
    for res in (one, two):              # warm-up: lazy imports and first-use caches are not the model's cost
        powered(args.sut, res.sets, n).shutdown()
    for rep in range(args.repeat):
        for res in (one, two):
            run_once(res, args.sut, n, sim_us, kinds=rep == 0)
    if args.mem_seconds > 0:
        for res in (one, two):
            mem_run(res, args.sut, n, round(args.mem_seconds * S))
    load1 = os.getloadavg()

    def ratio(a: float | None, b: float | None) -> str:
        return f"{a / b:.2f}x" if a is not None and b else "-"

    rows = []
    for r in (one, two):
        rows.append([r.label, str(r.nodes), f"{r.setup_wall:.3f}", f"{r.wall:.3f}", f"{r.wall_per_sim_s:.3f}",
                     f"{r.cpu_per_sim_s:.3f}", f"{r.trace_per_sim_s:,.0f}", f"{r.trace_events / r.wall:,.0f}",
                     "-" if r.kernel_events is None else f"{r.kernel_events / (r.sim_us / S):,.0f}",
                     f"{r.mem_peak / 1e6:.1f}" if r.mem_peak else "-"])
    rows.append([f"ratio {2 * n}/{n}", ratio(two.nodes, one.nodes), ratio(two.setup_wall, one.setup_wall), "",
                 ratio(two.wall_per_sim_s, one.wall_per_sim_s), ratio(two.cpu_per_sim_s, one.cpu_per_sim_s),
                 ratio(two.trace_per_sim_s, one.trace_per_sim_s),
                 ratio(two.trace_events / two.wall, one.trace_events / one.wall),
                 ratio(two.kernel_events, one.kernel_events), ratio(two.mem_peak or None, one.mem_peak or None)])
    r = two.wall_per_sim_s / one.wall_per_sim_s
    per_event = (two.wall / max(two.trace_events, 1)) / (one.wall / max(one.trace_events, 1))
    table(f"8 vs 16 cars: {args.sim_seconds:g} s simulated after power-up, traction notch 7, best of {args.repeat} "
          f"(sut {args.sut})",
          ["composition", "ring nodes", "power-up s", "wall s", "wall s / sim s", "CPU s / sim s",
           "trace ev / sim s", "trace ev / wall s", "kernel ev / sim s (internal)", "peak MB (tracemalloc)"],
          rows, plain=args.plain,
          notes=[f"target: 16 cars <= {TARGET}x 8 cars (wall per simulated second) -> {r:.2f}x, "
                 f"{'met' if r <= TARGET else 'MISSED'} (CPU {two.cpu_per_sim_s / one.cpu_per_sim_s:.2f}x)",
                 f"work vs cost: trace events per simulated second {two.trace_per_sim_s / one.trace_per_sim_s:.2f}x, "
                 f"wall per trace event {per_event:.2f}x",
                 "power-up s: open, configure, key, direction, power on, 1 s, notch 7 (best over the runs)",
                 (f"peak MB: tracemalloc over {args.mem_seconds:g} s simulated in a separate run (the trace is kept); "
                  if args.mem_seconds > 0 else "peak MB: skipped (--mem-seconds 0); ")
                 + "kernel ev: driver.train.kernel.events, reference internals",
                 f"load (1/5/15 min) {' '.join(f'{x:.2f}' for x in load0)} at start, "
                 f"{' '.join(f'{x:.2f}' for x in load1)} at end; {os.cpu_count()} cores"])
    if one.kinds and two.kinds:
        sim_s = args.sim_seconds
        growth = sorted(set(one.kinds) | set(two.kinds),
                        key=lambda k: -(two.kinds.get(k, 0) - one.kinds.get(k, 0)))[:8]
        table("Trace kinds that grow the most (events per simulated second)",
              ["kind", f"{n} cars", f"{2 * n} cars", "ratio", "share of the increase"],
              [[k, f"{one.kinds.get(k, 0) / sim_s:,.0f}", f"{two.kinds.get(k, 0) / sim_s:,.0f}",
                ratio(two.kinds.get(k, 0), one.kinds.get(k, 0) or None),
                f"{100 * (two.kinds.get(k, 0) - one.kinds.get(k, 0)) / max(two.trace_events - one.trace_events, 1):.0f}%"]
               for k in growth], plain=args.plain)
    text("", plain=args.plain)
    figures: dict[str, float] = {"ratio_wall_per_sim_s": r,
                                 "ratio_cpu_per_sim_s": two.cpu_per_sim_s / one.cpu_per_sim_s,
                                 "ratio_trace_per_sim_s": two.trace_per_sim_s / one.trace_per_sim_s}
    for res in (one, two):
        cars = n * res.sets
        figures |= {f"cars{cars}_ring_nodes": res.nodes, f"cars{cars}_power_up_s": res.setup_wall,
                    f"cars{cars}_wall_s_per_sim_s": res.wall_per_sim_s,
                    f"cars{cars}_cpu_s_per_sim_s": res.cpu_per_sim_s,
                    f"cars{cars}_trace_events_per_sim_s": res.trace_per_sim_s,
                    f"cars{cars}_kernel_events_per_sim_s": None if res.kernel_events is None
                    else res.kernel_events / (res.sim_us / S),
                    f"cars{cars}_peak_traced_mb": res.mem_peak / 1e6 if res.mem_peak else None}
    _history.record(args, "cars_bench", figures, load_before=load0[0], load_after=load1[0],
                    selection=None if argv is None else _history.measured_options(argv))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
