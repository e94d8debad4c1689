"""The benchmark history and the page made from it (issue 32, item 4): bench/history.jsonl, docs/performance.md
and docs/performance.svg (bench/report.py, `make performance`)."""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
from datetime import datetime

from bench import _history
from bench.report import PAGE, PLOT, digest, render_markdown
from tests.helpers import REPO


def test_docs_performance_md_is_the_generators_output_for_the_history() -> None:
    rows = _history.read()
    assert rows, "bench/history.jsonl is empty"
    assert PAGE.read_text(encoding="utf-8") == render_markdown(rows), \
        "docs/performance.md is stale: make performance (or python -m bench.report)"


def test_the_plot_was_drawn_from_the_history_as_it_is() -> None:
    svg = PLOT.read_text(encoding="utf-8")
    assert svg.lstrip().startswith("<?xml") and "<svg" in svg
    assert f"series sha256 {digest(_history.read())}" in svg, \
        "docs/performance.svg was drawn from another history: make performance"


def test_every_row_says_when_what_and_where_from() -> None:
    scripts = {p.stem for p in (REPO / "bench").glob("*_bench.py")}
    for row in _history.read():
        where = f"{row.get('bench')} at {row.get('when')}"
        when = row["when"].replace("Z", "")
        datetime.fromisoformat(when)
        bench = row["bench"]
        assert bench in scripts or (bench.startswith("make_") and "make_bench" in scripts), where
        assert isinstance(row["load"], list) and len(row["load"]) == 2, where
        assert isinstance(row["args"], list), where
        assert row["figures"] and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                      for v in row["figures"].values()), where
        # a row either was measured by a script (the machine it ran on) or says which prose it was read from
        assert "machine" in row or row.get("source", "").startswith("from "), where


def test_a_bench_run_with_record_appends_its_row(tmp_path) -> None:
    history = tmp_path / "history.jsonl"
    run = subprocess.run([sys.executable, "bench/crc_bench.py", "--plain", "--sizes", "12", "--budget", "0.02",
                          "--repeat", "1", "--no-bitwise", "--record", str(history), "--note", "a test"],
                         cwd=REPO, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    (row,) = [json.loads(line) for line in history.read_text(encoding="utf-8").splitlines()]
    assert row["bench"] == "crc_bench" and row["note"] == "a test"
    assert row["args"] == ["--sizes", "12", "--budget", "0.02", "--repeat", "1", "--no-bitwise"]
    assert set(row["figures"]) == {"table_us_12b", "crc_opt_us_12b", "table_ns_per_byte_12b"}
    assert len(row["load"]) == 2 and row["commit"] and row["machine"]["cores"]


def test_without_record_nothing_is_written(tmp_path) -> None:
    args = argparse.Namespace(record=None)
    _history.record(args, "crc_bench", {"x_s": 1.0}, load_before=0.1, load_after=0.2)
    args = argparse.Namespace(record=tmp_path / "h.jsonl", note="")
    _history.record(args, "crc_bench", {"x_s": 1.0, "nan_s": float("nan"), "none": None}, load_before=0.1,
                    load_after=None, selection=[])
    (row,) = _history.read(tmp_path / "h.jsonl")
    assert row["figures"] == {"x_s": 1.0} and row["load"] == [0.1, None] and "note" not in row


def test_the_page_is_made_without_matplotlib() -> None:
    run = subprocess.run([sys.executable, "-c", "import sys; from bench import _history, report; "
                          "report.render_markdown(_history.read()); report.digest(_history.read()); "
                          "assert 'matplotlib' not in sys.modules"], cwd=REPO, capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stderr


def test_a_make_test_row_says_which_test_functions_took_its_minutes(tmp_path) -> None:
    """bench/make_bench.py reads make test's JUnit XML: each test function's seconds, its parameters merged, the
    largest few by name, and the page says them."""
    sys.path.insert(0, str(REPO / "bench"))
    import make_bench

    xml = tmp_path / "own-tests.xml"
    cases = [("test_features_accept_in_band_variant[FasterNodes]", 50.5),
             ("test_features_accept_in_band_variant[BriskMetro]", 10.0),
             ("test_kernel_orders_ties", 0.25)]
    xml.write_text('<testsuites><testsuite name="pytest">' + "".join(
        f'<testcase classname="tests.test_x" name="{name}" time="{seconds}"/>' for name, seconds in cases)
        + "</testsuite></testsuites>", encoding="utf-8")
    figures = make_bench.own_tests_by_function(xml, top=1)
    assert figures == {"own_cpu_s": 60.8, "own_features_accept_in_band_variant_s": 60.5}
    row = {"when": "2026-11-29T02:00:00Z", "bench": "make_test", "commit": "abc", "load": [None, None],
           "args": ["--clone"], "figures": {"wall_s": 1700.0, "own_tests_s": 1600.0, "conformance_s": 66.0, **figures}}
    page = render_markdown([row])                 # the page from this row alone: the history may hold later ones
    assert "features accept in band variant 60 s (100%)" in page
