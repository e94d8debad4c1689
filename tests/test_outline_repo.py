"""The real tree: features/registry.yaml, every feature file, the step library and docs/requirements.md.

Same check as `python -m outline check`, including the step lint: a step matching no definition or several
(pytest-bdd would pick one silently) and duplicate scenario titles (pytest-bdd would drop one). It fails while
the registry and the features disagree, e.g. with the skeleton's `items: []` no scenario carries the
`required_coverage` IDs. Fix the tree, not this test.
"""

import pytest

from outline.tree.check import check_tree
from outline.tree.paths import REPO
from outline.plugin.stepdefs import definitions_in_modules
from steps import STEP_MODULES

pytestmark = pytest.mark.repo


def test_outline_check_passes_on_the_repository():
    result = check_tree(REPO, definitions_in_modules(STEP_MODULES))
    problems = "\n".join(map(str, sorted(result.problems)))
    assert not result.problems, f"python -m outline check reports:\n{problems}"


def test_every_feature_file_is_bound():
    """features/test_outline.py binds what the registry lists, and nothing the registry does not know."""
    from outline.plugin.binding import feature_paths
    from outline.tree.registry import load_registry

    registry = load_registry(REPO.registry)
    listed = {path for item in registry.items.values() for path in (item.feature, *item.translations)}
    bound = {f"features/{p}" for p in feature_paths(REPO.features, asked=set(registry.items))}
    assert bound == listed
    # Unasked, the @on_request campaign is left out, and only it.
    by_default = {f"features/{p}" for p in feature_paths(REPO.features, asked=set())}
    assert listed - by_default == {registry.items[i].feature for i in ("F-NET-32", "F-NET-33")}
