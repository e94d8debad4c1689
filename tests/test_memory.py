"""A finished scenario's train is freed: pytest keeps every item (and its stash) until the session ends, so
anything of a scenario an item keeps stays for the whole run (a ten-minute scenario's trace is ~0.7 GB)."""

from __future__ import annotations

import os
import subprocess
import sys

from tests.helpers import REPO

PROBE = '''
import gc
from sut.driver import TrainDriver

def pytest_runtest_logfinish(nodeid, location):
    gc.collect()
    live = sum(1 for o in gc.get_objects() if isinstance(o, TrainDriver))
    print(f"\\nlive drivers after {nodeid.rsplit('::', 1)[-1]}: {live}", flush=True)
'''


def test_no_driver_outlives_its_scenario(tmp_path) -> None:
    (tmp_path / "memprobe.py").write_text(PROBE, encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path), str(REPO)])
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-s", "-p", "no:cacheprovider",
                          "-p", "no:xdist", "-p", "memprobe", "--item", "F-CTL-01"],
                         cwd=REPO, env=env, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    counts = [line for line in run.stdout.splitlines() if line.startswith("live drivers after")]
    assert len(counts) >= 2, run.stdout[-3000:]
    kept = [line for line in counts if not line.endswith(": 0")]
    assert not kept, "drivers kept after their scenario ended:\n" + "\n".join(kept)
