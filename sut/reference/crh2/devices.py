"""Vehicle-level devices (NET-09): CI and BCU take commands; current-loop devices are polled or fed one-way."""
from __future__ import annotations

from typing import TYPE_CHECKING

from sut.driver import DIRECTIONS

if TYPE_CHECKING:
    from sut.reference.crh2.boards import Board
    from sut.reference.crh2.context import TrainContext

# docs/decisions.md, "A/B steps": the lower half of the range drives step A, the upper half step B.
TRACTION_B_FROM = 6
BRAKE_B_FROM = 5


def to_steps(value: int, what: str) -> str:
    if value <= 0:
        return "-"
    threshold = TRACTION_B_FROM if what == "traction" else BRAKE_B_FROM
    return "B" if value >= threshold else "A"


class CommandDevice:
    """Main converter (CI) or brake control unit (BCU): records what it was commanded, and how."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, train: "TrainContext", name: str):
        self.train = train
        self.name = name

    def take(self, path: int, *, traction: int | None, brake: int | None, traction_step: str | None,
             brake_step: str | None, seq: int | None, direction: int | None = None) -> None:
        delay = self.train.cfg.behaviour.command_take_delay_us
        if delay:
            self.train.kernel.schedule(delay, self._act, path, traction, brake, traction_step, brake_step, seq,
                                       direction)
        else:
            self._act(path, traction, brake, traction_step, brake_step, seq, direction)

    def _act(self, path: int, traction: int | None, brake: int | None, traction_step: str | None,
             brake_step: str | None, seq: int | None, direction: int | None) -> None:
        direction_name = None if direction is None else DIRECTIONS[direction]
        self.train.emit(self.name, "cmd.in", path=path, traction=traction, brake=brake,
                        traction_step=traction_step, brake_step=brake_step, seq=seq, direction=direction_name)


class LoopDevice:
    """A device on a 20 mA or 30 mA current loop of its car's LCU (CPU3 runs the loop).

    `polled` devices answer each poll; one-way devices only receive (side destination display) or only
    send (distance detector)."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, train: "TrainContext", name: str, cpu3: "Board", loop: str, period_us: int, mode: str):
        assert mode in ("polled", "to-device", "from-device")
        self.train, self.name, self.cpu3 = train, name, cpu3
        self.loop, self.period_us, self.mode = loop, period_us, mode

    def start(self) -> None:
        # A free-running clock of its own: the loop's traffic changes nothing else in the train, so its
        # periods (up to the side display's 1 s) stay out of the train's steady period (kernel.metronome).
        self.train.kernel.metronome(self.period_us, self._cycle, phase=self.period_us // 2)

    def _cycle(self) -> None:
        if not self.cpu3.alive:
            return
        if self.mode == "polled":
            self.train.emit_free(self.name, "loop.poll", loop=self.loop, reply=True)
        elif self.mode == "to-device":
            self.train.emit_free(self.name, "loop.send", loop=self.loop, reply=False)
        else:
            self.train.emit_free(self.name, "loop.report", loop=self.loop, reply=False)

