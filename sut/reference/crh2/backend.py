"""`reference`: the embedded virtual-time CRH2 train, as one `TrainDriver` backend.

What it does not model (python-can's VirtualBus states its limits, so does this):
- electrical signal levels, light budgets and bit errors other than the injected ones;
- ARCNET reconfiguration bursts and node-ID arbitration (the CRH2 token protocol of S4 runs above them);
- the content of status data beyond what the monitor shows (health, link state, block requests);
- vehicle dynamics, interlocks and the brake system (issue 4).

Faulty variants subclass it and set `TIMING` / `BEHAVIOUR` overrides; the model itself is never edited.
"""
from __future__ import annotations

from typing import Any, ClassVar

from sut.driver import TrainDriver
from sut.snapshot import PickledState
from sut.errors import OutOfRange, SutError, UnknownName
from sut.reference import bulk
from sut.reference.crh2.boards import Board, PowerSupply
from sut.reference.crh2.config import BRAKE_STEPS, EMERGENCY, TRACTION_NOTCHES, TrainConfig
from sut.reference.crh2.environment import TRAIN_SUPPLY, WHOLE_TRAIN, TrainEnvironment
from sut.reference.crh2.frames import KIND_NAMES
from sut.reference.crh2.node import RingNode
from sut.reference.crh2.ring import Span
from sut.reference.crh2.train import Train
from sut.trace import Trace

FRAME_KINDS = {name: code for code, name in KIND_NAMES.items()}


