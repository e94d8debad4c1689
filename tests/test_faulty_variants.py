"""The features must reject a train that breaks one requirement, and accept one that differs only in band.

Each variant runs the real feature files through pytest in a subprocess, exactly as a user would with
`--sut tests.variants:<Variant>`; a run that fails proves the feature specifies that requirement. The faulty
variants share one run (`--sut` once per variant, tests/variant_plan.py keeps each on its own item): one
collection instead of one per variant.
"""
from __future__ import annotations

import fcntl
import json
import os
import subprocess
import sys
from collections import defaultdict
from pathlib import Path
from typing import Callable

import pytest

from tests.helpers import verdicts
from sut.reference.crh2.backend import ReferenceTrain
from tests.variants import FAULTY, FREEDOM, FREEDOM_CLASSES, IN_BAND

ROOT = Path(__file__).resolve().parents[1]


def run_features(variant: type, *args: str, sut: str | None = None) -> subprocess.CompletedProcess:
    cmd = [sys.executable, "-m", "pytest", "features", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
           f"--sut={sut or f'tests.variants:{variant.__name__}'}", *args]
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=1500)


def _once(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory, name: str,
          compute: Callable[[Path], dict[str, list[tuple[str, str]]]]) -> dict[str, list[tuple[str, str]]]:
    """compute(folder) once per pytest run, however many xdist workers ask: the first takes a lock in the
    run's shared temporary folder, computes and leaves the result there; the others wait and read it
    (pytest-xdist's pattern for session fixtures). `--dist loadgroup` with an xdist_group mark used to keep
    such tests on one worker, but silently stopped grouping under pytest 9.2 (pytest-dev/pytest-xdist#1386):
    each worker ran the whole shared run again."""
    base = tmp_path_factory.getbasetemp()
    shared = base.parent if hasattr(request.config, "workerinput") else base
    done = shared / f"{name}.json"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)                  # released when the file is closed
        if not done.exists():
            done.write_text(json.dumps(compute(shared)), encoding="utf-8")
        return json.loads(done.read_text(encoding="utf-8"))


def _run_variants(names: list[str], *args: str, env: dict[str, str] | None = None) -> dict[str, list[tuple[str, str]]]:
    """One run of the features against every named variant class (two workers); (test id, outcome) of each
    scenario, by variant."""
    suts = [f"--sut=tests.variants:{name}" for name in names]
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "features", "-q", "-rA", "-p", "no:cacheprovider", "-n", "2", *args, *suts],
        cwd=ROOT, capture_output=True, text=True, timeout=1500, env=dict(os.environ, **(env or {})))
    assert result.returncode in (0, 1), result.stdout[-3000:] + result.stderr[-3000:]
    # A faulty variant is rejected by a Then that fails, never by the suite asking it for something its
    # contract does not list (a ContractGap in a failure message's own reads would hide the verdict).
    gaps = sorted({line for line in result.stdout.splitlines() if "ContractGap" in line})
    assert not gaps, "the suite read outside the contract while rejecting a variant:\n" + "\n".join(gaps[:10])
    by_variant: dict[str, list[tuple[str, str]]] = defaultdict(list)
    for test_id, outcome in verdicts(result.stdout):
        # [<variant>] or [<variant>-<example>] (verdicts() cuts an id at its first space: no "]" then)
        params = test_id.rpartition("[")[2].rstrip("]") if "[" in test_id else ""
        found = [name for name in params.split("-") if name in names]
        if found:
            by_variant[found[0]].append((test_id, outcome))
    return by_variant


