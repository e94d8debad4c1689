"""outline/mutate/sharded_map.py: the map of who reaches what, learnt by two xdist workers, is the map mutmut
learns in one process (a small project of its own, mapped both ways by mutmut 3.8 itself)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("mutmut")

from tests import mutmut_project  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

SOURCE = '''
def double(x):
    return add(x, x)


def add(a, b):
    return a + b


class Meter:
    def __init__(self):
        self.total = 0

    def feed(self, n):
        for i in range(n):
            self.total = add(self.total, i)
        return self.total
'''

TESTS = '''
import pytest
from lib.calc import Meter, add, double


def test_add():
    assert add(2, 3) == 5


def test_double():
    assert double(4) == 8


@pytest.mark.parametrize("n", [1, 3, 4])
def test_meter(n):
    assert Meter().feed(n) == n * (n - 1) // 2


def test_nothing_of_the_library():
    assert True
'''


def _project(where: Path) -> Path:
    return mutmut_project.write(where, SOURCE, TESTS)


def _mutmut_run(project: Path, mutant: str, module: str = "outline.mutate.sharded_map"
                ) -> subprocess.CompletedProcess:
    """`python -m <module> run <mutant>` in the project, two xdist workers for the map and the clean run."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), MUTMUT_MAP_JOBS="2")
    env.pop("MUTANT_UNDER_TEST", None)
    return subprocess.run([sys.executable, "-m", module, "run", mutant], cwd=project, capture_output=True,
                          text=True, env=env, timeout=300)


def _map(project: Path, module: str) -> dict:
    done = _mutmut_run(project, "lib.calc.x_nothing__mutmut_1", module)
    stats = project / "mutants" / "mutmut-stats.json"
    assert stats.exists(), done.stdout[-3000:] + done.stderr[-3000:]
    data = json.loads(stats.read_text())
    return {"tests": {k: sorted(v) for k, v in data["tests_by_mangled_function_name"].items() if v},
            "callers": {k: sorted(v) for k, v in data["function_dependencies"].items() if v},
            "timed": sorted(data["duration_by_test"]), "sharded": _logged(project)}


def _logged(project: Path) -> bool:
    log = project / "mutants" / "map.log"
    return log.exists() and "mapped 6 tests in 2 processes" in log.read_text()


@pytest.mark.cost(20)
def test_a_sharded_map_is_mutmut_own_map(tmp_path: Path) -> None:
    own = _map(_project(tmp_path / "own"), "mutmut")
    sharded = _map(_project(tmp_path / "sharded"), "outline.mutate.sharded_map")
    assert sharded.pop("sharded") and not own.pop("sharded")
    assert sharded == own
    assert own["tests"]["lib.calc.x_add"] == ["tests/test_calc.py::test_add", "tests/test_calc.py::test_double",
                                              "tests/test_calc.py::test_meter[1]", "tests/test_calc.py::test_meter[3]",
                                              "tests/test_calc.py::test_meter[4]"]
    assert "tests/test_calc.py::test_nothing_of_the_library" in own["timed"]


@pytest.mark.cost(20)
def test_the_clean_run_is_dealt_out_too_and_a_failing_test_still_stops_mutmut(tmp_path: Path) -> None:
    project = _project(tmp_path / "ok")
    done = _mutmut_run(project, "lib.calc.x_add__mutmut_1")
    log = (project / "mutants" / "map.log").read_text()
    assert "clean run of 5 tests in 2 processes" in log, done.stdout[-2000:]      # the tests that reach add()
    meta = json.loads((project / "mutants" / "lib" / "calc.py.meta").read_text())
    assert meta["exit_code_by_key"]["lib.calc.x_add__mutmut_1"] == 1                # killed, as mutmut says
    # A test that passes while mutmut maps and fails unmutated: the sharded clean run must stop mutmut.
    project = _project(tmp_path / "failing")
    with open(project / "tests" / "test_calc.py", "a") as fh:
        fh.write("\n\ndef test_fails_unmutated():\n    import os\n    assert add(1, 1) == 2\n"
                 "    assert os.environ.get('MUTANT_UNDER_TEST') == 'stats'\n")
    done = _mutmut_run(project, "lib.calc.x_add__mutmut_1")
    assert done.returncode != 0 and "Failed to run clean test" in done.stdout
    assert "test_fails_unmutated" in done.stdout
