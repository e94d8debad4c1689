"""Continuous power-on, 72 h of an 8-car train: bulk advance against frame-by-frame simulation.

    PYTHONPATH=. python bench/bulk_bench.py [--hours 72] [--fbf-minutes 5] [--agree-minutes 0]

Prints, from one run on this machine:
  - frame by frame: wall seconds per simulated hour (measured over --fbf-minutes, then scaled), kernel
    events and trace events per simulated hour;
  - bulk (sut/reference/bulk.py) for --hours with one steady sample every 1 h and every 3 h: wall time,
    how much was simulated and how much skipped, jumps, the trace it left, peak traced memory;
  - a reading of the whole train (bulk.snapshot, the powered set): ms per read, the best of 15 batches of 20
    (bulk advance weighs three of them against simulating; an advance shorter than BULK_MIN_US is not read);
  - with --agree-minutes N: the same N minutes both ways, and whether every leaf of the state agrees
    (tests/test_bulk.py does this for 10 min with faults on the way).
Target (issue 5): 72 h in <= 10 s of wall time.
"""
from __future__ import annotations

import argparse
import resource
import sys
import time
import tracemalloc
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))      # the project root: `tests` below
sys.path.insert(0, str(Path(__file__).resolve().parent))

import _history                                                     # noqa: E402
from sut.reference import bulk                                      # noqa: E402
from tests.test_bulk import S, frame_by_frame as exactly, powered   # noqa: E402  as the agreement tests do

HOUR = 3600 * S


def _peak_rss_mib() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024      # KiB on Linux


def frame_by_frame(minutes: float) -> tuple[float, int, int, float]:
    """Wall seconds, kernel events, trace events and MiB of peak resident memory grown, per simulated hour
    frame by frame (what a train runs at when bulk advance is refused: issue 33 saw 3.4 GB in 3 min)."""
    rss0 = _peak_rss_mib()
    train = powered()
    k0, t0 = train.train.kernel.events, len(train.train.events)
    span = round(minutes * 60 * S)
    wall = time.perf_counter()
    with exactly():                     # a plain advance would skip steady periods too (bulk.advance)
        train.advance(span)
    wall = time.perf_counter() - wall
    per_hour = HOUR / span
    return (wall * per_hour, round((train.train.kernel.events - k0) * per_hour),
            round((len(train.train.events) - t0) * per_hour), (_peak_rss_mib() - rss0) * per_hour)


def read_ms() -> tuple[float, int]:
    """Milliseconds per reading of the powered train, the best of 15 batches of 20 (a shared VM's noise only
    ever adds), and the leaves a reading holds."""
    train = powered().train
    best = float("inf")
    for _ in range(15):
        wall = time.perf_counter()
        for _ in range(20):
            leaves = len(bulk.snapshot(train).shape)
        best = min(best, (time.perf_counter() - wall) / 20)
    return best * 1000, leaves


def bulk_run(hours: float, every_h: float) -> dict:
    train = powered()
    wall = time.perf_counter()
    report = bulk.run(train.train, round(hours * HOUR), round(every_h * HOUR))
    wall = time.perf_counter() - wall
    return {"wall": wall, "report": report, "trace": len(train.train.events), "events": train.train.kernel.events}


def peak_memory(hours: float, every_h: float) -> int:
    tracemalloc.start()
    train = powered()
    bulk.run(train.train, round(hours * HOUR), round(every_h * HOUR))
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


def agree(minutes: float) -> bool:
    exact, fast = powered(), powered()
    with exactly():
        exact.advance(round(minutes * 60 * S))
    fast.soak(round(minutes * 60 * S), sample_every_us=10 * 60 * S)
    a, b = bulk.snapshot(exact.train), bulk.snapshot(fast.train)
    return a.shape == b.shape and a.ints == b.ints


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--hours", type=float, default=72.0)
    ap.add_argument("--fbf-minutes", type=float, default=5.0, help="frame-by-frame stretch to measure")
    ap.add_argument("--agree-minutes", type=float, default=0.0, help="also run this long both ways and compare")
    _history.add_argument(ap)
    args = ap.parse_args()

    load_before = _history.load()
    wall_h, events_h, trace_h, rss_h = frame_by_frame(args.fbf_minutes)
    figures: dict[str, float] = {"fbf_wall_s_per_sim_h": wall_h, "fbf_kernel_events_per_sim_h": events_h,
                                 "fbf_trace_events_per_sim_h": trace_h, "fbf_peak_rss_mib_per_sim_h": rss_h}
    print(f"frame by frame   {wall_h:8.1f} s wall per simulated hour -> {wall_h * args.hours / 3600:.2f} h for "
          f"{args.hours:g} h; {events_h:,} kernel events and {trace_h:,} trace events per simulated hour; peak "
          f"resident memory grows {rss_h:,.0f} MiB per simulated hour (the model's repeated periods are held as "
          f"patterns, sut/eventlog.py; the metronomes' events still one by one)")
    ms, leaves = read_ms()
    figures["state_read_ms"] = ms
    print(f"a reading of the train {ms:8.2f} ms ({leaves:,} leaves of shape)")
    for every in (1.0, 3.0):
        r = bulk_run(args.hours, every)
        rep = r["report"]
        print(f"bulk, sample/{every:g} h {r['wall']:6.2f} s wall for {args.hours:g} h "
              f"({wall_h * args.hours / r['wall']:,.0f}x faster); simulated {rep.simulated_us / S:,.0f} s, "
              f"skipped {rep.skipped_us / S:,.0f} s in {rep.jumps} jumps of whole {rep.period_us / S:g} s periods; "
              f"trace {r['trace']:,} events; kernel events (counted, skipped included) "
              f"{r['events'] / args.hours:,.0f} per hour")
        figures |= {f"bulk_sample_{every:g}h_wall_s": r["wall"], f"bulk_sample_{every:g}h_jumps": rep.jumps,
                    f"bulk_sample_{every:g}h_simulated_s": rep.simulated_us / S}
    peak = peak_memory(args.hours, 3.0)
    figures["bulk_sample_3h_peak_traced_mib"] = peak / 2**20
    print(f"peak traced memory, bulk {args.hours:g} h sampled every 3 h: {peak / 2**20:.0f} MiB")
    if args.agree_minutes:
        same = agree(args.agree_minutes)
        figures["agree_minutes_identical"] = int(same)
        print(f"{args.agree_minutes:g} min both ways: state {'identical' if same else 'DIFFERENT'}")
    _history.record(args, "bulk_bench", figures, load_before=load_before, load_after=_history.load())


if __name__ == "__main__":
    main()
