"""Invariants the requirements state, checked after every stimulus of a random sequence (issue 31: random-
sequence testing as a judge of its own). Each names its requirement IDs; it reads the SUT only through the
driver interface, and what the sequence did (the stimuli so far) from the sequence itself.

A requirement that gives no reaction time (the interlocks, ILK-01..08) is checked only where the train has been
left alone for SETTLE_US since the last stimulus: a project decision (docs/decisions.md, "Random-sequence
invariants"), one second, far above any reaction time a requirement or the features give.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Callable

from steps import messages
from sut.driver import TrainDriver

from . import domains
from .stimuli import Action

SETTLE_US = 1_000_000


@dataclass
class Done:
    """What the sequence has done so far: the inputs it set, the desk, the faults it injected."""
    inputs: dict[str, Any] = field(default_factory=dict)
    keys: set[int] = field(default_factory=set)
    direction: dict[int, str] = field(default_factory=dict)
    brake: dict[int, int] = field(default_factory=dict)
    traction: dict[int, int] = field(default_factory=dict)
    faults: int = 0                     # boards failed, links or lines cut, supplies off, ever (repairs do not undo)
    restarts: int = 0                   # power_off of the VDX
    last_stimulus_us: int = 0
    failed: set[str] = field(default_factory=set)      # what fail() named and repair() has not brought back
    hit: set[str] = field(default_factory=set)         # every name a fault ever touched, lines as `WTB.A`
    cut: set[str] = field(default_factory=set)         # bus lines cut and not restored (`unit1.MVB.B`)
    history: list[tuple[int, Action]] = field(default_factory=list)   # every stimulus but time, with its time

    def note(self, action: Action, now_us: int) -> None:
        if action.method in ("advance", "advance_ms"):
            return
        self.last_stimulus_us = now_us
        self.history.append((now_us, action))
        for m, a in action.calls:
            self._note(m, a)

    def _note(self, m: str, a: tuple) -> None:
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
        elif m == "set_traction":
            self.traction[a[0]] = a[1]
        elif m == "repair":
            self.failed.discard(a[0])
        elif m == "restore_line":
            self.cut.discard(f"{a[0]}.{a[1]}")
        elif m in ("fail", "cut_link", "power_off", "set_supply_voltage", "cut_line", "disturb_line"):
            self.faults += 1
            if a[0] == "VDX" and m == "power_off":
                self.restarts += 1
            if m == "fail":
                self.failed.add(a[0])
                self.hit.add(a[0])
            elif m in ("cut_line", "disturb_line"):
                self.hit.add(f"{a[0]}.{a[1]}")
                if m == "cut_line":
                    self.cut.add(f"{a[0]}.{a[1]}")

    def since(self, t_us: int) -> list[Action]:
        """The stimuli given at or after `t_us`."""
        return [action for t, action in self.history if t >= t_us]


@dataclass
class Look:
    driver: TrainDriver
    done: Done
    memory: dict[str, Any]              # an invariant's own notes between looks (what it saw before)
    declaration: Any = None             # the SUT's declaration for the profile (its texts and parameters)

    @property
    def settled(self) -> bool:
        return self.driver.now_us - self.done.last_stimulus_us >= SETTLE_US

    def out(self, name: str) -> str:
        return self.driver.output(name)

    def accuracy(self, parameter: str) -> float:
        """A measurement accuracy the SUT declares (pressure_accuracy_kpa, speed_accuracy_kmh); 0 if none."""
        return (getattr(self.declaration, "parameters", None) or {}).get(parameter, 0)


@dataclass(frozen=True)
class Invariant:
    name: str
    requirements: tuple[str, ...]
    profile: str
    check: Callable[[Look], str | None]  # None while it holds, else what the SUT shows instead
    decision: str = ""                   # where a project decision bounds it (docs/decisions.md)
    focus: tuple[str, ...] = ()          # the kinds of stimulus it is about, in every sequence (sentences.py)

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
    # 590 +- 10: below 580 every conforming train trips, below 580 less its declared pressure accuracy if it
    # measures the pressure off (docs/decisions.md, "Measurement accuracy at the interlocks' edges")
    if not look.settled or kpa is None or kpa >= 580 - look.accuracy("pressure_accuracy_kpa"):
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
    if look.settled and look.out("door-open relay") == "acting" and kmh >= 5 + look.accuracy("speed_accuracy_kmh"):
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


# -- metro TCDS (metro-tcn): TCN-04, TCN-08, TCN-09, RED-04, RED-05, RED-06 ---------------------------------------
# Each unit's control units in the order they master its MVB, and its cab (TCN-02, RED-05); car 1's unit's three
# are the WTB's masters by rank (RED-04).
METRO_UNITS = {1: ("car1.CCU", "car2.VCU", "car3.VCU"), 2: ("car6.CCU", "car5.VCU", "car4.VCU")}
METRO_CAB = {1: 1, 2: 6}
WTB_RANKS = METRO_UNITS[1]
WINDOW_US = 100_000                     # the WTB master's polls looked at: four cycles of 25 ms (TCN-03)


def _of(name: str, node: str) -> bool:
    """`name` is `node` or one of its boards."""
    return name == node or name.startswith(node + ".")


def _unit(name: str) -> int:
    return next(u for u, cars in domains.METRO_UNIT_CARS.items() if domains.car_of(name) in cars)


def _sinks(look: Look) -> list[str]:
    """The train's VVVFs and BECUs, as the SUT names them (devices())."""
    if "sinks" not in look.memory:
        names = [d for car in range(1, domains.CARS["metro-tcn"] + 1) for d in look.driver.devices(car)]
        look.memory["sinks"] = [d for d in names if d.endswith((".VVVF", ".BECU"))]
    return look.memory["sinks"]


