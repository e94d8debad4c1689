"""Verdicts besides pass and fail (ISO/IEC 9646):
- "not applicable", for a scenario that needs an option the SUT's implementation declaration does not claim:
  a skip whose reason starts with NOT_APPLICABLE;
- "informative deviation", for a failed Then of an `@informative` scenario (a check of what no requirement
  states, docs/decisions.md): an xfail whose reason starts with INFORMATIVE, so it never fails conformance
  and the reviewer still sees what the SUT did.
Both are counted apart from other skips in the summary and the Allure report (outline/report/summary.py,
allure_meta.py)."""
from __future__ import annotations

import pytest

from outline.report.summary import INFORMATIVE, NOT_APPLICABLE   # the summary and the Allure categories read the same words
from sut.contract.catalogue import ContractBreach


def not_applicable(why: str) -> None:
    """End the scenario as not applicable to this SUT (found at run time: an option it does not claim)."""
    pytest.skip(NOT_APPLICABLE + why)


def informative(item: pytest.Item, error: BaseException) -> bool:
    """Whether `error`, raised by a scenario, is an informative deviation: an assertion of an @informative
    scenario. A SUT answering outside its contract (ContractBreach) still fails: that is not a reading of a
    requirement but a broken interface."""
    return (item.get_closest_marker("informative") is not None and isinstance(error, AssertionError)
            and not isinstance(error, ContractBreach))


def as_informative(error: BaseException) -> None:
    pytest.xfail(INFORMATIVE + (str(error).strip().splitlines() or ["a Then did not hold"])[0])
