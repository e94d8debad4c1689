"""The metro TCDS reference (profile `metro-tcn`) behind the driver interface.

Names: units `car1.CCU`, `car2.VCU`..`car5.VCU`, `car6.CCU` and their boards (`car1.CCU.VMS`); MVB I/O
modules `car1.IO1`, `car1.IO2`, `car6.IO1`, `car6.IO2`; devices `carN.VVVF|BECU|APU|VATC|DU`; buses `WTB`,
`unit1.MVB`, `unit2.MVB`, lines `A`/`B`. The desk of cab 1 or 6: key, direction, master controller
traction and brake in % (AI1, AI2 of both I/O modules of the cab car).
Inputs (`set_input`): `speed` (km/h), `emergency operation` (the hard-wired switch, bool), and a wiring
fault on one module's input, `car1.IO2.AI1` / `car1.IO2.DI02` (raw value, until set to None).
Readings: `speed`, `car2.VVVF.traction` and `car3.BECU.brake` (% applied).

Not modelled: vehicle dynamics beyond braking (traction does not accelerate the train), RS-485 devices,
inauguration of the WTB (the composition is fixed), message data on the MVB.
"""
from __future__ import annotations

from typing import Any, ClassVar

from sut.driver import TrainDriver
from sut.snapshot import PickledState
from sut.errors import OutOfRange, UnknownName
from sut.reference import bulk
from sut.reference.metro.bus import LINES
from sut.reference.metro.config import MetroConfig
from sut.reference.metro.tcds import MetroTrain
from sut.reference.metro.units import CAB_CARS
from sut.trace import Trace

BUSES = ("WTB", "unit1.MVB", "unit2.MVB")
INPUT_NAMES = ("speed", "emergency operation")


