from pathlib import Path

from outline.tree.check import check_tree
from outline.tree.paths import Tree
from outline.plugin.stepdefs import definitions_in_modules

from tests.helpers import DATA


def test_good_tree_passes(data_on_path):
    data_on_path("good")
    result = check_tree(Tree.at(DATA / "good"), definitions_in_modules(["good_steps"]), shared=[])
    assert result.problems == []
    assert result.warnings == []
    assert len(result.features) == 2


BAD_EXPECTED = [
    "features/registry.yaml:9: required coverage: NET-05 is carried by no scenario",
    "features/registry.yaml:17: item R-CTL-02: feature file features/routine/control/R-CTL-02.feature does not exist",
    "features/routine/control/R-CTL-01.feature:1: @req tags differ from registry item R-CTL-01 "
    "(in registry only: PRO-01; in @req tags only: NET-03, XXX-99)",
    'features/routine/control/R-CTL-01.feature:7: ambiguous step "Then the notch is 3" matches 2 definitions: '
    "bad_steps:16 ('the notch is {notch:d}'); bad_steps:21 ('the notch is 3')",
    'features/routine/control/R-CTL-01.feature:10: duplicate scenario title "R-CTL-01 Same title twice" '
    "(first at line 4); pytest-bdd would silently run only one of them",
    "features/routine/control/R-CTL-01.feature:13: @req:XXX-99: XXX-99 is not defined in docs/requirements.md",
    'features/routine/control/R-CTL-01.feature:14: scenario "Title without the item ID" is tagged @item:R-CTL-02; '
    "the file is item R-CTL-01",
    'features/routine/control/R-CTL-01.feature:14: scenario title "Title without the item ID" must start with '
    '"R-CTL-01 "',
    'features/routine/control/R-CTL-01.feature:18: scenario "R-CTL-01 No requirement tag" has no @req: tag',
    'features/routine/control/R-CTL-01.feature:20: unknown step "Given the driver does something"',
    "features/routine/control/R-CTL-01.feature:22: unknown tag kind @reqs:PRO-01 (known kinds: @item:, @req:, "
    "@profile:, @option:)",
    'features/routine/control/R-CTL-01.feature:23: scenario "R-CTL-01 Typo in a tag kind" has no @req: tag',
    "features/routine/control/R-CTL-09.feature: not listed in features/registry.yaml",
    "features/routine/display/R-CTL-03.feature: file name must be the item ID, R-DSP-<nn>.feature in this folder",
    "features/routine/display/R-CTL-03.feature: not listed in features/registry.yaml",
]


def test_bad_tree_reports_each_problem_once_with_file_and_line(data_on_path):
    data_on_path("bad")
    result = check_tree(Tree.at(DATA / "bad"), definitions_in_modules(["bad_steps"]), shared=[])
    assert [str(p) for p in sorted(result.problems)] == BAD_EXPECTED


def test_steps_are_optional(data_on_path):
    result = check_tree(Tree.at(DATA / "bad"), None, shared=[])
    assert not any("step" in p.message for p in result.problems if "scenario" not in p.message)


def test_shared_baseline_difference_is_a_warning(tmp_path: Path):
    copy = tmp_path / "requirements.md"
    copy.write_text("- NET-03 something else\n")
    result = check_tree(Tree.at(DATA / "good"), None, shared=[copy])
    assert [str(w) for w in result.warnings] == [
        f"docs/requirements.md: differs from {copy}; which one is the baseline?"
    ]
    assert result.problems == []


