"""Assembles one train: ring order, supplies, units, devices, the self-diagnostic line.

Ring order of one 8-car set (node number = position + 1, docs/decisions.md "Ring order"):
  car1.CCU.sys1, car1.CCU.sys2, car1.LCU .. car8.LCU, car8.CCU.sys2, car8.CCU.sys1
Two coupled sets (NET-08) make one ring of both, joined at the coupler by twisted pair.
"""
from __future__ import annotations

from typing import Any

from sut.reference.crh2.boards import PowerSupply
from sut.reference.crh2.ccu import Ccu, CcuSystem
from sut.reference.crh2.config import TrainConfig
from sut.reference.crh2.devices import LoopDevice
from sut.reference.crh2.display import DisplayTable
from sut.reference.crh2.environment import TrainEnvironment
from sut.reference.bulk import cyclic_period_us
from sut.reference.kernel import Kernel
from sut.reference.crh2.lcu import Lcu
from sut.reference.crh2.node import RingNode
from sut.reference.crh2.ring import Ring, Span
from sut.reference.crh2.selfdiag import SelfDiagLine
from sut.reference.crh2.vehicle import Vehicle
from sut.eventlog import EventLog
from sut.trace import TraceEvent, new_event

# The most token periods a steady speed's whole metres of mileage may take to repeat (bulk_period_us).
CRUISE_PERIODS = 100


