"""Where the conformance run's simulation goes, advance by advance, and why bulk advance left a long one whole.

    PYTHONPATH=. .venv/bin/python bench/advances_bench.py                   # every profile, one process each
    PYTHONPATH=. .venv/bin/python bench/advances_bench.py --profile crh2    # one
    PYTHONPATH=. .venv/bin/python bench/advances_bench.py -- --item F-MIL-01  # arguments for pytest after --

Runs `pytest features --profile P` in one process (snapshots and bulk advance as in any run) with
bench/_advances_plugin.py watching every `bulk.advance` of the reference models. Prints per profile and model the
advances shorter than bulk.BULK_MIN_US (simulated as they are), the longer ones that skipped some periods and those
that skipped nothing: how many, the simulated and skipped seconds, the wall seconds and the wall per simulated
second. Then, for the long advances that skipped nothing, what stopped bulk advance the last time it looked:
the state still changing (and where: the first leaf that differs), an integer that moved unevenly, the two
periods' traces not one pattern, an advance too short for three periods. That is what issue 33's remodel has
to make cheaper or steady: a ramp or a cruising train, the seconds after a fault, a power-up still settling.
The plugin reads a train again whole where a read stopped early, to say where it differs: wall figures are a
little above a plain run's.
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
KINDS = ("shorter than 1 s", "1 s or more, some skipped", "1 s or more, nothing skipped")


def watch(profile: str, extra: list[str]) -> tuple[dict, float, str]:
    return run_profile("_advances_plugin", "ADVANCES_PLUGIN_OUT", profile, extra)


def _per_sim_s(wall: float, simulated_us: int) -> str:
    return f"{1000 * wall / (simulated_us / 1e6):.1f} ms" if simulated_us else "-"


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--profile", action="append", choices=PROFILES,
                        help="a profile to watch (again for more; default: all)")
    parser.add_argument("--top", type=int, default=6, help="reasons listed per profile (default 6)")
    parser.add_argument("--plain", action="store_true", help="plain text tables, no rich")
    parser.add_argument("pytest_args", nargs="*", help="after --: passed to pytest")
    _history.add_argument(parser)
    args = parser.parse_args(argv)
    load_before = _history.load()
    kind_rows, why_rows, figures = [], [], {}
    for profile in args.profile or PROFILES:
        seen, wall, summary = watch(profile, args.pytest_args)
        figures[f"{profile}.wall_s"] = wall
        in_advances = 0.0
        for model, kind, n, secs, simulated, skipped in sorted(seen["kinds"], key=lambda r: (r[0], KINDS.index(r[1]))):
            in_advances += secs
            kind_rows.append((profile, model, kind, str(n), f"{simulated / 1e6:,.1f} s", f"{skipped / 1e6:,.1f} s",
                              f"{secs:.2f} s", _per_sim_s(secs, simulated)))
            figures |= {f"{profile}.{model}.{kind}.wall_s": secs, f"{profile}.{model}.{kind}.simulated_s":
                        simulated / 1e6, f"{profile}.{model}.{kind}.advances": n}
        figures[f"{profile}.in_advances_s"] = in_advances
        kind_rows.append((profile, "", f"in advances {in_advances:.1f} s of the run's {wall:.1f} s", "", "", "", "",
                          summary))
        for model, reason, n, secs, simulated, example, scenario in sorted(seen["why"], key=lambda r: -r[3])[:args.top]:
            why_rows.append((profile, model, reason + (f" (e.g. {example})" if example else ""), str(n),
                             f"{simulated / 1e6:,.1f} s", f"{secs:.2f} s", scenario))
            figures[f"{profile}.why.{model}: {reason}"] = secs
    table("Advances per profile and model (one process each)",
          ("profile", "model", "advances", "n", "simulated", "skipped", "wall", "wall per simulated s"),
          kind_rows, plain=args.plain)
    table("Long advances that skipped nothing: what stopped bulk advance the last time it looked",
          ("profile", "model", "reason", "n", "simulated", "wall", "first seen in"), why_rows, plain=args.plain)
    _history.record(args, "advances_bench", figures, load_before=load_before, load_after=_history.load(),
                    selection=None if argv is None else _history.measured_options(argv))


if __name__ == "__main__":
    main()
