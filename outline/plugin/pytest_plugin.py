"""pytest plugin of the test outline (loaded by the root conftest).

- tags -> marks: `@item:X` -> mark.item("X"), `@req:X` -> mark.req("X"), `@profile:X` -> mark.profile("X"),
  `@tentative`, `@informative`, `@pending` (also skipped, reason "pending"); an unknown `kind:` fails loudly.
- `--item ID` / `--req ID` keep only matching scenarios (repeatable, comma-separated; union of all given).
- Allure labels from the registry: epic = class, feature = category, story = "<item> <title>",
  one `requirement` label and one `req:` tag per requirement, `item:` and `profile:` tags; with
  `--allure-link-pattern tms:https://tracker/{}` also one `tms` link per requirement.
- A step matching no step definition, or several at the same scope, is a collection error naming file:line
  (pytest-bdd alone fails such a scenario only when it runs, or silently picks the last definition).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from pytest_bdd.scenario import iterparentnodeids

from outline.tree import tags as tagvocab
from outline.plugin import step_index
from outline.tree.registry import Registry, RegistryError, load_registry
from outline.plugin.stepdefs import StepDef, context_of, step_problem

MARKERS = (
    "item(id): test-outline item carried by the scenario (from @item:<ID>)",
    "req(id): requirement ID verified by the scenario (from @req:<ID>)",
    "profile(name): train/SUT profile the scenario needs (from @profile:<name>)",
    "option(name): an option of the implementation declaration form the scenario needs (from @option:<name>); "
    "not applicable to a SUT that does not claim it",
    "tentative: checks a project decision where the sources are ambiguous",
    "informative: checks what no requirement states; a failed Then is an informative deviation, not a failure",
    "pending: written but not yet runnable; skipped with reason 'pending'",
    "on_request: a feature bound only when its item is asked for with --item (the double-fault campaign)",
    "allure_label: allure label marker",
    "allure_link: allure link marker",
)
_REGISTRY = pytest.StashKey["Registry | None"]()


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("outline", "CRH2 test outline")
    for name, what in (("item", "test item (e.g. F-NET-03)"), ("req", "requirement (e.g. NET-03)")):
        group.addoption(
            f"--{name}",
            action="append",
            default=[],
            metavar="ID",
            help=f"run only scenarios of this {what}; repeatable or comma-separated; "
            "--item and --req together select the union",
        )


def pytest_configure(config: pytest.Config) -> None:
    # Registered here too, so fixture trees without our pyproject pass --strict-markers.
    for line in MARKERS:
        config.addinivalue_line("markers", line)
    step_index.install()       # pytest-bdd's per-step scan of every fixture, done once per module instead


def pytest_sessionstart(session: pytest.Session) -> None:
    config = session.config
    results = getattr(config.option, "allure_report_dir", None)
    if results and not hasattr(config, "workerinput"):      # once per run, not per xdist worker
        from outline.report import allure_meta

        allure_meta.write(results, Path(config.rootpath), " ".join(["pytest", *config.invocation_params.args]))


def pytest_bdd_apply_tag(tag: str, function):
    kind, value = tagvocab.classify(tag)  # TagError (a ValueError) for @typo:X: never silently ignored
    if kind is not None:
        getattr(pytest.mark, kind)(value)(function)
        return True
    if value == "pending":
        pytest.mark.pending(function)
        pytest.mark.skip(reason="pending")(function)
        return True
    if value in ("tentative", "informative", "on_request"):
        getattr(pytest.mark, value)(function)
        return True
    return None  # pytest-bdd's default: getattr(pytest.mark, tag); --strict-markers rejects unregistered ones


def features_dir(config: pytest.Config) -> Path:
    return Path(config.rootpath) / (config.getini("bdd_features_base_dir") or "features")


def registry(config: pytest.Config) -> Registry | None:
    """The registry, loaded once per run; None if missing or invalid (labels then fall back to tags only;
    `python -m outline check` is where registry problems are reported)."""
    if _REGISTRY not in config.stash:
        fdir = features_dir(config)
        try:
            config.stash[_REGISTRY] = load_registry(fdir / "registry.yaml", fdir.name)
        except (OSError, RegistryError):
            config.stash[_REGISTRY] = None
    return config.stash[_REGISTRY]


def _values(item: pytest.Item, mark: str) -> list[str]:
    return [str(m.args[0]) for m in item.iter_markers(mark) if m.args]


# --- collection-time step check -------------------------------------------------------------------------


@pytest.hookimpl(wrapper=True)
def pytest_make_collect_report(collector: pytest.Collector):
    report = yield
    if report.passed and isinstance(collector, pytest.Module):
        problems = _step_problems(collector, [i for i in report.result if isinstance(i, pytest.Function)])
        if problems:
            report.outcome = "failed"
            report.longrepr = "\n".join(problems)
            report.result = []
    return report


def _step_problems(collector: pytest.Module, items: list[pytest.Function]) -> list[str]:
    fixturemanager = collector.session._fixturemanager
    rootpath = Path(collector.config.rootpath)
    verdicts: dict[tuple[str, str], str | None] = {}  # every item of a module sees the same step definitions
    problems: dict[str, None] = {}
    for item in items:
        template = step_index.template_of(item)
        if template is None:
            continue
        example = getattr(item, "callspec", None) and item.callspec.params.get("_pytest_bdd_example", {})
        scenario = template.render(example or {})
        try:
            rel = Path(scenario.feature.filename).relative_to(rootpath).as_posix()
        except ValueError:
            rel = scenario.feature.filename
        for step in scenario.steps:
            key = (step.type, step.name)
            if key not in verdicts:
                verdicts[key] = step_problem(step.type, step.name, _visible(step, fixturemanager, item))
            if verdicts[key]:
                problems[f"{rel}:{step.line_number}: {verdicts[key]}"] = None
    return list(problems)


def _visible(step, fixturemanager, item) -> list[StepDef]:
    """Matching definitions at the closest scope: a closer one overriding a farther one is pytest-bdd's rule
    and fine; two at the same scope is the silent last-one-wins we refuse."""
    fixturedefs = step_index.index_of(fixturemanager).find(step, item)
    if not fixturedefs:
        return []
    depth = max(len(list(iterparentnodeids(fd.baseid))) for fd in fixturedefs)
    closest = [fd for fd in fixturedefs if len(list(iterparentnodeids(fd.baseid))) == depth]
    return [StepDef.from_context(ctx) for fd in closest if (ctx := context_of(fd.func)) is not None]


# --- allure: scenarios that never start ------------------------------------------------------------------


@pytest.hookimpl(wrapper=True)
def pytest_runtest_setup(item: pytest.Item):
    """allure-pytest-bdd 2.16.2 opens a scenario's result in pytest_bdd_before_scenario, which never runs
    when setup fails or skips: @pending scenarios and a `sut` fixture that cannot start would be missing from
    the report. Open the result ourselves then; its setup report fills in skipped/broken and the steps."""
    try:
        return (yield)
    except BaseException:
        _open_allure_result(item)
        raise


def _open_allure_result(item: pytest.Item) -> None:
    template = step_index.template_of(item)
    listener = next(
        (p for p in item.config.pluginmanager.get_plugins() if type(p).__name__ == "PytestBDDListener"), None
    )
    if template is None or listener is None:
        return
    example = getattr(item, "callspec", None) and item.callspec.params.get("_pytest_bdd_example", {})
    # The listener registers a finalizer that lists the steps not run; the item may not be set up (a skip
    # mark fires first), so run it now: every step of a scenario that never started is "skipped".
    finalizers: list = []
    item.addfinalizer = finalizers.append
    try:
        listener.pytest_bdd_before_scenario(
            request=item._request, feature=template.feature, scenario=template.render(example or {})
        )
        for finalizer in finalizers:
            finalizer()
    except Exception as exc:  # the report is secondary: never hide the setup outcome behind our own error
        item.warn(pytest.PytestWarning(f"could not open an allure result for a scenario that did not start: {exc}"))
    finally:
        del item.addfinalizer


# --- labels and selection -------------------------------------------------------------------------------


def _label(kind: str, *values: str) -> pytest.MarkDecorator:
    return pytest.mark.allure_label(*values, label_type=kind)


def _link_pattern(config: pytest.Config, link_type: str) -> str | None:
    """allure-pytest-bdd's --allure-link-pattern TYPE:PATTERN, which it applies only to allure.dynamic links."""
    patterns = dict(getattr(config.option, "allure_link_pattern", None) or [])
    return patterns.get(link_type)