@pytest.fixture(scope="session")
def faulty_verdicts(request: pytest.FixtureRequest,
                    tmp_path_factory: pytest.TempPathFactory) -> dict[str, list[tuple[str, str, list[str]]]]:
    """(test id, outcome, requirement tags) of every scenario run against each faulty variant: those of its
    own test item and those tagged with the requirement it breaks (tests/variant_plan.py)."""
    def compute(folder: Path) -> dict[str, list[tuple[str, str, list[str]]]]:
        plan: dict[str, dict[str, list[str]]] = defaultdict(lambda: {"items": [], "reqs": []})
        for variant, requirement, item in FAULTY:
            plan[variant.__name__]["items"].append(item)
            plan[variant.__name__]["reqs"].append(requirement)
        plan_file = folder / "faulty-plan.json"
        plan_file.write_text(json.dumps(plan), encoding="utf-8")
        ran = _run_variants(list(plan), "-p", "tests.variant_plan", env={"CRH2_VARIANT_PLAN": str(plan_file)})
        tags: dict[str, list[str]] = {}
        for written in folder.glob(f"{plan_file.name}.*.reqs.json"):
            tags.update(json.loads(written.read_text(encoding="utf-8")))
        # verdicts() cuts a test id at its first space, as pytest's summary lines show it
        tags = {node_id.split(" ")[0]: reqs for node_id, reqs in tags.items()}
        return {name: [(test_id, outcome, tags[test_id]) for test_id, outcome in results]
                for name, results in ran.items()}

    return _once(request, tmp_path_factory, "faulty-verdicts", compute)


def test_at_least_twelve_requirements_have_a_faulty_variant() -> None:
    assert len({req for _, req, _ in FAULTY}) >= 12


@pytest.mark.cost(60)
def test_every_faulty_variant_ran_on_its_own_items(faulty_verdicts: dict) -> None:
    # Starts the shared run early on one worker; the tests below read it and run last (tests/conftest.py).
    missing = {variant.__name__ for variant, _, _ in FAULTY} - set(faulty_verdicts)
    assert not missing, f"no scenario ran against {sorted(missing)}"


@pytest.mark.cost(-1)
@pytest.mark.parametrize(("variant", "requirement", "item"), FAULTY,
                         ids=[f"{v.__name__}-{r}" for v, r, _ in FAULTY])
def test_features_reject_faulty_variant(faulty_verdicts: dict, variant: type, requirement: str, item: str) -> None:
    ran = faulty_verdicts.get(variant.__name__, [])
    item_tag = item.lower().replace("-", "")
    mine = [(test_id, outcome) for test_id, outcome, _ in ran if f"::test_{item_tag}" in test_id]
    assert mine, f"no scenario of {item} ran against {variant.__name__}: {ran[:5]}"
    assert any(outcome == "FAILED" for _, outcome in mine), \
        f"{variant.__name__} ({requirement}) was not rejected by {item}: {mine}"


@pytest.mark.cost(-1)
@pytest.mark.parametrize(("variant", "requirement", "item"), FAULTY,
                         ids=[f"{v.__name__}-{r}" for v, r, _ in FAULTY])
def test_the_requirement_a_faulty_variant_breaks_selects_a_scenario_that_rejects_it(
        faulty_verdicts: dict, variant: type, requirement: str, item: str) -> None:
    """Tag accuracy: `--req <requirement>` alone rejects the variant, so the traceability matrix is true
    where it says a requirement is verified."""
    ran = faulty_verdicts.get(variant.__name__, [])
    selected = [(test_id, outcome) for test_id, outcome, reqs in ran if requirement in reqs]
    assert selected, f"no scenario tagged @req:{requirement} ran against {variant.__name__}"
    rejecting = [(test_id, reqs) for test_id, outcome, reqs in ran if outcome == "FAILED"]
    assert any(outcome == "FAILED" for _, outcome in selected), (
        f"--req {requirement} alone does not reject {variant.__name__}; the scenarios that do carry "
        f"{[f'{test_id} {reqs}' for test_id, reqs in rejecting][:5]}")


def _in_band_cost(variant: type) -> float:
    """About the seconds of one core a run of the whole profile takes (tests/conftest.py starts the longest
    first)."""
    return 50 if issubclass(variant, ReferenceTrain) else 7


@pytest.mark.parametrize("variant", [pytest.param(v, id=v.__name__, marks=pytest.mark.cost(_in_band_cost(v)))
                                     for v in IN_BAND + FREEDOM])