class Train:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    BULK_SKIP = ("events", "free_marks")   # the trace is history, not state (bulk.py)

    def __init__(self, cfg: TrainConfig):
        self.cfg = cfg
        self.kernel = Kernel()
        self.events: EventLog = EventLog()
        self.free_marks: list[int] = []   # where the metronomes' events are in `events` (bulk.py)
        self.supplies: dict[str, PowerSupply] = {}
        self.ccus: dict[int, Ccu] = {}
        self.lcus: list[Lcu] = []
        nodes: list[RingNode] = []
        media: list[str] = []
        per = cfg.cars_per_set
        for s in range(cfg.sets):
            first, last = s * per + 1, s * per + per
            for car in (first, last):
                for name in (f"car{car}.CCU.sys1", f"car{car}.CCU.sys2", f"car{car}.CCU.sys1.TXC",
                             f"car{car}.CCU.sys2.TXC", f"car{car}.desk"):
                    self.supplies[name] = PowerSupply(name)
                self.ccus[car] = Ccu(self, car, self.supplies)
            set_nodes: list[RingNode] = list(self.ccus[first].systems)
            for car in range(first, last + 1):
                self.supplies[f"car{car}.LCU"] = PowerSupply(f"car{car}.LCU")
                self.supplies[f"car{car}.LCU.RXC"] = PowerSupply(f"car{car}.LCU.RXC")
                own = cfg.behaviour.rxc_own_supply           # CMD-01; a faulty variant feeds it from the LCU's
                lcu = Lcu(self, car, self.supplies[f"car{car}.LCU"],
                          self.supplies[f"car{car}.LCU.RXC" if own else f"car{car}.LCU"])
                self._add_loop_devices(lcu)
                self.lcus.append(lcu)
                set_nodes.append(lcu)
            set_nodes.extend(reversed(self.ccus[last].systems))
            if media:
                media[-1] = "twisted-pair"          # the span into this set crosses the coupler
            media.extend(["fibre"] * len(set_nodes))
            nodes.extend(set_nodes)
        for i, node in enumerate(nodes):
            node.number = i + 1
        self.ring = Ring(self, nodes, media)
        for span in self.ring.spans:
            span.was_usable = span.usable
        self.selfdiag = SelfDiagLine(self)
        # PRO-06 block transfer bookkeeping at the master node
        self.block_queue: list[int] = []
        self.block_granted = 0
        self.block_records: dict[tuple[int, int], dict[int, bytes]] = {}   # (owner, record) -> blocks
        self.block_totals: dict[tuple[int, int], int] = {}
        self.vehicle = Vehicle(self)
        self.display = DisplayTable(self)
        self.environment = TrainEnvironment(self)

    def _add_loop_devices(self, lcu: Lcu) -> None:
        periods = dict(self.cfg.timing.current_loop_periods_us)
        car = lcu.car
        lcu.loop_devices.append(LoopDevice(self, f"car{car}.ACS", lcu.cpu3, "20mA", periods["ACS"], "polled"))
        lcu.loop_devices.append(LoopDevice(self, f"car{car}.PID", lcu.cpu3, "20mA", periods["PID"], "polled"))
        if car in self.cfg.apu_cars():
            lcu.loop_devices.append(LoopDevice(self, f"car{car}.APU", lcu.cpu3, "30mA", periods["APU"],
                                               "polled"))
        lcu.loop_devices.append(LoopDevice(self, f"car{car}.SDD", lcu.cpu3, "20mA", periods.get("SDD", 1_000_000),
                                           "to-device"))
        if car in self.cfg.cab_cars():
            lcu.loop_devices.append(LoopDevice(self, f"car{car}.DD", lcu.cpu3, "20mA", periods.get("DD", 100_000),
                                               "from-device"))

    # -- plumbing -------------------------------------------------------------------------------
    def emit(self, source: str, kind: str, /, **fields: Any) -> None:
        self.events.append(new_event(TraceEvent, (self.kernel.now, source, kind, fields)))

    def emit_free(self, source: str, kind: str, /, **fields: Any) -> None:
        self.free_marks.append(len(self.events))
        self.events.append(new_event(TraceEvent, (self.kernel.now, source, kind, fields)))

    def start(self) -> None:
        self.emit("train", "power.on", cars=self.cfg.cars, nodes=self.ring.size)
        self.vehicle.announce()
        for node in self.ring.nodes:
            node.start()
        for ccu in self.ccus.values():
            ccu.start()

    def bulk_period_us(self) -> int:
        """The steady period (sut/reference/bulk.py): every cyclic activity and the token's round, one
        holding time per hop. A wrong guess of the token's part only costs speed: bulk.py checks the line it
        finds, and traffic out of step with the guess shows in the two periods' traces. Not so the mileage
        shown, which moves by a whole metre less often than once a period and says nothing meanwhile: its
        part below must be exact (bulk_steady)."""
        period = self._token_period_us()
        # A train running at a steady speed: the cab monitor's mileage moves by whole metres, by the same
        # number of them only every few periods (1.2 m a period at 36 km/h: 6 m every 5), and those are its
        # steady period. A speed whose metres repeat only after more than CRUISE_PERIODS periods keeps the
        # token's, and the train says it is not steady (bulk_steady).
        periods = self.display.periods_to_repeat(period)
        return period * periods if periods <= CRUISE_PERIODS else period

    def bulk_steady(self) -> bool:
        """bulk.py: a train whose whole metres of mileage repeat only over more than CRUISE_PERIODS token
        periods (3.6 km/h as a float is a little over 3.6, and its metres never quite repeat) cannot be jumped
        over: its monitor's mileage, and the status data that carries it, stay the same for a few periods and
        then move by a metre, which a line through three periods does not show (three equal readings look
        like a standstill). Such a train is simulated, every frame."""
        return self.display.periods_to_repeat(self._token_period_us()) <= CRUISE_PERIODS

    def _token_period_us(self) -> int:
        hold = self.cfg.timing.token_hold_us
        return cyclic_period_us(self.kernel, *(hops * hold for hops in self._token_round_hops()))

    def _token_round_hops(self) -> list[int]:
        """Hops of each token's round: all the nodes on an intact ring; on a ring broken into lines (a cut
        span, a dead MDM8) each line's token goes to its end and back, and a node cut off on both sides
        keeps its own."""
        ring = self.ring
        usable = [span.usable for span in ring.spans]          # span i joins node i and node i + 1
        if all(usable):
            return [ring.size]
        first = usable.index(False) + 1
        rounds, line = [], []
        for k in range(ring.size):
            i = (first + k) % ring.size
            line.append(ring.nodes[i])
            if not usable[i]:
                if len(line) > 1:
                    rounds.append(2 * (len(line) - 1))
                elif line[0].mdm8.alive:
                    rounds.append(1)
                line = []
        return rounds or [1]

    def node_by_number(self, number: int) -> RingNode:
        return self.ring.nodes[number - 1]

    def span_changed(self, span: Span) -> None:
        """Called when light on a span may have come or gone; the end nodes notice at once."""
        now_usable = span.usable
        if span.was_usable == now_usable:
            return
        span.was_usable = now_usable
        for node, side in ((span.a, "R"), (span.b, "L")):
            node.port_changed(side, now_usable)

    def commanding_ccu(self) -> Ccu | None:
        for ccu in self.ccus.values():
            if ccu.commanding:
                return ccu
        return None

    def commanding_source_ok(self, fields: dict) -> bool:
        ccu = self.ccus.get(fields["cab"])
        return ccu is not None and ccu.commanding

    # -- PRO-06: block data -----------------------------------------------------------------------
    def block_master(self) -> CcuSystem | None:
        ccu = self.commanding_ccu() or self.ccus[min(self.ccus)]
        system = ccu.systems[ccu.master - 1]
        return system if system.cpu3.alive and system.mdm8.alive else None

    def block_grant_for(self, node: RingNode) -> int:
        if node is not self.block_master():
            return 0
        if node.pending_blocks and node.number != self.block_granted and node.number not in self.block_queue:
            self.block_queue.append(node.number)          # the master's own records queue like any other
        if self.block_granted == node.number and not node.pending_blocks and not node.block_busy:
            self.block_granted = 0
        if self.block_granted == 0 and self.block_queue:
            self.block_granted = self.block_queue.pop(0)
            self.emit(f"{node.name}.CPU3", "block.grant", node=self.node_by_number(self.block_granted).name)
        if self.block_granted == node.number and node.pending_blocks:
            node.start_blocks()
        return self.block_granted

    def block_master_saw_status(self, node: RingNode, fields: dict, src: int) -> None:
        if fields["grant"] == node.number and node.pending_blocks:
            node.start_blocks()
        if node is not self.block_master():
            return
        if fields["block_request"] and src != self.block_granted and src not in self.block_queue:
            self.block_queue.append(src)
            self.emit(f"{node.name}.CPU3", "block.request", node=self.node_by_number(src).name,
                      blocks=fields["block_request"])
        elif src == self.block_granted and not fields["block_request"]:
            self.block_granted = 0

    def block_received(self, node: RingNode, fields: dict, src: int) -> None:
        if node is not self.block_master():
            return
        key = (fields["owner"], fields["record"])
        self.block_records.setdefault(key, {})[fields["index"]] = fields["data"]
        self.block_totals[key] = fields["total"]
        self.emit(f"{node.name}.CPU3", "block.rx", owner=self.node_by_number(key[0]).name, record=key[1],
                  index=fields["index"], total=fields["total"], bytes=len(fields["data"]))

    def records(self) -> dict[str, list[bytes]]:
        """Complete records held at the master, by owner, in the order they were made."""
        out: dict[str, list[bytes]] = {}
        for (owner, record) in sorted(self.block_records):
            blocks = self.block_records[(owner, record)]
            total = self.block_totals[(owner, record)]
            if len(blocks) == total:
                out.setdefault(self.node_by_number(owner).name, []).append(
                    b"".join(blocks[i] for i in range(total)))
        return out

    # -- the cab monitor's equipment orders (docs/decisions.md, "Display") ----------------------------
    def orders_for(self, node: RingNode) -> list[dict[str, int]]:
        ccu = self.commanding_ccu()
        # Orders come from the monitor, so they ride in the status data of the system feeding it (the
        # master's CPU3 may be dead while its TXC still commands the train).
        if ccu is None or node is not ccu.monitor_source():
            return []
        return [self.display.order(name, value) for name, value in ccu.orders.items()]

    def orders_received(self, node: RingNode, fields: dict) -> None:
        for raw in fields.get("orders", ()):
            decoded = self.display.decode(raw)
            if decoded is None:
                continue
            name, value = decoded
            if self.display.by_name[name].owner == node.name:
                self.vehicle.apply_order(name, value)

    # -- NET-04: the self-diagnostic line carries commands only ----------------------------------
    def selfdiag_status_leak(self, node: RingNode, frame: Any) -> None:
        if self.cfg.behaviour.selfdiag_commands_only:
            return
        if not (node.port_ok("L") or node.port_ok("R")):
            self.selfdiag.send_status(node.name, node.number, frame.fields)

    def selfdiag_status_delivered(self, fields: dict) -> None:
        src = fields["src"]
        for node in self.ring.nodes:
            if node.number != src and node.cpu3.alive:
                node.heard[src] = self.kernel.now
                node.on_status(fields, src)
