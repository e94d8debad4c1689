"""The bidirectional optical ring (NET-03, NET-05, NET-06, NET-07, PRO-01).

Nodes sit in ring order; span i joins node i to node i+1 (the last span closes the ring). Each span has a
fibre each way; a `Link` is one direction of one span with its own transmit queue. A frame crossing a link
reaches the next node one pass-through time (0.25 ms) after it starts, and occupies the link for its
transmission time at 2.5 Mbit/s; a waiting frame goes first by priority (NET-06), never preempting one
already on the fibre.

Broadcasts go out both ways (reverse routing). Each copy is dropped at a node that already has the frame:
every node that copy would reach next was already reached by the other one, so on an intact ring each node
receives a broadcast once, and with one span cut everyone still receives it (NET-03).
"""
from __future__ import annotations

import heapq
from typing import TYPE_CHECKING, Any, Protocol

from sut.reference.crh2.frames import BROADCAST, Frame, declared_length, encode_pac, tx_time_us

if TYPE_CHECKING:
    from sut.reference.crh2.context import TrainContext

R, L = "R", "L"     # R: increasing node number, L: decreasing
# A span damaged by interference (environment.py) damages every frame for as long as the burst lasts: its
# count of frames to damage starts this high, never runs out meanwhile, and the burst's end takes it off.
ENDLESS = 1 << 40
OPPOSITE = {R: L, L: R}


class Optics(Protocol):
    alive: bool


class RingNode(Protocol):
    """What the ring needs of a node on it (node.py's RingNode is one; the ring does not import it)."""

    name: str
    number: int
    ports: dict[str, "Span"]
    out: dict[str, "Link"]
    seen: set[int]
    frames_discarded: int
    optics: Optics                  # its MDM8: light on both ports while it is alive

    def port_ok(self, direction: str) -> bool: ...

    def seen_add(self, uid: int) -> None: ...

    def receive(self, frame: Frame, direction: str, hops: int) -> None: ...

    def emit(self, kind: str, /, at: str | None = None, **fields: Any) -> None: ...


