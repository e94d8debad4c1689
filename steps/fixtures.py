"""The one `sut` fixture every step drives, and the `--sut` option that picks its backend.

After each scenario the SUT's trace is attached to the report (CSV, times in ms) with a timing diagram,
and the SUT is shut down; a backend that raised inside its simulation fails the scenario.
"""
from __future__ import annotations

import os

import gc
import re
import sys
from pathlib import Path
from typing import Callable

import pytest

from sut.backends import BACKENDS, ENV_VAR, resolve
from sut.contract import load as load_contract
from sut.contract import declaration as declarations
from sut.contract.guard import ContractDriver, Recorder
from sut.driver import TrainDriver
from sut.snapshot import SnapshotCache, SnapshotDriver
from outline.plugin import step_index
from outline.sequences import replay
from steps import report
from steps.diagram import Bound
from steps import verdicts
from steps.verdicts import NOT_APPLICABLE, not_applicable


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("crh2", "CRH2 conformance suite")
    group.addoption("--sut", action="append", default=[], metavar="NAME",
                    help=f"SUT backend: one of {', '.join(BACKENDS)}, package.module:Class or tcp://host:port "
                         f"(default: ${ENV_VAR} or 'reference'); given several times, every scenario runs "
                         f"against each, its test id ending in [<backend>]")
    group.addoption("--profile", action="append", default=[], metavar="NAME[,NAME]",
                    help="run only scenarios of these train profiles (@profile:<name>); default: every "
                         "profile the SUT declares. Scenarios of a profile the SUT does not declare are "
                         "skipped with that reason")
    group.addoption("--whole-trace", choices=("failed", "all"), default="failed",
                    help="attach the whole SUT trace (gzipped CSV) to the report for failed scenarios only "
                         "(default) or for all; the timing diagram and key events are always attached")
    group.addoption("--evidence", choices=("failed", "all"), default="all",
                    help="attach key events and the timing diagram to every scenario (default) or to failed "
                         "ones only (make campaign: 16,120 rows would make a report of gigabytes)")
    group.addoption("--no-snapshots", action="store_true", default=False,
                    help="simulate every scenario from power-up, never from a copy of a state another "
                         "scenario reached (sut/snapshot.py); verdicts and traces are the same either way")
    group.addoption("--snapshot-every-branch", action="store_true", default=False,
                    help="store a state wherever scenarios branch and restore it whenever one is stored, "
                         "whatever it costs (for checking snapshots: which states the measured costs choose "
                         "varies with the machine's load)")
    group.addoption("--frame-by-frame", action="store_true", default=False,
                    help="the reference simulates every advance frame by frame instead of skipping steady "
                         "periods (sut/reference/bulk.py); verdicts and traces are the same either way")
    group.addoption("--declaration", default=None, metavar="FILE",
                    help="the SUT's implementation declaration (options, parameters, texts; the form is "
                         "sut/contract/form.yaml); default: the backend's own (DECLARATION). Scenarios of an "
                         "option it does not claim are not applicable")
    group.addoption("--contract-record", default=None, metavar="FILE",
                    help="write down every method, name, event kind and field the steps ask of the SUT, by "
                         "profile, to FILE (JSON; with xdist one FILE.<worker> each): the catalogue test "
                         "compares it with sut/contract/<profile>.yaml")
    group.addoption("--record-stimuli", default=None, metavar="DIR",
                    help="write each scenario's calls that act on the train (its stimuli, in order, as the "
                         "snapshot journal saw them) to DIR/<worker>.pickle: the differential checker replays "
                         "them on a mutant its own random sequences never reach (outline/sequences/replay.py)")
    group.addoption("--trace-dir", default=None, metavar="DIR",
                    help="also write each scenario's whole trace to DIR/<test id>.csv (to compare runs: two "
                         "runs of one SUT, in-process against remote, serial against -n auto)")


@pytest.hookimpl(wrapper=True)
def pytest_pyfunc_call(pyfuncitem: pytest.Function):
    # A failed Then of an @informative scenario is reported, not counted against conformance (steps/verdicts.py).
    try:
        return (yield)
    except AssertionError as error:
        if not verdicts.informative(pyfuncitem, error):
            raise
        verdicts.as_informative(error)


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo):
    # Remember how each phase went, so the sut fixture's teardown knows whether the scenario failed.
    report = yield
    setattr(item, f"_crh2_{report.when}", report)
    return report


