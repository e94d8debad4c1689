"""pytest plugin for tests/test_faulty_variants.py: the features against every faulty variant in one run.

One pytest process with `--sut` given once per variant collects the features once (instead of once per
variant: ~70 start-ups of 2-3 s) and runs each variant on the test items the plan names for it, nothing
else. The plan is a JSON file named by $CRH2_VARIANT_PLAN: {variant class name: [item ID, ...]}.
"""
from __future__ import annotations

import json
import os

import pytest


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    with open(os.environ["CRH2_VARIANT_PLAN"], encoding="utf-8") as fh:
        plan = {name: set(item_ids) for name, item_ids in json.load(fh).items()}
    keep, drop = [], []
    for item in items:
        callspec = getattr(item, "callspec", None)
        variant = callspec.params.get("sut_class") if callspec is not None else None
        item_ids = {str(m.args[0]) for m in item.iter_markers("item") if m.args}
        wanted = variant is not None and item_ids & plan.get(variant.__name__, set())
        (keep if wanted else drop).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep
