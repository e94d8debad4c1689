"""python -m sut.contract check|update RECORD... | render: hold a run's record (pytest features --contract-record
RECORD) against the catalogue, refresh the catalogue's read_by lists from it (prune: also drop what no step of
the run read), or write docs/implementing-a-sut.md from the catalogue and the declaration form."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sut.contract.record import merge, problems, prune, update


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m sut.contract", description=__doc__)
    parser.add_argument("command", choices=("check", "update", "prune", "render"))
    parser.add_argument("record", nargs="*", type=Path, help="the --contract-record FILE of a run (FILE.<worker> too)")
    parser.add_argument("--profile", action="append", default=[], help="only these profiles (default: all recorded)")
    parser.add_argument("--partial", action="store_true",
                        help="the record is of part of the suite (some items, another SUT): entries no step read are "
                             "expected; say how many, fail on nothing (the guard already stopped any read outside)")
    args = parser.parse_args(argv)
    if args.command == "render":
        from sut.contract.render import write
        print(f"wrote {write()}")
        return 0
    if not args.record:
        parser.error(f"{args.command} needs the record of a run (pytest features --contract-record FILE)")
    record = merge(args.record)
    if not record:
        print(f"no record found at {', '.join(map(str, args.record))}", file=sys.stderr)
        return 2
    profiles = args.profile or sorted(record)
    if args.command in ("update", "prune"):
        for profile in profiles:
            print(f"{args.command}d {(update if args.command == 'update' else prune)(record, profile)}")
        return 0
    found = problems(record, profiles)
    if args.partial:
        print(f"contract: a partial run; {len(found)} catalogue entries of {', '.join(profiles)} not exercised by it")
        return 0
    for line in found:
        print(line)
    print(f"contract: {len(found)} problem(s) in {', '.join(profiles)}" if found
          else f"contract: catalogue and steps agree ({', '.join(profiles)})")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
