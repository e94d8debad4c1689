"""What an Allure report needs beside the results: defect categories and the executor (who ran it, on which
commit). Written into the results directory once per run by the pytest plugin (not by xdist workers).

Categories (Allure 3.18 reads the Allure 2 `categories.json`; first match wins):
- SUT not reachable: the backend could not be imported, connected to or started;
- Product defect: a Then step's assertion failed, the SUT does not conform;
- Test defect: any other error (a malformed step value, a bug of the suite): the SUT was not judged;
- Not applicable: an option the SUT's implementation declaration does not claim (ISO/IEC 9646's verdict);
- Pending / profile not declared: skipped on purpose.
"""
from __future__ import annotations

import datetime as _dt
import json
import re
import platform
import subprocess
from pathlib import Path

from outline.report.allure_env import write_environment
from outline.report.summary import INFORMATIVE, NOT_APPLICABLE

# The whole suite's title (allurerc.mjs names the report the same: tests/test_report_in_browser.py reads it there).
REPORT_NAME = "Train network conformance: CRH2, metro TCN, ATP"

CATEGORIES = [
    {"name": "SUT not reachable", "matchedStatuses": ["broken", "failed"],
     "messageRegex": r"(?s).*(SUT backend|cannot import|not reachable|Connection(Refused|Reset)?Error|timed out).*"},
    {"name": "Product defect: the SUT does not conform", "matchedStatuses": ["failed"]},
    {"name": "Test defect: the suite or its input, the SUT not judged", "matchedStatuses": ["broken"]},
    {"name": "Not applicable: an option the SUT's declaration does not claim", "matchedStatuses": ["skipped"],
     "messageRegex": r"(?s).*" + re.escape(NOT_APPLICABLE) + ".*"},
    {"name": "Informative deviation: no requirement states it, conformance not affected",
     "matchedStatuses": ["skipped"], "messageRegex": r"(?s).*" + re.escape(INFORMATIVE) + ".*"},
    {"name": "Pending test item", "matchedStatuses": ["skipped"], "messageRegex": r"(?s).*pending.*"},
    {"name": "Profile the SUT does not declare", "matchedStatuses": ["skipped"],
     "messageRegex": r"(?s).*profile .* declares.*"},
]


def _commit(root: Path) -> str:
    try:
        out = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=root, capture_output=True, text=True,
                             timeout=5)
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return out.stdout.strip() or "unknown"


def write(results_dir: str | Path, root: Path, command: str) -> None:
    results = Path(results_dir)
    results.mkdir(parents=True, exist_ok=True)
    (results / "categories.json").write_text(json.dumps(CATEGORIES, indent=1), encoding="utf-8")
    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    commit = _commit(root)
    executor = {"name": f"{platform.node() or 'local'} (pytest)", "type": "local",
                "buildName": f"{now}, commit {commit}", "reportName": REPORT_NAME,
                "buildOrder": int(_dt.datetime.now(_dt.timezone.utc).timestamp()),
                "reportUrl": "", "buildUrl": ""}
    if command:
        executor["name"] += f": {command}"
    (results / "executor.json").write_text(json.dumps(executor, indent=1), encoding="utf-8")
    # The run's own facts, once, beside each profile's SUT (steps/report.py keys those by profile).
    write_environment(results, {"[run] command": command or None, "[run] commit": commit,
                                "[run] date": now, "[run] host": platform.node() or None})
