"""Determinism (issue 9): the verdicts and every event of every trace depend on the features and the SUT only.

The reference has no randomness to seed: virtual time in integer microseconds and a sequence number for
ties (sut/reference/kernel.py). What could still leak in is the process: string hashing (set and dict order
under another PYTHONHASHSEED), the order pytest-xdist hands scenarios to workers, state left over from the
previous scenario in the same worker, or a powered-up snapshot (sut/snapshot.py) that is not exactly the
state it stands for. So the same sample runs three times: serially with two hash seeds (the second with
`--no-snapshots`, simulating every scenario from power-up), and on two xdist workers; the verdicts and the
traces (`--trace-dir`, CSV) must be byte-identical. tests/test_snapshot.py checks more of the snapshots.
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import traces, verdicts
from tests.test_faulty_variants import ROOT

# Every profile, the timing-heavy parts (takeover, token, power interruption, VDX self-test) and zh-CN.
SAMPLE = "R-CTL-03,R-DIA-02,F-NET-13,F-NET-03,F-ILK-05,H-PWR-02,F-ATP-04,F-ATP-12,F-NET-21,F-CTL-15"


def _run(trace_dir: Path, hash_seed: str, *args: str) -> tuple[list[tuple[str, str]], str]:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-rA", "-p", "no:cacheprovider",
           f"--item={SAMPLE}", f"--trace-dir={trace_dir}", *args]
    env = dict(os.environ, PYTHONHASHSEED=hash_seed)
    result = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env, timeout=900)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    return verdicts(result.stdout), result.stdout


@pytest.mark.cost(35)
def test_two_runs_and_a_parallel_run_give_identical_verdicts_and_traces(tmp_path: Path) -> None:
    first, out = _run(tmp_path / "first", "1", "-p", "no:xdist")
    second, _ = _run(tmp_path / "second", "2", "-p", "no:xdist", "--no-snapshots")
    parallel, _ = _run(tmp_path / "parallel", "3", "-n", "2")
    restored = re.search(r"^snapshots: (\d+) restored", out, re.M)
    assert restored and int(restored.group(1)) >= 10, f"the first run used no snapshots: {out[-1500:]}"
    assert len(first) >= 60
    assert first == second, "two serial runs disagree"
    assert first == parallel, "a run on two xdist workers disagrees with a serial run"
    expected = traces(tmp_path / "first")
    assert len(expected) == len(first) and sum(map(len, expected.values())) > 1_000_000
    for other in ("second", "parallel"):
        found = traces(tmp_path / other)
        differ = [name for name, text in found.items() if expected.get(name) != text]
        assert not differ and len(found) == len(expected), f"{other}: traces differ: {differ[:5]}"
