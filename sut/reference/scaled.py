"""A reading that travels as a whole number of units: what a display point carries on the wire (docs/decisions.md,
"Display"), shown as raw / scale.

To whoever reads it, a `Scaled` is the float raw / scale (the value the monitor shows, compared, printed and
written to JSON as that float). To bulk advance (sut/reference/bulk.py) it is the integer `raw`, which a train
running at a steady speed moves by the same amount every steady period: the cab monitor's mileage in whole
metres. A float that moves is a change of the train's shape; its integer is a straight line to jump along.
`ScaledStep` is such a move in a trace pattern: `value + step * k` is the value k periods on.
"""
from __future__ import annotations

from typing import Any


class Scaled(float):
    __slots__ = ("raw", "scale")

    raw: int
    scale: int

    def __new__(cls, raw: int, scale: int) -> "Scaled":
        self = float.__new__(cls, raw / scale)
        self.raw, self.scale = raw, scale
        return self

    def __reduce__(self) -> tuple:
        return Scaled, (self.raw, self.scale)

    def __copy__(self) -> "Scaled":
        return self

    def __deepcopy__(self, memo: dict) -> "Scaled":
        return self


class ScaledStep:
    """How far a Scaled field of a trace pattern moves per period, in its raw units."""

    __slots__ = ("raw", "scale")

    def __init__(self, raw: int, scale: int) -> None:
        self.raw, self.scale = raw, scale

    def __mul__(self, k: int) -> "ScaledStep":
        return ScaledStep(self.raw * k, self.scale)

    __rmul__ = __mul__

    def __radd__(self, value: Any) -> Scaled:
        # value + step: float's own addition declines a ScaledStep, so Python asks this one
        if type(value) is not Scaled or value.scale != self.scale:
            return NotImplemented
        return Scaled(value.raw + self.raw, self.scale)

    def __eq__(self, other: object) -> bool:
        return type(other) is ScaledStep and (other.raw, other.scale) == (self.raw, self.scale)

    def __hash__(self) -> int:
        return hash((self.raw, self.scale))

    def __bool__(self) -> bool:
        return bool(self.raw)

    def __repr__(self) -> str:
        return f"ScaledStep({self.raw}, {self.scale})"

    def __reduce__(self) -> tuple:
        return ScaledStep, (self.raw, self.scale)
