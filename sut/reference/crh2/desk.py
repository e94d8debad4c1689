"""The driver desk of one cab (CMD-05): key and master control relay, direction, traction and brake."""
from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import TYPE_CHECKING

from sut.driver import DIRECTIONS
from sut.reference.crh2.boards import PowerSupply
from sut.reference.crh2.config import BRAKE_STEPS

if TYPE_CHECKING:
    from sut.reference.crh2.context import TrainContext

# the command frame codes a direction by its place in the driver interface's list
DIRECTION_CODES = {name: code for code, name in enumerate(DIRECTIONS)}


@dataclass(frozen=True)
class Sample:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    direction: str
    traction: int
    brake: int
    mcr: bool

    def as_dict(self) -> dict:
        return asdict(self)

    def wire_fields(self) -> dict:
        # No master-control flag: only the CCU whose MCR is up puts commands on the ring (ILK-07), so
        # a receiver has nothing to decide with one (docs/decisions.md, "The command frame's content").
        return dict(direction=DIRECTION_CODES[self.direction], traction=self.traction, brake=self.brake)


class Desk:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext", car: int, supply: PowerSupply):
        self.train = train
        self.car = car
        self.supply = supply          # the desk's digital-input supply as the TXC sees it
        self.key = False
        self.mcr = False
        self.direction = "neutral"
        self.traction = 0
        self.brake = 0

    def sample(self, inverted: bool, misread: bool = False) -> Sample:
        if not self.supply.on:
            # FS-03: with inverted logic a dead input reads as the restrictive state: full service brake,
            # no traction. Without it, dead inputs would read as "nothing asked": released brake.
            return Sample("neutral", 0, BRAKE_STEPS if inverted else 0, self.mcr)
        vehicle = self.train.vehicle
        # ILK-08: the traction lines carry a notch only while every permission holds; an ATP brake
        # raises the brake demand (docs/decisions.md, "Traction permission").
        traction = self.traction if self.mcr and vehicle.traction_permitted() else 0
        brake = vehicle.brake_demand(self.brake)
        if misread:
            brake = (brake + 1) % (BRAKE_STEPS + 2)
        return Sample(self.direction, traction, brake, self.mcr)
