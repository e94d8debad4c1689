"""The equipment of the metro TCDS (TCN-02, TCN-07, TCN-08): CCUs, VCUs, MVB I/O modules, devices.

A CCU is VCPUS, VGWS (the WTB-MVB gateway), VMS (memory), VDIS, VDOS and VPS; a VCU is the same without
VMS and VDIS, so it records nothing (seed 002 §2.2).
"""
from __future__ import annotations

from dataclasses import dataclass, field

CCU_BOARDS = ("VCPUS", "VGWS", "VMS", "VDIS", "VDOS", "VPS")
VCU_BOARDS = ("VCPUS", "VGWS", "VDOS", "VPS")
VITAL_BOARDS = frozenset({"VCPUS", "VPS"})

CAB_CARS = (1, 6)
UNIT_CARS = {1: (1, 2, 3), 2: (4, 5, 6)}
CAB_DEVICES = ("DU", "IO1", "IO2", "BECU", "APU", "VATC")
MOTOR_DEVICES = ("VVVF", "BECU")
SINK_KINDS = ("VVVF", "BECU")


def unit_of(car: int) -> int:
    return 1 if car <= 3 else 2


@dataclass(frozen=True)
class Record:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    t_us: int
    origin: str
    seq: int
    text: str

    def __str__(self) -> str:
        return f"{self.t_us / 1000:.3f} {self.origin}: {self.text}"


@dataclass
class ControlUnit:
    """A CCU or VCU: one node on the WTB (through its VGWS) and on its unit's MVB."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    name: str
    car: int
    kind: str                                         # "CCU" or "VCU"
    failed: bool = False
    failed_boards: set[str] = field(default_factory=set)
    store: list[Record] = field(default_factory=list)        # VMS contents
    known: list[Record] = field(default_factory=list)        # what it can show on a display
    outbox: list[Record] = field(default_factory=list)       # its events not yet acknowledged
    awaiting: dict[int, set[str]] = field(default_factory=dict)   # seq -> destinations yet to acknowledge
    seq: int = 0
    stored_upto: dict[str, int] = field(default_factory=dict)    # origin -> highest seq taken in
    wtb_cmd: object = None
    wtb_cmd_t: int = -1

    @property
    def boards(self) -> tuple[str, ...]:
        return CCU_BOARDS if self.kind == "CCU" else VCU_BOARDS

    @property
    def unit(self) -> int:
        return unit_of(self.car)

    @property
    def alive(self) -> bool:
        return not self.failed and not (self.failed_boards & VITAL_BOARDS)

    @property
    def on_wtb(self) -> bool:
        # `alive` written out: asked a few times for every frame on the unit's MVB
        failed_boards = self.failed_boards
        return not self.failed and not (failed_boards & VITAL_BOARDS) and "VGWS" not in failed_boards

    @property
    def masters_mvb(self) -> bool:
        """Fit to master its unit's MVB: alive, and its gateway joins the unit to the train (docs/decisions.md,
        "Gateway failure": a unit mastered without one would be cut off from the train's command)."""
        return self.on_wtb

    @property
    def has_memory(self) -> bool:
        return self.alive and "VMS" in self.boards and "VMS" not in self.failed_boards


@dataclass
class IoModule:
    """MVB I/O module (TCN-07): 28 DI, 3 AI, an RS-485 port; its life signal counts its refreshes."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    name: str
    car: int
    failed: bool = False
    life: int = 0
    forced: dict[str, int] = field(default_factory=dict)     # "DI05" / "AI1" -> value: a wiring fault
    frozen: tuple[int, tuple[int, int, int]] | None = None   # inputs when it failed


@dataclass
class Device:
    """A subsystem on the MVB: VVVF, BECU, APU, VATC, DU. VVVF and BECU take the train command."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    name: str
    car: int
    kind: str
    failed: bool = False
    applied: int = 0          # 0.01 %: the traction (VVVF) or brake (BECU) effort applied now

    @property
    def sink(self) -> bool:
        return self.kind in SINK_KINDS