def _applies(look: Look, device: str) -> float:
    return look.driver.reading(f"{device}.traction" if device.endswith(".VVVF") else f"{device}.brake")


def _wired(done: Done) -> bool:
    """A wiring fault holds an input of an I/O module: the cab's inputs are then not the desk's."""
    return any(".IO" in name for name in done.inputs)


def _switched_to_emergency(done: Done) -> bool:
    return any(call == ("set_input", ("emergency operation", True)) for _, a in done.history for call in a.calls)


def _follows_the_active_cab(look: Look) -> str | None:
    """TCN-08, RED-05: the active cab's master controller reaches every VVVF and BECU, also through the failure
    of a CCU (the adjacent VCU takes over, the train runs on without restriction); without a key in either cab
    the train stays braked. Judged where no other fault was injected, at most one key is in and the
    emergency-operation switch was never turned on. A BECU may hold more than the demand while the cab asks no
    traction (a standstill holding brake, an option no requirement forbids: docs/decisions.md)."""
    done = look.done
    others = [n for n in done.hit if not any(_of(n, ccu) for ccu in ("car1.CCU", "car6.CCU"))]
    if not look.settled or len(done.keys) > 1 or others or _wired(done) or _switched_to_emergency(done):
        return None
    if done.keys:
        cab = next(iter(done.keys))
        direction, traction, brake = (done.direction.get(cab, "neutral"), done.traction.get(cab, 0),
                                      done.brake.get(cab, 0))
        pull = traction if direction != "neutral" else 0
        said = (f"with the key in cab {cab}, its direction switch at {direction} and its master controller at "
                f"{traction} % traction, {brake} % brake")
    else:
        pull, brake, said = 0, 100, "with no key in either cab"
    wrong = {}
    for device in _sinks(look):
        got = _applies(look, device)
        drive = device.endswith(".VVVF")
        if drive and got != pull or not drive and (got < brake or pull and got != brake):
            wrong[device] = got
    if not wrong:
        return None
    failed = f" ({', '.join(sorted(done.hit))} failed)" if done.hit else ""
    return f"{said}{failed}, every VVVF should apply {pull:g} % and every BECU {brake:g} %: {wrong}"


