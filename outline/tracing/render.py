"""The traceability matrix as Markdown and HTML (jinja2 templates in outline/tracing/templates/), and as an Allure
result carrying the HTML page, so the report links it as one entry of its own; `run` is `python -m outline
trace` (the tables on a terminal, or these files)."""
from __future__ import annotations

import json
import os
import sys
import time
import uuid
from pathlib import Path

from jinja2 import Environment, FileSystemLoader, select_autoescape

from outline.tracing.coverage import Coverage, counts, coverage
from outline.tree.paths import Tree
from outline.tracing.trace import build_trace, render_plain, render_rich

TEMPLATES = Path(__file__).parent / "templates"


def _env(autoescape: bool) -> Environment:
    return Environment(loader=FileSystemLoader(TEMPLATES), autoescape=select_autoescape(["html"]) if autoescape
                       else False, trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)


def render(kind: str, rows: list[Coverage], trace, requirements: dict, req_doc: str,
           results: str | None = None) -> str:
    """`kind` is "md" or "html"; `req_doc` the path links to requirements.md take from the output file."""
    template = _env(kind == "html").get_template(f"traceability.{kind}.j2")

    def req_link(req: str) -> str:
        line = requirements[req].line if req in requirements else 0
        return f"{req_doc}#L{line}" if line else req_doc

    return template.render(rows=rows, counts=counts(rows), items=sorted(trace.by_item.items()),
                           with_status=bool(trace.status), results=results, req_link=req_link)


def _run_span(results_dir: Path) -> tuple[int, int]:
    """The run's first start and last stop (ms since the epoch) from its results; now for an empty run.
    Without it Allure dates the whole report 1970 and its duration 56 years."""
    starts, stops = [], []
    for path in results_dir.glob("*-result.json"):
        try:
            result = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        if isinstance(result.get("start"), int) and result["start"] > 0:
            starts.append(result["start"])
            stops.append(result.get("stop") if isinstance(result.get("stop"), int) else result["start"])
    if not starts:
        now = int(time.time() * 1000)
        return now, now
    return min(starts), max(stops)


def write_allure_result(results_dir: str | Path, html: str, rows: list[Coverage]) -> Path:
    """One Allure result, "Traceability matrix", with the HTML page attached; failed when a requirement
    is covered by nothing (and not out of scope), so the report's front page shows it."""
    results_dir = Path(results_dir)
    results_dir.mkdir(parents=True, exist_ok=True)
    c = counts(rows)
    name = f"Traceability matrix: {c['full']} full, {c['partly']} partly, {c['none']} none"
    source = f"{uuid.uuid4()}-attachment.html"
    (results_dir / source).write_text(html, encoding="utf-8")
    missing = [r.req for r in rows if r.level == "none"]
    start, stop = _run_span(results_dir)
    result = {
        "uuid": str(uuid.uuid4()), "historyId": "traceability-matrix", "name": name, "fullName": name,
        "status": "failed" if missing else "passed",
        "statusDetails": {"message": f"covered by nothing: {', '.join(missing)}"} if missing else {},
        "stage": "finished", "start": start, "stop": stop,
        "labels": [{"name": "epic", "value": "Traceability"}, {"name": "suite", "value": "Traceability"},
                   {"name": "tag", "value": "traceability"}],
        "attachments": [{"name": "traceability matrix", "source": source, "type": "text/html"}],
        "description": "Requirement -> items -> scenarios and item -> requirements, with coverage levels.",
    }
    path = results_dir / f"{result['uuid']}-result.json"
    path.write_text(json.dumps(result), encoding="utf-8")
    return path


def run(tree: Tree, results_dir: str | None, out=sys.stdout, md: str | None = None, html: str | None = None,
        allure: str | None = None) -> int:
    trace = build_trace(tree, results_dir)
    if not (md or html or allure):
        (render_rich if out.isatty() else render_plain)(trace, out)
        return 0
    rows = coverage(trace, trace.requirements, trace.out_of_scope)
    for path, kind in ((md, "md"), (html, "html")):
        if path:
            doc = os.path.relpath(tree.requirements, Path(path).resolve().parent)
            Path(path).parent.mkdir(parents=True, exist_ok=True)
            Path(path).write_text(render(kind, rows, trace, trace.requirements, doc, results_dir), encoding="utf-8")
    if allure:
        page = render("html", rows, trace, trace.requirements, "requirements.md", results_dir)
        write_allure_result(allure, page, rows)
    c = counts(rows)
    print(f"traceability: {c['full']} full, {c['partly']} partly, {c['none']} none, {c['out of scope']} out of "
          f"scope" + "".join(f"; {p}" for p in (md, html) if p), file=out)
    return 0
