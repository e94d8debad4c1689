"""The conformance scenarios as stimulus sequences, for the differential checker's marks its random sequences
never reach (equivalence.py): a C019 needs a release a few milliseconds before a self-test, a balise linking
error a group announced and then missed, a WTB takeover a master silent long enough. The scenarios already
arrange such things, so each one's calls that act on the train (as its snapshot journal saw them: configure,
power_on, inputs, faults, time) are recorded once (`pytest features --record-stimuli DIR`, one pickle file
per worker) and replayed here on the reference and a mutant side by side, every observable compared after
each call. A replay is a sequence of the reference's own choices: where a step chose its next call from what
the SUT showed, the mutant gets the reference's call all the same, which is still a stimulus like any other.
"""
from __future__ import annotations

import os
import pickle
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "reports" / "stimuli"


@dataclass(frozen=True)
class Recorded:
    nodeid: str
    profile: str
    calls: tuple[tuple[str, tuple, tuple], ...]   # (method, args, sorted kwargs items)
    passed: bool
    # The lines of the references it ran itself, by path: what a snapshot restored for it was run by another
    # scenario. Only an order for the probes: the reach counter decides.
    lines: dict[str, frozenset[int]] = field(default_factory=dict, compare=False)

    def covers(self, path: str, line: int) -> bool:
        return line in self.lines.get(path, ())

    @property
    def simulated_us(self) -> int:
        """How much train time the scenario asks for (its advances), to replay the cheap ones first."""
        total = 0
        for method, args, _ in self.calls:
            if method == "advance" and args:
                total += int(args[0])
            elif method == "advance_ms" and args:
                total += int(args[0]) * 1000
            elif method == "soak" and args:
                total += int(args[0])
        return total

    def actions(self) -> list[Any]:
        from .stimuli import Action
        return [Action(method, tuple(args), kwargs=tuple(kwargs)) for method, args, kwargs in self.calls]


def _worker(config: Any) -> str:
    worker = getattr(config, "workerinput", {}).get("workerid")
    return worker or "main"


class Lines:
    """Which lines of the references run while it is on (coverage.py's C tracer, which mutmut, and so `make
    equivalence`, brings; without it nothing is recorded and the replay probes cheapest first). A recording
    run takes about twice the plain run's time (169 s against 74 s on two workers, 2026-11-28)."""
    REFERENCES = ROOT / "sut" / "reference"

    def __init__(self) -> None:
        try:
            import coverage
        except ImportError:
            self._coverage = None
            return
        self._coverage = coverage.Coverage(data_file=None, include=[f"{self.REFERENCES}/*"], config_file=False)
        # a scenario whose every call a snapshot restored runs no line: nothing to warn about
        self._coverage.set_option("run:disable_warnings", ["no-data-collected"])

    def start(self) -> "Lines":
        if self._coverage is not None:
            self._coverage.start()
        return self

    def stop(self) -> dict[str, frozenset[int]]:
        if self._coverage is None:
            return {}
        self._coverage.stop()
        data = self._coverage.get_data()
        return {Path(f).relative_to(ROOT).as_posix(): frozenset(data.lines(f) or ()) for f in data.measured_files()}


def write(folder: Path, config: Any, nodeid: str, profile: str | None, stimuli: list, *, passed: bool,
          lines: dict[str, frozenset[int]] | None = None) -> None:
    """Append one scenario's stimuli to this worker's file (pickled: the arguments keep their types)."""
    folder.mkdir(parents=True, exist_ok=True)
    calls = tuple((name, tuple(args), tuple(sorted(kwargs.items()))) for name, args, kwargs in stimuli)
    with open(folder / f"{_worker(config)}.pickle", "ab") as out:
        pickle.dump(Recorded(nodeid, profile or "", calls, passed, lines or {}), out)


def _records(path: Path) -> Iterator[Recorded]:
    with open(path, "rb") as stream:
        while True:
            try:
                yield pickle.load(stream)
            except EOFError:
                return


_LOADED: dict[str, dict[str, list[Recorded]]] = {}


def load(folder: Path = CORPUS) -> dict[str, list[Recorded]]:
    """The passed scenarios recorded in `folder`, by profile, cheapest first (then by id: a fixed order)."""
    key = str(folder)
    if key not in _LOADED:
        found: dict[str, list[Recorded]] = {}
        for path in sorted(folder.glob("*.pickle")) if folder.is_dir() else ():
            for record in _records(path):
                if record.passed and record.calls:
                    found.setdefault(record.profile, []).append(record)
        _LOADED[key] = {profile: sorted(records, key=lambda r: (r.simulated_us, len(r.calls), r.nodeid))
                        for profile, records in found.items()}
    return _LOADED[key]


_RAN: dict[str, dict[str, set[int]] | None] = {}


def ran_anywhere(path: str, line: int, folder: Path = CORPUS) -> bool | None:
    """Whether any recorded scenario ran that line of the references, passed or not (the union of their
    lines is the whole conformance run's: what a snapshot restored for one was run by the one that stored
    it); None where nothing was recorded with its lines. The union is read once per folder."""
    key = str(folder)
    if key not in _RAN:
        union: dict[str, set[int]] = {}
        for file in sorted(folder.glob("*.pickle")) if folder.is_dir() else ():
            for record in _records(file):
                for where, lines in record.lines.items():
                    union.setdefault(where, set()).update(lines)
        _RAN[key] = union or None
    union = _RAN[key]
    return None if union is None else line in union.get(path, ())


def recorded(folder: Path = CORPUS) -> bool:
    return folder.is_dir() and any(folder.glob("*.pickle"))


def clear(folder: Path = CORPUS) -> None:
    for path in folder.glob("*.pickle") if folder.is_dir() else ():
        os.remove(path)
    _LOADED.pop(str(folder), None)
    _RAN.pop(str(folder), None)


def stale(folder: Path = CORPUS) -> bool:
    """No corpus, or one older than a feature file or a step module (its scenarios would be others now)."""
    files = [p for part in ("features", "steps") for p in (ROOT / part).rglob("*") if p.suffix in (".feature", ".py")]
    if not recorded(folder):
        return True
    made = min(p.stat().st_mtime for p in folder.glob("*.pickle"))
    return any(p.stat().st_mtime > made for p in files)


def main(argv: list[str] | None = None) -> int:
    import argparse
    import subprocess
    import sys
    parser = argparse.ArgumentParser(prog="python -m outline.sequences.replay", description=(
        "Record the conformance scenarios' stimuli for the differential checker's replay stage "
        f"({CORPUS.relative_to(ROOT)}): one conformance run on two workers, ~2-3 min."))
    parser.add_argument("--if-stale", action="store_true",
                        help="only if there is none, or a feature file or step module is newer than it")
    parser.add_argument("--jobs", default="2", help="pytest-xdist workers (default 2)")
    args = parser.parse_args(argv)
    if args.if_stale and not stale():
        print(f"replay: {CORPUS.relative_to(ROOT)} is up to date")
        return 0
    clear()
    command = [sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-n", args.jobs,
               "--record-stimuli", str(CORPUS), "--evidence", "failed"]
    print("replay: " + " ".join(command[2:]), flush=True)
    status = subprocess.call(command, cwd=ROOT)
    found = load()
    print(f"replay: {sum(map(len, found.values()))} scenarios recorded ("
          + ", ".join(f"{p} {len(r)}" for p, r in sorted(found.items())) + ")")
    return status


if __name__ == "__main__":
    raise SystemExit(main())
