"""Shards (issue 16): the conformance run split across machines with pytest-split (`make shard SHARDS=N SHARD=i`,
balanced by the recorded .test_durations), each shard's Allure results merged by `allure generate` into one
report (`make merge`). The union of the shards must be the serial run: the same scenarios, the same verdicts,
none twice, and the merged report must count what the serial report counts."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import verdicts
from tests.test_faulty_variants import ROOT

ITEMS = "F-NET-30,R-CTL-01"        # a generated campaign and a hand-written item
SHARDS = 3


def _pytest(results: Path, *args: str) -> list[tuple[str, str]]:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-rA", "-p", "no:cacheprovider", "-p", "no:xdist",
           f"--item={ITEMS}", "--alluredir", str(results), *args]
    run = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    return verdicts(run.stdout)


def _results(*folders: Path) -> list[tuple[str, str]]:
    found = [json.loads(p.read_text(encoding="utf-8")) for folder in folders for p in folder.glob("*-result.json")]
    return sorted((r["fullName"], r["status"]) for r in found)


def _report(tmp_path: Path, name: str, *folders: Path) -> dict:
    html = tmp_path / f"{name}-html"
    config = tmp_path / f"{name}.allurerc.mjs"         # the project's config, output and history kept here
    config.write_text(f'import base from {json.dumps((ROOT / "allurerc.mjs").as_uri())};\n'
                      f"export default {{ ...base, output: {json.dumps(str(html))}, "
                      f"historyPath: {json.dumps(str(tmp_path / f'{name}-history.jsonl'))} }};\n", encoding="utf-8")
    run = subprocess.run(["npx", "--no-install", "allure", "generate", *map(str, folders), "--config", str(config),
                          "--output", str(html)], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    return json.loads((html / "summary.json").read_text(encoding="utf-8"))["stats"]


@pytest.mark.cost(20)
def test_the_shards_together_are_the_serial_run_and_merge_into_its_report(tmp_path: Path) -> None:
    serial = _pytest(tmp_path / "serial")
    shards = [_pytest(tmp_path / f"shard-{i}", "--splits", str(SHARDS), "--group", str(i),
                      "--splitting-algorithm", "least_duration")
              for i in range(1, SHARDS + 1)]
    assert all(shards), f"an empty shard: {[len(s) for s in shards]}"
    ids = [test_id for shard in shards for test_id, _ in shard]
    assert len(ids) == len(set(ids)), "a scenario ran in two shards"
    assert sorted(v for shard in shards for v in shard) == serial
    assert len(serial) > 80
    folders = [tmp_path / f"shard-{i}" for i in range(1, SHARDS + 1)]
    assert _results(*folders) == _results(tmp_path / "serial")
    merged = _report(tmp_path, "merged", *folders)
    assert merged == _report(tmp_path, "serial", tmp_path / "serial")
    assert merged.get("passed") == len(serial)
