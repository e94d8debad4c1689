"""What the CRH2 design does under a set of faults: by which path each car's CI and BCU get the driver's command.

The campaigns' expectations (outline/campaigns/campaign.py, outline/campaigns/double_campaign.py) come from here, and this is the
articles' design, not the reference's code:
- the ring (NET-03): a node takes part while its MDM8 lives (its unit's supply on); a span carries frames while
  it is not cut and both its nodes take part; broadcasts go both ways, so a node hears every node it is joined
  to through such spans;
- the commanding cab's systems (RED-01/02): system 1 commands while its TXC lives; system 2 takes over when it
  hears nothing from system 1 on the ring, if its TXC lives and it hears the ring at all (sut/reference/
  docs/decisions.md "Redundancy": a standby deaf to the ring would otherwise take over blindly). Commands enter
  the ring where a commanding system's MDM8 lives, and the self-diagnostic line from a commanding TXC;
- a car (CMD-01..04): path 1 when its LCU hears a commanding system on the ring and its MDM9 lives; path 2
  when it hears one but its MDM9 is dead and its RXC lives; else path 3 when its RXC lives and a commanding
  TXC drives the self-diagnostic line; else nothing reaches it. TXC and RXC have their own supplies (CMD-01).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

COMMAND_BOARDS = ("TXC", "RXC")    # boards with their own supply (CMD-01), named <unit>.<board>
# docs/decisions.md "Fault records": a node's CPU3 writes a record of each of its boards that fails, as block data
# to the master; a failed CPU3 writes nothing and a failed MDM8 sends nothing, so these are the boards whose
# failure alone is recorded.
RECORDED_BOARDS = ("MDM9", "TXC", "RXC")


@dataclass(frozen=True)
class Fault:
    kind: str                  # span, board, supply
    values: tuple[str, ...]    # (a, b) of a span, the board, the supply


def fault_record(fault: "Fault") -> tuple[str, str] | None:
    """(node, board) of the fault record a single fault makes its node's CPU3 write, None if it makes none:
    a span cut fails no board, and a unit's own supply takes its CPU3 and MDM8 with it (a command board's own
    supply takes only that board, CMD-01). One fault leaves the node's CPU3 and MDM8 and a way round the
    ring to the master."""
    if fault.kind == "span":
        return None
    node, _, board = fault.values[0].rpartition(".")
    if fault.kind == "supply" and board not in COMMAND_BOARDS:
        return None
    return (node, board) if board in RECORDED_BOARDS else None


def car_of(unit: str) -> int:
    """'car12.LCU' -> 12."""
    return int(unit.split(".")[0][3:])


class TrainShape:
    """What the driver says a CRH2 train is made of: ring nodes in order, their boards, the LCU cars."""

    def __init__(self, nodes: list[str], boards: dict[str, list[str]], supplies: list[str], cab: int = 1):
        self.nodes = nodes
        self.boards = boards
        self.supplies = supplies
        self.cars = sorted(car_of(n) for n in nodes if n.endswith(".LCU"))
        self.systems = (f"car{cab}.CCU.sys1", f"car{cab}.CCU.sys2")     # the commanding cab's CCU

    @classmethod
    def of(cls, sut) -> "TrainShape":
        nodes = sut.ring_nodes()
        return cls(nodes, {n: sut.boards(n) for n in nodes}, sut.supplies())

    def dead_boards(self, faults: tuple[Fault, ...] | list[Fault]) -> set[str]:
        """The boards the faults take out: a unit's supply feeds its boards but the command boards."""
        dead: set[str] = set()
        for fault in faults:
            if fault.kind == "board":
                dead.add(fault.values[0])
            elif fault.kind == "supply":
                supply = fault.values[0]
                if supply.rpartition(".")[2] in COMMAND_BOARDS:
                    dead.add(supply)
                elif supply in self.boards:
                    dead |= {f"{supply}.{b}" for b in self.boards[supply] if b not in COMMAND_BOARDS}
        return dead

    def _ring(self, faults: tuple[Fault, ...] | list[Fault]) -> "_Ring":
        """The ring under `faults` and who commands on it: shared by paths() and records()."""
        dead = self.dead_boards(faults)
        cut = {frozenset(f.values) for f in faults if f.kind == "span"}
        nodes = self.nodes
        on = {n: f"{n}.MDM8" not in dead for n in nodes}

        def joined(a: str, b: str) -> bool:
            return frozenset((a, b)) not in cut and on[a] and on[b]

        def heard_from(start: str) -> set[str]:
            heard, i0 = {start}, nodes.index(start)
            for step in (1, -1):
                i = i0
                while (j := (i + step) % len(nodes)) != i0 and joined(nodes[i], nodes[j]):
                    heard.add(nodes[j])
                    i = j
            return heard

        sys1, sys2 = self.systems
        txc1, txc2 = f"{sys1}.TXC" not in dead, f"{sys2}.TXC" not in dead
        on_ring1 = txc1 and on[sys1]
        i2 = nodes.index(sys2)
        hears_ring2 = on[sys2] and (joined(sys2, nodes[i2 - 1]) or joined(sys2, nodes[(i2 + 1) % len(nodes)]))
        takes_over = txc2 and hears_ring2 and not (on_ring1 and sys2 in heard_from(sys1))
        return _Ring(dead, heard_from, txc1, on_ring1, takes_over, on[sys2])

    def paths(self, faults: tuple[Fault, ...] | list[Fault]) -> dict[int, int | None]:
        """Car -> the path its CI and BCU get the command by (1, 2, 3), None if the design leaves it none."""
        ring = self._ring(faults)
        dead = ring.dead
        sys1, sys2 = self.systems
        entering = [s for s, ok in ((sys1, ring.on_ring1), (sys2, ring.takes_over and ring.on2)) if ok]
        heard = set().union(*(ring.heard_from(s) for s in entering))
        self_diagnostic = ring.txc1 or ring.takes_over
        out: dict[int, int | None] = {}
        for car in self.cars:
            lcu = f"car{car}.LCU"
            rxc = f"{lcu}.RXC" not in dead
            if lcu in heard and f"{lcu}.MDM9" not in dead:
                out[car] = 1
            elif lcu in heard and rxc:
                out[car] = 2
            elif rxc and self_diagnostic:
                out[car] = 3
            else:
                out[car] = None
        return out

    def records(self, faults: tuple[Fault, ...] | list[Fault]) -> Records:
        """Where the fault records the faults make must end up (docs/decisions.md "Block data", "Fault records").

        The master is the commanding cab's master system: system 1, or system 2 once it has taken over; it
        stores records while its CPU3 and MDM8 live. A record is written by the failed board's CPU3 (one
        record per failed board, fault_record) and reaches the master if that CPU3 and its MDM8 live and the
        master hears the node on the ring. Where system 2 takes over while system 1 still commands its own
        segment of a split ring, each takes the mastership back from the other whenever it has heard nothing
        for a takeover time (RED-02): which one holds a record is then not the design's to say."""
        made = dict.fromkeys(r for f in faults if (r := fault_record(f)) is not None)
        if not made:
            return Records(None, (), None)
        ring = self._ring(faults)
        sys1, sys2 = self.systems
        if ring.takes_over and ring.on_ring1:
            return Records(None, (), "system 1 and system 2 command two segments of the ring: the mastership "
                                     "goes back and forth between them (RED-02)")
        master = sys2 if ring.takes_over else sys1
        if {f"{master}.CPU3", f"{master}.MDM8"} & ring.dead:
            return Records(None, (), f"the master, {master}, cannot store records: its CPU3 or MDM8 is dead")
        heard = ring.heard_from(master)
        kept = tuple((node, board) for node, board in made
                     if node in heard and not {f"{node}.CPU3", f"{node}.MDM8"} & ring.dead)
        return Records(master, kept, None)


@dataclass(frozen=True)
class _Ring:
    dead: set[str]
    heard_from: Callable[[str], set[str]]
    txc1: bool                  # system 1's TXC lives: it drives the self-diagnostic line
    on_ring1: bool              # and its MDM8 too: system 1 puts commands on the ring
    takes_over: bool            # system 2 takes over (RED-02, docs/decisions.md: only if it hears the ring)
    on2: bool                   # system 2's MDM8 lives


@dataclass(frozen=True)
class Records:
    """records(): the master that must hold them, the (node, board) records, or why none can be asked for."""
    master: str | None
    held: tuple[tuple[str, str], ...]
    unchecked: str | None
