"""What a scenario leaves in the Allure report: the SUT's trace and its parameters.

Per scenario: a timing diagram (steps/diagram.py), the key events (faults, inputs, token initialisation and
formation, takeover, fail-safe cuts, path changes, discards, block transfer, lamps, state changes) as a CSV
shown inline, and, for a failed scenario (or every one with --whole-trace=all), the whole trace, every event,
as gzipped CSV. The periodic traffic (thousands of command and status frames a
second) would make the inline table unreadable and the single-file report tens of megabytes.
"""
from __future__ import annotations

import gzip

import allure
import pytest

from steps.diagram import Bound, render_svg, wavejson as diagram_of
from sut.driver import TrainDriver
from sut.trace import Trace

PERIODIC_KINDS = frozenset({
    "cmd.tx", "cmd.rx", "cmd.in", "status.tx", "status.rx", "token.rx", "token.pass", "sd.rx",
    "loop.poll", "loop.send", "loop.report", "link.tx", "mvb.msg", "wtb.msg", "bus.frame",
})


def _is_key(ev) -> bool:
    if ev.kind in PERIODIC_KINDS:
        return False
    # a displayed number (speed, mileage, pressure) changes every status cycle: that is traffic, not news
    return not (ev.kind == "display.change" and isinstance(ev.get("value"), (int, float)))


def _maybe_key(kind: str) -> bool:
    return kind not in PERIODIC_KINDS


def recording(config: pytest.Config) -> bool:
    """Whether this run writes Allure results (--alluredir): without them every attachment is dropped."""
    return bool(getattr(config.option, "allure_report_dir", None))


def attach_run(driver: TrainDriver, request: pytest.FixtureRequest, whole_trace: bool = True,
               bounds: tuple[Bound, ...] = (), evidence: bool = True) -> None:
    """The scenario's evidence (key events, timing diagram, with whole_trace the trace) and the SUT's
    environment; without `evidence` the environment alone (make campaign: thousands of passing rows)."""
    # Building the diagram and the CSVs is a sixth of a plain run's time (bench/suite_bench.py): skip it
    # when nobody records them.
    if not driver.powered or not recording(request.config):
        return
    if not evidence:
        _write_environment(driver, request.config)
        return
    trace = driver.trace
    key = Trace([ev for ev in trace.of_kinds(_maybe_key) if _is_key(ev)])
    allure.attach(key.to_csv(), name=f"key events ({len(key)} of {len(trace)}, t in ms)",
                  attachment_type=allure.attachment_type.CSV)
    if whole_trace:
        allure.attach(gzip.compress(trace.to_csv().encode(), mtime=0), name=f"whole trace ({len(trace)} events)",
                      attachment_type="application/gzip", extension="csv.gz")
    _attach_diagram(trace, key, driver.now_us, bounds)
    _write_environment(driver, request.config)


def _attach_diagram(trace: Trace, key: Trace, now_us: int, bounds: tuple[Bound, ...] = ()) -> None:
    """Draw from just before the first action after power-up (a fault, an input, the desk, an order; else
    the first thing that happened) to the end of the scenario, the start of every checked bound included."""
    acts = ("fault.", "env.", "in.", "desk.", "order.", "mcr.")
    moments = [ev.t for ev in key if ev.t > 0 and ev.kind.startswith(acts)] or [ev.t for ev in key if ev.t > 0]
    moments += [b.start_us for b in bounds]
    if not moments:
        return
    first = min(moments)
    start = max(0, first - max(10_000, (now_us - first) // 10))
    diagram = diagram_of(trace, start, max([now_us, *(b.end_us for b in bounds)]), bounds)
    if diagram is not None:
        allure.attach(render_svg(diagram), name="timing diagram", attachment_type=allure.attachment_type.SVG)


_WRITTEN = pytest.StashKey[set]()


def environment_of(described: dict[str, object]) -> dict[str, object]:
    """A SUT's description as report environment keys: each under its profile (`[crh2] SUT class`), so the
    trains of a run that covers several profiles stay apart; `[run] profiles` lists the profiles that ran."""
    profile = str(described.get("profile") or "no profile")
    keyed: dict[str, object] = {f"[{profile}] {k}": v for k, v in described.items() if k != "profile"}
    keyed["[run] profiles"] = profile
    return keyed


def _write_environment(driver: TrainDriver, config: pytest.Config) -> None:
    # Every scenario adds its SUT's parameters: values that differ (one set, two sets) are merged, not lost.
    # A mapping this process already merged is not merged again (reading, merging and rewriting the file under
    # its lock for each of 528 scenarios was a tenth of what the report costs).
    results_dir = getattr(config.option, "allure_report_dir", None)
    if results_dir:
        from outline.report.allure_env import write_environment

        described = driver.describe()
        seen = config.stash.setdefault(_WRITTEN, set())
        key = tuple(sorted((str(k), str(v)) for k, v in described.items()))
        if key not in seen:
            seen.add(key)
            write_environment(results_dir, environment_of(described))
