"""What the cab monitor shows and how it gets there: display points in status data (docs/decisions.md, "Display").

Every display point has an owner node, the LCU of the car where the state is measured (train-wide readings
such as speed and main pipe pressure: car 1's LCU; a traction unit's: its first motor car's LCU). The owner
puts the point's current value in its status data; the monitor decodes it when the status data arrives, so
what the driver sees is at most one status cycle old. Equipment orders from the monitor travel the other
way in the commanding CCU's status data and stay there until the monitor shows them done.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from sut.driver import DIRECTIONS
from sut.reference.scaled import Scaled

if TYPE_CHECKING:
    from sut.reference.crh2.node import RingNode
    from sut.reference.crh2.context import TrainContext

# numeric readings: name -> (unit shown, scale on the wire)
NUMERIC = {"speed": ("km/h", 10), "main pipe pressure": ("kPa", 10), "mileage": ("km", 1000),
           "traction notch": ("", 1), "brake step": ("", 1)}
# the running state: what car 1's LCU last received over the network from the commanding cab
RUNNING = {"traction notch": "traction", "brake step": "brake", "direction": "direction"}


@dataclass(frozen=True)
class Point:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    id: int
    name: str
    owner: str                  # node name
    values: tuple[str, ...]     # allowed states; empty for a numeric reading


class DisplayTable:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext"):
        self.train = train
        vehicle = train.vehicle
        per = train.cfg.cars_per_set
        points: list[Point] = []
        for name in list(NUMERIC) + ["direction"] + sorted(vehicle.outputs_spec):
            values = DIRECTIONS if name == "direction" else vehicle.outputs_spec.get(name, ())
            points.append(Point(len(points) + 1, name, self._owner(name, per), values))
        self.by_name = {p.name: p for p in points}
        self.by_id = {p.id: p for p in points}
        self.by_owner: dict[str, list[Point]] = {}
        for p in points:
            self.by_owner.setdefault(p.owner, []).append(p)

    def _owner(self, name: str, per: int) -> str:
        head = name.split(".", 1)[0]
        if head.startswith("car"):
            return f"{head}.LCU"
        if head.startswith("unit"):
            cars = self.train.vehicle.units[int(head[4:])]
            motors = [c for c in cars if c in self.train.cfg.motor_cars()] or cars
            return f"car{motors[0]}.LCU"
        return "car1.LCU"

    # -- owner side -----------------------------------------------------------------------------
    def points_for(self, node: "RingNode") -> list[dict[str, int]]:
        return [{"id": p.id, "value": self.encode(p, self.current(p.name, node))}
                for p in self.by_owner.get(node.name, ())]

    def current(self, name: str, node: "RingNode") -> Any:
        if name in RUNNING:
            latest = getattr(node, "fresh_command", lambda: None)()
            if name == "direction":
                return DIRECTIONS[latest["direction"]] if latest else "neutral"
            return latest[RUNNING[name]] if latest else 0
        vehicle = self.train.vehicle
        return vehicle.reading(name) if name in NUMERIC else vehicle.output(name)

    def encode(self, point: Point, value: Any) -> int:
        if not point.values:
            if point.name == "mileage":
                # from the exact distance, to the nearest metre, a half up (docs/decisions.md, "Display"): a whole
                # number of metres more run is that many more shown
                return self.train.vehicle.mileage_in(NUMERIC["mileage"][1])
            return round(value * NUMERIC[point.name][1])
        return point.values.index(value)

    def periods_to_repeat(self, period_us: int) -> int:
        """The fewest periods of `period_us` in which the train at its present speed runs whole metres: the
        mileage shown moves by the same number of them every that many periods."""
        return self.train.vehicle.periods_to_repeat(period_us, NUMERIC["mileage"][1])

    # -- monitor side ---------------------------------------------------------------------------
    def decode(self, raw: dict) -> tuple[str, Any] | None:
        point = self.by_id.get(raw["id"])
        if point is None:
            return None
        if not point.values:
            return point.name, Scaled(raw["value"], NUMERIC[point.name][1])
        if not 0 <= raw["value"] < len(point.values):
            return None
        return point.name, point.values[raw["value"]]

    def order(self, name: str, value: str) -> dict[str, int]:
        point = self.by_name[name]
        return {"id": point.id, "value": point.values.index(value)}
