"""One profile of the conformance run in one pytest process with a bench plugin loaded, which leaves its figures
as JSON in the file named by an environment variable (bench/events_bench.py, bench/advances_bench.py)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run_profile(plugin: str, out_variable: str, profile: str, extra: list[str]) -> tuple[dict, float, str]:
    """(the plugin's JSON, the wall seconds of the run, pytest's last summary line)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / f"{plugin}.json"
        env = dict(os.environ, **{out_variable: str(out)},
                   PYTHONPATH=os.pathsep.join([str(ROOT / "bench"), str(ROOT), os.environ.get("PYTHONPATH", "")]))
        started = time.perf_counter()
        run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:xdist", "-p",
                              "no:cacheprovider", "-p", plugin, "--profile", profile, *extra],
                             cwd=ROOT, env=env, capture_output=True, text=True)
        wall = time.perf_counter() - started
        summary = run.stdout.strip().splitlines()[-1] if run.stdout.strip() else run.stderr[-500:]
        if run.returncode not in (0, 5) or not out.exists():
            raise SystemExit(f"pytest --profile {profile} failed:\n{run.stdout[-3000:]}{run.stderr[-2000:]}")
        return json.loads(out.read_text(encoding="utf-8")), wall, summary
