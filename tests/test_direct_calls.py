"""outline/mutate/direct_calls.py: a mutant's run that calls every function but the mutated one directly gives
mutmut's own verdict, mutant by mutant (a small project of its own, run by mutmut 3.8 both ways), and
everything it rebinds is put back."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import types
from pathlib import Path

import pytest

trampoline = pytest.importorskip("mutmut.mutation.trampoline")

from outline.mutate import direct_calls  # noqa: E402
from tests import mutmut_project  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

SOURCE = '''
HANDLERS = {}


def double(x):
    return add(x, x)


def add(a, b):
    return a + b


def square(x):
    return x * x


HANDLERS["square"] = square


def by_table(x):
    return HANDLERS["square"](x) + 1


def countdown(n):
    while n > 0:
        yield n
        n -= 1
    return "done"


class Base:
    def describe(self):
        return "base"


class Meter(Base):
    def __init__(self):
        self.total = 0

    def feed(self, n):
        for i in range(n):
            self.total = add(self.total, i)
        return self.total

    def describe(self):
        return "meter of " + super().describe()

    @staticmethod
    def scale(x):
        return x * 3

    @classmethod
    def make(cls, n):
        meter = cls()
        meter.feed(n)
        return meter
'''

TESTS = '''
import pytest
from lib.calc import Meter, add, by_table, countdown, double


def test_add():
    assert add(2, 3) == 5


def test_double():
    assert double(4) == 8


def test_by_table():
    assert by_table(3) == 10


def test_countdown():
    assert list(countdown(3)) == [3, 2, 1]          # its return value is never read: those mutants survive


@pytest.mark.parametrize("n", [1, 3, 4])
def test_meter(n):
    assert Meter.make(n).total == n * (n - 1) // 2


def test_describe_and_scale():
    assert Meter().describe().startswith("meter of ")
    assert Meter.scale(2) > 0
'''

CONFTEST = '''
import os
from pathlib import Path


def pytest_collection_finish(session):
    if os.environ.get("DIRECT_CALLS"):
        from mutmut.mutation.trampoline import get_mutant_under_test
        from outline.mutate import direct_calls
        rebound = direct_calls.install(get_mutant_under_test(), Path.cwd())
        with open(os.environ["DIRECT_CALLS"], "a") as fh:
            fh.write(f"{get_mutant_under_test()} {rebound}\\n")


def pytest_unconfigure(config):
    from outline.mutate import direct_calls
    direct_calls.uninstall()
'''


def _verdicts(where: Path, direct: Path | None) -> dict[str, int]:
    """mutmut's exit code for every mutant of the small project, run with or without direct calls."""
    mutmut_project.write(where, SOURCE, TESTS, CONFTEST)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    env.pop("MUTANT_UNDER_TEST", None)
    if direct:
        env["DIRECT_CALLS"] = str(direct)
    done = subprocess.run([sys.executable, "-m", "mutmut", "run", "--max-children", "2"], cwd=where,
                          capture_output=True, text=True, env=env, timeout=600)
    meta = where / "mutants" / "lib" / "calc.py.meta"
    assert meta.exists(), done.stdout[-3000:] + done.stderr[-3000:]
    return json.loads(meta.read_text())["exit_code_by_key"]


@pytest.mark.cost(40)
def test_a_mutant_run_with_direct_calls_gives_mutmut_own_verdicts(tmp_path: Path) -> None:
    log = tmp_path / "direct.log"
    own = _verdicts(tmp_path / "own", None)
    direct = _verdicts(tmp_path / "direct", log)
    assert direct == own
    assert len(own) > 30
    assert {code for code in own.values()} >= {0, 1}                 # some survive, some are killed
    rebound = dict(line.rsplit(" ", 1) for line in log.read_text().splitlines())
    # The clean run: every function of lib/calc.py called directly, there and where the tests imported it.
    functions, imported = SOURCE.count("    def ") + SOURCE.count("\ndef "), ("add", "by_table", "countdown", "double")
    assert rebound.get("") == str(functions + len(imported))
    mutants = {name: int(n) for name, n in rebound.items() if "__mutmut_" in name}
    assert set(mutants) == set(own)                    # every mutant's run went through it...
    for name, count in mutants.items():                # ...and called all but its own function directly
        own_names = 2 if name.split(".")[-1].removeprefix("x_").split("__mutmut_")[0] in imported else 1
        assert count == functions + len(imported) - own_names, name


# What mutmut writes into a mutated module, made here by hand: tables of mutants, functions in trampolines.
def _orig_inner(x: int) -> int:
    return x + 1


def _mutant_inner(x: int) -> int:
    return x - 1


def _orig_outer(x: int) -> int:
    return inner(x) * 2


_inner_table = {"_mutmut_orig": _orig_inner, "x_inner__mutmut_1": _mutant_inner}
_outer_table = {"_mutmut_orig": _orig_outer}


@trampoline.wrap_in_trampoline(_inner_table)
def inner(x: int) -> int:
    return x + 1


@trampoline.wrap_in_trampoline(_outer_table)
def outer(x: int) -> int:
    return inner(x) * 2


class Box:
    @staticmethod
    @trampoline.wrap_in_trampoline({"_mutmut_orig": lambda x: x})
    def same(x: int) -> int:
        return x


def test_every_trampoline_but_the_mutant_s_is_unwrapped_and_put_back(monkeypatch: pytest.MonkeyPatch) -> None:
    here = sys.modules[__name__]
    before = {"inner": inner, "outer": outer, "same": Box.__dict__["same"]}
    monkeypatch.setenv("MUTANT_UNDER_TEST", f"{__name__}.x_inner__mutmut_1")
    try:
        rebound = direct_calls.install(f"{__name__}.x_inner__mutmut_1", Path(__file__))
        assert rebound == 2
        assert here.inner is before["inner"]                             # the mutant's own: still routed
        assert here.outer is before["outer"].__wrapped__                 # the others: called directly
        assert isinstance(Box.__dict__["same"], staticmethod) and Box.same(4) == 4
        assert here.outer(3) == 4                                        # (3 - 1) * 2: the mutant ran
        assert direct_calls.install("", Path(__file__)) == 0     # once per session
    finally:
        direct_calls.uninstall()
    assert {"inner": here.inner, "outer": here.outer, "same": Box.__dict__["same"]} == before


@pytest.mark.parametrize("mutant", ["stats", "fail", "list_all_tests"])
def test_mutmut_own_runs_keep_their_trampolines(mutant: str) -> None:
    assert direct_calls.install(mutant, Path(__file__)) == 0
    assert isinstance(sys.modules[__name__].outer, types.FunctionType)
    assert sys.modules[__name__].outer.__code__.co_name == "_trampoline_wrapper"
