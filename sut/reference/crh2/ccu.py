"""The central unit CCU of a cab car: systems 1 and 2, each with CPU3, MDM8 and a TXC (NET-02, RED-01..03).

Each system is a ring node on its own supply; its TXC has a supply of its own (CMD-01). Both TXCs sample
the driver desk every command interval (RED-02); only the master system puts commands on the ring and the
self-diagnostic line, while the standby system watches the ring for the master's commands and takes over
when it has seen none for 50 ms.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from sut.reference.crh2 import frames as fr
from sut.reference.crh2.boards import Board, PowerSupply
from sut.reference.crh2.desk import Desk, Sample
from sut.reference.crh2.node import RingNode

if TYPE_CHECKING:
    from sut.reference.kernel import Timer
    from sut.reference.crh2.context import TrainContext

LAMPS = ("MCR", "traction", "brake")


class Txc:
    """Command transmitter with two CPU groups (FS-01..03): #1 works, #2 monitors."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, system: "CcuSystem", supply: PowerSupply):
        self.system = system
        self.name = f"{system.name}.TXC"
        self.board = Board(self.name, supply)
        self.group1 = Board(f"{self.name}.group1", supply)
        self.group2 = Board(f"{self.name}.group2", supply)
        self.failsafe = False

    @property
    def alive(self) -> bool:
        return self.board.alive

    def sample(self, desk: Desk) -> Sample | None:
        """Both groups sample the desk and compare; None when the fail-safe circuit has cut the output."""
        if not self.alive or self.failsafe:
            return None
        train = self.system.train
        inverted = train.cfg.behaviour.txc_inverted_inputs
        mine = desk.sample(inverted)
        theirs = desk.sample(inverted, misread=self.group2.failed)
        healthy = not self.group1.failed
        if train.cfg.behaviour.txc_compare and (mine != theirs or not healthy):
            self.failsafe = True
            train.emit(self.name, "txc.failsafe", group1=mine.as_dict(), group2=theirs.as_dict(),
                       group1_healthy=healthy)
            self.system.board_changed()
            return None
        return mine


class CcuSystem(RingNode):
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    unit = "CCU"

    def __init__(self, train: "TrainContext", ccu: "Ccu", index: int, supply: PowerSupply, txc_supply: PowerSupply):
        super().__init__(train, f"car{ccu.car}.CCU.sys{index}", ccu.car, supply)
        self.ccu = ccu
        self.index = index
        self.txc = Txc(self, txc_supply)
        self.last_status: dict[int, dict] = {}
        self.cmd_seq = 0
        self._health_seen = self.health_byte()
        self.txc.board.listeners.append(self.board_changed)

    def board(self, short: str) -> Board | None:
        return {"CPU3": self.cpu3, "MDM8": self.mdm8, "TXC": self.txc.board}.get(short)

    def board_healthy(self, short: str) -> bool:
        if short == "TXC":
            return self.txc.alive and not self.txc.failsafe
        return super().board_healthy(short)

    def counters(self) -> dict[str, int]:
        return dict(super().counters(), **{"commands sent": self.cmd_seq})

    def _clock_ms(self) -> int:
        if self.train.cfg.behaviour.clock_from_us32:          # faulty variants only
            return (self.kernel.now & 0xFFFF_FFFF) // 1000
        return self.kernel.now // 1000

    # -- commands out (PRO-01) ------------------------------------------------------------------
    def put_command(self, sample: Sample) -> None:
        """TXC -> 20 mA loop -> MDM8 -> ring, and TXC -> self-diagnostic line."""
        self.cmd_seq += 1               # unbounded here; the wire carries it modulo 256 (frames.py)
        fields = dict(seq=self.cmd_seq, cab=self.car, system=self.index, **sample.wire_fields(),
                      clock_ms=self._clock_ms())
        hold = self.train.cfg.behaviour.standstill_holding_brake        # freedom variants only
        if hold and fields["traction"] == 0 and fields["brake"] < hold and self.train.vehicle.inputs["speed"] == 0:
            # A holding brake is the CCU's function, not the driver's: the cab lamp still shows the handle,
            # and the same command that first carries a notch carries the hold off.
            fields["brake"] = hold
        self.kernel.schedule(self.train.cfg.timing.txc_loop_us, self._mdm8_send, fields)
        self.train.selfdiag.send_command(self.txc.name, fields)

    def _mdm8_send(self, fields: dict) -> None:
        if not self.mdm8.alive:
            return
        self.emit("cmd.tx", seq=fields["seq"], system=self.index, traction=fields["traction"],
                  brake=fields["brake"])
        self.train.ring.broadcast(self, fr.data_frame(fr.K_COMMAND, self.number, fr.BROADCAST,
                                                      fr.P_COMMAND, **fields))

    # -- frames in ------------------------------------------------------------------------------
    def on_command(self, fields: dict, direction: str, hops: int) -> None:
        self.ccu.heard_command(self, fields)

    def on_status(self, fields: dict, src: int) -> None:
        self.last_status[src] = fields
        if self.ccu.monitor_source() is self:
            self.train.emit(f"car{self.car}.monitor", "status.rx",
                            frm=self.train.node_by_number(src).name, seq=fields["seq"])
            for raw in fields.get("points", ()):
                decoded = self.train.display.decode(raw)
                if decoded is not None:
                    self.ccu.display_update(*decoded)
        super().on_status(fields, src)


