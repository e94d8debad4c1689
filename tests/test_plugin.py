"""outline.plugin.pytest_plugin end to end: throwaway projects bound by the real features/test_outline.py."""

import json

from tests.helpers import run_pytest


def _tail(proc) -> str:
    return proc.stdout.strip().splitlines()[-1]


def test_good_tree_runs_with_pending_skipped(project):
    proc = run_pytest(project(), "features", "-rs")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "4 passed, 1 skipped" in _tail(proc)
    assert any(line.startswith("SKIPPED [1]") and line.endswith(": pending") for line in proc.stdout.splitlines())


def test_select_by_item_and_req(project):
    root = project()
    proc = run_pytest(root, "features", "--item", "r-ctl-01")
    assert "2 passed, 3 deselected" in _tail(proc)
    proc = run_pytest(root, "features", "--req", "NET-03,PRO-01", "-q")
    assert "3 passed, 2 deselected" in _tail(proc)
    proc = run_pytest(root, "features", "--item", "F-NET-01", "--req", "CMD-02", "-q")
    assert "3 passed, 1 skipped, 1 deselected" in _tail(proc)
    proc = run_pytest(root, "features", "-k", "R-CTL-01 and not PRO-01", "-q")
    assert "1 passed, 4 deselected" in _tail(proc)


def test_unknown_selection_is_an_error(project):
    proc = run_pytest(project(), "features", "--item", "R-CTL-07", "--req", "NET-03")
    assert proc.returncode == 4
    assert "--item R-CTL-07: no collected scenario carries it" in proc.stderr


def test_empty_tree_collects_nothing(project):
    root = project()
    for path in (root / "features").rglob("*.feature"):
        path.unlink()
    proc = run_pytest(root, "features")
    assert proc.returncode == 5, proc.stdout + proc.stderr


UNKNOWN_AND_AMBIGUOUS = """
  @req:PRO-01
  Scenario: R-CTL-01 Emergency handle
    When the driver pulls the emergency handle
    Then the command interval is 10 ms
"""
DUPLICATE_STEP = """
from pytest_bdd import parsers, then


@then(parsers.parse("the command interval is {ms} ms"))
def _(ms):
    pass
"""


def test_unknown_and_ambiguous_steps_fail_collection_with_file_and_line(project):
    root = project(steps=("good_steps", "more_steps"))
    (root / "more_steps.py").write_text(DUPLICATE_STEP)
    feature = root / "features" / "routine" / "control" / "R-CTL-01.feature"
    feature.write_text(feature.read_text() + UNKNOWN_AND_AMBIGUOUS)
    proc = run_pytest(root, "features")
    assert proc.returncode == 2, proc.stdout + proc.stderr
    out = proc.stdout
    assert "ERROR collecting features/test_outline.py" in out
    assert (
        'features/routine/control/R-CTL-01.feature:17: ambiguous step "Then the command interval is 10 ms" '
        "matches 2 definitions: good_steps:31 ('the command interval is {ms:d} ms'); "
        "more_steps:5 ('the command interval is {ms} ms')"
    ) in out
    assert (
        'features/routine/control/R-CTL-01.feature:21: unknown step "When the driver pulls the emergency handle"'
    ) in out
    assert "Traceback" not in out


def test_malformed_feature_fails_collection_with_file_and_line(project):
    root = project()
    (root / "features" / "routine" / "control" / "R-CTL-02.feature").write_text(
        "Feature: x\n  Scenario: R-CTL-02 a\n    And oops\n"
    )
    proc = run_pytest(root, "features")
    assert proc.returncode == 2
    assert (
        "features/routine/control/R-CTL-02.feature:3: first step must start with Given, When or Then, not And"
        in proc.stdout
    )


def test_unregistered_plain_tag_fails_collection_with_file_and_line(project):
    root = project()
    feature = root / "features" / "routine" / "control" / "R-CTL-01.feature"
    feature.write_text(feature.read_text().replace("@tentative", "@wip"))
    proc = run_pytest(root, "features")
    assert proc.returncode == 2
    assert (
        "features/routine/control/R-CTL-01.feature:13: @wip is neither a project tag (tentative, informative, pending, on_request) "
        "nor a registered pytest marker"
    ) in proc.stdout


