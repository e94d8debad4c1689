"""What each test mutmut maps is made of, for `make mutate`'s map (outline/mutate/mutation.py): a scenario is made of
its feature file, the step modules its steps bind to and each step definition they bind to (named by its
module and the digest of its source, `steps/x.py@<digest>`), found as pytest-bdd finds them (the step index);
every test also of its own file (tests/test_bulk.py, tests/test_kernel.py are no scenarios).

Loaded into a collect-only run (`-p outline.mutate.scenario_inputs`), it writes {nodeid: [files]} as JSON to the path
in $CRH2_SCENARIO_INPUTS. When some of those files change, only the tests made of them are mapped again.
"""
from __future__ import annotations

import ast
import hashlib
import json
import os
from pathlib import Path

import pytest
from pytest_bdd.steps import step_function_context_registry

from outline.plugin import step_index

OUT = "CRH2_SCENARIO_INPUTS"


def sha(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def step_definitions(path: Path) -> tuple[dict[int, str], str]:
    """A step module's decorated functions (by the line of their first decorator, which is the function's
    co_firstlineno) with a digest of each one's source, and a digest of the rest of the module."""
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines(keepends=True)
    found, spans = {}, []
    for node in ast.parse(text).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.decorator_list:
            first = node.decorator_list[0].lineno
            found[first] = sha("".join(lines[first - 1:node.end_lineno]))
            spans.append((first, node.end_lineno or first))
    # Blank and comment lines are left out of the rest: a step definition added with its comment changes none
    # of what the module's other tests are made of.
    rest = [line for i, line in enumerate(lines, start=1) if not any(a <= i <= b for a, b in spans)
            and line.strip() and not line.lstrip().startswith("#")]
    return found, sha("".join(rest))


def inputs_of(session: pytest.Session) -> dict[str, list[str]]:
    root = Path(session.config.rootpath).resolve()
    index = step_index.index_of(session._fixturemanager)
    inputs: dict[str, list[str]] = {}
    digests: dict[str, dict[int, str]] = {}
    for item in session.items:
        files = {item.nodeid.split("::")[0]}
        template = step_index.template_of(item)
        if template is not None:
            files.add(Path(template.feature.filename).resolve().relative_to(root).as_posix())
            example = getattr(item, "callspec", None) and item.callspec.params.get("_pytest_bdd_example", {})
            for step in template.render(example or {}).steps:
                # Every definition that matches, not only the one pytest-bdd picks: more files only maps more.
                for fixturedef in index.find(step, item):
                    context = step_function_context_registry.get(fixturedef.func)
                    function = getattr(context, "step_func", None)
                    module = getattr(function, "__module__", "") or ""
                    if not module.startswith("steps."):
                        continue
                    name = module.replace(".", "/") + ".py"
                    files.add(name)
                    if name not in digests:
                        digests[name] = step_definitions(root / name)[0]
                    digest = digests[name].get(function.__code__.co_firstlineno)
                    files.add(f"{name}@{digest}" if digest else name)
        inputs[item.nodeid] = sorted(files)
    return inputs


@pytest.hookimpl(trylast=True)
def pytest_collection_finish(session: pytest.Session) -> None:
    out = os.environ.get(OUT)
    if out:
        Path(out).write_text(json.dumps(inputs_of(session), indent=0, sort_keys=True), encoding="utf-8")
