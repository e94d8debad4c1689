import pytest

from outline.tree import tags
from outline.plugin.pytest_plugin import pytest_bdd_apply_tag


def _marks(function):
    return [(m.name, m.args, m.kwargs) for m in function.pytestmark]


@pytest.mark.parametrize(
    ("tag", "expected"),
    [
        ("item:R-CTL-01", [("item", ("R-CTL-01",), {})]),
        ("req:NET-03", [("req", ("NET-03",), {})]),
        ("profile:crh2", [("profile", ("crh2",), {})]),
        ("tentative", [("tentative", (), {})]),
        ("pending", [("pending", (), {}), ("skip", (), {"reason": "pending"})]),
    ],
)
def test_known_tags_become_marks(tag, expected):
    def scenario():
        pass

    assert pytest_bdd_apply_tag(tag, scenario) is True
    assert _marks(scenario) == expected


def test_unknown_kind_fails_loudly():
    with pytest.raises(tags.TagError, match=r"unknown tag kind @reqs:NET-03 \(known kinds: @item:, @req:, @profile:, @option:\)"):
        pytest_bdd_apply_tag("reqs:NET-03", lambda: None)


def test_empty_value_fails():
    with pytest.raises(tags.TagError, match="has no value"):
        tags.classify("req:")


def test_other_plain_tags_go_to_pytest_bdd_default():
    # pytest-bdd then does getattr(pytest.mark, tag): --strict-markers rejects unregistered names.
    assert pytest_bdd_apply_tag("slow", lambda: None) is None
