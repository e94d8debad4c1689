"""Shared constants and helpers for the project's own tests."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

DATA = Path(__file__).parent / "data"
REPO = Path(__file__).resolve().parents[1]

PYTEST_INI = """\
[pytest]
pythonpath = .
bdd_features_base_dir = features/
# hypothesis and xdist are not needed in these small projects and cost ~1 s per subprocess to load.
addopts = --strict-markers -p no:cacheprovider -p no:hypothesispytest -p no:xdist
"""


def run_pytest(path: Path, *args: str) -> subprocess.CompletedProcess:
    """pytest in a subprocess: pytest-bdd keeps module-level state (parsed features, config stack)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}
    env["PYTHONPATH"] = os.pathsep.join([str(path), str(REPO)])
    return subprocess.run(
        [sys.executable, "-m", "pytest", *args],
        cwd=path,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )


# What `pytest -rA` printed per test, and the traces `--trace-dir` wrote: how two runs are compared
# (in process against remote, serial against xdist).
OUTCOME = re.compile(r"^(PASSED|FAILED|SKIPPED|ERROR) (\S+)", re.M)


def verdicts(stdout: str) -> list[tuple[str, str]]:
    """(test id, outcome) of every test of a `-rA` run, sorted."""
    return sorted((name, outcome) for outcome, name in OUTCOME.findall(stdout))


def traces(folder: Path) -> dict[str, bytes]:
    """Every trace file a `--trace-dir` run wrote, by name."""
    return {p.name: p.read_bytes() for p in sorted(folder.glob("*.csv"))}