def _decorate(item: pytest.Item, reg: Registry | None) -> None:
    # Tags reach us from a set: sort, so labels and the report are the same from run to run.
    item_ids, reqs, profiles = (sorted(set(_values(item, kind))) for kind in ("item", "req", "profile"))
    # -k R-CTL-01 / -k NET-03 then work, not only the python-ised test name (test_rctl01_...).
    item.extra_keyword_matches.update(item_ids + reqs)
    for item_id in item_ids:
        entry = reg.items.get(item_id) if reg else None
        if entry is not None:
            cls = reg.classes[entry.cls]
            item.add_marker(_label("epic", cls.title))
            item.add_marker(_label("feature", cls.categories[entry.category].title))
            item.add_marker(_label("story", f"{entry.id} {entry.title}"))
        else:
            item.add_marker(_label("story", item_id))
        item.add_marker(_label("tag", f"item:{item_id}"))
    tms = _link_pattern(item.config, "tms")
    known = _requirements(item.config)
    for req in reqs:
        item.add_marker(_label("requirement", req))
        item.add_marker(_label("tag", f"req:{req}"))
        if tms:  # a tracker given with --allure-link-pattern tms:...: link there
            item.add_marker(pytest.mark.allure_link(tms.format(req), name=req, link_type="tms"))
        elif req in known:  # else its line in docs/requirements.md, relative to reports/html/index.html
            item.add_marker(pytest.mark.allure_link(f"../../docs/requirements.md#L{known[req].line}",
                                                    name=f"{req} (requirements.md line {known[req].line})",
                                                    link_type="tms"))
    for profile in profiles:
        item.add_marker(_label("tag", f"profile:{profile}"))
    item.add_marker(pytest.mark.allure_description(_reviewers_view(item, reg, item_ids, reqs, profiles)))


