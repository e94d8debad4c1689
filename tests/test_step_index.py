"""The step index (outline/plugin/step_index.py) finds exactly what pytest-bdd's own scan finds, in the same order,
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


def test_a_literal_prefix_is_never_longer_than_what_every_match_starts_with() -> None:
    from pytest_bdd import parsers

    from outline.plugin.step_index import literal_chunks, literal_prefix

    assert literal_prefix(parsers.string("the train is powered")) == ("the train is powered", False)
    assert literal_prefix(parsers.parse('the cab {cab:d} monitor shows "{text}"')) == ("the cab ", True)
    assert literal_chunks(parsers.parse('the cab {cab:d} monitor shows "{text}"')) == ("the cab ", " monitor shows \"")
    assert literal_prefix(parsers.re(r'the "(?P<o>[^"]+)" stays')) == ('the "', False)
    assert literal_prefix(parsers.re(r"the trains? stops?")) == ("the train", False)       # "s?": s optional
    assert literal_prefix(parsers.re(r"the train stops|a train halts")) == ("", False)    # alternation
    assert literal_prefix(parsers.re(r"(?i)the train"))[0] == ""
    assert literal_prefix(parsers.re(r"THE train", flags=__import__("re").IGNORECASE)) == ("THE train", True)
    assert literal_prefix(parsers.parse("持续观察{cab:d}号")) == ("", True)                   # no case folding guess
    for parser, text in ((parsers.parse("The Cab {n:d} is Open"), "the cab 3 is open"),
                         (parsers.re(r"the trains? stops?"), "the train stop")):
        prefix, fold = literal_prefix(parser)
        assert parser.is_matching(text) and (text.lower() if fold else text).startswith(prefix.lower() if fold else prefix)