_SUTS = pytest.StashKey[dict]()           # test id suffix -> backend class, in --sut order
# With several --sut, a plugin may narrow the backends a scenario runs on before its items exist
# (tests/variant_plan.py: each faulty variant on the scenarios its plan names): chooser(definition, ids) -> the
# ids to keep. Collecting every scenario once per backend and deselecting most was a quarter of that run.
SUT_CHOOSER = pytest.StashKey[Callable[[pytest.Item, list[str]], list[str]]]()
_SNAPSHOTS = pytest.StashKey[SnapshotCache]()
_RECORDER = pytest.StashKey[Recorder]()


def pytest_configure(config: pytest.Config) -> None:
    # Resolve the backend before collection, so a wrong --sut is a usage error (exit 4), not N failures.
    suts: dict[str, type[TrainDriver]] = {}
    for spec in config.getoption("--sut") or [None]:
        try:
            suts.setdefault(_sut_id(spec), resolve(spec))
        except Exception as exc:
            raise pytest.UsageError(f"--sut: {exc}") from None
    config.stash[_SUTS] = suts
    override = config.getoption("--declaration")
    if override and len(suts) > 1:
        raise pytest.UsageError("--declaration: one file for one --sut (each of several backends carries its own)")
    for cls in suts.values():
        try:
            declarations.of_backend(cls, override)
        except declarations.DeclarationError as exc:
            raise pytest.UsageError(f"declaration of the SUT {cls.__qualname__}: {exc}") from None
    config.stash[_SNAPSHOTS] = SnapshotCache(every_branch=config.getoption("--snapshot-every-branch"))
    if config.getoption("--contract-record"):
        config.stash[_RECORDER] = Recorder()
    if config.getoption("--frame-by-frame"):
        # An environment variable, not an import of the reference: the steps know only the driver, and a
        # remote server started from this run (or an xdist worker) inherits it.
        os.environ["CRH2_FRAME_BY_FRAME"] = "1"


# Allocations (net of frees) between automatic passes of the cyclic collector while scenarios run.
SCENARIO_GC_THRESHOLD = 500_000


@pytest.hookimpl(trylast=True)
def pytest_collection_finish(session: pytest.Session) -> None:
    # What collection built (features, steps, items) lives to the end of the run: moved out of the cyclic
    # collector's sight. A finished scenario's train is a web of cycles that only the collector frees: it is
    # freed at the scenario's end (pytest_runtest_teardown below), so the collector need not run during a
    # scenario, where each automatic pass walked the live train (a restored 8-car state is ~5 k tracked
    # objects, its trace's events more as they come) and, each 50th, every train not yet freed. The
    # threshold stays as a net for a scenario that makes cyclic garbage by the million. Conformance run in
    # one process, 2026-12-07: GC 16.7 s -> 6.5 s of ~100 s, peak RSS 559 -> 293 MB.
    gc.collect()
    gc.freeze()
    gc.set_threshold(SCENARIO_GC_THRESHOLD, 50, 100)


@pytest.hookimpl(trylast=True)
def pytest_runtest_teardown(item: pytest.Item, nextitem: pytest.Item | None) -> None:
    # After the fixtures' teardown (trylast): the scenario's driver is shut down and garbage now. The young
    # generations hold what the scenario made; what survives it (caches) moves on to the oldest.
    gc.collect(1)


def pytest_sessionfinish(session: pytest.Session) -> None:
    recorder = session.config.stash.get(_RECORDER, None)
    if recorder is not None:
        import json
        path = Path(session.config.getoption("--contract-record"))
        worker = getattr(session.config, "workerinput", {}).get("workerid")
        if worker:
            path = path.with_name(f"{path.name}.{worker}")
        path.write_text(json.dumps(recorder.as_json(), indent=1, sort_keys=True), encoding="utf-8")
    cache = session.config.stash.get(_SNAPSHOTS, None)
    if cache is not None and hasattr(session.config, "workeroutput"):     # an xdist worker: tell the controller
        session.config.workeroutput["crh2_snapshots"] = cache.figures()


