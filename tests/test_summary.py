import json
from pathlib import Path

from outline.report.summary import format_summary, load_results, main, statuses_by_name, summarize


def _result(path: Path, name: str, status: str, reqs=(), history=None, stop=1):
    data = {
        "name": name,
        "status": status,
        "historyId": history or name,
        "stop": stop,
        "labels": [{"name": "requirement", "value": r} for r in reqs] + [{"name": "epic", "value": "x"}],
    }
    (path / f"{name.replace(' ', '_')}-{stop}-result.json").write_text(json.dumps(data))


def test_summary_line(tmp_path: Path, capsys):
    _result(tmp_path, "R-CTL-01 a", "passed", ["CMD-02", "PRO-01"])
    _result(tmp_path, "R-CTL-01 b", "failed", ["PRO-01", "TST-03"])
    _result(tmp_path, "F-NET-01 c", "broken", ["NET-03"])
    _result(tmp_path, "F-NET-01 d", "skipped", ["NET-05"])
    _result(tmp_path, "F-NET-01 e", "passed", ["NET-03"])
    (tmp_path / "environment.properties").write_text("sut=reference\n")
    (tmp_path / "junk-result.json").write_text("{not json")
    assert main([str(tmp_path)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "5 scenarios: 2 passed, 1 failed, 1 broken, 1 skipped; 3 requirement IDs covered by passing scenarios "
        "(of 5 exercised)",
        "covered: CMD-02 NET-03 PRO-01",
        "broken: F-NET-01 c",
        "failed: R-CTL-01 b",
    ]


def test_rerun_counts_once_and_outline_reports_worst(tmp_path: Path):
    _result(tmp_path, "x", "failed", history="h1", stop=1)
    _result(tmp_path, "x", "passed", history="h1", stop=2)
    _result(tmp_path, "y", "passed", history="h2")
    _result(tmp_path, "y", "failed", history="h3", stop=3)
    results = load_results(tmp_path)
    assert len(results) == 3
    assert statuses_by_name(results) == {"x": "passed", "y": "failed"}


def test_empty_and_missing(tmp_path: Path, capsys):
    assert format_summary(summarize([])) == "0 scenarios: 0 passed, 0 failed, 0 broken, 0 skipped; " \
        "0 requirement IDs covered by passing scenarios"
    assert main([str(tmp_path / "nope")]) == 1


def test_summary_counts_each_train_profile(tmp_path: Path):
    for i, (profile, status) in enumerate([("crh2", "passed"), ("crh2", "failed"), ("metro-tcn", "passed")]):
        data = {"name": f"s{i}", "status": status, "historyId": f"h{i}", "stop": 1,
                "labels": [{"name": "tag", "value": f"profile:{profile}"}, {"name": "tag", "value": "item:X"}]}
        (tmp_path / f"s{i}-result.json").write_text(json.dumps(data))
    text = format_summary(summarize(load_results(tmp_path)))
    assert "by profile: crh2 2 (1 passed, 1 failed); metro-tcn 1 (1 passed)" in text.splitlines()


def test_an_informative_deviation_is_counted_apart_and_listed(tmp_path: Path, capsys):
    """A failed Then of an @informative scenario (an xfail whose message says so) is neither a pass nor a
    failure: counted on its own, listed for the reviewer, its requirements not counted as covered."""
    _result(tmp_path, "F-NET-01 a", "passed", ["NET-03"])
    data = {"name": "F-NET-01 b", "status": "skipped", "historyId": "b", "stop": 1,
            "statusDetails": {"message": "XFailed: informative deviation: period 52 ms, the reference's 50"},
            "labels": [{"name": "requirement", "value": "NET-05"}]}
    (tmp_path / "b-1-result.json").write_text(json.dumps(data))
    assert main([str(tmp_path)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "2 scenarios: 1 passed, 0 failed, 0 broken, 1 informative deviation, 0 skipped; 1 requirement IDs covered "
        "by passing scenarios (of 2 exercised)",
        "covered: NET-03",
        "informative deviation: F-NET-01 b",
    ]
