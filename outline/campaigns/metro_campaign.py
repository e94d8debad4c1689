"""The metro single-fault campaign (F-NET-34, issue 16): every single fault of the metro TCDS's units, boards,
I/O modules, devices and bus lines, one scenario each, generated from what the SUT says it is made of.

`python -m outline campaign` writes it beside the CRH2 campaigns (outline/campaigns/campaign.py's `run`): it opens the
metro train through its driver, reads the fault space from it (`devices(car)` for the six cars,
`boards(unit)`, the buses its backend names) and puts each fault in the Scenario Outline of what the design
says the train does under it (`expectation`: the articles' and docs/decisions.md's answer, not a
recording of the reference), or lists it as left out with the reason. At the instant of the fault the
driver moves the master controller of cab 1: the campaign checks the way into the degraded mode (a
takeover, module 2, the other line), not only the mode once settled.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass

from outline.campaigns.campaign_text import background, examples, powered
from .fault_model import Fault  # kind: line, unit, board, module, device; values: (bus, line) or the name

ITEM = "F-NET-34"
PATH = "features/function/network-transmission-redundancy/F-NET-34.feature"
TITLE = "Single-fault campaign, metro 6-car train"
GIVEN = "Given a 6-car metro train with its train control and diagnosis system"
PCT = 60                       # the master controller's traction demand, moved at the instant of the fault

# The design, written once (not read from the reference):
CAB = 1                                             # the key is in cab 1
LINES = ("A", "B")                                  # RED-06: WTB and every MVB run lines A and B
WTB_RANKS = ("car1.CCU", "car2.VCU", "car3.VCU")    # RED-04: WTB master, then its backups in order
# TCN-02, TCN-04: each unit's MVB is mastered by its cab car's CCU; RED-05 (docs/decisions.md "Masters by rank"):
# when that CCU fails, the VCU next to it takes the MVB, and in the keyed cab's unit the control too.
MVB1, ACTIVE_CCU, ACTIVE_BACKUP = "unit1.MVB", "car1.CCU", "car2.VCU"
MVB2, OTHER_CCU, OTHER_BACKUP = "unit2.MVB", "car6.CCU", "car5.VCU"
VITAL = ("VCPUS", "VPS")       # seed 002 §2.1: processor and power supply; without either the unit is dead
GATEWAY = "VGWS"               # §3.1: the WTB-MVB gateway
ASIDE_BOARDS = ("VMS", "VDIS", "VDOS")     # §2.1: records, digital in, digital out; §3.2: the command rides the MVB

# Bounds (ms), each from a hand-written metro feature:
DELIVERY = 100       # F-CTL-15: the master controller reaches every VVVF within 100 ms (F-CTL-16: from module 2)
WTB_CYCLE = 25       # F-NET-21, F-NET-22: the WTB master polls within every 25 ms cycle (TCN-03)
MVB_PERIOD = 1       # F-NET-21: each unit's MVB master polls every 1 ms basic period (TCN-03)
MVB_TAKEOVER = 100   # F-CTL-15: the adjacent VCU masters the MVB within 100 ms
WTB_TAKEOVER = 250   # F-NET-22: a WTB fallback completes within 10 cycles
# The fault and the move coincide, so after a takeover the new command still has its DELIVERY to go.
# WINDOW: F-NET-22 and F-CTL-15 watch 1000 ms after a fault; it outlasts the 250 ms gateway and 100 ms VVVF/BECU
# supervision (docs/decisions.md, TCN-09), so a command lost on the way shows as a brake.
WINDOW = 1000


@dataclass(frozen=True)
class Group:
    """Faults the design answers alike, and its answer in the hand-written metro features' sentences."""
    title: str                 # <fault>: the fault as a title names it
    reqs: tuple[str, ...]
    then: tuple[str, ...]


@dataclass(frozen=True)
class LeftOut:
    reason: str


def named(fault: Fault) -> str:
    """How the feature's list of faults left out names one: a line by its bus, the rest by their name."""
    return f"{fault.values[0]} line {fault.values[1]}" if fault.kind == "line" else fault.values[0]


def _wtb(node: str, bound: int) -> str:
    return f'"{node}" is the WTB master within {bound} ms and stays so'


def _mvb(node: str, bus: str, bound: int) -> str:
    return f'"{node}" is the master of "{bus}" within {bound} ms and stays so'


def _pulls(bound: int) -> str:
    return f"every VVVF applies {PCT} % traction within {bound} ms"


MASTERS_STAY = (_wtb(WTB_RANKS[0], WTB_CYCLE), _mvb(ACTIVE_CCU, MVB1, MVB_PERIOD), _mvb(OTHER_CCU, MVB2, MVB_PERIOD))
STAY_REQS = ("RED-04", "TCN-04", "TCN-08")     # WTB master by rank; each CCU masters its MVB; the command reaches

