"""Loaded by tests/test_step_index.py into a collect-only run of the features: every step of every scenario
looked up both ways, pytest-bdd's scan and the index (outline/plugin/step_index.py); prints what it found."""
from __future__ import annotations

import pytest

from outline.plugin import step_index


@pytest.hookimpl(trylast=True)
def pytest_collection_finish(session: pytest.Session) -> None:
    fixturemanager = session._fixturemanager
    index = step_index.index_of(fixturemanager)
    checked, differ = 0, []
    # The step fixtures an item sees are its module's and conftests': a step said alike in one file (every
    # Background's, most Thens) is looked up once per file.
    agreed: dict[tuple, bool] = {}
    for item in session.items:
        template = step_index.template_of(item)
        if template is None:
            continue
        example = getattr(item, "callspec", None) and item.callspec.params.get("_pytest_bdd_example", {})
        for step in template.render(example or {}).steps:
            key = (item.path, step.type, step.name)
            if key not in agreed:
                agreed[key] = list(step_index.SCAN(step, fixturemanager, item)) == index.find(step, item)
            if not agreed[key]:
                differ.append(f"{item.nodeid}: {step.type} {step.name}")
            checked += 1
    for line in differ:
        print(f"STEP INDEX DIFFERS {line}")
    print(f"STEP INDEX CHECKED {checked}")