class Ccu:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext", car: int, supplies: dict[str, PowerSupply]):
        self.train = train
        self.car = car
        self.desk = Desk(train, car, supplies[f"car{car}.desk"])
        self.systems = [CcuSystem(train, self, i, supplies[f"car{car}.CCU.sys{i}"],
                                  supplies[f"car{car}.CCU.sys{i}.TXC"]) for i in (1, 2)]
        self.master = 1
        self._watch: "Timer | None" = None
        self.lamps = {name: False for name in LAMPS}
        self.display: dict[str, Any] = {}         # what the cab monitor shows, from status data
        self.orders: dict[str, str] = {}          # equipment orders given on this monitor, not yet shown done

    @property
    def commanding(self) -> bool:
        return self.desk.mcr

    def start(self) -> None:
        t = self.train.cfg.timing
        self.train.kernel.every(t.command_interval_us, self._tick)

    # -- the command cycle ----------------------------------------------------------------------
    def _tick(self) -> None:
        samples = {s.index: s.txc.sample(self.desk) for s in self.systems}
        self._drive_lamps(samples)
        if not self.commanding:
            return
        standby_too = self.train.cfg.behaviour.standby_transmits
        for system in self.systems:
            sample = samples[system.index]
            if sample is not None and (system.index == self.master or standby_too):
                system.put_command(sample)
        if self._watch is None:
            self._arm_watch()

    # -- RED-02: the standby watches the master -------------------------------------------------
    def _arm_watch(self) -> None:
        # put off, not replaced: every command the standby hears from the master re-arms it (Kernel.put_off)
        self._watch = self.train.kernel.put_off(self._watch, self.train.cfg.timing.takeover_us, self._takeover)

    def heard_command(self, system: CcuSystem, fields: dict) -> None:
        if (self.commanding and system.index != self.master and fields["cab"] == self.car
                and fields["system"] == self.master):
            self._arm_watch()

    def _takeover(self) -> None:
        self._watch = None
        if not self.commanding:
            return
        standby = self.systems[2 - self.master]    # the other one
        hears_ring = standby.port_ok("L") or standby.port_ok("R")
        if not (hears_ring and standby.txc.alive and not standby.txc.failsafe):
            self._arm_watch()                      # nobody able to take over; keep watching
            return
        old = self.master
        self.master = standby.index
        self.train.emit(standby.name, "ccu.takeover", frm=f"sys{old}", silent_us=self.train.cfg.timing.takeover_us)
        self._arm_watch()

    def mcr_changed(self) -> None:
        if not self.commanding and self._watch is not None:
            self._watch.cancel()
            self._watch = None

    # -- RED-03: lamps driven by both TXCs in parallel ------------------------------------------
    def _drive_lamps(self, samples: dict[int, Sample | None]) -> None:
        drivers = (1, 2) if self.train.cfg.behaviour.lamps_parallel else (1,)
        wanted = {name: False for name in LAMPS}
        for index in drivers:
            system = self.systems[index - 1]
            sample = samples[index]
            if sample is None and system.txc.alive and system.txc.failsafe:
                sample = self.desk.sample(self.train.cfg.behaviour.txc_inverted_inputs)  # lamp outputs are not cut
            if sample is None:
                continue
            wanted["MCR"] |= self.desk.mcr
            wanted["traction"] |= sample.traction > 0
            wanted["brake"] |= sample.brake > 0
        for name, on in wanted.items():
            if on != self.lamps[name]:
                self.lamps[name] = on
                self.train.emit(f"car{self.car}.cab", "lamp.on" if on else "lamp.off", lamp=name)

    # -- the cab monitor ------------------------------------------------------------------------
    def display_update(self, name: str, value: Any) -> None:
        delay = self.train.cfg.behaviour.display_delay_us
        if delay:
            self.train.kernel.call_later(delay, self._show, name, value)
        else:
            self._show(name, value)

    def _show(self, name: str, value: Any) -> None:
        if self.display.get(name) != value:
            self.display[name] = value
            self.train.emit(f"car{self.car}.monitor", "display.change", name=name, value=value)
        if self.orders.get(name) == value:
            del self.orders[name]                 # the order is shown done: stop sending it

    def order(self, name: str, value: str) -> None:
        if not self.commanding:
            self.train.emit(f"car{self.car}.monitor", "order.void", name=name, value=value)   # ILK-07
            return
        self.orders[name] = value
        self.train.emit(f"car{self.car}.monitor", "order.given", name=name, value=value)

    def monitor_source(self) -> CcuSystem | None:
        for system in self.systems:
            if system.cpu3.alive:
                return system
        return None

    def monitor_view(self, stale_us: int) -> dict[str, Any]:
        source = self.monitor_source()
        now = self.train.kernel.now
        faults: list[str] = []
        for node in self.train.ring.nodes if source is not None else ():
            if node is source:       # its own state it knows without the ring
                fields = {"health": source.health_byte(),
                          "ports": (1 if source.port_ok("L") else 0) | (2 if source.port_ok("R") else 0)}
            else:
                heard = source.heard.get(node.number)
                if heard is None or now - heard > stale_us:
                    faults.append(f"no status data from {node.name}")
                    continue
                fields = source.last_status.get(node.number, {})
            for bit, side in ((1, "L"), (2, "R")):
                if not fields.get("ports", 3) & bit:
                    a, b = sorted((node, node.neighbour(side)), key=lambda n: n.number)
                    faults.append(f"optical transmission fault between {a.name} and {b.name}")
            for i, board in enumerate(fr.HEALTH_BITS):
                if not fields.get("health", 0xFF) & (1 << i):
                    faults.append(f"{node.name}.{board} failure")
        # What the contract's monitor lists, no more: how old a node's status data is, status_table() answers.
        return {"faults": sorted(set(faults)), "fed_by": source.name if source else None,
                "display": dict(self.display)}
