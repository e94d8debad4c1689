"""Invariants the requirements state, checked after every stimulus of a random sequence (issue 31: random-
sequence testing as a judge of its own). Each names its requirement IDs; it reads the SUT only through the
driver interface, and what the sequence did (the stimuli so far) from the sequence itself.

A requirement that gives no reaction time (the interlocks, ILK-01..08) is checked only where the train has been
left alone for SETTLE_US since the last stimulus: a project decision (docs/decisions.md, "Random-sequence
invariants"), one second, far above any reaction time a requirement or the features give.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

from sut.driver import TrainDriver

from .stimuli import Action

SETTLE_US = 1_000_000


@dataclass
class Done:
    """What the sequence has done so far: the inputs it set, the desk, the faults it injected."""
    inputs: dict[str, Any] = field(default_factory=dict)
    keys: set[int] = field(default_factory=set)
    direction: dict[int, str] = field(default_factory=dict)
    brake: dict[int, int] = field(default_factory=dict)
    faults: int = 0                     # boards failed, links cut, supplies off, ever (repairs do not undo)
    restarts: int = 0                   # power_off of the VDX
    last_stimulus_us: int = 0

    def note(self, action: Action, now_us: int) -> None:
        m, a = action.method, action.args
        if m == "advance":
            return
        self.last_stimulus_us = now_us
        if m == "set_input":
            self.inputs[a[0]] = a[1]
        elif m == "insert_key":
            self.keys.add(a[0])
        elif m == "remove_key":
            self.keys.discard(a[0])
        elif m == "set_direction":
            self.direction[a[0]] = a[1]
        elif m == "set_brake":
            self.brake[a[0]] = a[1]
        elif m in ("fail", "cut_link", "power_off", "set_supply_voltage"):
            self.faults += 1
            if a[0] == "VDX" and m == "power_off":
                self.restarts += 1


@dataclass
class Look:
    driver: TrainDriver
    done: Done
    memory: dict[str, Any]              # an invariant's own notes between looks (what it saw before)

    @property
    def settled(self) -> bool:
        return self.driver.now_us - self.done.last_stimulus_us >= SETTLE_US

    def out(self, name: str) -> str:
        return self.driver.output(name)


@dataclass(frozen=True)
class Invariant:
    name: str
    requirements: tuple[str, ...]
    profile: str
    check: Callable[[Look], str | None]  # None while it holds, else what the SUT shows instead
    decision: str = ""                   # where a project decision bounds it (docs/decisions.md)

    def __str__(self) -> str:
        return f"{self.name} ({', '.join(self.requirements)})"


def _one_mcr(look: Look) -> str | None:
    lit = [cab for cab in (1, 8) if look.driver.lamp(cab, "MCR")]
    return f"the MCR lamps of cabs {lit} are lit together" if len(lit) > 1 else None


def _separation_brakes(look: Look) -> str | None:
    if not look.settled or "separated" not in [v for k, v in look.done.inputs.items() if k.startswith("coupler")]:
        return None
    shown = {n: look.out(n) for n in ("EB valve", "emergency brake", "rapid brake")}
    want = {"EB valve": "de-energised", "emergency brake": "applied", "rapid brake": "commanded"}
    return None if shown == want else f"the train is separated, and it shows {shown}"


def _low_pipe_brakes(look: Look) -> str | None:
    kpa = look.done.inputs.get("main pipe pressure")
    if not look.settled or kpa is None or kpa >= 580:       # 590 +- 10: below 580 every conforming train trips
        return None
    shown = {n: look.out(n) for n in ("EB valve", "rapid-brake valve", "emergency brake", "rapid brake")}
    want = {"EB valve": "de-energised", "rapid-brake valve": "de-energised", "emergency brake": "applied",
            "rapid brake": "commanded"}
    return None if shown == want else f"the main pipe is at {kpa:g} kPa, and the train shows {shown}"


def _traction_only_when_allowed(look: Look) -> str | None:
    if not look.settled or look.out("traction") != "permitted":
        return None
    done = look.done
    why = []
    if look.out("emergency brake") != "released" or look.out("rapid brake") != "not commanded":
        why.append("a rapid or emergency brake acts")
    if done.inputs.get("doors") == "open" and done.inputs.get("door bypass") != "on":
        why.append("the doors are open and the bypass switch is off")
    if done.inputs.get("ATP brake", "none") != "none":
        why.append(f"the ATP commands a {done.inputs['ATP brake']} brake")
    if not done.faults:                 # the desk is heard only while the network is whole
        cabs = [c for c in done.keys if look.driver.lamp(c, "MCR")]
        if not cabs:
            why.append("no cab's MCR is up")
        for cab in cabs:
            if done.direction.get(cab, "neutral") == "neutral":
                why.append(f"cab {cab}'s direction switch is at neutral")
            if done.brake.get(cab, 0):
                why.append(f"cab {cab}'s brake handle is at step {done.brake[cab]}")
    return "traction is permitted though " + "; ".join(why) if why else None


def _main_circuit_protection(look: Look) -> str | None:
    if not look.settled:
        return None
    for unit, cars in (("unit1", (2, 3)), ("unit2", (6, 7))):
        fault = look.done.inputs.get(f"{unit}.transformer", "normal")
        if fault != "normal" and look.out(f"{unit}.VCB") != "open":
            return f"{unit}'s transformer reports {fault}, and its VCB is {look.out(f'{unit}.VCB')}"
        opens = "overcurrent" in fault or look.done.inputs.get(f"{unit}.oil pump") == "stopped"
        for car in cars if opens else ():
            shown = (look.out(f"car{car}.CI contactor"), look.out(f"car{car}.CI gates"))
            if shown != ("open", "blocked"):
                return f"{unit} has {fault} / oil pump {look.done.inputs.get(f'{unit}.oil pump')}, and car{car}'s " \
                       f"converter input contactor is {shown[0]}, its gates {shown[1]}"
    return None


def _doors_open_only_slow(look: Look) -> str | None:
    kmh = look.done.inputs.get("speed", 0.0)
    if look.settled and look.out("door-open relay") == "acting" and kmh >= 5:
        return f"the door-open relay acts at {kmh:g} km/h"
    return None


def _loop_through_both_relays(look: Look) -> str | None:
    loop, eb1r, eb2r = (look.out(n) for n in ("EB loop", "EB1R", "EB2R"))
    isolated = bool(look.done.inputs.get("ATP isolation switch"))
    closed = isolated or (eb1r == "de-energised" and eb2r == "energised")
    if (loop == "closed") != closed:
        return f"the loop is {loop} with EB1R {eb1r}, EB2R {eb2r}, isolation switch {'on' if isolated else 'off'}"
    return None


def _c019_stays_until_restart(look: Look) -> str | None:
    fault = look.out("VDX fault")
    seen = look.memory.get("c019 at restart")
    if fault == "C019":
        look.memory["c019 at restart"] = look.done.restarts
    elif seen is not None and seen == look.done.restarts:
        return "C019 cleared without a restart of the VDX"
    if fault == "C019" and look.settled and look.out("EB2R") != "de-energised":
        return "C019 is shown, and the FS output still holds EB2R"
    return None


INVARIANTS = [
    Invariant("only one cab's master control relay is up", ("ILK-07",), "crh2", _one_mcr),
    Invariant("a separated train brakes", ("ILK-01",), "crh2", _separation_brakes),
    Invariant("a main pipe below the trip band brakes", ("ILK-02",), "crh2", _low_pipe_brakes),
    Invariant("traction is permitted only when every condition holds", ("ILK-08",), "crh2",
              _traction_only_when_allowed),
    Invariant("a transformer or oil fault opens the main circuit", ("ILK-06",), "crh2", _main_circuit_protection),
    Invariant("the door-open relay acts only below 5 km/h", ("ILK-05",), "crh2", _doors_open_only_slow),
    Invariant("the loop is closed exactly when both relays or the isolation switch close it", ("VDX-01",), "vdx",
              _loop_through_both_relays),
    Invariant("C019 stays, the FS output off, until the VDX restarts", ("VDX-03", "VDX-06"), "vdx",
              _c019_stays_until_restart),
]
