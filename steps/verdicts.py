"""Verdicts besides pass and fail (ISO/IEC 9646): "not applicable", for a scenario that needs an option the
SUT's implementation declaration does not claim. Reported as a skip whose reason starts with NOT_APPLICABLE,
counted apart from other skips in the summary and the Allure report (outline/summary.py, allure_meta.py)."""
from __future__ import annotations

import pytest

from outline.summary import NOT_APPLICABLE     # the summary and the Allure category read the same words


def not_applicable(why: str) -> None:
    """End the scenario as not applicable to this SUT (found at run time: an option it does not claim)."""
    pytest.skip(NOT_APPLICABLE + why)
