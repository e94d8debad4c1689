"""A small project of its own for the tests that run mutmut itself (test_sharded_map, test_direct_calls): one
module lib/calc.py under mutation, its tests in tests/."""
from __future__ import annotations

from pathlib import Path


def write(where: Path, source: str, tests: str, conftest: str = "") -> Path:
    (where / "lib").mkdir(parents=True)
    (where / "tests").mkdir()
    (where / "lib" / "__init__.py").write_text("")
    (where / "lib" / "calc.py").write_text(source)
    (where / "tests" / "test_calc.py").write_text(tests)
    if conftest:
        (where / "tests" / "conftest.py").write_text(conftest)
    (where / "pyproject.toml").write_text(
        '[tool.mutmut]\nsource_paths = ["lib/"]\npytest_add_cli_args_test_selection = ["tests/"]\n'
        'pytest_add_cli_args = ["-p", "no:cacheprovider", "-p", "no:xdist"]\n'
        '[tool.pytest.ini_options]\npythonpath = ["."]\n')
    return where