def test_examples_tags_must_be_plain(tmp_path: Path):
    for sub in ("docs", "features/routine/control"):
        (tmp_path / sub).mkdir(parents=True)
    (tmp_path / "docs/requirements.md").write_text("- NET-03 x\n")
    (tmp_path / "features/registry.yaml").write_text(
        "classes: {routine: {code: R, title: R, categories: {control: {code: CTL, title: C}}}}\n"
        "required_coverage: []\nitems:\n"
        "  - {id: R-CTL-01, class: routine, category: control, title: t, requirements: [NET-03],"
        " feature: features/routine/control/R-CTL-01.feature}\n"
    )
    (tmp_path / "features/routine/control/R-CTL-01.feature").write_text(
        "@item:R-CTL-01 @req:NET-03\nFeature: f\n  Scenario Outline: R-CTL-01 o\n    Given <x>\n\n"
        "    @req:NET-03\n    Examples:\n      | x |\n      | 1 |\n"
    )
    result = check_tree(Tree.at(tmp_path), None, shared=[])
    assert [str(p) for p in result.problems] == [
        "features/routine/control/R-CTL-01.feature:6: @req:NET-03: kind:value tags cannot go on Examples"
    ]


def _good_tree_with(tmp_path: Path, extra: str) -> Tree:
    import shutil

    shutil.copytree(DATA / "good", tmp_path / "good")
    registry = tmp_path / "good" / "features" / "registry.yaml"
    registry.write_text(registry.read_text(encoding="utf-8") + extra, encoding="utf-8")
    return Tree.at(tmp_path / "good")


def test_out_of_scope_makes_every_requirement_need_an_item_or_a_reason(tmp_path: Path):
    # NET-01 is claimed by no item of the good tree: silent without out_of_scope, a problem with it.
    tree = _good_tree_with(tmp_path, "out_of_scope: {}\n")
    problems = [str(p) for p in check_tree(tree, None, shared=[]).problems]
    assert problems == ["features/registry.yaml:28: NET-01 is claimed by no item and not listed in out_of_scope "
                        "with a reason"]


def test_out_of_scope_with_a_reason_is_accepted(tmp_path: Path):
    tree = _good_tree_with(tmp_path, 'out_of_scope:\n  NET-01: "Two levels: the layout, not behaviour"\n')
    assert check_tree(tree, None, shared=[]).problems == []


def test_out_of_scope_must_give_a_reason_and_not_name_a_claimed_requirement(tmp_path: Path):
    tree = _good_tree_with(tmp_path, 'out_of_scope:\n  NET-01: ""\n  NET-03: "duplicate"\n')
    problems = [str(p) for p in check_tree(tree, None, shared=[]).problems]
    assert any("out_of_scope: NET-01 needs a reason" in p for p in problems), problems
    tree = _good_tree_with(tmp_path / "again", 'out_of_scope:\n  NET-01: "layout"\n  NET-03: "duplicate"\n')
    problems = [str(p) for p in check_tree(tree, None, shared=[]).problems]
    assert problems == ["features/registry.yaml:28: out_of_scope: NET-03 is claimed by item F-NET-01; take it out"]


def test_a_translation_is_listed_by_its_item_and_named_after_it(tmp_path: Path):
    import shutil

    shutil.copytree(DATA / "good", tmp_path / "good")
    root = tmp_path / "good"
    registry = root / "features" / "registry.yaml"
    english = root / "features" / "routine" / "control" / "R-CTL-01.feature"
    (english.parent / "R-CTL-01.zh-CN.feature").write_text(english.read_text(encoding="utf-8"), encoding="utf-8")
    text = registry.read_text(encoding="utf-8")
    # unlisted: a problem like any other unknown feature file
    assert "features/routine/control/R-CTL-01.zh-CN.feature: not listed in features/registry.yaml" in \
        [str(p) for p in check_tree(Tree.at(root), None, shared=[]).problems]
    listed = text.replace("    feature: features/routine/control/R-CTL-01.feature\n",
                          "    feature: features/routine/control/R-CTL-01.feature\n"
                          "    translations: [features/routine/control/R-CTL-01.zh-CN.feature]\n")
    registry.write_text(listed, encoding="utf-8")
    assert check_tree(Tree.at(root), None, shared=[]).problems == []
    registry.write_text(listed.replace("R-CTL-01.zh-CN.feature]", "R-CTL-01-chinese.feature]"), encoding="utf-8")
    problems = [str(p) for p in check_tree(Tree.at(root), None, shared=[]).problems]
    assert any("a translation is features/routine/control/R-CTL-01.<language>.feature" in p for p in problems), problems
