"""Run environment (SUT backend, profile, timing parameters) for the Allure report.

Allure 3 (3.18.0) still reads the Allure 2 `environment.properties` file from the results directory; the
awesome report shows it as the "Environment" block on the overview page. pytest-xdist workers and several
scenarios may each call `write_environment`, so values are merged under a file lock: a key that took
several values in one run (one set and two coupled sets) lists each once, " | "-separated, first seen first.
Keys are the caller's: the step library prefixes a SUT's with its profile (`[crh2] SUT class`) and the run's
own facts with `[run]` (steps/report.py), so three trains in one run are three groups, not one list.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator, Mapping
from pathlib import Path

FILE_NAME = "environment.properties"
_SEP = " | "

try:
    import fcntl
except ImportError:  # pragma: no cover - not POSIX: no cross-process lock, merges may race
    fcntl = None


def _escape(text: str, is_key: bool) -> str:
    out = []
    for ch in text:
        if ch == "\\":
            out.append("\\\\")
        elif ch == "\n":
            out.append("\\n")
        elif ch in "=:#!" or (is_key and ch == " "):
            out.append("\\" + ch)
        elif ord(ch) > 0x7E or ord(ch) < 0x20:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out)


def _unescape(text: str) -> str:
    out, i = [], 0
    while i < len(text):
        ch = text[i]
        if ch == "\\" and i + 1 < len(text):
            nxt = text[i + 1]
            if nxt == "u" and i + 6 <= len(text):
                out.append(chr(int(text[i + 2 : i + 6], 16)))
                i += 6
                continue
            out.append({"n": "\n", "t": "\t"}.get(nxt, nxt))
            i += 2
            continue
        out.append(ch)
        i += 1
    return "".join(out)


def read_environment(results_dir: str | os.PathLike) -> dict[str, str]:
    """The mapping a previous write_environment left (only the simple `key=value` lines it writes)."""
    path = Path(results_dir) / FILE_NAME
    if not path.is_file():
        return {}
    found: dict[str, str] = {}
    for line in path.read_text(encoding="ascii").splitlines():
        if not line or line[0] in "#!":
            continue
        i = 0
        while i < len(line) and line[i] != "=":
            i += 2 if line[i] == "\\" else 1  # skip the escaped character: it cannot be the separator
        found[_unescape(line[:i])] = _unescape(line[i + 1 :])
    return found


@contextlib.contextmanager
def _locked(directory: Path) -> Iterator[None]:
    if fcntl is None:
        yield
        return
    with open(directory / f".{FILE_NAME}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def write_environment(results_dir: str | os.PathLike | None, mapping: Mapping[str, object]) -> Path | None:
    """Merge `mapping` into `<results_dir>/environment.properties`; return its path.

    `results_dir` is pytest's `--alluredir` (`request.config.option.allure_report_dir`); None (no report
    requested) does nothing and returns None. Values are str()-ed; None values are skipped. Keys are sorted in
    the file so reruns give identical files.
    """
    if not results_dir:
        return None
    directory = Path(results_dir)
    directory.mkdir(parents=True, exist_ok=True)
    with _locked(directory):
        current = read_environment(directory)
        for key, value in mapping.items():
            if value is None:
                continue
            # A value holding the separator would never be found among the merged ones again (it was
            # appended once per scenario: the same MVB line ~60 times).
            value = str(value).replace(_SEP, " / ")
            old = current.get(str(key))
            if old is None:
                current[str(key)] = value
            elif value not in old.split(_SEP):
                current[str(key)] = old + _SEP + value
        text = "".join(f"{_escape(k, True)}={_escape(v, False)}\n" for k, v in sorted(current.items()))
        tmp = directory / f".{FILE_NAME}.{os.getpid()}.tmp"
        tmp.write_text(text, encoding="ascii")
        os.replace(tmp, directory / FILE_NAME)  # readers never see a half-written file
    return directory / FILE_NAME