@pytest.hookimpl(optionalhook=True)          # an xdist hook: unknown when xdist is not loaded
def pytest_testnodedown(node, error) -> None:
    figures = getattr(node, "workeroutput", {}).get("crh2_snapshots")
    cache = node.config.stash.get(_SNAPSHOTS, None)
    if figures and cache is not None:
        cache.add_figures(figures)


def pytest_terminal_summary(terminalreporter, config: pytest.Config) -> None:
    # "not applicable" (ISO/IEC 9646) is a skip to pytest; say how many of the skips it was, and why.
    count = sum(NOT_APPLICABLE in str(getattr(r, "longrepr", "")) for r in terminalreporter.stats.get("skipped", []))
    if count:
        terminalreporter.write_line(f"not applicable: {count} of the skipped scenarios (an option the SUT's "
                                    f"declaration does not claim; -rs lists why)", yellow=True)
    deviations = len(terminalreporter.stats.get("xfailed", []))
    if deviations:
        terminalreporter.write_line(f"informative deviation: {deviations} xfailed scenarios checked what no "
                                    f"requirement states and found the SUT doing otherwise; conformance is not "
                                    f"affected (-rx lists them)", yellow=True)
    cache = config.stash.get(_SNAPSHOTS, None)
    if cache is None or config.getoption("--no-snapshots") or hasattr(config, "workeroutput"):
        return
    for note in dict.fromkeys(cache.notes):
        terminalreporter.write_line(note, yellow=True)
    if cache.restored or cache.stored:
        terminalreporter.write_line(cache.summary())


def _sut_id(spec: str | None) -> str:
    """How a backend shows in test ids: its class name, its registry name or its address."""
    spec = spec or "reference"
    return re.sub(r"[^\w.-]+", "-", spec.rsplit(":", 1)[-1] if ":" in spec and "://" not in spec else spec)


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    # Several --sut: each scenario once per backend (a rig beside the reference, or the suite's own variants).
    suts = metafunc.config.stash[_SUTS]
    if len(suts) > 1 and step_index.is_scenario(metafunc.function):
        if "sut_class" not in metafunc.fixturenames:
            metafunc.fixturenames.append("sut_class")     # steps ask for `sut` at run time, not in the signature
        chooser = metafunc.config.stash.get(SUT_CHOOSER, None)
        ids = chooser(metafunc.definition, list(suts)) if chooser is not None else list(suts)
        metafunc.parametrize("sut_class", [suts[i] for i in ids], ids=ids, scope="function")


def _profiles_of(item: pytest.Item) -> list[str]:
    return [str(arg) for mark in item.iter_markers("profile") for arg in mark.args]


def _first_sut(config: pytest.Config) -> type[TrainDriver]:
    return next(iter(config.stash[_SUTS].values()))


def _sut_of(item: pytest.Item, config: pytest.Config) -> type[TrainDriver]:
    callspec = getattr(item, "callspec", None)
    if callspec is not None and "sut_class" in callspec.params:
        return callspec.params["sut_class"]
    return _first_sut(config)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    suts = config.stash[_SUTS]
    declared = tuple(dict.fromkeys(p for cls in suts.values() for p in cls.PROFILES))
    wanted = [p.strip() for value in config.getoption("--profile") for p in value.split(",") if p.strip()]
    unknown = [p for p in wanted if p not in declared]
    if unknown:
        names = " and ".join(cls.__qualname__ for cls in suts.values())
        raise pytest.UsageError(f"--profile {', '.join(unknown)}: the SUT {names} declares "
                                f"{', '.join(declared) or 'no profile'}")
    keep, drop = [], []
    for item in items:
        sut_class = _sut_of(item, config)
        if not isinstance(sut_class, type):           # NOTSET: the chooser kept no backend for this scenario
            drop.append(item)
            continue
        declared = tuple(sut_class.PROFILES)
        profiles = _profiles_of(item)
        if not profiles:
            keep.append(item)
        elif not any(p in declared for p in profiles):
            item.add_marker(pytest.mark.skip(
                reason=f"profile {', '.join(profiles)}: the SUT {sut_class.__qualname__} declares "
                       f"{', '.join(declared) or 'no profile'}"))
            keep.append(item)
        elif wanted and not any(p in wanted for p in profiles):
            drop.append(item)
        else:
            reason = _not_applicable(item, sut_class, config)
            if reason:
                item.add_marker(pytest.mark.skip(reason=reason))
            keep.append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep


def _profile_for(item: pytest.Item, sut_class: type[TrainDriver]) -> str | None:
    """The scenario's profile this SUT implements (its train), or None."""
    return next((p for p in _profiles_of(item) if p in sut_class.PROFILES), None)


def _declared(item: pytest.Item, sut_class: type[TrainDriver], config: pytest.Config):
    """The SUT's declaration (None if it has none) and its part for the scenario's profile (None if absent)."""
    found = declarations.of_backend(sut_class, config.getoption("--declaration"))
    profile = _profile_for(item, sut_class)
    return found, (found.of(profile) if found and profile else None)


def _not_applicable(item: pytest.Item, sut_class: type[TrainDriver], config: pytest.Config) -> str | None:
    """Why a scenario's verdict is "not applicable" to this SUT (an option of the form it does not claim)."""
    needed = [str(a) for mark in item.iter_markers("option") for a in mark.args]
    if not needed:
        return None
    found, mine = _declared(item, sut_class, config)
    missing = [o for o in needed if mine is None or not mine.claims(o)]
    if not missing:
        return None
    where = found.path if found else f"{sut_class.__qualname__} (no declaration)"
    return f"{NOT_APPLICABLE}the SUT's declaration {where} does not claim the option {', '.join(missing)}"


@pytest.fixture
def declaration(sut_class: type[TrainDriver], request: pytest.FixtureRequest) -> declarations.ProfileDeclaration:
    """This scenario's SUT's declaration for the scenario's profile: the options it claims, its parameters and
    its display texts. A scenario that needs one of a SUT that declares none is not applicable."""
    _, mine = _declared(request.node, sut_class, request.config)
    if mine is None:
        profile = _profile_for(request.node, sut_class) or "its profile"
        not_applicable(f"the SUT {sut_class.__qualname__} declares no parameters for {profile} "
                       f"(--declaration FILE; the form is sut/contract/form.yaml)")
    return mine


@pytest.fixture
def sut_class(request: pytest.FixtureRequest) -> type[TrainDriver]:
    """The backend of this scenario: the one --sut (with several, pytest_generate_tests parametrizes this name
    directly, and each value stands in for this fixture)."""
    return _first_sut(request.config)


_BOUNDS = pytest.StashKey[list]()


def pytest_bdd_after_step(request, feature, scenario, step, step_func, step_func_args) -> None:
    # A Then step that checked "... within <bound> ms" of the action: draw that window on the timing diagram.
    args = step_func_args
    # "within 15 ms of its transmission" (zh-CN "发出后15 ms内") is a latency of each command, not a window
    # after the action.
    if re.search(r"within [\d.]+ ms(?! of)|(?<![后\d.])[\d.]+ ms内", step.name) \
            and isinstance(args.get("bound"), (int, float)) \
            and isinstance(args.get("t_action"), int):
        start = args["t_action"]
        request.node.stash.setdefault(_BOUNDS, []).append(
            Bound(step.name, start, start + round(args["bound"] * 1000)))


# A scenario's guard and the driver behind it: the end-of-scenario check asks a snapshot for its trace as far
# as it was simulated, which the driver interface does not offer.
_GUARD = pytest.StashKey[tuple[ContractDriver, object]]()


def pytest_bdd_after_scenario(request, feature, scenario) -> None:
    """A passed scenario's trace, beyond the events its steps were handed, held to the contract. Called from
    pytest-bdd's `finally`: a scenario already failing (or not applicable) is left as it is."""
    found = request.node.stash.get(_GUARD, None)
    if found is None or sys.exc_info()[0] is not None:
        return
    guard, driver = found
    trace = driver.simulated_trace if isinstance(driver, SnapshotDriver) else driver.trace
    if trace is not None:
        guard.check_trace(trace)


