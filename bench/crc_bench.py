"""Throughput of our table CRC-16/ARC (`sut.codecs.arcnet.crc16_arc`) against the `crc` package.

    PYTHONPATH=. python bench/crc_bench.py [--sizes 12 240 508] [--budget 1.0]

`crc.Calculator(crc.Crc16.IBM, optimized=True)` computes CRC-16/ARC (same value; checked before timing).
Sizes: 12 bytes (a COMMAND payload), 240 (a STATUS payload), 508 (the longest ARCNET packet data).
The `crc` package without `optimized=True` (bit by bit) is timed too, as a reference point.

With --record the microseconds per frame of each, by size, go to bench/history.jsonl as one row (the earlier
ones are there: docs/performance.md, `make performance`); the table version has been ~50x faster than the crc
package with optimized=True.
"""
from __future__ import annotations

import argparse
import random
import sys
import timeit
from pathlib import Path
from typing import Callable

if __package__ in (None, ""):
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import _history  # noqa: E402
from sut.codecs.arcnet import crc16_arc  # noqa: E402


def measure(fn: Callable[[bytes], int], data: bytes, budget: float, repeat: int) -> float:
    """Best microseconds per call over `repeat` timings of about `budget / repeat` seconds each."""
    timer = timeit.Timer(lambda: fn(data))
    one = min(timer.repeat(repeat=3, number=1))
    number = max(1, int(budget / repeat / max(one, 1e-7)))
    return min(timer.repeat(repeat=repeat, number=number)) / number * 1e6


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="CRC-16/ARC throughput: our table version vs the crc package.")
    ap.add_argument("--sizes", type=int, nargs="+", default=[12, 240, 508], help="buffer sizes in bytes")
    ap.add_argument("--budget", type=float, default=1.0,
                    help="seconds of timing per (implementation, size) (default 1.0)")
    ap.add_argument("--repeat", type=int, default=5, help="timings per measurement; the best is kept")
    ap.add_argument("--no-bitwise", action="store_true", help="skip the crc package's bit-by-bit register")
    ap.add_argument("--plain", action="store_true", help="plain text output even if rich is installed")
    _history.add_argument(ap)
    args = ap.parse_args(argv)
    load_before = _history.load()

    try:
        import crc
    except ImportError:
        print("the crc package is not installed (pip install crc)", file=sys.stderr)
        return 2
    fast = crc.Calculator(crc.Crc16.IBM, optimized=True).checksum
    slow = crc.Calculator(crc.Crc16.IBM, optimized=False).checksum
    # (column label, function); the first is ours and the ratios are taken against it
    impls: list[tuple[str, Callable[[bytes], int]]] = [("table", crc16_arc), ("crc opt", fast)]
    if not args.no_bitwise:
        impls.append(("crc bitwise", slow))

    rng = random.Random(878_1)
    rows = []
    figures: dict[str, float] = {}       # the history's row: microseconds per frame of each, by size
    for size in args.sizes:
        data = bytes(rng.getrandbits(8) for _ in range(size))
        values = {name: fn(data) for name, fn in impls}
        if len(set(values.values())) != 1:
            print(f"MISMATCH on {size} bytes: {values}", file=sys.stderr)
            return 1
        us = [measure(fn, data, args.budget, args.repeat) for _name, fn in impls]
        figures |= {f"{name.replace(' ', '_')}_us_{size}b": u for (name, _fn), u in zip(impls, us)}
        figures[f"table_ns_per_byte_{size}b"] = us[0] / size * 1000
        rows.append([str(size), *(f"{u:,.2f}" for u in us), *(f"{u / us[0]:.1f}x" for u in us[1:]),
                     f"{us[0] / size * 1000:.0f}"])
    headers = ["bytes", *(f"{name} us" for name, _ in impls),
               *(f"{name} / table" for name, _ in impls[1:]), "table ns/byte"]
    title = (f"CRC-16/ARC, microseconds per frame (best of {args.repeat}; values checked equal)\n"
             "table = sut.codecs.arcnet.crc16_arc; crc opt = crc.Calculator(Crc16.IBM, optimized=True); "
             "crc bitwise = optimized=False")

    if not args.plain:
        try:
            from rich.console import Console
            from rich.table import Table
        except ImportError:
            args.plain = True
    if not args.plain:
        table = Table(title=title)
        for h in headers:
            table.add_column(h, justify="right")
        for row in rows:
            table.add_row(*row)
        console = Console()
        console.width = max(console.width, 112)
        console.print(table)
    else:
        print(title)
        widths = [max(len(x) for x in col) for col in zip(headers, *rows)]
        print("  ".join(h.rjust(w) for h, w in zip(headers, widths)))
        for row in rows:
            print("  ".join(c.rjust(w) for c, w in zip(row, widths)))
    _history.record(args, "crc_bench", figures, load_before=load_before, load_after=_history.load(),
                    selection=None if argv is None else _history.measured_options(argv))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
