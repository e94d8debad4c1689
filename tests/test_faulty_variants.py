"""The features must reject a train that breaks one requirement, and accept one that differs only in band.

Each variant runs the real feature files through pytest in a subprocess, exactly as a user would with
`--sut tests.variants:<Variant>`; a run that fails proves the feature specifies that requirement.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.variants import FAULTY, IN_BAND

ROOT = Path(__file__).resolve().parents[1]


def run_features(variant: type, *args: str, sut: str | None = None) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
           f"--sut={sut or f'tests.variants:{variant.__name__}'}", "-o", "addopts=--strict-markers", *args]
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env, timeout=1500)


def test_at_least_twelve_requirements_have_a_faulty_variant() -> None:
    assert len({req for _, req, _ in FAULTY}) >= 12


@pytest.mark.parametrize(("variant", "requirement", "item"), FAULTY,
                         ids=[f"{v.__name__}-{r}" for v, r, _ in FAULTY])
def test_features_reject_faulty_variant(variant: type, requirement: str, item: str) -> None:
    result = run_features(variant, f"--item={item}")
    summary = result.stdout.strip().splitlines()[-1] if result.stdout.strip() else result.stderr
    assert result.returncode == 1, (f"{variant.__name__} ({requirement}) was not rejected by {item}: "
                                    f"exit {result.returncode}, {summary}\n{result.stderr[-2000:]}")
    assert " failed" in summary, summary


@pytest.mark.parametrize("variant", IN_BAND, ids=[v.__name__ for v in IN_BAND])
def test_features_accept_in_band_variant(variant: type) -> None:
    result = run_features(variant)
    failed = [line for line in result.stdout.splitlines() if line.startswith(("FAILED", "ERROR"))]
    assert result.returncode == 0, f"{variant.__name__} was rejected:\n" + "\n".join(failed or [result.stdout[-3000:]])
