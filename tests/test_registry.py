from pathlib import Path

import pytest

from outline.tree.registry import RegistryError, load_registry

from tests.helpers import DATA, REPO


def test_good_registry_loads():
    reg = load_registry(DATA / "good" / "features" / "registry.yaml")
    assert set(reg.classes) == {"routine", "function"}
    assert reg.classes["routine"].categories["control"].code == "CTL"
    item = reg.items["R-CTL-01"]
    assert item.requirements == ("CMD-02", "PRO-01", "TST-03")
    assert item.partly == {"PRO-01": "8-car set only"}
    assert reg.item_for_feature("features/routine/control/R-CTL-01.feature") is item
    assert reg.required_coverage == ("NET-03", "PRO-01")


def test_real_registry_skeleton():
    reg = load_registry(REPO / "features" / "registry.yaml")
    assert [c.code for c in reg.classes.values()] == ["H", "R", "F"]
    assert len(reg.classes["hardware-software"].categories) == 8
    assert list(reg.classes["routine"].categories) == ["display", "control", "diagnosis"]
    assert len(reg.classes["function"].categories) == 14
    assert reg.classes["function"].categories["network-transmission-redundancy"].code == "NET"
    for cls in reg.classes.values():
        for key in cls.categories:
            assert (REPO / "features" / cls.key / key).is_dir(), f"missing folder features/{cls.key}/{key}"


BAD = """\
classes:
  routine:
    code: R
    title: Routine
    categories:
      control: {code: CTL, title: Control}
required_coverage: [NET-03, bogus]
items:
  - id: R-CTL-01
    class: routine
    category: control
    title: ok
    requirements: [NET-03]
    feature: features/routine/control/R-CTL-01.feature
  - id: R-CTL-01
    class: routine
    category: control
    title: duplicate
    requirements: [NET-03]
    feature: features/routine/control/R-CTL-01.feature
  - id: R-DSP-02
    class: routine
    category: control
    title: prefix does not match category
    requirements: [NET-03]
    partly: {PRO-01: "not one of its requirements"}
    feature: features/routine/display/R-DSP-02.feature
  - id: F-NET-01
    class: function
    category: net
    title: unknown class
    requirements: []
    feature: x
    colour: blue
"""


def test_bad_registry_reports_every_problem_with_its_line(tmp_path: Path):
    path = tmp_path / "registry.yaml"
    path.write_text(BAD)
    with pytest.raises(RegistryError) as caught:
        load_registry(path)
    problems = caught.value.problems
    messages = "\n".join(f"{line}: {msg}" for line, msg in problems)
    assert "1: required_coverage: 'bogus' is not a requirement ID" in messages
    assert "15: item R-CTL-01: duplicate id (first at line 9)" in messages
    assert "21: item R-DSP-02: id prefix must be R-CTL- for routine/control" in messages
    assert "21: item R-DSP-02: partly names PRO-01, which is not in its requirements" in messages
    assert "21: item R-DSP-02: feature must be features/routine/control/R-DSP-02.feature" in messages
    assert "28: item F-NET-01: unknown key 'colour'" in messages
    assert "28: item F-NET-01: unknown class 'function'" in messages
    assert "28: item F-NET-01: requirements must be a non-empty list of IDs" in messages
    assert str(path) in str(caught.value)


def test_invalid_yaml_names_the_line(tmp_path: Path):
    path = tmp_path / "registry.yaml"
    path.write_text("classes:\n  routine: {code: R\nitems: []\n")
    with pytest.raises(RegistryError) as caught:
        load_registry(path)
    assert caught.value.problems[0][0] == 3
    assert "invalid YAML" in caught.value.problems[0][1]
