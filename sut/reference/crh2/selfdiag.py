"""The self-diagnostic transmission line (NET-01, NET-04, CMD-04): HDLC on a twisted-pair bus.

It joins every CCU and LCU (and both sets when coupled, NET-08). The master TXC puts each command on it;
every RXC receives it at the end of the frame. It carries control commands only.
"""
from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING

from sut.reference.crh2.boards import Board, PowerSupply
from sut.reference.crh2.frames import COMMAND, STATUS_SIZE

if TYPE_CHECKING:
    from sut.reference.crh2.context import TrainContext

HDLC_OVERHEAD = 6          # flag, address, control, FCS x2, closing flag
COMMAND_FRAME_BYTES = COMMAND.sizeof() + 2      # the payload and its FCS (CRC-16/X-25)


class SelfDiagLine:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext"):
        self.train = train
        self.board = Board("selfdiag", PowerSupply("selfdiag.supply"))
        self.busy_until = 0
        self.queue: deque = deque()
        self._timer = None
        self.disturbed_until = 0     # environment.py: bursts above the immunity level damage frames until then

    def _duration(self, payload: int) -> int:
        bits = (payload + HDLC_OVERHEAD) * 8
        return -(-bits * 1_000_000 // self.train.cfg.timing.selfdiag_bitrate)

    def send_command(self, sender: str, fields: dict) -> None:
        if not self.board.alive:
            return
        # The line's time is the frame's length, which the command layout fixes (the ring's copy of the same
        # fields is built and checked byte by byte; building this one too cost 2 % of a CRH2 run).
        self._queue(("command", sender, fields, COMMAND_FRAME_BYTES))

    def send_status(self, sender: str, src: int, fields: dict) -> None:
        """Only a faulty variant calls this (NET-04 says the line carries commands only); it talks
        politely, only on an idle line."""
        if self.board.alive and not self.queue and self.busy_until <= self.train.kernel.now:
            self._queue(("status", sender, dict(fields, src=src), STATUS_SIZE))

    def _queue(self, item: tuple) -> None:
        self.queue.append(item)
        if self._timer is None:
            self._next()

    def _next(self) -> None:
        self._timer = None
        if not self.queue:
            return
        kernel = self.train.kernel
        kind, sender, fields, size = self.queue.popleft()
        start = max(kernel.now, self.busy_until)
        self.busy_until = start + self._duration(size)
        kernel.call_at(self.busy_until, self._deliver, kind, sender, fields)
        self._timer = kernel.call_at(self.busy_until, self._next)

    def _deliver(self, kind: str, sender: str, fields: dict) -> None:
        if not self.board.alive:
            return
        if kind == "command" and self.disturbed_until > self.train.kernel.now:
            if self.train.cfg.behaviour.selfdiag_fcs_check:
                self.train.emit("selfdiag", "sd.discard", frame=kind, frm=sender, seq=fields.get("seq"))
                return
            fields = dict(fields, traction=fields["traction"] ^ 8)   # the damaged bit, taken as sent
        self.train.emit("selfdiag", "sd.rx", frame=kind, frm=sender, seq=fields.get("seq"))
        if kind == "command":
            for lcu in self.train.lcus:
                lcu.rxc.from_selfdiag(fields)
        else:
            self.train.selfdiag_status_delivered(fields)