# RED-06: the line fault is diagnosed and recorded (F-NET-23's text); RED-05: in both CCU memories, once each.
RECORDED = tuple(f'"{ccu}" holds the record "<bus> line <line>: fault" exactly once' for ccu in (ACTIVE_CCU, OTHER_CCU))
LINE = Group("<fault>: the other line carries everything, the train pulls", ("RED-06", "RED-05", *STAY_REQS),
             (_pulls(DELIVERY), 'no message on "<bus>" is lost', *MASTERS_STAY, *RECORDED))
STANDBY = Group("<fault>, a standby lost: the masters stay, the train pulls", ("RED-05", *STAY_REQS),
                (_pulls(DELIVERY), *MASTERS_STAY))
ASIDE = Group("<fault>, off the command's way: the masters stay, the train pulls", STAY_REQS,
              (_pulls(DELIVERY), *MASTERS_STAY))
MODULE_2 = Group("<fault>, module 1 of the keyed cab lost: module 2's inputs drive the train", ("RED-07", *STAY_REQS),
                 (_pulls(DELIVERY), *MASTERS_STAY))
MODULE_IDLE = Group("<fault>, a module whose inputs are not in use: the train pulls", ("RED-07", *STAY_REQS),
                    (_pulls(DELIVERY), *MASTERS_STAY))
ACTIVE_LOST = Group(f"<fault>, the keyed cab's CCU lost: {ACTIVE_BACKUP} takes both buses and the control",
                    ("RED-05", "RED-04", "TCN-04", "TCN-08"),
                    (_pulls(WTB_TAKEOVER + DELIVERY), _mvb(ACTIVE_BACKUP, MVB1, MVB_TAKEOVER),
                     _wtb(WTB_RANKS[1], WTB_TAKEOVER), _mvb(OTHER_CCU, MVB2, MVB_PERIOD)))
OTHER_LOST = Group(f"<fault>, the other cab's CCU lost: {OTHER_BACKUP} takes its MVB and relays the command",
                   ("RED-05", "RED-04", "TCN-04", "TCN-08"),
                   (_pulls(MVB_TAKEOVER + DELIVERY), _mvb(OTHER_BACKUP, MVB2, MVB_TAKEOVER),
                    _wtb(WTB_RANKS[0], WTB_CYCLE), _mvb(ACTIVE_CCU, MVB1, MVB_PERIOD)))
GROUPS = (LINE, STANDBY, ASIDE, MODULE_2, MODULE_IDLE, ACTIVE_LOST, OTHER_LOST)

# Fail-safety over the whole trace, and the train running on from the fault (RED-05: "without restriction").
INVARIANTS = (f"no VVVF ever applies a traction other than 0 or {PCT} %",
              "no VVVF ever pulls while a BECU brakes",
              "no BECU applies a brake from the fault on")

KIND_ORDER = ("line", "unit", "board", "module", "device")
# Per kind: the hand-written metro features' sentence, its Examples columns, how a title names it.
SENTENCES = {
    "line": ('line <line> of "<bus>" is cut', ("bus", "line"), 'line <line> of "<bus>" cut'),
    "unit": ('"<unit>" fails', ("unit",), "<unit> failed"),
    "board": ('"<board>" fails', ("board",), "board <board> failed"),
    "module": ('"<module>" fails', ("module",), "I/O module <module> failed"),
    "device": ('"<device>" fails', ("device",), "<device> failed"),
}

DEAD_DRIVE = LeftOut("the VVVF itself: no answer of the network makes a dead drive pull, and the articles do "
                     "not say what the train does with one drive out")
DEAD_BRAKE = LeftOut("the BECU itself: whether a brake unit out cuts traction is the brake system's answer, "
                     "not the network's, and the articles do not say")


def expectation(fault: Fault) -> Group | LeftOut:
    """What the design does under `fault`, the key in cab 1, or why the campaign leaves the fault out."""
    if fault.kind == "line":
        return LINE                      # RED-06: every frame on both lines, a line lost switches without loss
    name = fault.values[0]
    car, _, rest = name.partition(".")
    what, _, board = rest.partition(".")
    if fault.kind == "device":
        if what == "VVVF":
            return DEAD_DRIVE
        if what == "BECU":
            return DEAD_BRAKE
        if what in ("DU", "APU", "VATC"):
            return ASIDE                 # §3.2: they answer status polls; the command goes CCU -> MVB -> VVVF/BECU
    elif fault.kind == "module":
        if name == f"car{CAB}.IO1":
            return MODULE_2              # RED-07: module 1's life signal 0 -> module 2's inputs
        if what in ("IO1", "IO2"):
            return MODULE_IDLE           # RED-07: not module 2 while module 1 lives; TCN-08: nor the keyless cab's
    elif what == "VCU":
        return STANDBY                   # RED-04/05: a VCU masters nothing while the CCUs live, the WTB goes on
    elif what == "CCU":
        unit = f"{car}.{what}"
        if board in ASIDE_BOARDS:
            return ASIDE                 # the CCU still computes, masters and relays: nothing changes hands
        # The CCU dead, or cut off from the train by its gateway (docs/decisions.md "Gateway failure"): RED-05 its
        # VCU takes the MVB and the control, RED-04 the WTB if it is car 1's.
        if not board or board in VITAL or board == GATEWAY:
            if unit in (ACTIVE_CCU, OTHER_CCU):
                return ACTIVE_LOST if unit == ACTIVE_CCU else OTHER_LOST
    raise ValueError(f"the design has no rule for {fault.kind} {name!r}: add one to outline/campaigns/metro_campaign.py")