class Span:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, a: "RingNode", b: "RingNode", medium: str):
        self.a, self.b = a, b
        self._optics = (a.optics, b.optics)     # read on every frame: the boards, not the nodes' properties
        self.medium = medium
        self.cut = False
        self.corrupt: dict[tuple[str, int], int] = {}   # (sending node, frame kind) -> frames to corrupt
        self.tapped = False
        self.was_usable = True            # what the end nodes last noticed (Train.span_changed)

    @property
    def name(self) -> str:
        return f"{self.a.name}~{self.b.name}"

    def bulk_steady(self) -> bool:
        """bulk.py: frames still to damage (corrupt_frames) are a countdown that stops at zero, which no
        straight line through the periods shows: simulated until it ran out. An interference burst's
        endless count only goes down the whole time, and its end is a timer bulk.py does not jump."""
        return all(left == 0 or left > ENDLESS // 2 for left in self.corrupt.values())

    @property
    def usable(self) -> bool:
        optics_a, optics_b = self._optics
        return not self.cut and optics_a.alive and optics_b.alive


class Link:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    __slots__ = ("span", "src", "dst", "direction", "busy_until", "queue", "timer")

    def __init__(self, span: Span, src: "RingNode", dst: "RingNode", direction: str):
        self.span, self.src, self.dst, self.direction = span, src, dst, direction
        self.busy_until = 0
        self.queue: list = []
        self.timer = None


class Ring:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext", nodes: list["RingNode"], media: list[str]):
        self.train = train
        self.kernel = train.kernel
        self.nodes = nodes
        self.size = len(nodes)
        self.spans = [Span(nodes[i], nodes[(i + 1) % self.size], media[i]) for i in range(self.size)]
        for i, node in enumerate(nodes):
            node.ports = {R: self.spans[i], L: self.spans[i - 1]}
            node.out = {R: Link(self.spans[i], node, nodes[(i + 1) % self.size], R),
                        L: Link(self.spans[i - 1], node, nodes[i - 1], L)}
        self._order = 0                   # arrival order among equal priorities (a plain int: bulk.py)
        self.uids = 0                     # transmissions numbered per train, so runs do not share a count
        timing, behaviour = train.cfg.timing, train.cfg.behaviour
        self.pass_through = timing.pass_through_us
        self.bitrate = timing.bitrate
        self.by_priority = behaviour.priorities
        self.check = behaviour.frame_check
        self.both_ways = behaviour.reverse_routing
        self.source_id = behaviour.packet_source_id

    def span_between(self, a: "RingNode", b: "RingNode") -> Span | None:
        for span in self.spans:
            if {span.a, span.b} == {a, b}:
                return span
        return None

    # -- sending --------------------------------------------------------------------------------
    def _number(self, frame: Frame) -> None:
        if not frame.uid:
            self.uids += 1
            frame.uid = self.uids

    def broadcast(self, node: "RingNode", frame: Frame) -> None:
        self._number(frame)
        if self.source_id is not None:         # faulty variants only: the nodes still read frame.src
            offset, _ = declared_length(frame.wire)
            frame.wire = encode_pac(self.source_id, frame.dst, frame.wire[offset:-2])
        node.seen_add(frame.uid)
        for direction in ((R, L) if self.both_ways else (R,)):
            if node.port_ok(direction):
                self._enqueue(node.out[direction], frame, 1)

    def send(self, node: "RingNode", frame: Frame, direction: str) -> None:
        """Unicast toward frame.dst in one direction (the token goes to a neighbour this way)."""
        self._number(frame)
        node.seen_add(frame.uid)
        if node.port_ok(direction):
            self._enqueue(node.out[direction], frame, 1)

    def _enqueue(self, link: Link, frame: Frame, hops: int) -> None:
        now = self.kernel.now
        if not link.queue and link.busy_until <= now:
            self._start(link, frame, hops)
            return
        key = frame.prio if self.by_priority else 0
        self._order += 1
        heapq.heappush(link.queue, (key, self._order, frame, hops))
        if link.timer is None:
            link.timer = self.kernel.call_at(max(link.busy_until, now), self._link_free, link)

    def _link_free(self, link: Link) -> None:
        link.timer = None
        if link.queue:
            _key, _order, frame, hops = heapq.heappop(link.queue)
            self._start(link, frame, hops)
        if link.queue:
            link.timer = self.kernel.call_at(link.busy_until, self._link_free, link)

    def _start(self, link: Link, frame: Frame, hops: int) -> None:
        span = link.span
        optics_a, optics_b = span._optics               # Span.usable, inlined: once per hop
        if span.cut or not (optics_a.alive and optics_b.alive):
            return                                        # light is gone: the frame is lost
        now = self.kernel.now
        duration = tx_time_us(len(frame.wire), self.bitrate)
        link.busy_until = now + duration
        if span.corrupt:
            key = (link.src.name, frame.kind)
            left = span.corrupt.get(key)
            if left:
                span.corrupt[key] = left - 1
                frame = frame.corrupted()
        if span.tapped:
            self.train.emit(f"link.{span.name}", "link.tx", frm=link.src.name, to=link.dst.name,
                            frame=frame.name, bytes=len(frame.wire),
                            data_bytes=frame.data_bytes, start_us=now, end_us=now + duration,
                            medium=span.medium, hex=frame.wire.hex())
        self.kernel.schedule(self.pass_through, self._arrive, link, frame, hops)

    # -- receiving ------------------------------------------------------------------------------
    def _arrive(self, link: Link, frame: Frame, hops: int) -> None:
        node = link.dst
        span = link.span
        optics_a, optics_b = span._optics
        if span.cut or not (optics_a.alive and optics_b.alive):
            return
        if self.check and not frame.ok:
            node.frames_discarded += 1
            node.emit("frame.discard", frame=frame.name, frm=link.src.name, hops=hops)
            return
        uid = frame.uid
        if uid in node.seen:
            return                                        # the other copy got here first
        node.seen_add(uid)
        dst, direction = frame.dst, link.direction
        if dst == BROADCAST or dst == node.number:
            node.receive(frame, direction, hops)
        if dst != node.number and hops < self.size - 1 and node.port_ok(direction):
            self._enqueue(node.out[direction], frame, hops + 1)
