"""Train profiles: a SUT declares the profiles it implements; scenarios of other profiles are skipped with
that reason (never run, never passed), and --profile picks among the declared ones."""
from __future__ import annotations

from sut.reference.backend import ReferenceTrain
from tests.test_faulty_variants import run_features


class MetroOnly(ReferenceTrain):
    """Declares only the metro profile: every CRH2 scenario must be skipped, not run."""
    PROFILES = ("metro-tcn",)


def test_scenarios_of_an_undeclared_profile_are_skipped_with_the_reason() -> None:
    result = run_features(MetroOnly, "--item=R-CTL-01", "-rs", sut="tests.test_profiles:MetroOnly")
    assert result.returncode == 0, result.stdout[-2000:]
    summary = result.stdout.strip().splitlines()[-1]
    assert "skipped" in summary and "passed" not in summary and "failed" not in summary, summary
    assert "profile crh2: the SUT MetroOnly declares metro-tcn" in result.stdout


def test_an_undeclared_profile_on_the_command_line_is_a_usage_error() -> None:
    result = run_features(ReferenceTrain, "--profile=metro-tcn", sut="reference")
    assert result.returncode == 4
    assert "--profile metro-tcn: the SUT ReferenceTrain declares crh2" in result.stderr


def test_a_declared_profile_selects_its_scenarios() -> None:
    result = run_features(ReferenceTrain, "--profile=crh2", "--item=R-CTL-01", sut="reference")
    assert result.returncode == 0 and " passed" in result.stdout.strip().splitlines()[-1], result.stdout[-500:]