def _cut_off_unit_brakes(look: Look) -> str | None:
    """TCN-09: a unit that can no longer hear the train command brakes to a stop: both lines of its MVB cut, its
    CCU and both VCUs failed, or the WTB dead (both lines cut, or car 1's unit's three failed) while its own cab
    has no key. Every live VVVF of it applies 0 %, every live BECU 100 % (F-NET-25). Not while the
    emergency-operation switch is on (hard-wired operation, TCN-09's other way), nor with a wiring fault on a cab's
    inputs (a key the desk does not have)."""
    done = look.done
    if not look.settled or done.inputs.get("emergency operation") or _wired(done):
        return None
    dead = lambda unit: all(node in done.failed for node in METRO_UNITS[unit])   # noqa: E731
    wtb_dead = {"WTB.A", "WTB.B"} <= done.cut or dead(1)
    for unit in METRO_UNITS:
        why = ("both lines of its MVB are cut" if {f"unit{unit}.MVB.A", f"unit{unit}.MVB.B"} <= done.cut
               else "its CCU and both VCUs have failed" if dead(unit)
               else f"the WTB is dead and cab {METRO_CAB[unit]} has no key"
               if wtb_dead and METRO_CAB[unit] not in done.keys else None)
        if why is None:
            continue
        wrong = {}
        for device in _sinks(look):
            if _unit(device) == unit and device not in done.failed:
                want = 0.0 if device.endswith(".VVVF") else 100.0
                if (got := _applies(look, device)) != want:
                    wrong[device] = got
        if wrong:
            return f"unit {unit} is cut off from the train command ({why}), and it does not brake: {wrong}"
    return None


def _wtb_master_by_rank(look: Look) -> str | None:
    """RED-04: the car 1 CCU masters the WTB, else the car 2 VCU, else the car 3 VCU; nothing of the other unit
    ever does, one node at a time, and the WTB stops only when all three have failed. A backup may master only
    where every node above it has met a fault (a repaired node need not take the WTB back); with both WTB lines
    disturbed or cut a backup may have taken it from a node it could not hear."""
    if not look.settled:
        return None
    done, now = look.done, look.driver.now_us
    masters = sorted({ev["master"] for ev in look.driver.trace.select(kind="wtb.msg", source="WTB",
                                                                      since=now - WINDOW_US)})
    down = lambda node: any(_of(n, node) for n in done.failed)          # noqa: E731
    touched = lambda node: any(_of(n, node) for n in done.hit)          # noqa: E731
    if not masters:
        up = [node for node in WTB_RANKS if not down(node)]
        return f"the WTB is silent though {', '.join(up)} has not failed" if up else None
    if len(masters) > 1 or masters[0] not in WTB_RANKS:
        return f"the WTB master frames of the last {WINDOW_US // 1000} ms come from {', '.join(masters)}"
    if {"WTB.A", "WTB.B"} <= done.hit:
        return None
    above = [node for node in WTB_RANKS[:WTB_RANKS.index(masters[0])] if not touched(node)]
    return f"{masters[0]} masters the WTB though {', '.join(above)} never failed" if above else None


def _one_line_loses_nothing(look: Look) -> str | None:
    """RED-06: a fault on one line of a bus (cut, or frames disturbed) switches the receivers to the other line
    without the loss of a message. Checked after every stimulus, on every bus of which at most one line has ever
    met a fault."""
    done, checked = look.done, look.memory.setdefault("checked until", {})
    for bus in domains.METRO_BUSES:
        hit = sorted(line for line in "AB" if f"{bus}.{line}" in done.hit)
        if len(hit) > 1:
            continue
        kind = "wtb.msg" if bus == "WTB" else "mvb.msg"
        lost = look.driver.trace.first(kind=kind, source=bus, since=checked.get(bus, 0), lost=True)
        checked[bus] = look.driver.now_us + 1
        if lost is not None:
            fault = f"only line {hit[0]} met a fault" if hit else "neither line met a fault"
            return f"a message on {bus} was lost at {lost.t / 1000:g} ms though {fault}"
    return None