def pytest_bdd_before_step(request, feature, scenario, step, step_func) -> None:
    recorder = request.config.stash.get(_RECORDER, None)
    if recorder is not None:
        recorder.step = step_index.pattern_of(step_func, step.type)


def open_driver(sut_class: type[TrainDriver], profile: str | None, config: pytest.Config) -> TrainDriver:
    """A fresh SUT of the profile: behind the run's snapshot journal where the backend is deterministic (a
    scenario's train, and each random sequence's: they all start with the same power-up)."""
    if config.getoption("--no-snapshots") or not sut_class.DETERMINISTIC:
        return sut_class.open(profile)
    return SnapshotDriver(sut_class, profile, config.stash[_SNAPSHOTS])


@pytest.fixture
def sut(sut_class: type[TrainDriver], request: pytest.FixtureRequest):
    profile = _profile_for(request.node, sut_class)
    driver = open_driver(sut_class, profile, request.config)
    recorder = request.config.stash.get(_RECORDER, None)
    if recorder is not None:
        recorder.item = ",".join(str(a) for m in request.node.iter_markers("item") for a in m.args) or "?"
    guard = ContractDriver(driver, profile or "", load_contract(profile or ""), recorder)
    request.node.stash[_GUARD] = (guard, driver)
    stimuli_dir = request.config.getoption("--record-stimuli")
    lines = replay.Lines().start() if stimuli_dir else None
    try:
        yield guard
    finally:
        ran = lines.stop() if lines is not None else {}
    outcome = [getattr(request.node, f"_crh2_{phase}", None) for phase in ("setup", "call")]
    failed = any(r is not None and r.failed for r in outcome)
    whole = failed or request.config.getoption("--whole-trace") == "all"
    try:
        report.attach_run(driver, request, whole_trace=whole, bounds=tuple(request.node.stash.get(_BOUNDS, [])),
                          evidence=failed or request.config.getoption("--evidence") == "all")
        trace_dir = request.config.getoption("--trace-dir")
        if trace_dir:
            _write_trace(Path(trace_dir), request.node.nodeid, driver)
        if stimuli_dir and isinstance(driver, SnapshotDriver):
            replay.write(Path(stimuli_dir), request.config, request.node.nodeid, profile, driver.stimuli,
                         passed=not failed, lines=ran)
    finally:
        # An item lives as long as the session: its stash must not keep this scenario's train (a ten-minute
        # scenario's trace is ~0.7 GB).
        del request.node.stash[_GUARD]
        driver.shutdown()


def _write_trace(folder: Path, nodeid: str, driver: TrainDriver) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    name = re.sub(r"[^\w.\[\]-]+", "_", nodeid.split("::")[-1])
    text = driver.trace.to_csv() if driver.powered else ""
    (folder / f"{name}.csv").write_text(text, encoding="utf-8")


@pytest.fixture
def ramps() -> dict[str, float]:
    """The signed rate (per second) of each vehicle input a When step of this scenario ramps: a band met on a
    ramp allows the ground the input covers in the SUT's declared reaction margin (steps/budgets.py)."""
    return {}


@pytest.fixture
def accuracy(sut_class: type[TrainDriver], request: pytest.FixtureRequest) -> dict[str, float]:
    """How far the speed and main pipe pressure the SUT's interlocks act on may lie from the train's, by vehicle
    input: its declared speed_accuracy_kmh and pressure_accuracy_kpa (IXIT; steps/vehicle.py feeds the edges
    that far clear and widens the bands). 0 (exact) where it declares none, and a scenario that only sets a
    speed never becomes not applicable for want of a declaration."""
    _, mine = _declared(request.node, sut_class, request.config)
    declared = mine.parameters if mine is not None else {}
    return {"speed": declared.get("speed_accuracy_kmh", 0),
            "main pipe pressure": declared.get("pressure_accuracy_kpa", 0)}


@pytest.fixture
def edge_shifts() -> dict[str, float]:
    """By vehicle input, how far a When step of this scenario last fed it from the value written, to keep it
    clear of an edge by the declared accuracy (steps/vehicle.py): a display of that input is compared with what
    was fed."""
    return {}


@pytest.fixture
def t_action() -> int:
    """Time of the last action, in us: steps that act return it as `t_action`; 0 (power-up) if none did."""
    return 0
