"""The generated Allure report, opened in headless Chromium, loads, shows every test that ran, logs no error.

The report is built here the way `make report` builds it, on a small run (two routine items): pytest with
--alluredir (the plugin writes categories, executor and environment), `python -m outline trace --allure` (one
"Traceability matrix" entry), `npx allure generate` with the project's allurerc.mjs (history kept in tmp, not
in reports/), `python -m outline.report.allure_html` (drops the analytics tag). Then outline.report.report_browser opens
index.html from disk (file://, as a reader does) with Playwright driving Debian's Chromium; see that module
for what counts as an error. One test opens a scenario's page; another breaks copies of the report and checks
that the same assertions catch each break.

Chromium is not skipped when missing: CI runs `make test`, which installs Debian's `chromium`; so is the npm
Allure CLI (`node_modules`, from package-lock.json).
"""
from __future__ import annotations

import base64
import fcntl
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from outline.report import report_browser
from outline.report.allure_meta import REPORT_NAME    # allurerc.mjs names the report the same

ROOT = Path(__file__).resolve().parents[1]
ITEMS = "R-CTL-01,R-DIA-01"
TRACE_SECTION = "Traceability"          # outline/tracing/render.py: the matrix entry's tree section
_COUNTED = ("passed", "failed", "skipped", "xfailed", "xpassed")


def _run(cmd: list[str], what: str, timeout: float = 300) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    result = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env, timeout=timeout)
    assert result.returncode == 0, (f"{what} failed (exit {result.returncode}): {' '.join(cmd)}\n"
                                    f"{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    return result


def _build(work: Path) -> dict:
    """Run ITEMS into work/results, build work/html/index.html; return the run's scenario count and the path."""
    assert os.access(report_browser.CHROMIUM, os.X_OK), (
        f"{report_browser.CHROMIUM} is missing: {report_browser.INSTALL_HINT}")
    assert (ROOT / "node_modules" / ".bin" / "allure").exists(), (
        "node_modules/.bin/allure is missing: `make test` installs it (npm ci from package-lock.json)")
    results, html = work / "results", work / "html"
    run = _run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                f"--item={ITEMS}", "--alluredir", str(results)], f"the conformance run of {ITEMS}")
    summary = run.stdout.strip().splitlines()[-1]
    ran = sum(int(n) for n, kind in re.findall(r"(\d+) (\w+)", summary) if kind in _COUNTED)
    assert ran > 0, summary
    _run([sys.executable, "-m", "outline", "trace", "--results", str(results), "--allure", str(results)],
         "outline trace --allure")
    # The project's allurerc.mjs with the output and the history moved here: reports/ stays untouched.
    config = work / "allurerc.mjs"
    config.write_text(f'import base from {json.dumps((ROOT / "allurerc.mjs").as_uri())};\n'
                      f"export default {{ ...base, output: {json.dumps(str(html))}, "
                      f"historyPath: {json.dumps(str(work / 'history.jsonl'))} }};\n", encoding="utf-8")
    _run(["npx", "--no-install", "allure", "generate", str(results), "--config", str(config),
          "--output", str(html)], "allure generate")
    _run([sys.executable, "-m", "outline.report.allure_html", str(html / "index.html")], "outline.report.allure_html")
    return {"ran": ran, "index": str(html / "index.html"), "summary": summary}