def _silent_device_shown(look: Look) -> str | None:
    """TCN-04: the CCU polls its unit's devices for status data, and a device that stops answering is shown on the
    display unit (its unit's, cab 1 for cars 1-3, cab 6 for cars 4-6), in the SUT's declared words. Judged for a
    device silent since the last stimulus at least, where no control unit of its unit and neither line of its MVB
    ever met a fault (its unit's master then polls it) and the display is lit."""
    if not look.settled:
        return None
    done = look.done
    for device in sorted(done.failed):
        if device.count(".") != 1 or device.endswith((".CCU", ".VCU", ".IO1", ".IO2")):
            continue                    # a control unit, a board, an I/O module: not a device the CCU polls
        unit = _unit(device)
        if any(any(_of(n, node) for node in METRO_UNITS[unit]) or n.startswith(f"unit{unit}.MVB.") for n in done.hit):
            continue
        cab = METRO_CAB[unit]
        shown = look.driver.monitor(cab)
        if shown.get("blank"):
            continue
        pattern, say = _declared_message(look, f"{device}: no status data")
        if not any(pattern.search(text) for text in shown["faults"]):
            return f"{device} has been silent since the last stimulus or longer, and the cab {cab} display does not " \
                   f"show {say}: {list(shown['faults'])}"
    return None


def _declared_message(look: Look, text: str) -> tuple[re.Pattern, str]:
    """How the SUT words the message `text` names (steps/messages.py), its identifier's own words if it declares
    nothing."""
    if look.declaration is None:
        return re.compile(re.escape(text)), repr(text)
    return messages.message(look.declaration, text)


# -- CTCS-2 200C ATP (atp): ATP-01, ATP-03..07, ATP-09, ATP-10 ----------------------------------------------------
def _new_stimuli(look: Look) -> list[tuple[int, Action]]:
    """The stimuli since this invariant's last look (the one just given, or the opening's at the first look)."""
    seen = look.memory.get("stimuli seen", 0)
    look.memory["stimuli seen"] = len(look.done.history)
    return look.done.history[seen:]


def _sets(action: Action, name: str) -> list[Any]:
    """The values `action` gives the input `name`."""
    return [a[1] for m, a in action.calls if m == "set_input" and a[0] == name]


def _packets(action: Action, kind: str) -> list[dict]:
    return [p for p in action.args[1] if p.get("type") == kind] if action.method == "pass_balise" else []


def _odometry(done: Done, now_us: int) -> tuple[float, float] | None:
    """Where the rig's odometry puts the front now (m) and its speed (km/h), from the positions and speeds the
    sequence set (the train runs on at the speed set); None before a position was set."""
    pos, kmh, at = None, 0.0, 0
    for t, action in done.history:
        for m, a in action.calls:
            if m == "set_input" and a[0] in ("position", "speed"):
                pos = None if pos is None else pos + kmh / 3.6 * (t - at) / 1e6
                at = t
                pos, kmh = (float(a[1]), kmh) if a[0] == "position" else (pos, float(a[1]))
    return None if pos is None else (pos + kmh / 3.6 * (now_us - at) / 1e6, kmh)


def _speed_at(done: Done, t_us: int) -> float:
    speeds = [v for t, a in done.history if t <= t_us for v in _sets(a, "speed")]
    return float(speeds[-1]) if speeds else 0.0


