"""pytest plugin for tests/test_faulty_variants.py: the features against every faulty variant in one run.

One pytest process with `--sut` given once per variant collects the features once (instead of once per
variant: ~70 start-ups of 2-3 s) and runs each variant on what the plan names for it, nothing else: the
scenarios of its test item, and those tagged with the requirement it breaks (what `--req` would select).
The plan is a JSON file named by $CRH2_VARIANT_PLAN: {variant class name: {"items": [...], "reqs": [...]}}.

Each process writes, beside the plan, the requirement tags of every scenario it kept
(`<plan>.<worker>.reqs.json`: {test id: [requirement, ...]}), so that the test can tell which selection a
rejecting scenario belongs to. A variant's own item runs first; once a scenario of each of its items and one
tagged with each requirement it breaks have failed (tests/variants.py may list a variant more than once), its
remaining scenarios are skipped: the variant is rejected every way, and the rest would only cost time. The workers tell each other (`<plan>.rejected`, a line per
rejection), so a worker does not go on running a variant the other one has already rejected.
"""
from __future__ import annotations

import json
import os

import pytest

from outline.campaigns.campaign import CAMPAIGNS
from steps.fixtures import SUT_CHOOSER

CAMPAIGN_ITEMS = {campaign.item for campaign in CAMPAIGNS}

_PLAN = pytest.StashKey[dict[str, dict[str, set[str]]]]()
_REJECTED = pytest.StashKey[dict[str, set[str]]]()      # variant name -> {"item:<ID>", "req:<ID>"} already failed


def _variant(item: pytest.Item) -> str | None:
    callspec = getattr(item, "callspec", None)
    variant = callspec.params.get("sut_class") if callspec is not None else None
    return variant.__name__ if variant is not None else None


def _tags(item: pytest.Item, mark: str) -> set[str]:
    return {str(m.args[0]) for m in item.iter_markers(mark) if m.args}


def _plan(config: pytest.Config) -> dict[str, dict[str, set[str]]]:
    with open(os.environ["CRH2_VARIANT_PLAN"], encoding="utf-8") as fh:
        return {name: {kind: set(ids) for kind, ids in wanted.items()} for name, wanted in json.load(fh).items()}


def _why(item: pytest.Item, wanted: dict[str, set[str]]) -> set[str]:
    """Which selections of the plan keep this scenario: "item", "req", both or none."""
    return ({"item"} if _tags(item, "item") & wanted.get("items", set()) else set()) | \
           ({"req"} if _tags(item, "req") & wanted.get("reqs", set()) else set())


def _met(item: pytest.Item, wanted: dict[str, set[str]]) -> set[str]:
    """Which of the plan's items and requirements a failure of this scenario rejects the variant by
    ("item:<ID>", "req:<ID>"): a variant listed under two requirements or two items (tests/variants.py may
    list it once for each) is rejected only once each has failed a scenario."""
    return ({f"item:{i}" for i in _tags(item, "item") & wanted.get("items", set())}
            | {f"req:{r}" for r in _tags(item, "req") & wanted.get("reqs", set())})


def _needed(wanted: dict[str, set[str]]) -> set[str]:
    return {f"item:{i}" for i in wanted.get("items", set())} | {f"req:{r}" for r in wanted.get("reqs", set())}


def pytest_configure(config: pytest.Config) -> None:
    plan = config.stash[_PLAN] = _plan(config)
    config.stash[_REJECTED] = {}

    def chooser(definition: pytest.Item, ids: list[str]) -> list[str]:
        # Each scenario only for the variants whose plan selects it: ~3,000 items, not ~80,000 to deselect.
        return [sut_id for sut_id in ids if _why(definition, plan.get(sut_id, {}))]

    config.stash[SUT_CHOOSER] = chooser


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    # Every item is a variant on a scenario its plan selects: the chooser parametrized nothing else, and
    # steps/fixtures.py dropped the scenarios no plan selects. Stable: a variant's own item first, then the
    # scenarios its requirement selects, the generated campaigns' rows last: a targeted scenario usually
    # rejects it first, and the sweep is then skipped.
    plan = config.stash[_PLAN]
    items.sort(key=lambda item: ("item" not in _why(item, plan[_variant(item)]),
                                 bool(_tags(item, "item") & CAMPAIGN_ITEMS)))
    worker = getattr(config, "workerinput", {}).get("workerid", "main")
    tags = {item.nodeid: sorted(_tags(item, "req")) for item in items}
    with open(f"{os.environ['CRH2_VARIANT_PLAN']}.{worker}.reqs.json", "w", encoding="utf-8") as fh:
        json.dump(tags, fh)


def _rejections() -> str:
    return f"{os.environ['CRH2_VARIANT_PLAN']}.rejected"


def _heard(config: pytest.Config) -> dict[str, set[str]]:
    """The rejections of every worker so far: this one's, and what the others wrote to the shared file."""
    rejected = config.stash[_REJECTED]
    try:
        with open(_rejections(), encoding="utf-8") as fh:
            for line in fh:
                name, _, why = line.strip().partition(" ")
                rejected.setdefault(name, set()).update(why.split())
    except FileNotFoundError:
        pass
    return rejected


@pytest.hookimpl(tryfirst=True)                       # before the fixtures build a train
def pytest_runtest_setup(item: pytest.Item) -> None:
    name = _variant(item)
    if _needed(item.config.stash[_PLAN][name]) <= _heard(item.config).get(name, set()):
        pytest.skip("this variant already failed a scenario of each of its items and requirements")


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo):
    report = yield
    if report.failed and report.when == "call":
        name = _variant(item)
        why = _met(item, item.config.stash[_PLAN][name])
        item.config.stash[_REJECTED].setdefault(name, set()).update(why)
        with open(_rejections(), "a", encoding="utf-8") as fh:      # one short line: appended whole
            fh.write(f"{name} {' '.join(sorted(why))}\n")
    return report
