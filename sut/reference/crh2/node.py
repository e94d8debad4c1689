"""A ring node: its MDM8 (optics, token protocol) and CPU3 (status data, block data).

Token protocol (PRO-03..05), as processes of one node:
- watchdog: no status data 500 ms after power-up, or no token seen for 500 ms -> broadcast token-init;
- formation: on token-init, wait node number x 20 ms; the first node whose wait ends without having heard
  a token-send forms the token and broadcasts token-send (so the lowest-numbered live node wins);
- holding: status data goes out when the token arrives; the token leaves so that the neighbour has it one
  holding time (10 ms) after this node did; a node whose onward span is down sends it back the other way.
The token is handled by MDM8 (the ARCNET controller), so a node whose CPU3 is dead still passes it on but
sends no status data.
"""
from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING, Any

from sut.reference.crh2 import frames as fr
from sut.reference.crh2.boards import Board, PowerSupply
from sut.reference.crh2.ring import L, OPPOSITE, R

if TYPE_CHECKING:
    from sut.reference.kernel import Timer
    from sut.reference.crh2.ring import Link, Span
    from sut.reference.crh2.context import TrainContext

# The frames a node remembers having had, to drop the second copy of a broadcast. That copy comes within a
# handful of the node's frames (at most 6 over every CRH2 item with faults and cuts, measured 2026-11-25), so
# 64 keeps a wide margin; and a memory that fills within half a second of power-up is soon steady, which
# bulk advance needs (a memory still filling changes the train's shape every period; 512 took seconds).
SEEN_MEMORY = 64


