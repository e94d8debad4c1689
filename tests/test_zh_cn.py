"""The routine class in `# language: zh-CN` (issue 8): same step functions, Chinese sentences. Both languages
must give the same verdicts, item by item, on the reference (all pass) and on a faulty variant (the same
scenarios fail)."""
from __future__ import annotations

import re
from collections import Counter

import pytest

from tests.test_faulty_variants import ROOT, run_features

ROUTINE = "R-CTL-01,R-CTL-02,R-CTL-03,R-DIA-01,R-DIA-02,R-DIA-03,R-DSP-01"
CJK = re.compile(r"[\u4e00-\u9fff]")
OUTCOME = re.compile(r"^(PASSED|FAILED|SKIPPED|ERROR) features/test_outline\.py::test_(r[a-z]{3}\d\d)_(\S+)")


def _verdicts(variant: str | None) -> dict[str, Counter]:
    """{"en"/"zh": Counter((item, outcome))} from one run of the routine items."""
    result = run_features(None, f"--item={ROUTINE}", "-rA",
                          sut=variant or "reference")
    found = {"en": Counter(), "zh": Counter()}
    for line in result.stdout.splitlines():
        match = OUTCOME.match(line)
        if match:
            outcome, item, name = match.groups()
            found["zh" if CJK.search(name) else "en"][(item, outcome)] += 1
    assert sum(found["en"].values()) >= 17, result.stdout[-2000:]
    return found


def test_every_routine_item_has_a_zh_cn_feature() -> None:
    for item in ROUTINE.split(","):
        english = next((ROOT / "features" / "routine").rglob(f"{item}.feature"))
        chinese = english.with_name(f"{item}.zh-CN.feature")
        assert chinese.is_file(), f"{item} has no zh-CN feature"
        assert chinese.read_text(encoding="utf-8").startswith("# language: zh-CN\n")
        count = lambda text, words: sum(1 for line in text.splitlines() if line.strip().startswith(words))  # noqa: E731
        assert count(chinese.read_text(encoding="utf-8"), ("场景:", "场景大纲:")) == \
            count(english.read_text(encoding="utf-8"), ("Scenario:", "Scenario Outline:")), item


@pytest.mark.parametrize("variant", [None, "tests.variants:SlowTakeover", "tests.variants:FullNotchesOnDigitalOutputs"],
                         ids=["reference", "SlowTakeover", "FullNotchesOnDigitalOutputs"])
def test_both_languages_give_the_same_verdicts(variant: str | None) -> None:
    found = _verdicts(variant)
    assert found["zh"] == found["en"], f"English {dict(found['en'])} vs zh-CN {dict(found['zh'])}"
    if variant is None:
        assert {outcome for _, outcome in found["en"]} == {"PASSED"}
    else:
        assert any(outcome == "FAILED" for _, outcome in found["en"]), f"{variant} was not rejected"
