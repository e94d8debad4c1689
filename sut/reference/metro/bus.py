"""A dual-line bus (RED-06): WTB and MVB both run lines A and B side by side.

A sender puts every frame on both lines; receivers read the line they trust and, when that line brings
silence or a frame that fails its check, take the copy from the other line and trust it from then on
(IEC 61375: "switch-over without loss"). Both copies are checked, so the unit that diagnoses the bus also
sees a line that went bad while it was not the trusted one.

The bus knows nothing of frame layouts: a `decode` function turns the bits on a line into data or raises
`FrameError`; a corrupt frame is never decoded into data.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, NamedTuple

LINES = ("A", "B")


class FrameError(ValueError):
    """A frame that fails its check sequence or layout."""


@dataclass
class Line:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    name: str
    cut: bool = False
    disturb: int = 0           # the next `disturb` frames get one bit flipped
    bad_run: int = 0           # consecutive frames this line did not bring intact
    reported: bool = False     # the diagnosing unit has reported this line faulty

    def bulk_steady(self) -> bool:
        # bulk.py: frames still to disturb are a countdown that stops at zero, which no straight line
        # through the periods shows: simulated until it ran out.
        return self.disturb == 0


class Carried(NamedTuple):
    """What one frame became on the bus: data for the receivers, or None if no line brought it intact.
    (A tuple: one is made per frame, thousands per simulated second.)"""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    data: Any
    line: str | None
    errors: tuple[str, ...]


_carried = tuple.__new__


def flip_one_bit(wire: bytes) -> bytes:
    # The middle byte's lowest bit: inside the check-sequence-covered part of every frame layout used here.
    buf = bytearray(wire)
    buf[len(buf) // 2] ^= 0x01
    return bytes(buf)


class DualLineBus:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, name: str, lines_sent: str, switch_after: int):
        self.name = name
        self.lines = {ln: Line(ln) for ln in LINES}
        self.lines_sent = lines_sent
        self.switch_after = switch_after
        self.trusted = "A"
        self._trusted_bad = 0

    @property
    def whole(self) -> bool:
        """Both lines whole and carrying the same bits: a frame arrives on both as it was sent."""
        a, b = self.lines["A"], self.lines["B"]
        return not (a.cut or b.cut or a.disturb or b.disturb) and len(self.lines_sent) == 2

    def carry_as_sent(self, data: Any) -> Carried:
        """`carry` on whole lines of a frame whose decoding is known to be `data` (the sender's own frame:
        decoding undoes encoding), without its bits."""
        a, b = self.lines["A"], self.lines["B"]
        a.bad_run = b.bad_run = 0
        self._trusted_bad = 0
        return _carried(Carried, (data, self.trusted, ()))     # Carried(...) without its Python __new__

    def carry(self, wire: bytes, decode: Callable[[bytes], Any],
              on_switch: Callable[[str, str, str], None]) -> Carried:
        if self.whole:
            # One decode answers for both lines (decode is a pure function of the bits), which is what almost
            # every frame of a run is.
            try:
                data = decode(wire)
            except ValueError:
                pass             # refused on both lines: counted below, line by line, as any refused frame is
            else:
                return self.carry_as_sent(data)
        copies: dict[str, Any] = {}
        errors: list[str] = []
        for ln in LINES:
            line = self.lines[ln]
            if ln not in self.lines_sent or line.cut:
                copies[ln] = None
                line.bad_run += 1
                continue
            raw = wire
            if line.disturb:
                line.disturb -= 1
                raw = flip_one_bit(wire)
            try:
                copies[ln] = (decode(raw),)
                line.bad_run = 0
            except ValueError as exc:      # FrameError, MvbFrameError: a check that failed
                copies[ln] = None
                line.bad_run += 1
                errors.append(f"line {ln}: {exc}")
        mine = copies[self.trusted]
        if mine is not None:
            self._trusted_bad = 0
            return Carried(mine[0], self.trusted, tuple(errors))
        self._trusted_bad += 1
        other = "B" if self.trusted == "A" else "A"
        if copies[other] is not None and self._trusted_bad >= self.switch_after:
            before, self.trusted, self._trusted_bad = self.trusted, other, 0
            on_switch(before, other, "silent" if not errors else errors[0])
            return Carried(copies[other][0], other, tuple(errors))
        return Carried(None, None, tuple(errors))

    @staticmethod
    def frame_us(bits: int, bit_ns: int) -> int:
        return -(-bits * bit_ns // 1000)
