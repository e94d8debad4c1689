"""What can be seen of a SUT at its driver interface after a stimulus, as plain data two runs can compare:
every output, reading and lamp the contract names, each cab's monitor, the records, every ring node's
counters, rated_limits(), and the trace events of the kinds the contract lists since the last look: their
time, source and the fields the contract lists for the kind (a field it does not list is the implementer's
own: no conforming SUT owes it, so two SUTs do not differ by it; of a free text the contract fixes only in part,
that part; of a number the contract fixes to a resolution, the number in steps of it). An answer that is an error is seen as its
error's class: two SUTs that refuse alike do not differ."""
from __future__ import annotations

import fnmatch
import math
import re
from typing import Any, Callable

from sut.contract import load as load_contract
from sut.driver import TrainDriver

from . import domains
from .stimuli import _expand, _names


def _ask(call: Callable[[], Any]) -> Any:
    try:
        return _plain(call())
    except Exception as error:          # noqa: BLE001  (what is compared is which error, not why)
        return ("error", type(error).__name__)


def _plain(value: Any) -> Any:
    """Comparable data: floats to 9 significant digits (a float printed by another path is the same value)."""
    if isinstance(value, float):
        return float(f"{value:.9g}") if math.isfinite(value) else repr(value)
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in sorted(value.items(), key=lambda kv: str(kv[0]))}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, bytes):
        return value.hex()
    return value


SKIPPED = "skipped stretches"


def comparable(a: dict[str, Any], b: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """Two looks as they are compared: the stretches either SUT skipped (time.skip: "a backend that records
    everything emits none", so whether and where one skips is its own choice) left out of both event lists,
    time.skip itself too. A stretch is (frm, to]: what happens at frm was recorded, at to not. What the skip
    leaves behind is still compared: the state after it, the counters (which count skipped traffic), every
    event outside it."""
    windows = [*a.get(SKIPPED, ()), *b.get(SKIPPED, ())]

    def kept(look: dict[str, Any]) -> dict[str, Any]:
        look = {k: v for k, v in look.items() if k != SKIPPED}
        if "events" in look:
            look["events"] = [ev for ev in look["events"] if ev[2] != "time.skip"
                              and not any(frm < ev[0] <= to for frm, to in windows)]
        return look
    return kept(a), kept(b)


class Observer:
    """Looks at one driver of `profile`; `look()` answers what it shows now and the contract's trace events
    since the previous look."""

    def __init__(self, profile: str, driver: TrainDriver, vehicle: dict[str, list[str]] | None = None) -> None:
        self.driver = driver
        contract = load_contract(profile)
        has = set(contract.methods).__contains__
        # `vehicle`: the names to look at, given where two SUTs are compared (the first one's): a SUT listing
        # its names otherwise (vehicle_names, which no contract lists) must not change what is looked at.
        if vehicle is None:
            vehicle = driver.vehicle_names() if has("output") or has("reading") else {}
        self.vehicle = vehicle
        cars = [f"car{n}" for n in range(1, domains.CARS.get(profile, 0) + 1)]
        self.probes: dict[str, Callable[[], Any]] = {}
        for kind, method in (("outputs", "output"), ("readings", "reading")):
            if has(method):
                for pattern in contract.names.get(kind, {}):
                    names = _expand(pattern, vehicle.get(kind, [])) or _expand(pattern.replace("car*", "car?"),
                                                                               [f"{c}{pattern[4:]}" for c in cars])
                    for name in names:
                        self.probes[f"{method} {name}"] = lambda m=getattr(driver, method), n=name: m(n)
        for cab in domains.CABS.get(profile, (1,)):
            if has("monitor"):
                self.probes[f"monitor {cab}"] = lambda c=cab: driver.monitor(c)
            for lamp in contract.names.get("lamps", {}) if has("lamp") else ():
                self.probes[f"lamp {cab} {lamp}"] = lambda c=cab, n=lamp: driver.lamp(c, n)
        for unit in domains.RECORD_UNITS.get(profile, ()) if has("records") else ():
            self.probes[f"records {unit}"] = lambda u=unit: driver.records(u)
        for node in _names(driver, "ring_nodes") if has("counters") else ():
            self.probes[f"counters {node}"] = lambda n=node: driver.counters(n)
        if has("rated_limits"):
            self.probes["rated_limits"] = driver.rated_limits
        self.contract_kinds = contract.events
        self.fields: dict[str, frozenset[str] | None] = {}     # by kind seen: the fields compared, None: not listed
        self.fixed: dict[str, dict[str, re.Pattern]] = {}       # by kind seen: the fields fixed only in part
        self.resolution: dict[str, dict[str, float]] = {}       # by kind seen: the numbers fixed to a step
        self.seen = 0

    def _listed(self, kind: str) -> frozenset[str] | None:
        if kind not in self.fields:
            # a kind the contract lists by itself or under a pattern (`loop.*`): the fields of every entry for it
            entries = [e for name, e in self.contract_kinds.items() if name == kind or fnmatch.fnmatchcase(kind, name)]
            self.fields[kind] = frozenset(f for e in entries for f in e.fields) if entries else None
            self.fixed[kind] = {f: re.compile(str(spec["fixed"])) for e in entries for f, spec in e.fields.items()
                                if "fixed" in spec}
            self.resolution[kind] = {f: float(spec["resolution"]) for e in entries for f, spec in e.fields.items()
                                     if "resolution" in spec}
        return self.fields[kind]

    def _compared(self, kind: str, name: str, value: Any) -> Any:
        """What of a field is compared: where the contract fixes only part of a free text (`fixed`, a regular
        expression), that part; the rest is the implementation's wording. Where it fixes a number only to a
        resolution (`resolution`), the number in whole steps of it: two SUTs that state it to a finer grain do
        not differ (a value at the middle of a step may still read as a difference: the safe side)."""
        step = self.resolution[kind].get(name)
        if step is not None and isinstance(value, (int, float)) and not isinstance(value, bool) \
                and math.isfinite(value):
            return round(value / step)
        pattern = self.fixed[kind].get(name)
        found = pattern.match(value) if pattern is not None and isinstance(value, str) else None
        return found.group(0) if found else value

    def look(self) -> dict[str, Any]:
        shown = {name: _ask(probe) for name, probe in self.probes.items()}
        shown["now us"] = self.driver.now_us
        events = self.driver.trace[self.seen:]
        self.seen += len(events)
        # Where a backend skipped steady traffic it records nothing (time.skip, listed or not): what is not
        # recorded there is no behaviour (comparable() leaves that stretch out on both sides).
        shown[SKIPPED] = [(ev.fields["frm"], ev.fields["to"]) for ev in events if ev.kind == "time.skip"]
        shown["events"] = [(ev.t, ev.source, ev.kind,
                            _plain({k: self._compared(ev.kind, k, v) for k, v in ev.fields.items() if k in listed}))
                           for ev in events if (listed := self._listed(ev.kind)) is not None]
        return shown