def _default_telegram_brakes(look: Look) -> str | None:
    """ATP-07: a default telegram from a side-line balise on a diverging entry (the ATP supervising, FS or AM)
    brings maximum service brake, held while the train runs at 45 km/h or more; below 45 km/h the ATP enters PS
    and deletes the line data it held. The PS and deletion are judged where nothing but the speed and the position
    were set after the telegram (a later balise or mode input may rightly change the mode again)."""
    done, mem, driver = look.done, look.memory, look.driver
    before = mem.get("mode")                    # the mode just before this stimulus
    for t, action in _new_stimuli(look):
        if any(p.get("side_line") for p in _packets(action, "default")) and before in ("FS", "AM"):
            tracks = [s for s, a in done.history if s <= t and _packets(a, "MA")]
            deleted = driver.trace.last(kind="linedata.delete", until=t)
            mem["telegram"] = (t, bool(tracks) and (deleted is None or deleted.t < tracks[-1]))
    mode = mem["mode"] = driver.output("ATP mode")
    if "telegram" not in mem or not look.settled:
        return None
    t, held = mem["telegram"]
    # The speeds since the telegram, each with how long it held: one set and at once replaced the ATP never saw.
    sets = [(_speed_at(done, t), t)] + [(v, s) for s, a in done.history if s > t for v in _sets(a, "speed")]
    spans = [(v, s, nxt) for (v, s), (_, nxt) in zip(sets, [*sets[1:], (None, driver.now_us)])]
    if not any(v < 45 and end > start for v, start, end in spans):
        if driver.output("ATP brake") == "none":
            return f"after the default telegram at {t / 1000:g} ms, the train at 45 km/h or more since, the ATP " \
                   f"commands no brake"
        return None
    if sets[-1][0] >= 45:
        return None
    del mem["telegram"]                         # judged once, at the first quiet look below 45 km/h
    if not all(call[0] == "set_input" and call[1][0] in ("speed", "position")
               for action in done.since(t + 1) for call in action.calls):
        return None
    if mode != "PS":
        return f"at {sets[-1][0]:g} km/h for a second after the default telegram at {t / 1000:g} ms, the ATP is in " \
               f"mode {mode}, not PS"
    if held and driver.trace.first(kind="linedata.delete", since=t) is None:
        return f"below 45 km/h after the default telegram at {t / 1000:g} ms, the ATP kept its line data"
    return None


def _cfsk_fault_recorded(look: Look) -> str | None:
    """ATP-01, ATP-05: a faulty CFSK sends its fault information to the safety computer, never a decoded result,
    until it is repaired; every time it becomes faulty a CFSK record with the state fault is written (two faults
    close together are two records), in the SUT's declared words."""
    mem, driver = look.memory, look.driver
    for t, action in _new_stimuli(look):
        if action.calls[0] == ("fail", ("CFSK",)) and mem.get("failed at") is None:
            mem["failed at"], mem["faults"] = t, mem.get("faults", 0) + 1
        elif action.calls[0] == ("repair", ("CFSK",)):
            mem["failed at"] = None
    at = mem.get("failed at")
    if at is not None and (decoded := driver.trace.first(kind="cfsk.report", since=at + 1)) is not None:
        return f"the CFSK failed at {at / 1000:g} ms and reported {decoded['carrier']} Hz with code " \
               f"{decoded['code']} at {decoded.t / 1000:g} ms"
    if not look.settled or not mem.get("faults"):
        return None
    if at is not None and driver.trace.first(kind="cfsk.fault", since=at) is None:
        return f"the CFSK failed at {at / 1000:g} ms, and no fault information reached the safety computer"
    declaration = look.declaration
    marker = declaration.text("CFSK") if declaration else "CFSK"
    word = declaration.text("state=fault") if declaration else "state=fault"
    records = [r for r in driver.records("ATP") if marker in r]
    faulty = [r for r in records if word in r.split()]
    if len(faulty) < mem["faults"]:
        return f"the CFSK became faulty {mem['faults']} times, and the ATP holds {len(faulty)} CFSK record(s) with " \
               f"{word!r}: {records}"
    return None