SETUP_FAILS_FOR_TENTATIVE = """
import pytest


@pytest.fixture(autouse=True)
def _sut_that_cannot_start(request):
    if request.node.get_closest_marker("tentative"):
        raise RuntimeError("SUT did not start")
"""


def test_allure_results_carry_outline_labels_and_unstarted_scenarios(project):
    root = project(conftest_extra=SETUP_FAILS_FOR_TENTATIVE)
    proc = run_pytest(root, "features", "--alluredir", "results", "--allure-link-pattern", "tms:https://req.example/{}")
    assert proc.returncode == 1
    results = {}
    for path in (root / "results").glob("*-result.json"):
        data = json.loads(path.read_text())
        results.setdefault(data["name"], []).append(data)
    assert sorted((name, len(r)) for name, r in results.items()) == [
        ("F-NET-01 A frame with a bad checksum is discarded", 1),
        ("F-NET-01 One cut link leaves every node reachable", 2),
        ("R-CTL-01 Commands repeat every 10 ms", 1),
        ("R-CTL-01 Traction notch reaches every car", 1),
    ]

    def labels(result):
        return sorted((lab["name"], lab["value"]) for lab in result["labels"] if lab["name"] not in
                      ("host", "thread", "framework", "language"))

    (notch,) = results["R-CTL-01 Traction notch reaches every car"]
    assert notch["status"] == "passed"
    assert labels(notch) == [
        ("epic", "System routine tests"),
        ("feature", "Control"),
        ("requirement", "CMD-02"),
        ("requirement", "TST-03"),
        ("story", "R-CTL-01 Traction and brake command transmission"),
        ("tag", "item:R-CTL-01"),
        ("tag", "profile:crh2"),
        ("tag", "req:CMD-02"),
        ("tag", "req:TST-03"),
    ]
    assert [(link["name"], link["url"], link["type"]) for link in notch["links"]] == [
        ("CMD-02", "https://req.example/CMD-02", "tms"),
        ("TST-03", "https://req.example/TST-03", "tms"),
    ]
    outline = results["F-NET-01 One cut link leaves every node reachable"]
    assert sorted(tuple(p["value"] for p in r["parameters"]) for r in outline) == [("8", "3", "4"), ("8", "8", "1")]

    # Never started: allure-pytest-bdd alone would leave both out of the report.
    (pending,) = results["F-NET-01 A frame with a bad checksum is discarded"]
    assert pending["status"] == "skipped"
    assert pending["statusDetails"]["message"] == "Skipped: pending"
    assert [s["status"] for s in pending["steps"]] == ["skipped"] * 3
    assert ("tag", "pending") in labels(pending)
    (broken,) = results["R-CTL-01 Commands repeat every 10 ms"]
    assert broken["status"] == "broken"
    assert "SUT did not start" in broken["statusDetails"]["message"]


def test_allure_results_get_categories_executor_and_requirement_line_links(project):
    root = project()
    proc = run_pytest(root, "features", "--alluredir", "results", "-p", "no:xdist")
    assert proc.returncode == 0, proc.stdout[-1500:]
    categories = json.loads((root / "results" / "categories.json").read_text())
    assert [c["name"] for c in categories][:3] == ["SUT not reachable", "Product defect: the SUT does not conform",
                                                   "Test defect: the suite or its input, the SUT not judged"]
    executor = json.loads((root / "results" / "executor.json").read_text())
    assert executor["type"] == "local" and "commit" in executor["buildName"]
    notch = next(json.loads(p.read_text()) for p in (root / "results").glob("*-result.json")
                 if json.loads(p.read_text())["name"] == "R-CTL-01 Traction notch reaches every car")
    # Without a tracker pattern each requirement links to its line of docs/requirements.md (fixture: CMD-02 is
    # on line 12, TST-03 on line 15), relative to reports/html/index.html.
    assert [(link["name"], link["url"]) for link in notch["links"]] == [
        ("CMD-02 (requirements.md line 12)", "../../docs/requirements.md#L12"),
        ("TST-03 (requirements.md line 15)", "../../docs/requirements.md#L15"),
    ]
