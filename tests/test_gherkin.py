from pathlib import Path

import pytest

from outline.tree.gherkin import FeatureParseError, parse_feature

from tests.helpers import DATA

GOOD = DATA / "good" / "features"


def test_tags_are_inherited_and_steps_typed():
    feature = parse_feature(GOOD / "routine" / "control" / "R-CTL-01.feature")
    assert feature.name == "R-CTL-01 Traction and brake command transmission"
    first, second = feature.scenarios
    assert first.title == "R-CTL-01 Traction notch reaches every car"
    assert first.line == 9
    assert first.tag_names == {"item:R-CTL-01", "req:CMD-02", "req:TST-03", "profile:crh2"}
    assert second.tag_values("req") == ["PRO-01"]
    assert "tentative" in second.tag_names
    # Background first; "And" takes the type of the step before it.
    assert [(s.keyword, s.type, s.line) for s in second.steps] == [
        ("Given", "given", 6),
        ("When", "when", 15),
        ("Then", "then", 16),
        ("And", "then", 17),
    ]


def test_outline_instances_render_each_example_row():
    feature = parse_feature(GOOD / "function" / "network-transmission-redundancy" / "F-NET-01.feature")
    outline = feature.scenarios[0]
    instances = outline.instances()
    assert [line for line, _ in instances] == [12, 13]
    assert instances[1][1][1].text == "the link between car 8 and car 1 is cut"
    assert outline.steps[1].text == "the link between car <a> and car <b> is cut"


def test_duplicate_titles_are_all_kept():
    feature = parse_feature(DATA / "bad" / "features" / "routine" / "control" / "R-CTL-01.feature")
    titles = [s.title for s in feature.scenarios]
    assert titles.count("R-CTL-01 Same title twice") == 2


@pytest.mark.parametrize(
    ("text", "line", "fragment"),
    [
        ("Feature: x\n  Scenario: a\n    And oops\n", 3, "must start with Given, When or Then"),
        ("Feature: x\n  Scenario: a\n    Given ok\nFeature: y\n", 4, "Multiple features"),
        ("", 1, "no Feature"),
    ],
)
def test_malformed_files_name_their_line(tmp_path: Path, text, line, fragment):
    path = tmp_path / "x.feature"
    path.write_text(text)
    with pytest.raises(FeatureParseError) as caught:
        parse_feature(path)
    assert caught.value.line == line
    assert fragment in caught.value.message


def test_rules_inherit_tags_and_backgrounds(tmp_path: Path):
    path = tmp_path / "r.feature"
    path.write_text(
        "@item:X\nFeature: f\n  Background:\n    Given a\n"
        "  @req:NET-03\n  Rule: r\n    Background:\n      Given b\n"
        "    Scenario: s\n      Then c\n"
    )
    (scenario,) = parse_feature(path).scenarios
    assert scenario.rule == "r"
    assert scenario.tag_names == {"item:X", "req:NET-03"}
    assert [s.text for s in scenario.steps] == ["a", "b", "c"]