def _generator_and_set(done: Done, before_us: int) -> tuple[tuple[int, str] | None, str, int]:
    """What the signal generator sends, the carrier set selected (the DMI or a balise's line information; down at
    power-up), and when either last changed, from the stimuli given before `before_us`."""
    heard, selected, changed = None, "down", 0
    carrier, code = None, None
    for t, action in done.history:
        if t >= before_us:
            break
        for value in _sets(action, "carrier"):
            carrier = value
        for value in _sets(action, "low frequency code"):
            code = value
        now = (carrier, code) if carrier is not None else None
        chosen = [a[2] for m, a in action.calls if m == "monitor_order" and a[1] == "carrier set"]
        chosen += [p["direction"] for p in _packets(action, "line direction")]
        new_set = chosen[-1] if chosen else selected
        if now != heard or new_set != selected:
            changed = t
        heard, selected = now, new_set
    return heard, selected, changed


def _cfsk_confirms(look: Look) -> str | None:
    """ATP-03, ATP-04: the CFSK decodes the carrier set last selected (balise line information or the driver at
    the DMI); it reports a carrier of that set only as the generator sends it, with its code, and not before 3
    comparisons can have agreed: (3 - 1) comparison periods after the carrier, its code or the set last changed
    (the first comparison may come at once), less the declared timing resolution."""
    done, driver, mem = look.done, look.driver, look.memory
    period = tick = None
    if look.declaration is not None:
        period = look.declaration.parameter("cfsk_period_ms") * 1000
        tick = look.declaration.parameter("timing_resolution_us")
    for report in driver.trace.select(kind="cfsk.report", since=mem.get("reports since", 0)):
        heard, selected, changed = _generator_and_set(done, report.t)
        if any(t == report.t for t, _ in done.history):
            continue                            # a stimulus at the report's own microsecond: either order
        said = f"the CFSK reported {report['carrier']} Hz with code {report['code']} at {report.t / 1000:g} ms"
        if report["carrier"] not in domains.ATP_CARRIER_SETS[selected]:
            return f"{said}, outside the {selected}-line carrier set selected"
        if heard != (report["carrier"], report["code"]):
            return f"{said} while the generator sent {heard}"
        if period is not None and report.t - changed < 2 * period - tick:
            return f"{said}, {(report.t - changed) / 1000:g} ms after the generator or the carrier set changed: " \
                   f"fewer than 3 comparisons {period / 1000:g} ms apart"
    mem["reports since"] = driver.now_us + 1
    if look.settled:
        _, selected, _ = _generator_and_set(done, driver.now_us + 1)
        if (used := driver.output("CFSK carrier set")) != selected:
            return f"the {selected}-line carrier set was selected last, and the CFSK uses the {used}-line set"
    return None


def _permissions_only_when_due(look: Look) -> str | None:
    """ATP-09, ATP-10: ATO allowed only under full supervision (FS, or AM once started) without an ATP brake; door
    enable only standing within -0.5 .. +0.5 m of the stop point the precise-positioning balise gave; platform-
    screen-door permission only with door enable where that balise said the platform has screen doors."""
    if not look.settled:
        return None
    done, driver = look.done, look.driver
    ato, mode, brake = driver.output("ATO allowed"), driver.output("ATP mode"), driver.output("ATP brake")
    if ato == "granted" and (mode not in ("FS", "AM") or brake != "none"):
        return f"ATO allowed is granted in mode {mode} with {brake} brake"
    door, psd = driver.output("door enable"), driver.output("PSD permission")
    if "granted" not in (door, psd):
        return None
    stops = [p for _, a in done.history for p in _packets(a, "stop point")]
    where = _odometry(done, driver.now_us)
    granted = "door enable" if door == "granted" else "PSD permission"
    if not stops or where is None:
        return f"{granted} is granted, and no stop point was given or no position set"
    (pos, kmh), stop = where, stops[-1]
    if kmh != 0 or abs(pos - stop["at_m"]) > 0.5 + 1e-6:
        return f"{granted} is granted at {pos:.2f} m, {kmh:g} km/h; the stop point is at {stop['at_m']:g} m"
    if psd == "granted" and not stop.get("psd"):
        return f"PSD permission is granted at a stop point without platform screen doors"
    return None


