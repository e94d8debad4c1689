import io
import json
from pathlib import Path

from outline.tree.paths import Tree
from outline.tracing.trace import build_trace, render_plain, render_rich

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


def test_matrix_as_markdown_html_and_an_allure_entry(tmp_path, data_on_path):
    import json

    from outline.tracing.render import run

    data_on_path("good")
    out = io.StringIO()
    md, html, results = tmp_path / "t.md", tmp_path / "t.html", tmp_path / "results"
    assert run(Tree.at(DATA / "good"), None, out, md=str(md), html=str(html), allure=str(results)) == 0
    # good tree: NET-03, NET-05, PRO-01, CMD-02, TST-03 claimed with scenarios; PRO-01 partly; NET-01 by none
    assert "traceability: 4 full, 1 partly, 1 none, 0 out of scope" in out.getvalue()
    text = md.read_text(encoding="utf-8")
    assert "| [NET-01](" in text and "| none |" in text
    assert "(partly: 8-car set only)" in text
    page = html.read_text(encoding="utf-8")
    assert '<tr class="none">' in page and "requirements.md#L" in page
    (result,) = [json.loads(p.read_text()) for p in results.glob("*-result.json")]
    assert result["status"] == "failed" and "NET-01" in result["statusDetails"]["message"]
    assert (results / result["attachments"][0]["source"]).read_text(encoding="utf-8") .startswith("<!DOCTYPE html>")
