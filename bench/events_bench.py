"""The conformance run's event budget: how many kernel callbacks each profile runs, and of which kind.

    PYTHONPATH=. .venv/bin/python bench/events_bench.py                  # every profile, one process each
    PYTHONPATH=. .venv/bin/python bench/events_bench.py --profile atp    # one
    PYTHONPATH=. .venv/bin/python bench/events_bench.py -- --item F-NET-31   # arguments for pytest after --

Runs `pytest features --profile P` in one process (snapshots and bulk advance as in any run) with
bench/_events_plugin.py counting every callback `Kernel.run` makes, by the function it calls (a cyclic
activity by its tick). Prints per profile the events, the wall seconds of the run, and the largest kinds:
what the simulation must still do once snapshots and bulk advance have taken out all they can, which bounds
how close to its floor the conformance run can come (README, "Speed").
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _history  # noqa: E402
from _plugin_run import run_profile  # noqa: E402
from _table import table  # noqa: E402

PROFILES = ("crh2", "metro-tcn", "atp", "vdx", "atp-crh2")


def count(profile: str, extra: list[str]) -> tuple[dict, float, str]:
    return run_profile("_events_plugin", "EVENTS_PLUGIN_OUT", profile, extra)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--profile", action="append", choices=PROFILES,
                        help="a profile to count (again for more; default: all three)")
    parser.add_argument("--top", type=int, default=8, help="kinds listed per profile (default 8)")
    parser.add_argument("--plain", action="store_true", help="plain text tables, no rich")
    parser.add_argument("pytest_args", nargs="*", help="after --: passed to pytest")
    _history.add_argument(parser)
    args = parser.parse_args(argv)
    rows, total = [], 0
    load_before = _history.load()
    figures: dict[str, float] = {}          # the history's row: per profile, its events and its largest kinds
    for profile in args.profile or PROFILES:
        kinds, wall, summary = count(profile, args.pytest_args)
        events = sum(kinds.values())
        total += events
        largest = sorted(kinds.items(), key=lambda kv: -kv[1])[:args.top]
        rows.append((profile, f"{events / 1e6:.2f} M", f"{wall:.1f} s", summary,
                     ", ".join(f"{name} {n / 1e6:.2f} M" for name, n in largest)))
        figures |= {f"{profile}.events": events, f"{profile}.wall_s": wall,
                    **{f"{profile}.kind.{name}": n for name, n in largest}}
    table("Kernel events per profile (one process each)", ("profile", "events", "wall", "pytest", "largest kinds"),
          rows, plain=args.plain, notes=[f"all profiles: {total / 1e6:.2f} M events"])
    figures["all.events"] = total
    _history.record(args, "events_bench", figures, load_before=load_before, load_after=_history.load(),
                    selection=None if argv is None else _history.measured_options(argv))


if __name__ == "__main__":
    main()
