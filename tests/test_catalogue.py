"""The step catalogue (outline/tree/catalogue.py): what a test engineer reads instead of the step modules."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import steps
from outline.tree.catalogue import entries, render_markdown

ROOT = Path(__file__).resolve().parents[1]


def test_docs_steps_md_is_the_catalogue_of_todays_steps() -> None:
    found = entries(steps.STEP_MODULES, ROOT / "features")
    assert (ROOT / "docs" / "steps.md").read_text(encoding="utf-8") == render_markdown(found), \
        "docs/steps.md is stale: python -m outline steps --md docs/steps.md"


def test_every_step_has_an_english_sentence_and_a_chinese_twin() -> None:
    found = entries(steps.STEP_MODULES)
    assert len(found) > 300
    for entry in found:
        assert entry.english, f"{entry.module}:{entry.line} has no English sentence"
        assert entry.chinese, f"{entry.module}:{entry.line} ({entry.english[0]}) has no zh-CN twin"


def test_the_catalogue_says_what_a_step_does_at_the_driver() -> None:
    found = {e.english[0]: e for e in entries(steps.STEP_MODULES)}
    doors = found["the driver commands the doors {state:w}"]
    assert "set_input" in doors.calls and doors.params == {"state": doors.params["state"]}
    taken = next(e for s, e in found.items() if s.startswith("every CI and BCU receives traction notch {notch:d} over"))
    assert "cmd.in" in taken.kinds and taken.budgeted


def test_searching_door_finds_the_door_sentences() -> None:
    run = subprocess.run([sys.executable, "-m", "outline", "steps", "door"], cwd=ROOT, capture_output=True,
                         text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert "the driver commands the doors {state:w}" in run.stdout and "司机发出车门{state:w}指令" in run.stdout
    nothing = subprocess.run([sys.executable, "-m", "outline", "steps", "no-such-words-anywhere"], cwd=ROOT,
                             capture_output=True, text=True, timeout=120)
    assert nothing.returncode == 1 and "no step sentence contains" in nothing.stderr
