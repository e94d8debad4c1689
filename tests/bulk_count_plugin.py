"""Loaded by tests/test_bulk.py into a run of the features: counts the steady periods bulk advance skipped
(an advance leaves no mark in the trace, so the run itself is the only witness) and prints the figure."""
from __future__ import annotations

import pytest

from sut.reference import bulk

SKIPPED: list[int] = []


def pytest_configure(config: pytest.Config) -> None:
    skip = bulk._skip

    def counted(train, window, until, period):
        periods = skip(train, window, until, period)
        if periods:
            SKIPPED.append(periods * period)
        return periods

    bulk._skip = counted


def pytest_unconfigure(config: pytest.Config) -> None:
    print(f"BULK SKIPPED {len(SKIPPED)} {sum(SKIPPED)}")
