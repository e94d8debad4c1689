"""Small tables for the bench scripts: rich if it is installed (and not --plain), plain aligned text otherwise."""
from __future__ import annotations

from collections.abc import Sequence


def _console(plain: bool):
    if plain:
        return None
    try:
        from rich.console import Console
    except ImportError:
        return None
    console = Console()
    console.width = max(console.width, 120)      # the tables are unreadable when squeezed to 80 columns
    return console


def table(title: str, headers: Sequence[str], rows: Sequence[Sequence[object]], *, plain: bool = False,
          left: int = 1, notes: Sequence[str] = ()) -> None:
    """Print one table; the first `left` columns are left-aligned, the others right-aligned."""
    cells = [[str(c) for c in row] for row in rows]
    console = _console(plain)
    if console is not None:
        from rich.table import Table

        # wide enough for the widest cell of each column (header words may wrap), up to 220 columns
        need = sum(max([len(c) for c in col] + [max(map(len, h.split()), default=0)]) + 3
                   for h, col in zip(headers, zip(*cells) if cells else [()] * len(headers))) + 1
        console.width = max(console.width, min(need, 220))
        t = Table(title=title, title_justify="left")
        for i, h in enumerate(headers):
            t.add_column(h, justify="left" if i < left else "right", overflow="fold", no_wrap=i < left)
        for row in cells:
            t.add_row(*row)
        console.print(t)
        for line in notes:
            console.print(line, highlight=False, markup=False)
        return
    print(f"\n{title}")
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *cells)] if cells else [len(h) for h in headers]
    fmt = lambda row: "  ".join(c.ljust(w) if i < left else c.rjust(w)        # noqa: E731
                                for i, (c, w) in enumerate(zip(row, widths)))
    print(fmt(list(headers)))
    print("  ".join("-" * w for w in widths))
    for row in cells:
        print(fmt(row))
    for line in notes:
        print(line)


def text(line: str = "", *, plain: bool = False) -> None:
    console = _console(plain)
    if console is not None:
        console.print(line, highlight=False, markup=False)
    else:
        print(line)