def buses(sut) -> tuple[str, ...]:
    """The buses `cut_line` takes. The driver interface has no read for them; the backend's module names them
    (sut/reference/metro/backend.py BUSES), found through the driver's class and its bases, so a variant
    subclass reads its reference's."""
    for cls in type(sut).__mro__:
        found = getattr(cls, "BUSES", None) or getattr(sys.modules.get(cls.__module__), "BUSES", None)
        if found:
            return tuple(found)
    raise LookupError(f"{type(sut).__qualname__} names no buses (BUSES): the metro campaign cannot cut their lines")


def fault_space(sut) -> list[Fault]:
    """Every single fault of the train the driver describes: the lines of its buses, then car by car its
    units (CCU, VCU) with their boards, its MVB I/O modules and its devices."""
    faults = [Fault("line", (bus, line)) for bus in buses(sut) for line in LINES]
    for car in range(1, 7):
        for name in sut.devices(car):
            kind = name.rpartition(".")[2]
            if kind in ("CCU", "VCU"):
                faults.append(Fault("unit", (name,)))
                faults += [Fault("board", (f"{name}.{board}",)) for board in sut.boards(name)]
            else:
                faults.append(Fault("module" if kind.startswith("IO") else "device", (name,)))
    return faults


def render(faults: list[Fault]) -> str:
    answers = {fault: expectation(fault) for fault in faults}
    left_out = [(fault, answer) for fault, answer in answers.items() if isinstance(answer, LeftOut)]
    used = [group for group in GROUPS if group in answers.values()]
    reqs = sorted({r for group in used for r in group.reqs})
    lines = [
        "# Generated by `python -m outline campaign` from the SUT's own description (devices, boards, buses);",
        "# edit outline/campaigns/metro_campaign.py, not this file. tests/test_metro_campaign.py fails when the two differ.",
        f"@item:{ITEM} @profile:metro-tcn @req:TST-04",
        f"Feature: {ITEM} {TITLE}",
        f"  Requirements: {', '.join(reqs)}, TST-04.",
        f"  Every single fault of the train's bus lines, units, boards, I/O modules and devices ({len(faults)}; "
        f"{len(faults) - len(left_out)} run, one",
        f"  scenario each): at the instant of the fault the driver moves the master controller of cab {CAB} to "
        f"{PCT} %",
        "  traction; every VVVF must apply it within the bound of the design's answer to that fault, and the",
        "  masters that answer names must hold the buses. Over the whole trace no VVVF applies another traction",
        "  and none pulls while a BECU brakes; from the fault on no BECU brakes (the train runs on).",
        f"  Bounds from the hand-written metro features: delivery {DELIVERY} ms and an MVB takeover "
        f"{MVB_TAKEOVER} ms (F-CTL-15),",
        f"  a WTB fallback {WTB_TAKEOVER} ms (F-NET-22), the WTB cycle {WTB_CYCLE} ms and the MVB period "
        f"{MVB_PERIOD} ms (F-NET-21);",
        f"  after a takeover the command still has its delivery to go. Each scenario watches {WINDOW} ms.",
        "  Not in the campaign:",
        *[f"  - {', '.join(named(f) for f, a in left_out if a is why)}: {why.reason}"
          for why in dict.fromkeys(answer for _, answer in left_out)],
        "",
        *background(GIVEN),
    ]
    for group in GROUPS:
        for kind in KIND_ORDER:
            members = [fault for fault in faults if fault.kind == kind and answers[fault] is group]
            if members:
                lines += ["", *_outline(group, kind, members)]
    return "\n".join(lines) + "\n"


def _outline(group: Group, kind: str, members: list[Fault]) -> list[str]:
    when, columns, named = SENTENCES[kind]
    return [
        f"  {' '.join('@req:' + r for r in group.reqs)}",
        f"  Scenario Outline: {ITEM} {group.title.replace('<fault>', named[0].upper() + named[1:])}",
        f"    When {when}",
        f"    And the driver moves the master controller of cab {CAB} to {PCT} % traction",
        f"    And {WINDOW} ms pass",
        f"    Then {group.then[0]}",
        *[f"    And {then}" for then in (*group.then[1:], *INVARIANTS)],
        "",
        *examples([list(columns), *[list(fault.values) for fault in members]]),
    ]


def generate(spec: str) -> tuple[str, str] | None:
    """(path, text) of F-NET-34 from the SUT `spec`'s metro train; None if it has no metro-tcn profile."""
    from sut.backends import resolve

    if "metro-tcn" not in resolve(spec).PROFILES:
        return None
    with powered(spec, "metro-tcn", 1, 6) as sut:
        return PATH, render(fault_space(sut))
