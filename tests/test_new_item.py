"""`python -m outline new` on a copy of the repository: the item it adds passes `outline check` and runs
at once, reported as pending (issue 8: "the new item runs at once, pending steps reported as such")."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from outline.tree.new_item import NewItemError, add_item, next_item_id
from outline.tree.paths import Tree

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def repo_copy(tmp_path: Path) -> Path:
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout.split()
    for rel in files:
        if rel.startswith(("features/", "steps/", "sut/", "outline/", "docs/")) or rel in ("conftest.py",
                                                                                          "pyproject.toml"):
            (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / rel, tmp_path / rel)
    return tmp_path


def test_new_item_is_checked_and_runs_as_pending(repo_copy: Path) -> None:
    tree = Tree.at(repo_copy)
    want = next_item_id(tree, "function", "display")
    result = subprocess.run([sys.executable, "-m", "outline", "--root", str(repo_copy), "new", "--class",
                             "function", "--category", "display", "--title", "Door states on the monitor",
                             "--req", "ILK-05,TST-04"], cwd=repo_copy, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    assert result.returncode == 0, result.stderr
    assert f"{want}: wrote features/function/display/{want}.feature" in result.stdout
    check = subprocess.run([sys.executable, "-m", "outline", "--root", str(repo_copy), "check"], cwd=repo_copy,
                           capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr
    run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p",
                          "no:xdist", "--item", want, "-rs"], cwd=repo_copy, capture_output=True, text=True)
    summary = run.stdout.strip().splitlines()[-1]
    assert run.returncode == 0 and "1 skipped" in summary and "passed" not in summary, run.stdout[-1500:]
    assert "pending" in run.stdout


@pytest.mark.parametrize(("args", "words"), [
    (("nope", "display", "t", ["TST-04"], "crh2"), ["no class 'nope'", "function"]),
    (("function", "nope", "t", ["TST-04"], "crh2"), ["no category 'nope' in class function", "control"]),
    (("function", "display", " ", ["TST-04"], "crh2"), ["needs a title"]),
    (("function", "display", "t", ["XXX-99"], "crh2"), ["XXX-99", "NET-01"]),
    (("function", "display", "t", ["TST-04"], "tram"), ["no profile 'tram'", "metro-tcn"]),
])
def test_bad_input_names_what_is_allowed(repo_copy: Path, args, words) -> None:
    with pytest.raises(NewItemError) as err:
        add_item(Tree.at(repo_copy), *args)
    for word in words:
        assert word in str(err.value)