@pytest.fixture(scope="session")
def report(tmp_path_factory) -> dict:
    """Built once per run, also under xdist: the first worker builds, the others wait and reuse it."""
    if not os.environ.get("PYTEST_XDIST_WORKER"):
        return _build(tmp_path_factory.mktemp("report"))
    shared = tmp_path_factory.getbasetemp().parent / "report-in-browser"
    shared.mkdir(exist_ok=True)
    with open(shared / "lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        done = shared / "built.json"
        if not done.exists():
            done.write_text(json.dumps(_build(shared)), encoding="utf-8")
        return json.loads(done.read_text(encoding="utf-8"))


def problems(page: report_browser.PageLoad, ran: int) -> list[str]:
    """What is wrong with the page as a reader would see it; empty when it is right."""
    found = list(page.errors)  # console errors, exceptions, failed or external loads, errors shown in the page
    if not page.rendered:
        found.append(f"not rendered: #app children {page.app_children}, loading screen "
                     f"{'still shown' if page.loader_shown else 'gone'}, total {page.total}")
    if page.title != REPORT_NAME:
        found.append(f"title {page.title!r}, expected {REPORT_NAME!r}")
    # The summary's Total counts the scenarios that ran plus the traceability matrix entry.
    if page.total != ran + 1:
        found.append(f"Total shows {page.total}, expected {ran} scenarios + 1 traceability entry = {ran + 1}")
    scenarios = sum(n for title, n in page.sections.items() if title != TRACE_SECTION)
    if page.sections.get(TRACE_SECTION) != 1 or scenarios != ran:
        found.append(f"tree sections {page.sections}: expected {TRACE_SECTION!r}: 1 and {ran} scenarios in the rest")
    if "1970" in page.excerpt(100_000):
        found.append("the report is dated 1970: a result without start/stop times")
    return found


def test_report_renders_in_headless_chromium(report: dict) -> None:
    page = report_browser.load(report["index"])
    found = problems(page, report["ran"])
    assert not found, (f"report of `pytest features --item={ITEMS}` ({report['summary']}) in headless Chromium, "
                       f"{page.url}:\n  " + "\n  ".join(found) + f"\npage text: {page.excerpt()}")


def _result_id(index: str, name_prefix: str) -> str:
    """The report's id of the first test result whose name starts with `name_prefix` (singleFile embeds each
    result as d("data/test-results/<id>.json", "<base64 JSON>"))."""
    html = Path(index).read_text(encoding="utf-8")
    for rid, data in re.findall(r'd\("data/test-results/([0-9a-f]+)\.json","([^"]*)"\)', html):
        if json.loads(base64.b64decode(data)).get("name", "").startswith(name_prefix):
            return rid
    raise AssertionError(f"no test result named {name_prefix}... in {index}")


def test_a_scenario_page_shows_what_a_reviewer_signs_off(report: dict) -> None:
    """Issue 17: the item's title, the full text of each requirement verified, the profile, the attachments."""
    from outline.tree.requirements import load_requirements

    page = report_browser.load(f"{Path(report['index']).as_uri()}#{_result_id(report['index'], 'R-CTL-01')}")
    assert not page.errors, page.errors
    shown = page.description or ""
    ctl01 = "Traction and brake command transmission"              # features/registry.yaml
    requirement = load_requirements(ROOT / "docs" / "requirements.md")["CMD-05"].text
    for expected in (f"Test item R-CTL-01: {ctl01}", "Profile crh2", "Requirements verified",
                     f"CMD-05 {requirement}"):
        assert expected in shown, f"the page's description lacks {expected!r}: {shown[:1500]}"
    for expected in ("timing diagram", "key events", "profile:crh2", "req:CMD-05"):
        assert expected in page.text, f"the page lacks {expected!r}: {page.excerpt(3000)}"


def _throwing_script(html: str) -> str:
    return html.replace("</body>", "<script>throw new Error('mutant: broken report script')</script></body>", 1)


def _missing_data_file(html: str) -> str:
    # singleFile embeds each data file as d("<name>", "<base64>") in one Promise.allSettled([...]) list.
    return re.sub(r'd\("widgets/statistic\.json","[^"]*"\),', "", html, count=1)


def _calling_out(html: str) -> str:
    # What outline/report/allure_html.py strips from Allure's page: a script fetched from the network.
    return html.replace("</head>", '<script async src="https://analytics.invalid/tag.js"></script></head>', 1)


@pytest.mark.parametrize(("mutate", "expected"), [(_throwing_script, "uncaught exception: Error: mutant"),
                                                  (_missing_data_file, "Total shows 0"),
                                                  (_calling_out, "external request: https://analytics.invalid")],
                         ids=["throwing-script", "missing-data-file", "calling-out"])
def test_check_catches_a_broken_report(report: dict, tmp_path: Path, mutate, expected: str) -> None:
    original = Path(report["index"]).read_text(encoding="utf-8")
    broken = mutate(original)
    assert broken != original, f"{mutate.__name__} no longer applies to Allure's index.html: update the mutant"
    (tmp_path / "index.html").write_text(broken, encoding="utf-8")
    page = report_browser.load(tmp_path / "index.html", timeout=10)
    found = problems(page, report["ran"])
    assert any(expected in line for line in found), f"{mutate.__name__} went unnoticed: {found}"
