"""The benchmark history (bench/history.jsonl): one JSON row per measurement, appended by a bench script run with
`--record`, read by `python -m bench.report` (docs/performance.md and its plot).

A row: when (UTC, ISO 8601: the run's end, to the second; a row read from prose to the minute or the day),
bench (the script's name), commit (short hash of HEAD) and dirty (the working tree had changes: the figures are
of that tree, not of the commit alone), load (the 1-minute load average before and after; null where not
known), args (what narrowed the run; [] = the bench's default, e.g. the whole suite), figures (named numbers,
units in the names: `_s`, `_mb`, `_us`, ...), note (what changed since the row before, in a few words), machine
(cores, Python) and, for a figure read back from older prose, source (where it was read). Rows are only ever
appended: a figure measured on a slower hour stays, with its load beside it.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HISTORY = ROOT / "bench" / "history.jsonl"
KEYS = ("when", "bench", "commit", "dirty", "load", "args", "figures", "note", "source", "machine")


def add_argument(parser: argparse.ArgumentParser) -> None:
    """The one `--record [FILE]` option every bench script offers."""
    parser.add_argument("--record", nargs="?", const=HISTORY, default=None, type=Path, metavar="FILE",
                        help=f"append this run's figures as a row to the history (default {HISTORY.relative_to(ROOT)})")
    parser.add_argument("--note", default="", help="with --record: what changed since the last row, in a few words")


def _git(*args: str) -> str:
    try:
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


def load() -> float:
    return round(os.getloadavg()[0], 2)


def row(bench: str, figures: dict[str, float], *, load_before: float | None, load_after: float | None,
        args: list[str] | None = None, note: str = "", when: str | None = None) -> dict:
    """A row of this machine and working tree, now."""
    numbers = {k: (round(v, 4) if isinstance(v, float) else v) for k, v in figures.items()
               if v is not None and not (isinstance(v, float) and not math.isfinite(v))}
    return {"when": when or now(), "bench": bench, "commit": _git("rev-parse", "--short", "HEAD") or None,
            # the rows of the benches recorded before this one are not a change to what is measured
            "dirty": bool(_git("status", "--porcelain", "--untracked-files=no", "--", ".",
                               ":(exclude)bench/history.jsonl")),
            "load": [None if x is None else round(x, 2) for x in (load_before, load_after)],
            "args": list(args or []), "figures": numbers, "note": note,
            "machine": {"cores": os.cpu_count(), "python": platform.python_version()}}


def append(entry: dict, path: Path | None = HISTORY) -> None:
    """One line, keys in the order of KEYS, so the file reads (and diffs) as a table."""
    path = Path(path or HISTORY)
    kept = ("commit", "load", "args")           # said even when empty: null commit, unknown load, default run
    ordered = {k: entry[k] for k in KEYS if k in entry and (entry[k] not in ("", None) or k in kept)}
    with path.open("a", encoding="utf-8") as fh:
        fh.write(json.dumps(ordered, ensure_ascii=False, separators=(", ", ": ")) + "\n")


# Options that change how a run is shown or kept, not what it measures: left out of a row's args.
_QUIET = {"--plain": 0, "--record": None, "--note": 1, "--json": 1, "--logdir": 1, "--top": 1, "--profile-out": 1}


def measured_options(argv: list[str]) -> list[str]:
    """The command line's options that decide what was measured ([] = the bench's defaults)."""
    out, i = [], 0
    while i < len(argv):
        name = argv[i].split("=", 1)[0]
        if name in _QUIET and "=" not in argv[i]:
            takes = _QUIET[name]
            i += 1 + (takes if takes is not None else int(i + 1 < len(argv) and not argv[i + 1].startswith("-")))
            continue
        if name not in _QUIET:
            out.append(argv[i])
        i += 1
    return out


def record(args: argparse.Namespace, bench: str, figures: dict[str, float], *, load_before: float | None,
           load_after: float | None, selection: list[str] | None = None) -> None:
    """What a bench script calls at its end: appends its row when it was run with --record (args: the given
    selection, else the script's command line without the options that only show or keep)."""
    if getattr(args, "record", None) is None:
        return
    if selection is None:
        selection = measured_options(sys.argv[1:])
    entry = row(bench, figures, load_before=load_before, load_after=load_after, args=selection,
                note=getattr(args, "note", ""))
    append(entry, args.record)
    print(f"recorded: {bench} at {entry['when']} ({entry['commit']}{', dirty' if entry['dirty'] else ''}) "
          f"in {args.record}")


def read(path: Path = HISTORY) -> list[dict]:
    """Every row, in the file's order (appended in time order; rows read back from prose are sorted in)."""
    if not Path(path).exists():
        return []
    return [json.loads(line) for line in Path(path).read_text(encoding="utf-8").splitlines() if line.strip()]