class RingNode:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    unit = "?"

    def __init__(self, train: "TrainContext", name: str, car: int, supply: PowerSupply):
        self.train = train
        self.kernel = train.kernel
        self.name = name
        self.car = car
        self.number = 0                      # set when the ring is built (position + 1)
        self.supply = supply
        self.cpu3 = Board(f"{name}.CPU3", supply)
        self.mdm8 = Board(f"{name}.MDM8", supply)
        self.ports: dict[str, "Span"] = {}
        self.out: dict[str, "Link"] = {}
        self.seen: set[int] = set()
        self._seen_order: deque[int] = deque()
        # token protocol state
        self.has_token = False
        self.ever_held = False
        self._isolated = False
        self.token_dir = R
        self._hold: "Timer | None" = None
        self._watch: "Timer | None" = None
        self._forming: "Timer | None" = None
        # status data and block data
        self.status_seq = 0                  # status frames sent (PRO-02), unbounded
        self.tokens_received = 0
        self.token_inits = 0
        self.frames_discarded = 0            # NET-05, counted by the ring on arrival
        self.heard: dict[int, int] = {}       # node number -> time of its last status data here
        self.pending_blocks: list[tuple[int, int, int, bytes]] = []   # (record, index, total, 236 bytes)
        self.records_made = 0
        self._block_timer: "Timer | None" = None
        self.granted = False
        self.mdm8.listeners.append(self._optics_changed)

    # -- helpers --------------------------------------------------------------------------------
    def emit(self, kind: str, /, at: str | None = None, **fields: Any) -> None:
        self.train.emit(at or self.mdm8.name, kind, **fields)        # the board's name: f"{name}.MDM8"

    @property
    def optics(self) -> Board:
        return self.mdm8

    def port_ok(self, direction: str) -> bool:
        return self.mdm8.alive and self.ports[direction].usable

    def seen_add(self, uid: int) -> None:
        if uid not in self.seen:
            self.seen.add(uid)
            self._seen_order.append(uid)
            if len(self._seen_order) > SEEN_MEMORY:
                self.seen.discard(self._seen_order.popleft())

    def neighbour(self, direction: str) -> "RingNode":
        return self.out[direction].dst

    def health_byte(self) -> int:
        bits = 0
        for i, board in enumerate(fr.HEALTH_BITS):
            if self.board_healthy(board):
                bits |= 1 << i
        return bits

    def board_changed(self) -> None:
        """CPU3 writes a fault record (block data to the master) for every board that failed or recovered
        (docs/decisions.md, "Fault records"); a dead CPU3 writes nothing."""
        health = self.health_byte()
        last = getattr(self, "_health_seen", health)
        self._health_seen = health
        if health == last or not self.cpu3.alive:
            return
        for i, board in enumerate(fr.HEALTH_BITS):
            was, now = bool(last >> i & 1), bool(health >> i & 1)
            if was != now:
                event = "recovered" if now else "failed"
                word = dict(self.train.cfg.behaviour.record_words).get(event, event)
                line = f"F|{self.kernel.now // 1000}|{self.name}|{board}|{word}"
                self.emit("fault.record", at=f"{self.name}.CPU3", board=board, event=event)
                self.queue_record(line.encode())

    def board_healthy(self, short: str) -> bool:
        """What this node reports of a board in its status data (absent boards count as healthy)."""
        b = self.board(short)
        return b is None or b.alive

    def board(self, short: str) -> Board | None:
        """The board of that short name on this node, None if it has none: each kind of node names its own
        (CcuSystem, Lcu)."""
        raise NotImplementedError

    # -- life cycle -----------------------------------------------------------------------------
    def start(self) -> None:
        if self.mdm8.alive:
            self._arm_watch(self.train.cfg.timing.init_silence_us)

    def _optics_changed(self) -> None:
        """MDM8 died or came back: neighbours see light go or return on their ports."""
        for direction in (R, L):
            self.train.span_changed(self.ports[direction])
        if not self.mdm8.alive:
            self._drop_token()
            self._cancel(self._watch, self._forming)
            self._watch = self._forming = None
        else:
            self._arm_watch(self.train.cfg.timing.init_silence_us)

    def port_changed(self, direction: str, up: bool) -> None:
        if not self.mdm8.alive:
            return
        self.emit("link.up" if up else "link.down", port=direction,
                  peer=self.neighbour(direction).name)
        if up:
            # A ring that grew back may hold two tokens: re-form one (docs/decisions.md, "Link restored").
            self._token_init(reason="link restored")

    @staticmethod
    def _cancel(*timers: "Timer | None") -> None:
        for t in timers:
            if t is not None:
                t.cancel()

    # -- token protocol -------------------------------------------------------------------------
    def _arm_watch(self, delay: int) -> None:
        self._watch = self.kernel.put_off(self._watch, delay, self._watch_expired)

    def _watch_expired(self) -> None:
        self._watch = None
        if self.mdm8.alive and self._forming is None:
            self._token_init(reason="no token" if self.heard or self.ever_held else "no status data since power-up")

    def _token_init(self, reason: str) -> None:
        self.token_inits += 1
        self.emit("token.init", reason=reason)
        self.train.ring.broadcast(self, fr.data_frame(fr.K_TOKEN_INIT, self.number, fr.BROADCAST,
                                                      fr.P_TOKEN, node=self.number))
        self._begin_formation()

    def _begin_formation(self) -> None:
        if self._forming is not None:
            return
        self._drop_token()
        self._cancel(self._watch)
        self._watch = None
        step = self.train.cfg.timing.formation_step_us
        rank = self.number
        if self.train.cfg.behaviour.regeneration_from_the_top:      # faulty variants only
            if self.heard or self.ever_held:                        # a token formed again, not the first
                rank = self.train.ring.size + 1 - self.number
        self._forming = self.kernel.call_later(rank * step, self._form)

    def _form(self) -> None:
        self._forming = None
        self.emit("token.form", node=self.number)
        self.train.ring.broadcast(self, fr.data_frame(fr.K_TOKEN_SEND, self.number, fr.BROADCAST,
                                                      fr.P_TOKEN, node=self.number))
        self._take_token(R, frm=None)

    def _drop_token(self) -> None:
        if self.has_token:
            self.has_token = False
        self._cancel(self._hold)
        self._hold = None

    def _take_token(self, direction: str, frm: str | None) -> None:
        self.has_token = self.ever_held = True
        self.tokens_received += 1
        self.token_dir = direction
        self.emit("token.rx", frm=frm, dir=direction)
        self._arm_watch(self.train.cfg.timing.token_loss_us)
        self.hold_token()
        t = self.train.cfg.timing
        self._hold = self.kernel.call_later(max(0, t.token_hold_us - t.pass_through_us), self._pass_token)

    def _pass_token(self) -> None:
        self._hold = None
        direction, reversed_ = self.token_dir, False
        if not self.port_ok(direction) and self.train.cfg.behaviour.token_reversal:
            direction, reversed_ = OPPOSITE[direction], True
        if not self.port_ok(direction) and reversed_:
            # Cut off on both sides: keep the token, holding it again and again; say so once.
            if not self._isolated:
                self._isolated = True
                self.emit("token.keep")
            self._arm_watch(self.train.cfg.timing.token_loss_us)
            self.hold_token()
            self._hold = self.kernel.call_later(self.train.cfg.timing.token_hold_us, self._pass_token)
            return
        self._isolated = False
        self.has_token = False
        nxt = self.neighbour(direction)
        self.emit("token.pass", to=nxt.name, dir=direction, reversed=reversed_)
        self.train.ring.send(self, fr.token_frame(self.number, nxt.number), direction)

    def counters(self) -> dict[str, int]:
        """Diagnostic counters as the node keeps them (TrainDriver.counters)."""
        return {"status sent": self.status_seq, "tokens received": self.tokens_received,
                "token initialisations": self.token_inits, "frames discarded": self.frames_discarded}

    # -- frames in ------------------------------------------------------------------------------
    def receive(self, frame: fr.Frame, direction: str, hops: int) -> None:
        fields = frame.fields if frame.ok else self._raw_fields(frame)
        if fields is None:
            return
        kind = frame.kind
        if kind == fr.EOT:
            if self.has_token or self._forming is not None:
                self.emit("token.discard", frm=self.train.node_by_number(frame.src).name)
                return
            self._take_token(direction, frm=self.train.node_by_number(frame.src).name)
        elif kind == fr.K_STATUS:
            self.heard[frame.src] = self.kernel.now
            if self._forming is None:
                self._arm_watch(self.train.cfg.timing.token_loss_us)
            if self.cpu3.alive:
                self.on_status(fields, frame.src)
        elif kind == fr.K_TOKEN_INIT:
            self._begin_formation()
        elif kind == fr.K_TOKEN_SEND:
            self._cancel(self._forming)
            self._forming = None
            self._arm_watch(self.train.cfg.timing.token_loss_us)
        elif kind == fr.K_COMMAND:
            self.on_command(fields, direction, hops)
        elif kind == fr.K_BLOCK and self.cpu3.alive:
            self.on_block(fields, frame.src)

    @staticmethod
    def _raw_fields(frame: fr.Frame) -> dict | None:
        """What a node without a frame check would make of a damaged frame (faulty variants only)."""
        if frame.kind == fr.EOT:
            return {}
        try:
            return fr.payload_unchecked(frame.wire)
        except fr.FrameError:
            return None

    # -- hooks for CCU/LCU ----------------------------------------------------------------------
    def on_command(self, fields: dict, direction: str, hops: int) -> None:
        pass

    def on_status(self, fields: dict, src: int) -> None:
        self.train.block_master_saw_status(self, fields, src)
        self.train.orders_received(self, fields)

    def on_block(self, fields: dict, src: int) -> None:
        self.train.block_received(self, fields, src)

    # -- status data (PRO-02) and block data (PRO-06) -------------------------------------------
    def hold_token(self) -> None:
        if not self.cpu3.alive:
            return
        self.status_seq += 1            # unbounded here; the wire carries it modulo 2**16 (frames.py)
        ports = (1 if self.port_ok(L) else 0) | (2 if self.port_ok(R) else 0)
        request = min(255, len(self.pending_blocks))
        grant = self.train.block_grant_for(self)
        self.emit("status.tx", at=f"{self.name}.CPU3", seq=self.status_seq, block_request=request,
                  grant=grant)
        frame = fr.data_frame(fr.K_STATUS, self.number, fr.BROADCAST, fr.P_STATUS, node=self.number,
                              car=self.car, unit=1 if self.unit == "CCU" else 2, health=self.health_byte(),
                              ports=ports, block_request=request, grant=grant, seq=self.status_seq,
                              points=self.train.display.points_for(self), orders=self.train.orders_for(self))
        self.train.ring.broadcast(self, frame)
        self.train.selfdiag_status_leak(self, frame)
        if self.pending_blocks and not self.train.cfg.behaviour.block_grant_required:
            self.start_blocks()

    def queue_record(self, data: bytes) -> None:
        size = fr.BLOCK_SIZE
        blocks = [data[i:i + size].ljust(size, b"\0") for i in range(0, len(data), size)] or [bytes(size)]
        self.records_made += 1
        record = self.records_made
        self.pending_blocks.extend((record, i, len(blocks), block) for i, block in enumerate(blocks))
        self.emit("block.queued", at=f"{self.name}.CPU3", record=record, blocks=len(blocks), bytes=len(data))

    @property
    def block_busy(self) -> bool:
        return self._block_timer is not None

    def start_blocks(self) -> None:
        if self._block_timer is None and self.pending_blocks:
            self._send_block()

    def _send_block(self) -> None:
        self._block_timer = None
        if not self.pending_blocks or not self.cpu3.alive:
            return
        record, index, total, block = self.pending_blocks.pop(0)
        master = self.train.block_master()
        self.emit("block.tx", at=f"{self.name}.CPU3", record=record, index=index, total=total,
                  to=master.name if master else None)
        if master is self:          # the master's own records go straight into its store
            self.train.block_received(self, dict(owner=self.number, record=record, index=index, total=total,
                                                 data=block), self.number)
        elif master is not None:
            frame = fr.data_frame(fr.K_BLOCK, self.number, master.number, fr.P_BLOCK, owner=self.number,
                                  record=record, index=index, total=total, data=block)
            if self.train.cfg.behaviour.block_data_both_ways:
                self.train.ring.broadcast(self, frame)
            else:                   # faulty variants only: the shorter way round, and no other
                size = self.train.ring.size
                self.train.ring.send(self, frame, R if (master.number - self.number) % size <= size // 2 else L)
        if self.pending_blocks:
            self._block_timer = self.kernel.call_later(self.train.cfg.timing.block_spacing_us,
                                                       self._send_block)