def test_features_accept_in_band_variant(variant: type) -> None:
    # One single-process run each, not one shared run on two workers as for the faulty variants: each runs
    # every scenario of its profile, and a process of its own keeps all its powered-up snapshots (tried on
    # 2026-11-25: with one shared run, make test's own tests took 6 min 41 s instead of 6 min 3 s).
    result = run_features(variant)
    failed = [line for line in result.stdout.splitlines() if line.startswith(("FAILED", "ERROR"))]
    assert result.returncode == 0, f"{variant.__name__} was rejected:\n" + "\n".join(failed or [result.stdout[-3000:]])


@pytest.mark.parametrize("variant", [pytest.param(v, id=v.__name__, marks=pytest.mark.cost(_in_band_cost(v)))
                                     for v in FREEDOM])
def test_a_freedom_variant_exercises_its_freedom(variant: type, tmp_path: Path) -> None:
    """Evidence that a freedom variant exercises its freedom. One with its own declaration: held to the
    reference's instead, the features reject it (so they read the declaration, not the reference's habits).
    One without (a choice nothing declares): the trace of the item it names in EXERCISED_BY differs from the
    reference's (so the suite really met the other choice, and accepted it)."""
    assert variant.FREEDOM_CLASS in FREEDOM_CLASSES, f"{variant.__name__}: unknown FREEDOM_CLASS"
    if variant.DECLARATION != ReferenceTrain.DECLARATION:
        result = run_features(variant, "--declaration=sut/reference/declaration.yaml", "-x")
        assert result.returncode == 1, \
            f"{variant.__name__} passed under the reference's declaration:\n{result.stdout[-2000:]}"
        return
    item = variant.EXERCISED_BY
    traces = {}
    for name, sut in (("reference", "reference"), ("variant", f"tests.variants:{variant.__name__}")):
        out = tmp_path / name
        result = run_features(variant, f"--item={item}", f"--trace-dir={out}", sut=sut)
        assert result.returncode == 0, result.stdout[-2000:]
        traces[name] = {f.name: f.read_bytes() for f in sorted(out.rglob("*")) if f.is_file()}
    assert traces["reference"], f"{item} wrote no trace"
    assert traces["reference"] != traces["variant"], \
        f"{variant.__name__}: the traces of {item} are the reference's, so its freedom is never exercised there"


def test_an_in_band_variant_of_the_atp02_edge_differs_where_the_features_do_not_look() -> None:
    """TouchingSectionOutsideTheRange is accepted (above) and is not the reference: with the receiver range's
    front exactly on a section boundary it finds the next section's carrier inconsistent, the reference
    consistent. F-ATP-08 tests 0.1 m either side, so both readings of "overlapping" pass."""
    from sut.backends import open_backend
    from sut.contract.declaration import of_backend
    from sut.reference.atp.backend import ReferenceAtp

    declared = of_backend(ReferenceAtp).of("atp").parameters     # the variant declares none of its own
    front = 1000 - declared["position_uncertainty_m"] + declared["d_sen_m"]     # Dmax = 1000 m
    shown = {}
    for name in ("reference", "tests.variants:TouchingSectionOutsideTheRange"):
        atp = open_backend(name, "atp")
        atp.power_on()
        atp.advance(22_000_000)                              # past the DEF start-up self-test
        atp.set_input("speed", 0)
        atp.set_input("position", front)
        atp.pass_balise("2-1-1-1", [{"type": "CTCS-1", "sections": [(0.0, 1000.0, 1700), (1000.0, 1000.0, 2300)]},
                                    {"type": "MA", "end_m": 3000}])
        atp.set_input("carrier", 2300)
        atp.set_input("low frequency code", "L")
        atp.advance(500_000)
        shown[name] = atp.monitor(1)["faults"]
    assert shown == {"reference": [], "tests.variants:TouchingSectionOutsideTheRange": ["carrier inconsistent"]}