def _fs_until_150m(look: Look) -> str | None:
    """ATP-06: full supervision turns into partial supervision 150 m before the end of authority: FS no nearer,
    and no FS left for PS farther (but after a default telegram, ATP-07's). Distances from the odometry the
    sequence set, to within 5 m and the travel of 100 ms; the end of authority of the last balise that gave one,
    unless the ATP deleted its line data since."""
    done, driver, mem = look.done, look.driver, look.memory
    mode = driver.output("ATP mode")
    before, mem["mode"] = mem.get("mode"), mode
    tracks = [(t, p["end_m"]) for t, a in done.history for p in _packets(a, "MA")]
    where = _odometry(done, driver.now_us)
    if not tracks or where is None:
        return None
    t_track, eoa = tracks[-1]
    deleted = driver.trace.last(kind="linedata.delete")
    if deleted is not None and deleted.t >= t_track:
        return None
    (pos, kmh), left = where, tracks[-1][1] - where[0]
    slack = 5 + kmh / 3.6 * 0.1
    if mode == "FS" and look.settled and left < 150 - slack:
        return f"the ATP is in FS {left:.1f} m before the end of authority at {eoa:g} m"
    diverging = any(_packets(a, "default") for a in done.since(t_track))
    if before == "FS" and mode == "PS" and left > 150 + slack and not diverging:
        return f"the ATP left FS for PS {left:.1f} m before the end of authority at {eoa:g} m"
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
    Invariant("every VVVF and BECU follows the active cab, through a CCU failure", ("TCN-08", "RED-05"),
              "metro-tcn", _follows_the_active_cab, focus=("CCU fails", "key out")),
    Invariant("a unit cut off from the train command brakes", ("TCN-09",), "metro-tcn", _cut_off_unit_brakes,
              focus=("line cut", "units fail together")),
    Invariant("only car 1's unit masters the WTB, one node at a time, by rank", ("RED-04",), "metro-tcn",
              _wtb_master_by_rank, focus=("CCU fails", "VCU fails", "units fail together")),
    Invariant("a fault on one line of a bus loses no message", ("RED-06",), "metro-tcn", _one_line_loses_nothing,
              focus=("line cut", "line restored", "line disturbed")),
    Invariant("a silent device is shown on its unit's display", ("TCN-04",), "metro-tcn", _silent_device_shown,
              focus=("device fails", "device repaired")),
    Invariant("a default telegram brakes, and below 45 km/h the ATP is in PS without line data", ("ATP-07",), "atp",
              _default_telegram_brakes, focus=("default telegram", "speed")),
    Invariant("a faulty CFSK is recorded and sends no decoded result", ("ATP-01", "ATP-05"), "atp",
              _cfsk_fault_recorded, focus=("CFSK fails", "CFSK repaired", "generator")),
    Invariant("the CFSK reports a carrier of its selected set only after 3 agreeing comparisons",
              ("ATP-03", "ATP-04"), "atp", _cfsk_confirms,
              focus=("generator", "carrier set at the DMI", "line information")),
    Invariant("ATO, door and screen-door permissions are granted only when their conditions hold",
              ("ATP-09", "ATP-10"), "atp", _permissions_only_when_due, focus=("stop point", "stop", "ATP input")),
    Invariant("full supervision lasts until 150 m before the end of authority", ("ATP-06",), "atp", _fs_until_150m,
              focus=("position", "track circuits")),
]
