"""What a scenario leaves in the Allure report: the SUT's trace and its parameters."""
from __future__ import annotations

import allure
import pytest

from sut.driver import TrainDriver

_ENV_WRITTEN = "_crh2_env_written"


def attach_run(driver: TrainDriver, request: pytest.FixtureRequest) -> None:
    if not driver.powered:
        return
    trace = driver.trace
    allure.attach(trace.to_csv(), name=f"SUT trace ({len(trace)} events, t in ms)",
                  attachment_type=allure.attachment_type.CSV)
    _write_environment(driver, request.config)


def _write_environment(driver: TrainDriver, config: pytest.Config) -> None:
    results_dir = getattr(config.option, "allure_report_dir", None)
    if not results_dir or getattr(config, _ENV_WRITTEN, False):
        return
    from outline.allure_env import write_environment

    write_environment(results_dir, driver.describe())
    setattr(config, _ENV_WRITTEN, True)
