"""Fault campaigns (issue 16): every single fault of a CRH2 train's boards, ring spans and power supplies, one
scenario each, generated from what the SUT says it is made of (and every pair of them: outline/campaigns/double_campaign.py;
the metro train's single faults, F-NET-34: outline/campaigns/metro_campaign.py).

`python -m outline campaign` opens the SUT through its driver (the reference by default), reads the fault
space from it (`ring_nodes`: the spans between neighbours; `boards`; `supplies`), and writes each campaign's
feature file: Scenario Outlines whose Examples are the faults, grouped by what the design says the train
does under them. The expectation of each group is the articles' (the requirement IDs on its outline; the
groups equal outline/campaigns/fault_model.py: tests/test_campaign.py), not a recording of what the reference did, so a
reference that behaves otherwise fails the campaign. Faults outside the campaign are listed in the feature
with the reason. `--check` compares instead of writing (the project's
tests run it): a campaign that no longer covers the SUT's fault space fails.

The command goes out at the instant of the fault: the campaign checks the way into a degraded mode (takeover,
fallback to path 2 or 3), not only the mode once settled.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

from outline.campaigns import double_campaign
from outline.campaigns import metro_campaign
from outline.campaigns.campaign_text import (INVARIANTS, KIND_ORDER, NOTCH, RIDE, STEP, TAKEOVER, WINDOW, background, example_rows,
                            examples, numbered, powered, record_bound)
from outline.campaigns.fault_model import Fault, TrainShape, car_of, fault_record

@dataclass(frozen=True)
class Group:
    """Faults the design answers alike, and its answer in the sentences the hand-written features use
    (`<car>` is the car the fault cuts off)."""
    title: str
    reqs: tuple[str, ...]
    then: tuple[str, ...]


RIDES = Group("<fault>: every CI and BCU stays on path 1", ("NET-03", "CMD-01", "CMD-02"), (
    f"every CI and BCU receives traction notch {NOTCH} over path 1 within {RIDE} ms",
    f"from {RIDE} ms on every CI and BCU receives traction notch {NOTCH} over path 1"))
TAKES_OVER = Group("<fault>, the commanding system lost: system 2 takes over", ("RED-01", "RED-02"), (
    f"every CI and BCU receives traction notch {NOTCH} over path 1 within {TAKEOVER} ms",
    f"from {TAKEOVER} ms on every CI and BCU receives traction notch {NOTCH} over path 1"))
OFF_THE_RING = Group("<fault>, car <car> off the ring: path 3 for it, path 1 for the rest", ("CMD-04", "NET-03"), (
    f'the CI and BCU of car <car> receive traction step "{STEP}" over path 3 within {TAKEOVER} ms',
    f"from {RIDE} ms on every CI and BCU outside car <car> receives traction notch {NOTCH} over path 1"))
NO_MDM9 = Group("<fault>, car <car> without its MDM9: path 2 for it, path 1 for the rest", ("CMD-03",), (
    f'the CI and BCU of car <car> receive traction step "{STEP}" over path 2 within {RIDE} ms',
    f"from {RIDE} ms on every CI and BCU outside car <car> receives traction notch {NOTCH} over path 1"))
GROUPS = (RIDES, TAKES_OVER, OFF_THE_RING, NO_MDM9)


def fault_space(sut) -> tuple[list[Fault], list[tuple[str, str]]]:
    """The single faults of the train the driver describes, and those left out with the reason."""
    nodes = sut.ring_nodes()
    faults = [Fault("span", (a, b)) for a, b in zip(nodes, nodes[1:] + nodes[:1])]
    faults += [Fault("board", (f"{node}.{board}",)) for node in nodes for board in sut.boards(node)]
    left_out = []
    for supply in sut.supplies():
        if supply.endswith(".desk"):
            left_out.append((supply, "the desk's digital inputs: switching them off changes the driver's command "
                             "itself (CMD-05), no network fault"))
        else:
            faults.append(Fault("supply", (supply,)))
    return faults, left_out


def expectation(shape: TrainShape, fault: Fault, commanding: str) -> tuple[Group, int | None]:
    """What the design does under `fault` while `commanding` (a CCU system) puts the commands on the ring,
    and the car it cuts off (None if none)."""
    dead = shape.dead_boards([fault])
    if dead & {f"{commanding}.MDM8", f"{commanding}.TXC"}:
        return TAKES_OVER, None
    for board in sorted(dead):
        unit, _, kind = board.rpartition(".")
        if unit.endswith(".LCU") and kind in ("MDM8", "MDM9"):
            return (OFF_THE_RING if kind == "MDM8" else NO_MDM9), car_of(unit)
    return RIDES, None    # spans (NET-03), CPU3s (CMD-01: commands bypass them), RXCs, standby and far-cab systems


@dataclass(frozen=True)
class Campaign:
    item: str
    path: str
    title: str
    sets: int
    given: str
    pairs: str = ""            # the single-fault campaign whose faults it pairs (outline/campaigns/double_campaign.py)


CAMPAIGNS = (
    Campaign("F-NET-30", "features/function/network-transmission-redundancy/F-NET-30.feature",
             "Single-fault campaign, 8-car set", 1, "Given an 8-car CRH2 train set"),
    Campaign("F-NET-31", "features/function/network-transmission-redundancy/F-NET-31.feature",
             "Single-fault campaign, two coupled 8-car sets", 2, "Given two 8-car CRH2 train sets coupled together"),
    Campaign("F-NET-32", "features/function/network-transmission-redundancy/F-NET-32.feature",
             "Double-fault campaign, 8-car set", 1, "Given an 8-car CRH2 train set", pairs="F-NET-30"),
    Campaign("F-NET-33", "features/function/network-transmission-redundancy/F-NET-33.feature",
             "Double-fault campaign, two coupled 8-car sets", 2, "Given two 8-car CRH2 train sets coupled together",
             pairs="F-NET-31"),
)
COMMANDING = "car1.CCU.sys1"     # the key is in cab 1; system 1 commands after power-up (RED-01)
STANDBY = "car1.CCU.sys2"        # and takes over as the master (RED-02) when system 1 is lost


def render(campaign: Campaign, faults: list[Fault], left_out: list[tuple[str, str]], shape: TrainShape) -> str:
    rows: dict[Group, list[tuple[Fault, int | None]]] = {group: [] for group in GROUPS}
    for fault in faults:
        group, car = expectation(shape, fault, COMMANDING)
        rows[group].append((fault, car))
    reqs = sorted({r for group in GROUPS if rows[group] for r in group.reqs} | {"TST-04"}
                  | ({"PRO-06"} if any(fault_record(fault) for fault in faults) else set()))
    lines = [
        "# Generated by `python -m outline campaign` from the SUT's own description (ring_nodes, boards, supplies);",
        "# edit outline/campaigns/campaign.py, not this file. tests/test_campaign.py fails when the two differ.",
        f"@item:{campaign.item} @profile:crh2 @req:TST-04",
        f"Feature: {campaign.item} {campaign.title}",
        f"  Requirements: {', '.join(r for r in reqs if r != 'TST-04')}, TST-04.",
        f"  Every single fault of the train's boards, ring spans and power supplies ({len(faults)}), one scenario",
        "  each: at the instant of the fault the driver moves the traction notch; the command reaches every CI",
        "  and BCU by the path the design gives that fault, within its bound; no device ever takes a wrong",
        "  notch, and none goes without a command for longer than a takeover takes. Where the fault fails a",
        "  board its node's CPU3 reports (docs/decisions.md \"Fault records\"), the record is at the master, the",
        f"  commanding system, within {record_bound(len(shape.nodes))} ms of the fault: two token rounds of "
        f"{len(shape.nodes)} nodes (the request, then",
        "  the grant, PRO-02/04/06), a takeover and the 10 ms before a block.",
        "  Not in the campaign:",
        *[f"  - {name}: {why}" for name, why in left_out],
        "",
        *background(campaign.given),
    ]
    for group in GROUPS:
        for kind in KIND_ORDER:
            for recorded in (False, True):
                members = [(fault, car) for fault, car in rows[group]
                           if fault.kind == kind and (fault_record(fault) is not None) == recorded]
                if members:
                    lines += ["", *_outline(campaign, group, kind, members, recorded, shape)]
    return "\n".join(lines) + "\n"


def _outline(campaign: Campaign, group: Group, kind: str, members: list[tuple[Fault, int | None]],
             recorded: bool, shape: TrainShape) -> list[str]:
    when, columns, named = numbered(kind)
    with_car = "<car>" in group.title
    table = [[*columns, *(["car"] if with_car else []), *(["node", "part"] if recorded else [])]]
    table += [[*fault.values, *([str(car)] if with_car else []), *(fault_record(fault) if recorded else ())]
              for fault, car in members]
    title = group.title.replace("<fault>", named[0].upper() + named[1:])
    master = STANDBY if group is TAKES_OVER else COMMANDING
    record = [f'    And "{master}" holds a fault record of "<node>" saying "<part>" failed at most '
              f"{record_bound(len(shape.nodes))} ms after it"] if recorded else []
    return [
        f"  {' '.join('@req:' + r for r in (*group.reqs, *(['PRO-06'] if recorded else [])))}",
        f"  Scenario Outline: {campaign.item} {title}{f', recorded at {master}' if recorded else ''}",
        f"    When {when}",
        f"    And the driver moves the traction notch of cab 1 to {NOTCH}",
        f"    And {WINDOW} ms pass",
        f"    Then {group.then[0]}",
        *[f"    And {then}" for then in group.then[1:]],
        f"    And no CI or BCU goes without a command for more than {TAKEOVER} ms",
        *INVARIANTS,
        *record,
        "",
        *examples(table),
    ]


def run(root: Path, spec: str, check: bool) -> int:
    stale = []
    described: dict[int, tuple] = {}          # sets -> (faults, left out, shape): one train per composition
    for campaign in CAMPAIGNS:
        if campaign.sets not in described:
            with powered(spec, "crh2", campaign.sets, 8) as sut:
                described[campaign.sets] = (*fault_space(sut), TrainShape.of(sut))
        faults, left_out, shape = described[campaign.sets]
        if campaign.pairs:
            text = double_campaign.render(campaign.item, campaign.title, campaign.given, faults, shape,
                                          campaign.pairs)
        else:
            text = render(campaign, faults, left_out, shape)
        count = f"{len(example_rows(text))} {'pairs of faults' if campaign.pairs else 'faults'}"
        _write_or_check(root, campaign.path, text, check, stale, count)
    metro = metro_campaign.generate(spec)           # F-NET-34: the metro train's single faults
    if metro is None:
        print(f"{metro_campaign.PATH}: {spec} has no metro-tcn train; left as it is", file=sys.stderr)
    else:
        path, text = metro
        _write_or_check(root, path, text, check, stale, f"{len(example_rows(text))} faults")
    for path in stale:
        print(f"{path}:1: the campaign differs from the SUT's fault space; run `python -m outline campaign`",
              file=sys.stderr)
    return 1 if stale else 0


def _write_or_check(root: Path, relative: str, text: str, check: bool, stale: list[str], count: str) -> None:
    path = root / relative
    if check:
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            stale.append(relative)
    else:
        path.write_text(text, encoding="utf-8")
        print(f"{relative}: {count}")

