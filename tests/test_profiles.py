"""Train profiles: a SUT declares the profiles it implements; scenarios of other profiles are skipped with
that reason (never run, never passed), and --profile picks among the declared ones."""
from __future__ import annotations

import pytest

from sut.backends import open_backend
from sut.errors import UnknownName
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.metro.backend import ReferenceMetro
from tests.test_faulty_variants import ROOT, run_features


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
    result = run_features(ReferenceTrain, "--profile=etcs", sut="reference")
    assert result.returncode == 4
    assert "--profile etcs: the SUT Reference declares crh2, metro-tcn, atp" in result.stderr


def test_the_reference_opens_the_train_of_each_profile() -> None:
    assert isinstance(open_backend("reference", "crh2"), ReferenceTrain)
    assert isinstance(open_backend("reference", "metro-tcn"), ReferenceMetro)
    assert isinstance(open_backend("reference"), ReferenceTrain)
    with pytest.raises(UnknownName, match="no profile of the reference named .etcs."):
        open_backend("reference", "etcs")


def test_profile_metro_runs_only_the_metro_scenarios() -> None:
    metro, items = _scenarios_tagged("@profile:metro-tcn")
    result = run_features(ReferenceMetro, "--profile=metro-tcn", "--co", sut="reference")
    collected = [line for line in result.stdout.splitlines() if "::" in line]
    prefixes = tuple("::test_" + item.lower().replace("-", "") for item in items)
    strangers = [c for c in collected if prefixes and not any(p in c for p in prefixes)]
    assert len(collected) == metro and not strangers, result.stdout[-1500:]


def test_a_crh2_only_sut_skips_every_metro_scenario() -> None:
    result = run_features(ReferenceTrain, "--item=F-NET-22", "-rs", sut="sut.reference.crh2.backend:ReferenceTrain")
    summary = result.stdout.strip().splitlines()[-1]
    assert result.returncode == 0 and "skipped" in summary and "passed" not in summary, summary
    assert "profile metro-tcn: the SUT ReferenceTrain declares crh2" in result.stdout


def _scenarios_tagged(tag: str) -> tuple[int, list[str]]:
    """Cases (examples expanded) of the feature files carrying `tag`, counted from the files themselves
    (English and zh-CN keywords), and the items of those files."""
    total, items = 0, []
    for path in (ROOT / "features").rglob("*.feature"):
        lines = path.read_text(encoding="utf-8").splitlines()
        tags = next((line for line in lines if line.startswith("@")), "")   # after a "# language:" line
        if tag not in tags.split():
            continue
        items.append(path.name.split(".")[0])                                 # F-NET-24.zh-CN.feature
        total += sum(1 for line in lines if line.strip().startswith(("Scenario:", "场景:")))
        rows, in_examples = 0, False
        for line in lines:
            stripped = line.strip()
            if stripped.startswith(("Examples:", "例子:")):
                in_examples, header = True, True
                continue
            if in_examples and stripped.startswith("|"):
                if header:
                    header = False
                else:
                    rows += 1
            elif stripped:
                in_examples = False
        total += rows
    return total, items


def test_a_declared_profile_selects_its_scenarios() -> None:
    result = run_features(ReferenceTrain, "--profile=crh2", "--item=R-CTL-01", sut="reference")
    assert result.returncode == 0 and " passed" in result.stdout.strip().splitlines()[-1], result.stdout[-500:]
