"""The boards' environment for the hardware/software class (TST-02): supply voltage and interruptions,
temperature, interference bursts, vibration (contact micro-interruptions), withstand-voltage tests.

Inside the rated range nothing changes. Outside it a board fails safe (FS-02: it stops talking rather
than talk wrong): its supply's output drops, through the same `PowerSupply` every board already hangs on,
so the existing redundancy takes over (CCU system 2, token reversal, command paths 2 and 3, monitor
alarms). When the condition is over the supply restarts after `restart_us` and the node's CPU3 writes a
fault record saying why it restarted. Figures and their sources: docs/decisions.md, "Environment".
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from sut.reference.crh2.frames import KIND_NAMES
from sut.reference.crh2.ring import ENDLESS

if TYPE_CHECKING:
    from sut.reference.crh2.boards import PowerSupply
    from sut.reference.kernel import Timer
    from sut.reference.crh2.node import RingNode
    from sut.reference.crh2.ring import Span
    from sut.reference.crh2.context import TrainContext

TRAIN_SUPPLY = "train 110V"
WHOLE_TRAIN = "train"
# Damaging "every frame for a while" rides on the span's per-sender corruption counts (the same place
# corrupt_frames writes): a count no run can use up (ring.ENDLESS).
BROKEN_MOHM = 0.5


class SupplyInput:
    """The input side of one board supply: what it is fed, and why its output is down."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, supply: "PowerSupply", node: "RingNode | None"):
        self.supply = supply
        self.node = node                  # the node whose CPU side it feeds (writes the restart record)
        self.own_v: float | None = None   # a voltage set on this supply alone; None: the train's 110 V
        self.open = 0                     # contact interruptions in progress
        self.heat: str | None = None      # "over-temperature" / "under-temperature"
        self.isolated = False             # unit disconnected for a withstand-voltage test
        self.broken = False               # insulation broke down in a withstand test
        self.zone = "rated"
        self.deadline: "Timer | None" = None
        self.restart: "Timer | None" = None
        self.down_reason: str | None = None
        self.down_at = 0
        self.brownout = False