def _reviewers_view(item: pytest.Item, reg: Registry | None, item_ids: list[str], reqs: list[str],
                    profiles: list[str]) -> str:
    """The scenario page's description (Markdown): what a reviewer signs off, on the page itself: the test
    item and its title, the profile, the full text of every requirement verified (not only its ID), then
    the feature's and the scenario's own description as allure-pytest-bdd would have shown them."""
    texts = _requirements(item.config)
    lines = []
    for item_id in item_ids:
        entry = reg.items.get(item_id) if reg else None
        lines += [f"**Test item** {item_id}" + (f": {entry.title}" if entry is not None else ""), ""]
    lines.append(f"**Profile** {', '.join(profiles) or 'any'}")
    if reqs:
        lines += ["", "**Requirements verified**", ""]
        lines += [f"- **{req}** {texts[req].text if req in texts else '(not in docs/requirements.md)'}"
                  for req in reqs]
    template = step_index.template_of(item)
    own = [text for text in (_text(getattr(template.feature, "description", None)),
                             _text(getattr(template, "description", None))) if text]
    return "\n".join(lines + ["", *own] if own else lines)


def _text(description: object) -> str:
    if isinstance(description, list):
        description = "\n".join(description)
    return description.strip() if isinstance(description, str) else ""


_REQ_TEXTS = pytest.StashKey[dict]()


def _requirements(config: pytest.Config) -> dict:
    if _REQ_TEXTS not in config.stash:
        from outline.tree.requirements import load_requirements

        path = Path(config.rootpath) / "docs" / "requirements.md"
        config.stash[_REQ_TEXTS] = load_requirements(path) if path.is_file() else {}
    return config.stash[_REQ_TEXTS]


def _wanted(config: pytest.Config, option: str) -> list[str]:
    return [v.strip().upper() for raw in config.getoption(option) for v in raw.split(",") if v.strip()]


@pytest.hookimpl(tryfirst=True)  # labels and keywords must be in place before -k / -m deselect
def pytest_collection_modifyitems(session: pytest.Session, config: pytest.Config, items: list[pytest.Item]) -> None:
    reg = registry(config)
    for item in items:
        if step_index.template_of(item) is not None:
            _decorate(item, reg)

    want_items, want_reqs = _wanted(config, "item"), _wanted(config, "req")
    if not (want_items or want_reqs):
        return
    hits = {("item", v): 0 for v in want_items} | {("req", v): 0 for v in want_reqs}
    keep, drop = [], []
    for item in items:
        matched = [k for k in hits if k[1] in (v.upper() for v in _values(item, k[0]))]
        for key in matched:
            hits[key] += 1
        (keep if matched else drop).append(item)
    missing = [f"--{kind} {value}" for (kind, value), n in hits.items() if n == 0]
    if missing:
        raise pytest.UsageError(f"{', '.join(missing)}: no collected scenario carries it")
    if drop:
        config.hook.pytest_deselected(items=drop)
    items[:] = keep
