from pathlib import Path

import pytest

from outline.plugin.binding import feature_paths

from tests.helpers import DATA


def test_lists_every_feature_relative_to_the_folder():
    assert feature_paths(DATA / "good" / "features") == [
        "function/network-transmission-redundancy/F-NET-01.feature",
        "routine/control/R-CTL-01.feature",
    ]


def test_empty_tree_binds_nothing(tmp_path: Path):
    (tmp_path / "features" / "routine").mkdir(parents=True)
    assert feature_paths(tmp_path / "features") == []


def test_bad_files_become_one_collection_error(tmp_path: Path):
    features = tmp_path / "features"
    (features / "a").mkdir(parents=True)
    (features / "a" / "broken.feature").write_text("Feature: x\n  Scenario: a\n    And oops\n")
    (features / "a" / "dup.feature").write_text(
        "Feature: y\n  @reqs:NET-03\n  Scenario: t\n    Given a\n  Scenario: t\n    Given b\n"
    )
    with pytest.raises(pytest.Collector.CollectError) as caught:
        feature_paths(features)
    assert str(caught.value).splitlines() == [
        "features/a/broken.feature:3: first step must start with Given, When or Then, not And",
        "features/a/dup.feature:2: unknown tag kind @reqs:NET-03 (known kinds: @item:, @req:, @profile:, @option:)",
        'features/a/dup.feature:5: duplicate scenario title "t" (first at line 3); '
        "pytest-bdd would silently run only one of them",
    ]