class TrainEnvironment:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext"):
        self.train = train
        self.kernel = train.kernel
        self.rated = train.cfg.environment
        self.behaviour = train.cfg.behaviour
        self.train_v = self.rated.nominal_v
        owners = {id(node.supply): node for node in train.ring.nodes}
        self.inputs = {name: SupplyInput(s, owners.get(id(s))) for name, s in train.supplies.items()}
        self.units = {node.name: sorted({node.board(b).supply.name for b in ("CPU3", "MDM8", "MDM9", "TXC", "RXC")
                                         if node.board(b) is not None}) for node in train.ring.nodes}
        self.temperature: dict[str, float] = {}

    # -- supply voltage and interruptions --------------------------------------------------------
    def supplies_of(self, name: str) -> list[SupplyInput]:
        return list(self.inputs.values()) if name == TRAIN_SUPPLY else [self.inputs[name]]

    def set_voltage(self, name: str, volts: float) -> None:
        self.train.emit(name, "env.voltage", volts=volts, un_pct=round(100 * volts / self.rated.nominal_v, 1))
        if name == TRAIN_SUPPLY:
            self.train_v = volts
        else:
            self.inputs[name].own_v = volts
        for si in self.supplies_of(name):
            self._evaluate(si)

    def interrupt(self, name: str, duration_us: int, cause: str = "env.interruption") -> None:
        self.train.emit(name, cause, open=True, ms=duration_us / 1000)
        targets = self.supplies_of(name)
        for si in targets:
            si.open += 1
            self._evaluate(si)
        self.kernel.call_later(duration_us, self._reclose, name, targets, cause)

    def _reclose(self, name: str, targets: list[SupplyInput], cause: str) -> None:
        self.train.emit(name, cause, open=False)
        for si in targets:
            si.open -= 1
            self._evaluate(si)

    def volts(self, si: SupplyInput) -> float:
        if si.open or si.isolated:
            return 0.0
        return self.train_v if si.own_v is None else si.own_v

    # -- temperature ----------------------------------------------------------------------------
    def set_temperature(self, unit: str, celsius: float) -> None:
        self.train.emit(unit, "env.temperature", celsius=celsius)
        r = self.rated
        heat = None if r.temp_lo_c <= celsius <= r.temp_hi_c else (
            "over-temperature" if celsius > r.temp_hi_c else "under-temperature")
        for name in (self.units if unit == WHOLE_TRAIN else [unit]):
            self.temperature[name] = celsius
            for supply in self.units[name]:
                si = self.inputs[supply]
                si.heat = heat
                self._evaluate(si)

    # -- interference and vibration on the lines -----------------------------------------------
    def burst(self, span: "Span | None", level_kv: float, duration_us: int) -> None:
        """Fast-transient bursts on a ring link (span) or the self-diagnostic line (None). Up to the
        immunity level nothing is damaged; above it every frame on that line while the burst lasts is."""
        source = "selfdiag" if span is None else f"link.{span.name}"
        self.train.emit(source, "env.burst", kv=level_kv, ms=duration_us / 1000)
        if level_kv <= self.rated.burst_immunity_kv:
            return
        if span is None:
            line = self.train.selfdiag
            line.disturbed_until = max(line.disturbed_until, self.kernel.now + duration_us)
        else:
            self._damage(span, duration_us)

    def _damage(self, span: "Span", duration_us: int) -> None:
        keys = [(node.name, kind) for node in (span.a, span.b) for kind in KIND_NAMES]
        for key in keys:
            span.corrupt[key] = span.corrupt.get(key, 0) + ENDLESS
        self.kernel.call_later(duration_us, self._undamage, span, keys)

    @staticmethod
    def _undamage(span: "Span", keys: list) -> None:
        for key in keys:
            left = span.corrupt.get(key, 0) - ENDLESS
            if left > 0:
                span.corrupt[key] = left
            else:
                span.corrupt.pop(key, None)

    def vibrate_supply(self, name: str, interruption_us: int, count: int, period_us: int) -> None:
        self.train.emit(name, "env.vibration", connector="supply", interruption_ms=interruption_us / 1000,
                        count=count, period_ms=period_us / 1000)
        for i in range(count):
            self.kernel.call_later(i * period_us, self.interrupt, name, interruption_us, "env.contact")

    def vibrate_link(self, span: "Span", interruption_us: int, count: int, period_us: int) -> None:
        self.train.emit(f"link.{span.name}", "env.vibration", connector="link", count=count,
                        interruption_ms=interruption_us / 1000, period_ms=period_us / 1000)
        for i in range(count):
            self.kernel.call_later(i * period_us, self._light_loss, span, interruption_us)

    def _light_loss(self, span: "Span", interruption_us: int) -> None:
        """Frames on the fibre while the light is gone arrive damaged; light gone longer than the MDM8
        rides out is a link fault until it comes back (the nodes beside it see the link go down)."""
        source = f"link.{span.name}"
        self.train.emit(source, "env.contact", open=True, ms=interruption_us / 1000)
        bridged = self.rated.contact_bridged_us
        self._damage(span, min(interruption_us, bridged))
        if interruption_us > bridged and not span.cut:
            self.kernel.call_later(bridged, self._link_lost, span, interruption_us - bridged)
        else:
            self.kernel.call_later(interruption_us, self._light_back, source)

    def _light_back(self, source: str) -> None:
        self.train.emit(source, "env.contact", open=False)

    def _link_lost(self, span: "Span", rest_us: int) -> None:
        if span.cut:                     # cut by hand meanwhile: that is the tester's to restore
            return
        span.cut = True
        self.train.span_changed(span)
        self.kernel.call_later(rest_us, self._link_back, span)

    def _link_back(self, span: "Span") -> None:
        self.train.emit(f"link.{span.name}", "env.contact", open=False)
        span.cut = False
        self.train.span_changed(span)

    # -- withstand voltage and insulation --------------------------------------------------------
    def withstand_test(self, unit: str, volts: float, duration_us: int) -> None:
        """The unit is disconnected (unpowered) for the test and reconnected afterwards."""
        breaks = volts > self.rated.breakdown_v
        self.train.emit(unit, "env.withstand", volts=volts, s=duration_us / 1_000_000, phase="start")
        targets = [self.inputs[s] for s in self.units[unit]]
        for si in targets:
            si.isolated = True
            self._evaluate(si)
        self.kernel.call_later(duration_us, self._withstand_end, unit, targets, breaks)

    def _withstand_end(self, unit: str, targets: list[SupplyInput], breaks: bool) -> None:
        self.train.emit(unit, "env.withstand", phase="end", breakdown=breaks)
        for si in targets:
            si.isolated = False
            si.broken = si.broken or breaks
            self._evaluate(si)

    def insulation_mohm(self, unit: str) -> float:
        broken = any(self.inputs[s].broken for s in self.units[unit])
        mohm = BROKEN_MOHM if broken else self.rated.insulation_mohm
        self.train.emit(unit, "env.insulation", mohm=mohm, test_volts_dc=500)
        return mohm

    # -- the supply's reaction --------------------------------------------------------------------
    def _zone(self, si: SupplyInput) -> tuple[str, int | None, str]:
        """(zone, how long the supply rides it out in us (None: for ever), reason when it gives up)."""
        r, un = self.rated, self.rated.nominal_v
        v = self.volts(si)
        if si.broken:
            return "broken", 0, "insulation breakdown"
        if si.isolated:
            return "isolated", 0, "withstand test"
        if si.heat:
            return si.heat, 0, si.heat
        if v > r.surge_hi * un:
            return "overvoltage", 0, "overvoltage"
        if v > r.continuous_hi * un:
            return "surge", r.surge_us, "overvoltage"
        if v >= r.continuous_lo * un:
            return "rated", None, ""
        if v >= r.dip_lo * un:
            return "dip", r.dip_us, "undervoltage"
        return "low", r.hold_up_us, "interruption" if v == 0 else "undervoltage"

    def _evaluate(self, si: SupplyInput) -> None:
        zone, allowed, reason = self._zone(si)
        changed, si.zone = zone != si.zone, zone
        if zone == "rated":
            self._cancel_deadline(si)
            if si.brownout:
                self._end_brownout(si)
            if si.down_reason is not None and si.restart is None and self.behaviour.restart_after_dropout:
                si.restart = self.kernel.call_later(self.rated.restart_us, self._restart, si)
            return
        if si.restart is not None:            # the input went bad again while the board was booting
            si.restart.cancel()
            si.restart = None
        if si.down_reason is not None or si.brownout:
            return
        if changed or si.deadline is None:
            self._cancel_deadline(si)
            if allowed == 0:
                self._drop(si, reason)
            else:
                # "for 0.1 s without deviation": exactly the allowance is still ridden out
                si.deadline = self.kernel.call_later(allowed + 1, self._drop, si, reason)

    @staticmethod
    def _cancel_deadline(si: SupplyInput) -> None:
        if si.deadline is not None:
            si.deadline.cancel()
            si.deadline = None

    def _drop(self, si: SupplyInput, reason: str) -> None:
        si.deadline = None
        if si.zone == "low" and not self.behaviour.undervoltage_lockout:
            self._start_brownout(si)
            return
        si.down_reason, si.down_at = reason, self.kernel.now
        self.train.emit(si.supply.name, "supply.dropout", reason=reason, volts=self.volts(si))
        si.supply.set_input_ok(False)

    def _restart(self, si: SupplyInput) -> None:
        si.restart = None
        reason, si.down_reason = si.down_reason, None
        self.train.emit(si.supply.name, "supply.restart", after=reason,
                        down_ms=(self.kernel.now - si.down_at) / 1000)
        si.supply.set_input_ok(True)
        node = si.node
        ccu = getattr(node, "ccu", None)
        if ccu is not None and ccu.commanding and ccu.master != node.index:
            # A restarted system comes back as standby: it has to watch the ring for a whole takeover
            # time itself before it may take over, not act on silence it slept through.
            ccu._arm_watch()
        if node is not None and node.cpu3.alive:
            event = f"restarted after {reason}"
            node.train.emit(f"{node.name}.CPU3", "fault.record", board="supply", event=event)
            node.queue_record(f"F|{si.down_at // 1000}|{node.name}|supply|{event}".encode())

    # -- faulty variants only: a supply without undervoltage lockout ---------------------------------
    def _start_brownout(self, si: SupplyInput) -> None:
        """Boards on too little voltage keep running and every frame their node sends leaves damaged."""
        si.brownout = True
        self.train.emit(si.supply.name, "supply.brownout", volts=self.volts(si))
        if si.node is not None:
            for span in si.node.ports.values():
                for kind in KIND_NAMES:
                    key = (si.node.name, kind)
                    span.corrupt[key] = span.corrupt.get(key, 0) + ENDLESS

    def _end_brownout(self, si: SupplyInput) -> None:
        si.brownout = False
        if si.node is not None:
            keys = [(si.node.name, kind) for kind in KIND_NAMES]
            for span in si.node.ports.values():
                self._undamage(span, keys)

    # -- what the SUT declares ---------------------------------------------------------------------
    def rated_limits(self) -> dict[str, object]:
        # The keys the contract lists (answers.rated_limits), no others: an unlisted figure is read by no step,
        # so nothing would notice it wrong.
        r, un = self.rated, self.rated.nominal_v
        return {
            "nominal supply voltage V": un,
            "continuous supply voltage V": (round(r.continuous_lo * un, 3), round(r.continuous_hi * un, 3)),
            "short dip supply voltage V": round(r.dip_lo * un, 3),
            "short dip ms": r.dip_us / 1000,
            "short surge supply voltage V": round(r.surge_hi * un, 3),
            "short surge ms": r.surge_us / 1000,
            "interruption bridged ms": r.hold_up_us / 1000,
            "operating temperature C": (r.temp_lo_c, r.temp_hi_c),
            "burst immunity kV": r.burst_immunity_kv,
            "contact interruption bridged ms": r.contact_bridged_us / 1000,
            "insulation resistance MOhm": r.insulation_mohm,
            "withstand voltage V rms": r.withstand_v,
        }