class ReferenceMetro(PickledState, TrainDriver):
    backend_name = "reference"
    PROFILES = ("metro-tcn",)
    DETERMINISTIC = True           # virtual time, no randomness, nothing outside the model
    DECLARATION = "sut/reference/declaration.yaml"
    TIMING: ClassVar[dict[str, Any]] = {}
    BEHAVIOUR: ClassVar[dict[str, Any]] = {}

    def __init__(self) -> None:
        super().__init__()
        self._train = MetroTrain(MetroConfig().with_timing(**self.TIMING).with_behaviour(**self.BEHAVIOUR))
        self._kept_trace: list | None = None              # the trace of a train shut down

    # -- life cycle and time -----------------------------------------------------------------
    def configure(self, *, sets: int = 1, cars_per_set: int = 6) -> None:
        if (sets, cars_per_set) != (1, 6):
            raise OutOfRange("metro composition", f"{sets} x {cars_per_set} cars", "one train of 6 cars (TCN-02)")

    def _power_on(self) -> None:
        self._train.start()

    def _shutdown(self) -> None:
        # As ReferenceTrain._shutdown: the trace goes by reference counting, not with the train's cycles.
        self._kept_trace, self._train.events = self._train.events, []

    @property
    def now_us(self) -> int:
        return self._train.kernel.now

    def _advance(self, us: int) -> None:
        bulk.advance(self._train, self._train.kernel.now + us)      # steady periods skipped, trace and all

    def _soak(self, us: int, sample_every_us: int | None) -> None:
        bulk.soak(self._train, us, sample_every_us)

    @property
    def trace(self) -> Trace:
        return self._trace_view(self._kept_trace if self._kept_trace is not None else self._train.events)

    def _mark(self, source: str, kind: str, **fields: Any) -> None:
        self._train.emit(source, kind, **fields)

    # -- desk ------------------------------------------------------------------------------------
    def _desk(self, cab: int) -> dict:
        if cab not in CAB_CARS:
            raise OutOfRange("cab", cab, "1 or 6 (the cab cars of a metro train)")
        return self._train.desk[cab]

    # Every desk input refreshes what the drives apply, as traction and brake do: in emergency operation the
    # desk acts through hard wires (TCN-09), so a key taken out or a direction switch at neutral acts at once.
    def insert_key(self, cab: int) -> None:
        self._desk(cab)["key"] = True
        self._mark(f"car{cab}.desk", "desk.key", inserted=True)
        self._train.refresh_outputs()

    def remove_key(self, cab: int) -> None:
        self._desk(cab)["key"] = False
        self._mark(f"car{cab}.desk", "desk.key", inserted=False)
        self._train.refresh_outputs()

    def set_direction(self, cab: int, direction: str) -> None:
        self._desk(cab)["direction"] = self.check_direction(direction)
        self._mark(f"car{cab}.desk", "desk.direction", value=direction)
        self._train.refresh_outputs()

    def set_traction(self, cab: int, notch: int) -> None:
        """Master controller traction demand in % (0-100)."""
        self._desk(cab)["traction"] = self._percent("traction demand", notch)
        self._mark(f"car{cab}.desk", "desk.traction", value=notch)
        self._train.refresh_outputs()

    def set_brake(self, cab: int, step: int) -> None:
        """Master controller brake demand in % (0-100)."""
        self._desk(cab)["brake"] = self._percent("brake demand", step)
        self._mark(f"car{cab}.desk", "desk.brake", value=step)
        self._train.refresh_outputs()

    @staticmethod
    def _percent(what: str, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 100:
            raise OutOfRange(what, value, "a whole percentage 0-100")
        return value

    # -- inputs, readings ------------------------------------------------------------------------
    def set_input(self, name: str, value: Any) -> None:
        train = self._train
        if name == "speed":
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value <= 120:
                raise OutOfRange("speed", value, "0-120 km/h")
            train.speed_kmh = float(value)
        elif name == "emergency operation":
            if not isinstance(value, bool):
                raise OutOfRange("emergency operation switch", value, "on (True) or off (False)")
            train.emergency_switch = value
            if not value and train.emergency_mode:
                train.emergency_mode = False
                self._train.refresh_outputs()
        else:
            module, _, channel = name.rpartition(".")
            if module not in train.ios:
                raise UnknownName("vehicle input", name, [*INPUT_NAMES, "car1.IO2.AI1", "car1.IO2.DI02"])
            if not (channel[:2] in ("DI", "AI") and channel[2:].isdigit()
                    and 1 <= int(channel[2:]) <= (28 if channel[:2] == "DI" else 3)):
                raise OutOfRange(f"input channel of {module}", channel, "DI01-DI28 or AI1-AI3 (TCN-07)")
            top = 1 if channel[:2] == "DI" else 65535
            if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= top:
                raise OutOfRange(f"raw value of {name}", value, f"0-{top} (a whole count)")
            train.ios[module].forced[channel] = value
        self._mark("train", "in.set", name=name, value=value)

    def input(self, name: str) -> Any:
        if name == "speed":
            return self._train.speed_kmh
        if name == "emergency operation":
            return self._train.emergency_switch
        raise UnknownName("vehicle input", name, INPUT_NAMES)

    def reading(self, name: str) -> float:
        if name == "speed":
            return round(self._train.speed_kmh, 3)
        device, _, quantity = name.rpartition(".")
        dev = self._train.devices.get(device)
        wanted = {"VVVF": "traction", "BECU": "brake"}.get(dev.kind) if dev else None
        if wanted is None or quantity != wanted:
            known = ["speed"] + [f"{d.name}.{'traction' if d.kind == 'VVVF' else 'brake'}"
                                 for d in self._train.devices.values() if d.sink]
            raise UnknownName("reading", name, known)
        return dev.applied / 100

    # -- faults ----------------------------------------------------------------------------------
    def _thing(self, name: str) -> tuple[Any, str | None]:
        train = self._train
        for table in (train.nodes, train.ios, train.devices):
            if name in table:
                return table[name], None
        unit, _, board = name.rpartition(".")
        if unit in train.nodes and board in train.nodes[unit].boards:
            return train.nodes[unit], board
        known = [*train.nodes, *train.ios, *train.devices,
                 *(f"{n}.{b}" for n, u in train.nodes.items() for b in u.boards)]
        raise UnknownName("unit, module, device or board", name, known)

    def fail(self, board: str) -> None:
        thing, part = self._thing(board)
        if part is not None:
            thing.failed_boards.add(part)
        elif board in self._train.ios:
            self._train.fail_io(thing)
        else:
            thing.failed = True
        self._mark(board, "fault.fail")
        self._train.refresh_outputs()

    def repair(self, board: str) -> None:
        thing, part = self._thing(board)
        if part is not None:
            thing.failed_boards.discard(part)
        else:
            thing.failed = False
        self._mark(board, "fault.repair")
        self._train.refresh_outputs()

    def _line(self, bus: str, line: str):
        if bus not in BUSES:
            raise UnknownName("bus", bus, BUSES)
        if line not in LINES:
            raise OutOfRange(f"line of {bus}", line, "A or B (RED-06)")
        return self._train.wtb if bus == "WTB" else self._train.segments[int(bus[4])].bus

    def cut_line(self, bus: str, line: str) -> None:
        self._line(bus, line).lines[line].cut = True
        self._mark(f"{bus}.{line}", "fault.cut")

    def restore_line(self, bus: str, line: str) -> None:
        self._line(bus, line).lines[line].cut = False
        self._mark(f"{bus}.{line}", "fault.restore")

    def disturb_line(self, bus: str, line: str, count: int = 1) -> None:
        if isinstance(count, bool) or not isinstance(count, int) or count < 1:
            raise OutOfRange("frames to disturb", count, "a whole number >= 1")
        self._line(bus, line).lines[line].disturb += count
        self._mark(f"{bus}.{line}", "fault.disturb", count=count)

    def tap_bus(self, bus: str) -> None:
        """Attach an analyser: every frame on `bus` appears in the trace as `bus.frame` (hex body)."""
        self._line(bus, "A")
        self._train.tapped.add(bus)

    # -- observations ----------------------------------------------------------------------------
    def records(self, unit: str) -> list[str]:
        node = self._train.nodes.get(unit)
        if node is None:
            raise UnknownName("CCU or VCU", unit, self._train.nodes)
        return [str(r) for r in node.store]

    def boards(self, unit: str) -> list[str]:
        node = self._train.nodes.get(unit)
        if node is None:
            raise UnknownName("CCU or VCU", unit, self._train.nodes)
        return list(node.boards)

    def devices(self, car: int) -> list[str]:
        if car not in range(1, 7):
            raise OutOfRange("car", car, "1-6 (TCN-02)")
        train = self._train
        return [n for n in (*train.nodes, *train.ios, *train.devices) if n.startswith(f"car{car}.")]

    def monitor(self, cab: int) -> dict[str, Any]:
        """The display unit (DU) of cab 1 or 6: what its unit's MVB master knows, the mode, the WTB master."""
        self._desk(cab)
        train = self._train
        seg = train.segments[1 if cab == 1 else 2]
        du = train.devices[f"car{cab}.DU"]
        master = train.nodes[seg.master]
        # The DU hears the train only through its unit's bus master (TCN-04): with that master silent it has
        # nothing current to show (docs/decisions.md, "A display whose bus master is silent").
        if du.failed or not master.alive:
            return {"faults": [], "mode": None, "WTB master": None, "blank": True}
        # A lit display says nothing of `blank` (the contract: absent or true only on a dark one).
        return {"faults": [r.text if r.origin == master.name else f"{r.origin}: {r.text}" for r in master.known],
                "mode": train.modes[seg.unit], "WTB master": train.wtb_master}

    def describe(self) -> dict[str, str]:
        t = self._train.cfg.timing
        return {"SUT backend": self.backend_name, "SUT class": f"{type(self).__module__}.{type(self).__qualname__}",
                "profile": "metro-tcn",
                "cars": "6 (2 units of 3: Tc-M-M + M-M-Tc)",
                "WTB": f"1 Mbit/s, cycle {t.wtb_cycle_us / 1000:g} ms",
                "MVB": f"1.5 Mbit/s, basic period {t.mvb_basic_period_us / 1000:g} ms"}
