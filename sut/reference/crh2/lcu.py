"""The terminal unit LCU of every car: CPU3, MDM8, MDM9 and the RXC (NET-02, CMD-01..04, NET-09).

Command paths into CI and BCU (docs/decisions.md, "Command paths"):
1. ring -> MDM8 -> MDM9 -> HDLC over fibre, polled every 10 ms: full notch resolution;
2. ring -> MDM8 -> 20 mA loop -> RXC -> digital outputs, when this car's MDM9 (or its HDLC leg) has failed;
3. self-diagnostic line -> RXC -> digital outputs, when no ring command has reached the RXC for 50 ms.
Paths 2 and 3 carry only traction steps A/B and brake steps A/B.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from sut.reference.crh2.boards import Board, PowerSupply
from sut.reference.crh2.devices import CommandDevice, LoopDevice, to_steps
from sut.reference.crh2.node import RingNode

if TYPE_CHECKING:
    from sut.reference.crh2.context import TrainContext


class Rxc:
    """Command receiver with two CPU groups (FS-01): both receive, #1 drives the digital outputs."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, lcu: "Lcu", supply: PowerSupply):
        self.lcu = lcu
        self.train = lcu.train
        self.name = f"{lcu.name}.RXC"
        self.board = Board(self.name, supply)
        self.group1 = Board(f"{self.name}.group1", supply)
        self.group2 = Board(f"{self.name}.group2", supply)
        self.failsafe = False
        self.last_ring_us = 0           # power-up counts as "just heard": no fallback in the first 50 ms
        self.source = "idle"

    def _set_source(self, source: str) -> None:
        if source != self.source:
            self.source = source
            self.train.emit(self.name, "rxc.source", source=source)

    def _checked(self) -> bool:
        if not self.board.alive or self.failsafe:
            return False
        if self.group1.failed or self.group2.failed:
            self.failsafe = True
            self.train.emit(self.name, "rxc.failsafe")
            self.lcu.board_changed()
            return False
        return True

    def from_loop(self, fields: dict, mdm9_ok: bool) -> None:
        """A ring command forwarded by this car's MDM8 over the 20 mA loop."""
        if not self._checked():
            return
        self.last_ring_us = self.train.kernel.now
        if mdm9_ok:
            self._set_source("idle")
        else:
            self._set_source("ring")
            self._drive(fields, path=2)

    def from_selfdiag(self, fields: dict) -> None:
        if not self._checked():
            return
        if self.train.kernel.now - self.last_ring_us >= self.train.cfg.timing.rxc_fallback_us:
            self._set_source("selfdiag")
            self._drive(fields, path=3)

    def _drive(self, fields: dict, path: int) -> None:
        behaviour = self.train.cfg.behaviour
        steps_only = behaviour.do_steps_only and (behaviour.path3_steps_only or path != 3
                                                  or not self.lcu.mdm8.alive)
        for device in self.lcu.command_devices:
            if steps_only:
                device.take(path, traction=None, brake=None, traction_step=to_steps(fields["traction"], "traction"),
                            brake_step=to_steps(fields["brake"], "brake"), seq=None)
            else:
                device.take(path, traction=fields["traction"], brake=fields["brake"], traction_step=None,
                            brake_step=None, seq=None)


class Lcu(RingNode):
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    unit = "LCU"

    def __init__(self, train: "TrainContext", car: int, supply: PowerSupply, rxc_supply: PowerSupply):
        super().__init__(train, f"car{car}.LCU", car, supply)
        self.mdm9 = Board(f"{self.name}.MDM9", supply)
        self.rxc = Rxc(self, rxc_supply)
        self.command_devices: list[CommandDevice] = []
        if car in train.cfg.motor_cars():
            self.command_devices.append(CommandDevice(train, f"car{car}.CI"))
        self.command_devices.append(CommandDevice(train, f"car{car}.BCU"))
        self.loop_devices: list[LoopDevice] = []
        self.latest: dict | None = None
        self.latest_us = -1
        self.commands_received = 0
        self._health_seen = self.health_byte()
        for board in (self.mdm9, self.rxc.board):
            board.listeners.append(self.board_changed)

    def board(self, short: str) -> Board | None:
        return {"CPU3": self.cpu3, "MDM8": self.mdm8, "MDM9": self.mdm9, "RXC": self.rxc.board}.get(short)

    def board_healthy(self, short: str) -> bool:
        if short == "RXC":
            return self.rxc.board.alive and not self.rxc.failsafe
        return super().board_healthy(short)

    def start(self) -> None:
        super().start()
        t = self.train.cfg.timing
        # Stagger the cars' polling a little, as independent MDM9 clocks would be.
        self.kernel.every(t.poll_us, self._poll, phase=(self.car * 250) % t.poll_us)
        for device in self.loop_devices:
            device.start()

    def on_command(self, fields: dict, direction: str, hops: int) -> None:
        if not self.train.commanding_source_ok(fields):
            return
        self.commands_received += 1
        self.emit("cmd.rx", seq=fields["seq"], system=fields["system"], cab=fields["cab"], dir=direction,
                  hops=hops)
        if not self.cpu3.alive and not self.train.cfg.behaviour.cmd_bypass_cpu3:
            return                       # a design that routed commands through CPU3 loses them here
        self.latest, self.latest_us = fields, self.kernel.now
        self.kernel.schedule(self.train.cfg.timing.rxc_loop_us, self.rxc.from_loop, fields, self.mdm9.alive)

    def counters(self) -> dict[str, int]:
        # The LCU's clock is set by the clock correction in every ring command (PRO-01 frame, CMD-02).
        return dict(super().counters(), **{"commands received": self.commands_received,
                                           "clock ms": self.latest["clock_ms"] if self.latest else 0})

    def fresh_command(self) -> dict | None:
        """The last ring command, if it is still fresh enough to act on."""
        if self.latest is None:
            return None
        if self.kernel.now - self.latest_us >= self.train.cfg.timing.command_stale_us and (
                self.train.cfg.behaviour.ring_commands_expire or not self.mdm8.alive):
            return None
        return self.latest

    def _poll(self) -> None:
        """MDM9 polls CI and BCU over HDLC (fibre) every 10 ms with the freshest ring command."""
        cmd = self.fresh_command()
        if not self.mdm9.alive or cmd is None:
            return
        for device in self.command_devices:
            device.take(1, traction=cmd["traction"], brake=cmd["brake"], traction_step=None, brake_step=None,
                        seq=cmd["seq"], direction=cmd["direction"])
