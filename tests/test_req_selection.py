"""`--req X` alone must reject a train that breaks X, run as a user runs it (issue 31, item 4).

tests/test_faulty_variants.py already holds every faulty variant to this through its shared run, which keeps
for each variant the scenarios tagged with the requirement it breaks (tests/variant_plan.py, the selection
`--req` makes). This file runs the command itself, `pytest features --sut <variant> --req <requirement>`, one
process per variant, and expects exit 1 from a failed scenario: so a change to how `--req` selects cannot leave
the shared run's selection and the user's apart unseen.

`make test` runs a sample: the held-out faults that only scenarios tagged with other requirements caught before
(a reverse-direction refusal under ILK-08, a late life-signal check under TCN-06, a C019 that clears itself
under VDX-06) and the two close CFSK faults (ATP-05). `make req-sweep` (REQ_SWEEP=1) runs every faulty variant
of tests/variants.py so, about half a minute each.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.variants import (FAULTY, C019Clears, CfskFaultsRecordedOnceAWhile, LateLifeSignalCheck,
                            ReverseRefused)

ROOT = Path(__file__).resolve().parents[1]

SAMPLE = [
    (ReverseRefused, "ILK-08", 40),
    (LateLifeSignalCheck, "TCN-06", 30),
    (C019Clears, "VDX-06", 30),
    (CfskFaultsRecordedOnceAWhile, "ATP-05", 20),
]
SWEEP = os.environ.get("REQ_SWEEP") == "1"
CASES = [(variant, requirement, 30) for variant, requirement, _ in FAULTY] if SWEEP else SAMPLE


def test_the_sample_breaks_the_requirements_it_is_run_for() -> None:
    # The sample's pairs are faulty variants as tests/variants.py lists them, not pairs of this file's own.
    listed = {(variant, requirement) for variant, requirement, _ in FAULTY}
    assert {(variant, requirement) for variant, requirement, _ in SAMPLE} <= listed


@pytest.mark.parametrize(("variant", "requirement"),
                         [pytest.param(v, r, id=f"{v.__name__}-{r}", marks=pytest.mark.cost(cost))
                          for v, r, cost in CASES])
def test_req_alone_rejects_a_variant_that_breaks_it(variant: type, requirement: str) -> None:
    # -x: the first failed scenario is the verdict; the rest of the selection would only cost time.
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "features", "-q", "-x", "-p", "no:cacheprovider", "-p", "no:xdist",
         f"--sut=tests.variants:{variant.__name__}", f"--req={requirement}"],
        cwd=ROOT, capture_output=True, text=True, timeout=1500)
    tail = result.stdout[-3000:] + result.stderr[-2000:]
    assert result.returncode == 1, f"--req {requirement} exit {result.returncode} for {variant.__name__}:\n{tail}"
    # Rejected by a Then that fails, not by the suite reading outside the contract.
    assert "ContractGap" not in result.stdout, tail
    assert any(line.startswith("FAILED") for line in result.stdout.splitlines()) or " failed" in result.stdout, tail