class ReferenceTrain(PickledState, TrainDriver):
    backend_name = "reference"
    PROFILES = ("crh2",)
    DETERMINISTIC = True           # virtual time, no randomness, nothing outside the model
    DECLARATION = "sut/reference/declaration.yaml"
    # Read by bulk advance where it is a part of a bigger model (the ATP fitted to a set); the index of the
    # trace a step built is history, not state.
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    BULK_SKIP = ("_view",)
    TIMING: ClassVar[dict[str, Any]] = {}
    BEHAVIOUR: ClassVar[dict[str, Any]] = {}

    INTERLOCKS: ClassVar[dict[str, Any]] = {}
    ENVIRONMENT: ClassVar[dict[str, Any]] = {}
    # The model's class: a variant of the train (tests/variants.py) is a subclass named here, not an edit.
    TRAIN: ClassVar[type[Train]] = Train

    def __init__(self) -> None:
        super().__init__()
        self._cfg = (TrainConfig().with_timing(**self.TIMING).with_behaviour(**self.BEHAVIOUR)
                     .with_interlocks(**self.INTERLOCKS).with_environment(**self.ENVIRONMENT))
        self._train: Train | None = None
        self._kept_trace: list | None = None              # the trace of a train shut down

    # -- composition and life cycle ------------------------------------------------------------
    def configure(self, *, sets: int = 1, cars_per_set: int = 8) -> None:
        if self._train is not None:
            raise SutError("configure the composition before anything else is done to the train")
        self._cfg = TrainConfig(sets=sets, cars_per_set=cars_per_set, timing=self._cfg.timing,
                                behaviour=self._cfg.behaviour, interlocks=self._cfg.interlocks,
                                environment=self._cfg.environment)

    @property
    def train(self) -> Train:
        if self._train is None:
            self._train = self.TRAIN(self._cfg)
        return self._train

    def _power_on(self) -> None:
        self.train.start()

    def _shutdown(self) -> None:
        # A finished train is a web of cycles (every part knows its train) that only the cyclic collector
        # frees, and it walked the whole trace with it: after a long advance, millions of events and ~1 s
        # per full collection. The trace leaves the train (still read through this driver) and goes with
        # the driver by reference counting; what the collector finds is the small web of parts.
        if self._train is not None:
            self._kept_trace, self._train.events = self._train.events, []

    @property
    def now_us(self) -> int:
        return self.train.kernel.now

    def _advance(self, us: int) -> None:
        bulk.advance(self.train, self.train.kernel.now + us)        # steady periods skipped, trace and all

    # -- long runs -----------------------------------------------------------------------------
    def _soak(self, us: int, sample_every_us: int | None) -> None:
        bulk.soak(self.train, us, sample_every_us)

    def counters(self, node: str) -> dict[str, int]:
        counts = self._node(node).counters()
        mask = (1 << self._cfg.behaviour.counter_bits) - 1
        return {name: value & mask for name, value in counts.items()}

    # -- names ---------------------------------------------------------------------------------
    def _node(self, name: str) -> RingNode:
        for node in self.train.ring.nodes:
            if node.name == name:
                return node
        raise UnknownName("ring node", name, self.ring_nodes())

    def _all_boards(self) -> dict[str, Board]:
        t = self.train
        boards: dict[str, Board] = {"selfdiag": t.selfdiag.board}
        for node in t.ring.nodes:
            for short in ("CPU3", "MDM8", "MDM9", "TXC", "RXC"):
                b = node.board(short)
                if b is not None:
                    boards[f"{node.name}.{short}"] = b
            for part in (getattr(node, "txc", None), getattr(node, "rxc", None)):
                if part is not None:
                    boards[f"{part.name}.group1"] = part.group1
                    boards[f"{part.name}.group2"] = part.group2
        return boards

    def _board(self, name: str) -> Board:
        boards = self._all_boards()
        if name not in boards:
            raise UnknownName("board", name, boards)
        return boards[name]

    def _supply(self, name: str) -> PowerSupply:
        if name not in self.train.supplies:
            raise UnknownName("power supply", name, self.train.supplies)
        return self.train.supplies[name]

    def _span(self, a: str, b: str) -> Span:
        na, nb = self._node(a), self._node(b)
        span = self.train.ring.span_between(na, nb)
        if span is None:
            pairs = [f"{s.a.name}~{s.b.name}" for s in self.train.ring.spans]
            raise UnknownName("ring span", f"{a}~{b}", pairs)
        return span

    def _cab(self, cab: int):
        ccu = self.train.ccus.get(cab)
        if ccu is None:
            raise OutOfRange("cab car", cab, ", ".join(str(c) for c in sorted(self.train.ccus)))
        return ccu

    def _mark(self, source: str, kind: str, **fields: Any) -> None:
        self.train.emit(source, kind, **fields)

    # -- driver desk ---------------------------------------------------------------------------
    def insert_key(self, cab: int) -> None:
        ccu = self._cab(cab)
        ccu.desk.key = True
        others_up = any(c.desk.mcr for c in self.train.ccus.values() if c is not ccu)
        self._mark(f"car{cab}.desk", "desk.key", inserted=True)
        if not others_up or not self._cfg.behaviour.mcr_exclusive:   # ILK-07: only one cab's MCR picks up
            ccu.desk.mcr = True
            self._mark(f"car{cab}.desk", "mcr.up")
        ccu.mcr_changed()
        self.train.vehicle.desk_changed()

    def remove_key(self, cab: int) -> None:
        ccu = self._cab(cab)
        ccu.desk.key = False
        if ccu.desk.mcr:
            ccu.desk.mcr = False
            self._mark(f"car{cab}.desk", "mcr.down")
        self._mark(f"car{cab}.desk", "desk.key", inserted=False)
        ccu.mcr_changed()
        if self._cfg.behaviour.waiting_key_picks_up:                       # faulty variants only
            waiting = next((c for c in self.train.ccus.values() if c.desk.key and not c.desk.mcr), None)
            if waiting is not None and not any(c.desk.mcr for c in self.train.ccus.values()):
                waiting.desk.mcr = True
                self._mark(f"car{waiting.car}.desk", "mcr.up")
                waiting.mcr_changed()
        self.train.vehicle.desk_changed()

    def set_direction(self, cab: int, direction: str) -> None:
        self._cab(cab).desk.direction = self.check_direction(direction)
        self._mark(f"car{cab}.desk", "desk.direction", direction=direction)
        self.train.vehicle.desk_changed()

    def set_traction(self, cab: int, notch: int) -> None:
        if not (isinstance(notch, int) and 0 <= notch <= TRACTION_NOTCHES):
            raise OutOfRange("traction notch", notch, f"0..{TRACTION_NOTCHES}")
        self._cab(cab).desk.traction = notch
        self._mark(f"car{cab}.desk", "desk.traction", notch=notch)
        self.train.vehicle.desk_changed()

    def set_brake(self, cab: int, step: int) -> None:
        if not (isinstance(step, int) and 0 <= step <= EMERGENCY):
            raise OutOfRange("brake step", step, f"0..{BRAKE_STEPS} service, {EMERGENCY} emergency")
        self._cab(cab).desk.brake = step
        self._mark(f"car{cab}.desk", "desk.brake", step=step)
        self.train.vehicle.desk_changed()

    # -- faults --------------------------------------------------------------------------------
    def _set_span(self, span: Span, cut: bool) -> None:
        span.cut = cut
        self._mark(f"link.{span.name}", "fault.link", cut=cut)
        self.train.span_changed(span)

    def cut_link(self, a: str, b: str) -> None:
        self._set_span(self._span(a, b), True)

    def restore_link(self, a: str, b: str) -> None:
        self._set_span(self._span(a, b), False)

    def corrupt_frames(self, a: str, b: str, kind: str, count: int = 1) -> None:
        if kind not in FRAME_KINDS:
            raise UnknownName("frame kind", kind, FRAME_KINDS)
        if not isinstance(count, int) or count < 1:
            raise OutOfRange("frame count", count, ">= 1")
        span = self._span(a, b)
        key = (a, FRAME_KINDS[kind])
        span.corrupt[key] = span.corrupt.get(key, 0) + count
        self._mark(f"link.{span.name}", "fault.corrupt", frame=kind, count=count)

    def fail(self, board: str) -> None:
        b = self._board(board)
        self._mark(board, "fault.board", failed=True)
        b.set_failed(True)

    def repair(self, board: str) -> None:
        b = self._board(board)
        self._mark(board, "fault.board", failed=False)
        b.set_failed(False)

    def power_off(self, supply: str) -> None:
        s = self._supply(supply)
        self._mark(supply, "fault.power", on=False)
        s.set(False)

    def restore_power(self, supply: str) -> None:
        s = self._supply(supply)
        self._mark(supply, "fault.power", on=True)
        s.set(True)

    # -- the vehicle (ILK) ---------------------------------------------------------------------
    def set_input(self, name: str, value: Any) -> None:
        self.train.vehicle.set_input(name, value)

    def ramp_input(self, name: str, to: float, per_s: float) -> None:
        self.train.vehicle.ramp_input(name, to, per_s)

    def input(self, name: str) -> Any:
        return self.train.vehicle.input(name)

    def output(self, name: str) -> str:
        return self.train.vehicle.output(name)

    def reading(self, name: str) -> float:
        return self.train.vehicle.reading(name)

    def monitor_order(self, cab: int, name: str, value: str) -> None:
        ccu = self._cab(cab)
        allowed = self.train.vehicle.orderable(name)
        if allowed is None or name not in self.train.display.by_name:
            known = [n for n in self.train.display.by_name if self.train.vehicle.orderable(n)]
            raise UnknownName("equipment the monitor can order", name, known)
        if value not in allowed:
            raise OutOfRange(f"order for {name}", value, ", ".join(allowed))
        ccu.order(name, value)

    def vehicle_names(self) -> dict[str, list[str]]:
        v = self.train.vehicle
        return {"inputs": sorted(v.inputs_spec), "outputs": sorted(v.outputs)}

    # -- environment (hardware/software class, TST-02) -----------------------------------------
    @property
    def environment(self) -> TrainEnvironment:
        return self.train.environment

    def _env_supply(self, name: str) -> str:
        if name != TRAIN_SUPPLY and name not in self.train.supplies:
            raise UnknownName("power supply", name, [TRAIN_SUPPLY, *self.train.supplies])
        return name

    def _env_unit(self, name: str, whole_train: bool) -> str:
        if name == WHOLE_TRAIN and whole_train:
            return name
        if name not in self.environment.units:
            raise UnknownName("unit", name, [WHOLE_TRAIN, *self.environment.units] if whole_train
                              else self.environment.units)
        return name

    def _env_span(self, line: str) -> Span:
        a, sep, b = line.partition("~")
        if not sep:
            raise UnknownName("line", line, ["selfdiag"] + [s.name for s in self.train.ring.spans])
        return self._span(a.strip(), b.strip())

    @staticmethod
    def _env_number(what: str, value: Any, lo: float, hi: float, unit: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not lo <= value <= hi:
            raise OutOfRange(what, value, f"{lo:g} .. {hi:g} {unit}")
        return float(value)

    _env_us = staticmethod(TrainDriver.check_us)

    def rated_limits(self) -> dict[str, Any]:
        return self.environment.rated_limits()

    def set_supply_voltage(self, supply: str, volts: float) -> None:
        name = self._env_supply(supply)
        un = self._cfg.environment.nominal_v
        self.environment.set_voltage(name, self._env_number("supply voltage", volts, 0, 2 * un, "V"))

    def interrupt_supply(self, supply: str, duration_us: int) -> None:
        name = self._env_supply(supply)
        self.environment.interrupt(name, self._env_us("interruption", duration_us))

    def set_temperature(self, unit: str, celsius: float) -> None:
        name = self._env_unit(unit, whole_train=True)
        self.environment.set_temperature(name, self._env_number("temperature", celsius, -60, 125, "degC"))

    def interfere(self, line: str, level_kv: float, duration_us: int) -> None:
        span = None if line == "selfdiag" else self._env_span(line)
        level = self._env_number("burst level", level_kv, 0.1, 8, "kV")
        self.environment.burst(span, level, self._env_us("burst duration", duration_us))

    def vibrate(self, connector: str, interruption_us: int, count: int, period_us: int) -> None:
        length = self._env_us("contact interruption", interruption_us)
        if isinstance(count, bool) or not isinstance(count, int) or count < 1:
            raise OutOfRange("number of contact interruptions", count, ">= 1")
        period = self._env_us("interruption period", period_us, lo=length + 1)
        if "~" in connector:
            self.environment.vibrate_link(self._env_span(connector), length, count, period)
        else:
            self.environment.vibrate_supply(self._env_supply(connector), length, count, period)

    def withstand_test(self, unit: str, volts_rms: float, duration_us: int) -> None:
        name = self._env_unit(unit, whole_train=False)
        volts = self._env_number("test voltage", volts_rms, 100, 10_000, "V rms")
        self.environment.withstand_test(name, volts, self._env_us("test duration", duration_us))

    def insulation_resistance(self, unit: str) -> float:
        return self.environment.insulation_mohm(self._env_unit(unit, whole_train=False))

    # -- traffic -------------------------------------------------------------------------------
    def request_block_transfer(self, node: str, data: bytes) -> None:
        if not data:
            raise OutOfRange("block record size", 0, ">= 1 byte")
        self._node(node).queue_record(bytes(data))

    def tap_link(self, a: str, b: str) -> None:
        self._span(a, b).tapped = True

    # -- observations --------------------------------------------------------------------------
    @property
    def trace(self) -> Trace:
        return self._trace_view(self._kept_trace if self._kept_trace is not None else self.train.events)

    def ring_nodes(self) -> list[str]:
        return [n.name for n in self.train.ring.nodes]

    def supplies(self) -> list[str]:
        return list(self.train.supplies)

    def boards(self, unit: str) -> list[str]:
        node = self._node(unit)
        return [short for short in ("CPU3", "MDM8", "MDM9", "TXC", "RXC") if node.board(short) is not None]

    def devices(self, car: int) -> list[str]:
        for lcu in self.train.lcus:
            if lcu.car == car:
                return sorted([d.name for d in lcu.command_devices] + [d.name for d in lcu.loop_devices])
        raise OutOfRange("car", car, f"1..{self._cfg.cars}")

    def token_holder(self) -> list[str]:
        return [n.name for n in self.train.ring.nodes if n.has_token]

    def monitor(self, cab: int) -> dict[str, Any]:
        view = self._screen(cab)
        view["maintenance"] = self._fault_history()
        return view

    def _monitor_faults(self, cab: int) -> list[str]:
        # A watch looks a thousand times a second: the screen alone, not the maintenance view.
        return self._screen(cab)["faults"]

    def _screen(self, cab: int) -> dict[str, Any]:
        view = self._cab(cab).monitor_view(stale_us=self._cfg.timing.token_loss_us)
        view["faults"] = sorted(view["faults"] + self.train.vehicle.monitor_alarms())
        return view

    def _fault_history(self) -> list[str]:
        """The maintenance view: fault records held at the master, oldest first (docs/decisions.md)."""
        entries = []
        for records in self.train.records().values():
            for record in records:
                text = record.rstrip(b"\0").decode("ascii", "replace")
                if text.startswith("F|"):
                    _, t_ms, node, board, event = text.split("|")
                    entries.append((int(t_ms), f"{t_ms} ms {node}.{board} {event}"))
        return [line for _, line in sorted(entries)]

    def status_table(self, node: str) -> dict[str, int | None]:
        me = self._node(node)
        now = self.now_us
        return {n.name: (None if n.number not in me.heard else now - me.heard[n.number])
                for n in self.train.ring.nodes if n is not me}

    def lamp(self, cab: int, name: str) -> bool:
        lamps = self._cab(cab).lamps
        if name not in lamps:
            raise UnknownName("cab lamp", name, lamps)
        return lamps[name]

    def block_store(self, node: str) -> dict[str, list[bytes]]:
        me = self._node(node)
        if me is not self.train.block_master():
            return {}
        return self.train.records()

    def describe(self) -> dict[str, str]:
        out = {"SUT backend": self.backend_name, "SUT class": f"{type(self).__module__}.{type(self).__qualname__}",
               "profile": "crh2", "ring nodes": str(len(self.train.ring.nodes))}
        out.update(self._cfg.describe())
        return out
