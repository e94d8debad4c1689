import io
import json
from pathlib import Path

from outline.paths import Tree
from outline.trace import build_trace, render_plain, render_rich

from tests.helpers import DATA


def _results(tmp_path: Path) -> Path:
    for i, (name, status) in enumerate(
        [
            ("F-NET-01 One cut link leaves every node reachable", "passed"),  # rendered outline rows
            ("F-NET-01 One cut link leaves every node reachable", "failed"),
            ("R-CTL-01 Traction notch reaches every car", "passed"),
        ]
    ):
        data = {"name": name, "status": status, "historyId": str(i), "stop": i, "labels": []}
        (tmp_path / f"{i}-result.json").write_text(json.dumps(data))
    return tmp_path


def test_trace_both_directions_with_partly_and_uncovered(tmp_path: Path):
    trace = build_trace(Tree.at(DATA / "good"), str(_results(tmp_path)))
    assert list(trace.by_requirement) == ["NET-03", "NET-05", "PRO-01", "CMD-02", "TST-03"]  # document order
    assert trace.by_requirement["PRO-01"] == {"R-CTL-01": ["R-CTL-01 Commands repeat every 10 ms"]}
    assert trace.uncovered == ["NET-01"]
    assert trace.status == {
        "R-CTL-01 Traction notch reaches every car": "passed",
        "R-CTL-01 Commands repeat every 10 ms": "not run",
        "F-NET-01 One cut link leaves every node reachable": "failed",
        "F-NET-01 A frame with a bad checksum is discarded": "not run",
    }
    out = io.StringIO()
    render_plain(trace, out)
    text = out.getvalue()
    assert "PRO-01\tR-CTL-01 (partly: 8-car set only)\n\t\tR-CTL-01 Commands repeat every 10 ms [not run]\n" in text
    assert "R-CTL-01\tTraction and brake command transmission: CMD-02, PRO-01 (partly: 8-car set only), TST-03" in text
    assert text.rstrip().endswith("Covered by nothing (1): NET-01")


def test_rich_tables_render(monkeypatch):
    monkeypatch.setenv("COLUMNS", "200")  # rich wraps cells to the terminal width
    out = io.StringIO()
    render_rich(build_trace(Tree.at(DATA / "good")), out)
    text = out.getvalue()
    assert "Requirement -> items -> scenarios" in text
    assert "8-car set only" in text
