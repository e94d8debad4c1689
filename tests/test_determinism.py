"""Determinism (issue 9): the verdicts and every event of every trace depend on the features and the SUT only.

The reference has no randomness to seed: virtual time in integer microseconds and a sequence number for
ties (sut/reference/kernel.py). What could still leak in is the process: string hashing (set and dict order
under another PYTHONHASHSEED), the order pytest-xdist hands scenarios to workers, state left over from the
previous scenario in the same worker, or a powered-up snapshot (sut/snapshot.py) that is not exactly the
state it stands for. So the same sample runs three times: serially with two hash seeds (the first with
snapshots, restoring states in every profile; the second with `--no-snapshots`, simulating every scenario
from power-up), and on two xdist workers; the verdicts and the traces (`--trace-dir`, CSV) must be
byte-identical. tests/test_snapshot.py checks more of the snapshots in process.
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
# And per backend, items whose scenarios share a Background (and features that share one with each other),
# so that states are stored and restored many times over: crh2 (routine class, English and zh-CN, and a
# coupled set), metro-tcn, atp (the rig and the ATP fitted to a CRH2 set).
SNAPSHOT_SAMPLES = {
    "ReferenceTrain": "R-CTL-01,R-CTL-02,R-CTL-03,R-DIA-01,F-NET-08,F-ILK-02",
    "ReferenceMetro": "F-NET-22,F-CTL-16",
    "ReferenceAtp": "F-ATP-04,F-ATP-07,F-ATP-13",
}
ITEMS = ",".join(dict.fromkeys(",".join([SAMPLE, *SNAPSHOT_SAMPLES.values()]).split(",")))


def _run(trace_dir: Path, hash_seed: str, *args: str) -> tuple[list[tuple[str, str]], str]:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-rA", "-p", "no:cacheprovider",
           f"--item={ITEMS}", f"--trace-dir={trace_dir}", *args]
    env = dict(os.environ, PYTHONHASHSEED=hash_seed)
    result = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env, timeout=900)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-2000:]
    return verdicts(result.stdout), result.stdout


@pytest.mark.cost(45)
def test_two_runs_snapshots_on_and_off_and_a_parallel_run_give_identical_verdicts_and_traces_in_every_profile(
        tmp_path: Path) -> None:
    # Every branch: what the measured costs store varies with load (a loaded clean clone once restored
    # only ATP states), and this checks the states themselves.
    first, out = _run(tmp_path / "first", "1", "-p", "no:xdist", "--snapshot-every-branch")
    second, off = _run(tmp_path / "second", "2", "-p", "no:xdist", "--no-snapshots")
    parallel, _ = _run(tmp_path / "parallel", "3", "-n", "2")
    summary = re.search(r"^snapshots: \d+ restored \((.*?)\),", out, re.M)
    assert summary, f"the first run used no snapshots: {out[-1500:]}"
    restored = {name: int(count) for name, count in re.findall(r"(\w+) (\d+)", summary.group(1))}
    assert all(restored.get(backend, 0) >= 2 for backend in SNAPSHOT_SAMPLES), f"restored per backend: {restored}"
    assert "snapshots:" not in off
    assert len(first) >= 100
    assert first == second, "two serial runs (snapshots on, then off) disagree"
    assert first == parallel, "a run on two xdist workers disagrees with a serial run"
    expected = traces(tmp_path / "first")
    assert len(expected) == len(first) and sum(map(len, expected.values())) > 1_000_000
    for other in ("second", "parallel"):
        found = traces(tmp_path / other)
        differ = [name for name, text in found.items() if expected.get(name) != text]
        assert not differ and len(found) == len(expected), f"{other}: traces differ: {differ[:5]}"
