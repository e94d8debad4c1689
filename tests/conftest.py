"""Fixtures for the project's own tests: fixture trees under tests/data and throwaway pytest projects."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from tests.helpers import DATA, PYTEST_INI, REPO

# tests/data holds fixture trees (feature files, step modules), not tests of this suite.
collect_ignore = ["data"]


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The costliest tests first (their `cost` mark), the others in their order, those marked with a
    negative cost last. A dozen tests run whole feature suites in a subprocess (30-130 s each against ~1 s
    for most): met at the end of the collection, as they were, they left one worker running alone for
    minutes. With `--dist loadgroup` (the Makefile) pytest-xdist hands the items out one by one as workers
    free up, so started first they share the two workers and the short tests fill the gaps."""
    def cost(item: pytest.Item) -> float:
        mark = item.get_closest_marker("cost")
        return mark.args[0] if mark else 0
    items.sort(key=cost, reverse=True)                # stable: equal costs keep the collection order


@pytest.fixture
def data_on_path(monkeypatch):
    """Make the fixture trees' step modules (good_steps, bad_steps) importable."""
    def add(tree: str) -> Path:
        monkeypatch.syspath_prepend(str(DATA / tree))
        return DATA / tree
    return add


@pytest.fixture
def project(tmp_path):
    """A copy of a fixture tree as a pytest project bound by the real features/test_outline.py."""
    def make(tree: str = "good", steps: tuple[str, ...] = ("good_steps",), conftest_extra: str = "") -> Path:
        shutil.copytree(DATA / tree, tmp_path, dirs_exist_ok=True)
        shutil.copy(REPO / "features" / "test_outline.py", tmp_path / "features" / "test_outline.py")
        plugins = ["outline.plugin.pytest_plugin", *steps]
        (tmp_path / "conftest.py").write_text(f"pytest_plugins = {plugins!r}\n{conftest_extra}")
        (tmp_path / "pytest.ini").write_text(PYTEST_INI)
        return tmp_path
    return make
