"""The step index (outline/step_index.py) finds exactly what pytest-bdd's own scan finds, in the same order,
for every step of every scenario of the real features (English and zh-CN)."""
from __future__ import annotations

import re
import subprocess
import sys

import pytest

from tests.test_faulty_variants import ROOT


@pytest.mark.cost(9)
def test_the_index_finds_what_pytest_bdd_finds_for_every_step() -> None:
    result = subprocess.run([sys.executable, "-m", "pytest", "features", "--collect-only", "-q", "-p", "no:xdist",
                             "-p", "no:cacheprovider", "-p", "tests.step_index_plugin"],
                            cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    differ = re.findall(r"^STEP INDEX DIFFERS (.*)$", result.stdout, re.M)
    assert not differ, "\n".join(differ[:10])
    checked = re.search(r"^STEP INDEX CHECKED (\d+)$", result.stdout, re.M)
    assert checked and int(checked.group(1)) >= 5000, result.stdout[-2000:]
