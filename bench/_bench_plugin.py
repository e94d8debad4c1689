"""pytest plugin loaded by bench/suite_bench.py into the pytest runs it times (`-p _bench_plugin`).

Records, without changing what runs, and writes as JSON to $BENCH_PLUGIN_OUT at the end of the session:
  - wall-clock marks: plugin configured, collection finished, session finished (time.time(), so the parent can
    line them up with its own clock);
  - per test: setup + call + teardown seconds and the outcome;
  - the number of collected items and of pytest-bdd steps run (pytest_bdd_before_step);
  - memory from /proc/self/status: the process's peak RSS (VmHWM) and the test during which it last rose
    (the heaviest scenario), with its RSS at setup. Read-only: the kernel's high-water mark is never reset,
    so the parent's getrusage(RUSAGE_CHILDREN).ru_maxrss stays the real peak.
  - internal (reference SUT only): wall seconds inside `sut.reference.kernel.Kernel.run`, the simulation
    proper (outermost calls only), so the benchmark can tell the SUT's share from the harness's in a plain
    run. One perf_counter pair per advance; absent (None) when another backend runs.
Not a file the project's runs load: only the benchmark passes `-p _bench_plugin`.
"""
from __future__ import annotations

import json
import os
import time

import pytest

_OUT = os.environ.get("BENCH_PLUGIN_OUT")


def _status_kb(*keys: str) -> dict[str, int]:
    out: dict[str, int] = {}
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                name, _, rest = line.partition(":")
                if name in keys:
                    out[name] = int(rest.split()[0])
    except OSError:
        pass
    return out


class _Recorder:
    def __init__(self) -> None:
        self.marks: dict[str, float] = {"configured": time.time()}
        self.tests: dict[str, dict] = {}
        self.collected = 0
        self.steps = 0
        self.hwm_kb = _status_kb("VmHWM").get("VmHWM", 0)
        self.rss_at_start: dict[str, int] = {}
        self.raised: list[dict] = []          # tests during which the high-water mark rose, with the new mark
        self.kernel: _KernelClock | None = None

    # -- collection ------------------------------------------------------------------------------------
    @pytest.hookimpl(trylast=True)
    def pytest_collection_finish(self, session: pytest.Session) -> None:
        self.collected = len(session.items)
        self.marks["collected"] = time.time()

    # -- per test ---------------------------------------------------------------------------------------
    def pytest_runtest_logstart(self, nodeid: str, location) -> None:
        self.rss_at_start[nodeid] = _status_kb("VmRSS").get("VmRSS", 0)

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        entry = self.tests.setdefault(report.nodeid, {"seconds": 0.0, "outcome": "passed"})
        entry["seconds"] += report.duration
        if report.failed:
            entry["outcome"] = "failed" if report.when == "call" else "error"
        elif report.skipped and entry["outcome"] == "passed":
            entry["outcome"] = "skipped"

    def pytest_runtest_logfinish(self, nodeid: str, location) -> None:
        hwm = _status_kb("VmHWM").get("VmHWM", 0)
        if hwm > self.hwm_kb:
            self.raised.append({"nodeid": nodeid, "hwm_kb": hwm, "rise_kb": hwm - self.hwm_kb,
                                "rss_at_start_kb": self.rss_at_start.get(nodeid, 0)})
            self.hwm_kb = hwm
        self.rss_at_start.pop(nodeid, None)

    def pytest_bdd_before_step(self) -> None:
        self.steps += 1

    # -- the end ----------------------------------------------------------------------------------------
    @pytest.hookimpl(trylast=True)
    def pytest_sessionfinish(self, session: pytest.Session, exitstatus: int) -> None:
        self.marks["finished"] = time.time()
        if not _OUT:
            return
        data = {"marks": self.marks, "collected": self.collected, "steps": self.steps, "tests": self.tests,
                "hwm_kb": max(self.hwm_kb, _status_kb("VmHWM").get("VmHWM", 0)), "raised": self.raised,
                "exitstatus": int(exitstatus),
                "kernel_run_s": None if self.kernel is None else self.kernel.seconds,
                "kernel_run_calls": None if self.kernel is None else self.kernel.calls}
        with open(_OUT, "w", encoding="utf-8") as fh:
            json.dump(data, fh)


class _KernelClock:
    """Wall time inside Kernel.run (reference internals), outermost calls only."""

    def __init__(self) -> None:
        self.seconds = 0.0
        self.calls = 0
        self._depth = 0

    def install(self) -> bool:
        try:
            from sut.reference.kernel import Kernel
        except ImportError:
            return False
        original = Kernel.run
        clock = self

        def run(kernel, until):
            if clock._depth:
                return original(kernel, until)
            clock._depth += 1
            t0 = time.perf_counter()
            try:
                return original(kernel, until)
            finally:
                clock.seconds += time.perf_counter() - t0
                clock.calls += 1
                clock._depth -= 1

        Kernel.run = run
        return True


def pytest_configure(config: pytest.Config) -> None:
    if not hasattr(config, "workerinput"):
        recorder = _Recorder()
        config.pluginmanager.register(recorder, "bench-recorder")
        # the conformance run only (the floor has no step library); stays 0 when the SUT runs elsewhere
        if config.pluginmanager.has_plugin("steps.fixtures"):
            clock = _KernelClock()
            if clock.install():
                recorder.kernel = clock
