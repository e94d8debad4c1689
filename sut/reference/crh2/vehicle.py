"""The vehicle around the network: brake loop, doors, main circuit, neutral-section passing, traction
permission (ILK-01..08, S0 §3).

Everything the test engineer can set is a named *input*, everything the train shows is a named *output*;
`CATALOGUE` below is the single list of both, with allowed values, so a wrong name or an out-of-range
value fails loudly. Outputs are re-evaluated after every input change and every 1 ms step of a ramp; each
change is one `out.change` trace event carrying the speed and main-pipe pressure of that instant, which
is what a band test reads (did the valve drop between 600 and 580 kPa?).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from sut.errors import OutOfRange, UnknownName

if TYPE_CHECKING:
    from sut.reference.crh2.config import Interlocks
    from sut.reference.kernel import Timer
    from sut.reference.crh2.context import TrainContext

MS = 1000
TRANSFORMER_STATES = ("normal", "primary overcurrent", "secondary overcurrent", "tertiary overcurrent",
                      "secondary earth fault", "tertiary earth fault")
OVERCURRENTS = TRANSFORMER_STATES[1:4]


@dataclass(frozen=True)
class Spec:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    kind: str                              # "number" or "choice"
    allowed: tuple = ()
    low: float = 0.0
    high: float = 0.0
    unit: str = ""
    initial: Any = None

    def check(self, name: str, value: Any) -> Any:
        if self.kind == "number":
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not self.low <= value <= self.high:
                raise OutOfRange(name, value, f"{self.low:g}..{self.high:g} {self.unit}".strip())
            return float(value)
        if value not in self.allowed:
            raise OutOfRange(name, value, ", ".join(map(str, self.allowed)))
        return value


def catalogue(cars: int, units: int) -> tuple[dict[str, Spec], dict[str, tuple]]:
    """(inputs, outputs) of a train of `cars` cars in `units` traction units."""
    inputs: dict[str, Spec] = {
        "speed": Spec("number", low=0, high=400, unit="km/h", initial=0.0),
        "main pipe pressure": Spec("number", low=0, high=1000, unit="kPa", initial=780.0),
        "doors": Spec("choice", ("closed", "open"), initial="closed"),
        "door bypass": Spec("choice", ("off", "on"), initial="off"),
        "ATP brake": Spec("choice", ("none", "service", "emergency"), initial="none"),
        "neutral section signal": Spec("choice", ("warning", "entry", "exit")),
        "neutral section device": Spec("choice", ("normal", "severe fault", "warning signal fault"),
                                       initial="normal"),
        "neutral section restore": Spec("choice", ("manual restore",)),
        "main circuit reset": Spec("choice", ("reset",)),
    }
    for car in range(1, cars + 1):
        inputs[f"car{car}.brake force"] = Spec("number", low=0, high=150, unit="% of demand", initial=100.0)
    for car in range(1, cars):
        inputs[f"coupler car{car}~car{car + 1}"] = Spec("choice", ("coupled", "separated"), initial="coupled")
    outputs = {
        "EB valve": ("energised", "de-energised"),
        "rapid-brake valve": ("energised", "de-energised"),
        "emergency brake": ("released", "applied"),
        "rapid brake": ("not commanded", "commanded"),
        "press-seal valve": ("de-energised", "energised"),
        "door-open relay": ("released", "acting"),
        "doors": ("closed", "open"),
        "traction": ("permitted", "blocked"),
        "neutral section": ("idle", "warned", "passing", "awaiting manual entry", "awaiting manual restore",
                            "manual passing"),
    }
    outputs["compressor"] = ("stopped", "running")
    outputs["passenger information"] = ("none", "next station", "welcome aboard")
    for unit in range(1, units + 1):       # each traction unit's main circuit: what it senses, what it drives
        inputs[f"unit{unit}.transformer"] = Spec("choice", TRANSFORMER_STATES, initial="normal")
        inputs[f"unit{unit}.oil pump"] = Spec("choice", ("running", "stopped"), initial="running")
        inputs[f"unit{unit}.oil temperature"] = Spec("choice", ("normal", "over-temperature"), initial="normal")
        outputs[f"unit{unit}.VCB"] = ("closed", "open")
        outputs[f"unit{unit}.pantograph"] = ("up", "down")
        outputs[f"unit{unit}.auxiliary supply"] = ("own", "extended", "none")
    for car in range(1, cars + 1):
        outputs[f"car{car}.air conditioning"] = ("on", "off")
        outputs[f"car{car}.lighting"] = ("on", "off")
    return inputs, outputs


# Outputs the driver can order from the cab monitor (service equipment and remote control), with the
# state each order sets; everything else only follows the train.
ORDERS = {
    "VCB": ("closed", "open"),
    "pantograph": ("up", "down"),
    "CI cut-out": ("in", "cut out"),
    "air conditioning": ("on", "off"),
    "lighting": ("on", "off"),
    "passenger information": ("none", "next station", "welcome aboard"),
}


# The odometer's unit: a speed in km/h is a binary float, an exact integer once scaled by 2**ODO_BITS (every
# speed the steps and ramps give, whose last bit is worth at least 2**-ODO_BITS km/h), and a distance is speed
# x time, summed as (start + end) x us for each piece: 2 x 3.6e9 x 2**ODO_BITS of them make a kilometre.
ODO_BITS = 80
ODO_PER_KM = 2 * 3_600_000_000 << ODO_BITS


def _fixed(speed: float) -> int:
    """The speed in km/h / 2**ODO_BITS: exact for every speed of that resolution, nearest otherwise."""
    num, den = float(speed).as_integer_ratio()
    shift = ODO_BITS - (den.bit_length() - 1)
    return num << shift if shift >= 0 else (2 * (num << ODO_BITS) + den) // (2 * den)


class Vehicle:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, train: "TrainContext"):
        self.train = train
        self.kernel = train.kernel
        self.cfg: Interlocks = train.cfg.interlocks
        per = train.cfg.cars_per_set
        self.units = {u + 1: [c for c in range(u * per // 2 + 1, (u + 1) * per // 2 + 1)]
                      for u in range(train.cfg.sets * 2)}
        self.inputs_spec, self.outputs_spec = catalogue(train.cfg.cars, len(self.units))
        for car in train.cfg.motor_cars():
            self.outputs_spec[f"car{car}.CI contactor"] = ("closed", "open")
            self.outputs_spec[f"car{car}.CI gates"] = ("enabled", "blocked")
            self.outputs_spec[f"car{car}.CI cut-out"] = ("in", "cut out")
        self.ordered: dict[str, str] = {}          # equipment states ordered from the monitor
        self.compressor = False
        # The distance run up to _odo_t, exactly, in odometer units (ODO_PER_KM to the km): the mileage the monitor
        # shows in whole metres then moves by the same number of them every few steady periods of a cruise, which
        # a float summed step by step does not (Train.bulk_period_us).
        self._odo_units = 0
        self._odo_t = 0
        self._odo_v = 0.0
        self.inputs: dict[str, Any] = {k: s.initial for k, s in self.inputs_spec.items() if s.initial is not None}
        self.outputs: dict[str, str] = {}
        self._pending_outputs: dict[str, str] = {}   # changes on their way (Behaviour.output_delay_us)
        self._ramps: dict[str, "Timer"] = {}
        # latched states
        self.pipe_tripped = False
        self.brake_force_low = False
        self._force_timer: "Timer | None" = None
        self.seal = False
        self.unit_faults: dict[int, set[str]] = {u: set() for u in self.units}
        self.ns_phase = "idle"
        self._ns_timer: "Timer | None" = None
        self.ns_vcb_open = False
        # The names _evaluate reads and writes on every call (every millisecond of a ramp): built once.
        self._couplers = [k for k in self.inputs if k.startswith("coupler ")]
        self._forces = [k for k in self.inputs if k.endswith(".brake force")]
        self._car_names = [(f"car{car}.air conditioning", f"car{car}.lighting")
                           for car in range(1, train.cfg.cars + 1)]
        self._unit_names = {u: (f"unit{u}.VCB", f"unit{u}.pantograph", f"unit{u}.auxiliary supply")
                            for u in self.units}
        self._ci_names = {u: [(f"car{car}.CI contactor", f"car{car}.CI cut-out", f"car{car}.CI gates")
                              for car in cars if f"car{car}.CI contactor" in self.outputs_spec]
                          for u, cars in self.units.items()}
        self._evaluate(initial=True)

    # -- the interface the driver uses ----------------------------------------------------------
    def set_input(self, name: str, value: Any) -> None:
        spec = self._spec(name)
        value = spec.check(name, value)
        self._cancel_ramp(name)
        self.train.emit("vehicle", "in.set", name=name, value=value)
        self._apply(name, value)

    def ramp_input(self, name: str, to: float, per_s: float) -> None:
        spec = self._spec(name)
        if spec.kind != "number":
            raise OutOfRange(f"ramp of {name}", to, "only numeric inputs ramp")
        to = spec.check(name, to)
        if not (isinstance(per_s, (int, float)) and per_s > 0):
            raise OutOfRange("ramp rate", per_s, f"> 0 {spec.unit}/s")
        self._cancel_ramp(name)
        self.train.emit("vehicle", "in.ramp", name=name, frm=self.inputs[name], to=to, per_s=per_s)
        step = per_s / 1000.0                     # per millisecond
        self._ramps[name] = self.kernel.call_later(MS, self._ramp_tick, name, to, step)

    def _ramp_tick(self, name: str, to: float, step: float) -> None:
        # A method with arguments, not a closure: a pending timer must pickle (sut/snapshot.py).
        now = self.inputs[name]
        nxt = min(to, now + step) if to > now else max(to, now - step)
        if name == "speed":
            self._odometer(nxt, linear=True)
        self.inputs[name] = round(nxt, 6)
        self._evaluate()
        if nxt != to:
            self._ramps[name] = self.kernel.call_later(MS, self._ramp_tick, name, to, step)
        else:
            self._ramps.pop(name, None)

    def output(self, name: str) -> str:
        if name not in self.outputs:
            raise UnknownName("vehicle output", name, self.outputs)
        return self.outputs[name]

    def announce(self) -> None:
        """At power-up every output is stated once, so the trace says where each one started."""
        inp = self.inputs
        # The governor starts from the pressure it measures at power-up: the pressures a rig sets before that (the
        # catalogue's initial 780 kPa sits on its start point) are no history of a train that was off.
        p_read = inp["main pipe pressure"] + self.train.cfg.behaviour.pressure_read_kpa
        self.compressor = p_read < self.cfg.compressor_start_kpa
        self.outputs["compressor"] = "running" if self.compressor else "stopped"
        for name, value in self.outputs.items():
            self.train.emit(name, "out.change", value=value, speed=inp["speed"], pressure=inp["main pipe pressure"])

    def desk_changed(self) -> None:
        self._evaluate()

    def input(self, name: str) -> Any:
        self._spec(name)
        return self.inputs.get(name)

    # -- inputs that are events rather than levels ----------------------------------------------
    def _apply(self, name: str, value: Any) -> None:
        if name == "neutral section signal":
            self._ns_signal(value)
        elif name == "neutral section restore":
            self._ns_restore()
        elif name == "main circuit reset":
            self._main_circuit_reset()
        else:
            if name == "speed":
                self._odometer(value, linear=False)
            self.inputs[name] = value
            resets_after = self.train.cfg.behaviour.protection_self_reset_us
            if resets_after is not None and name.endswith(".transformer") and value == "normal":
                # faulty variants only: the driver's reset, made by the train itself
                self.kernel.call_later(resets_after, self._apply, "main circuit reset", "reset")
        self._evaluate()

    # -- mileage: speed integrated exactly over piecewise-constant and linear pieces -------------
    def _odometer(self, new_speed: float, linear: bool) -> None:
        now = self.kernel.now
        start = self._odo_v
        end = new_speed if linear else start
        # (start + end) / 2 km/h for (now - _odo_t) us, in odometer units (half a km/h x us, over 2**ODO_BITS)
        self._odo_units += (_fixed(start) + _fixed(end)) * (now - self._odo_t)
        self._odo_t, self._odo_v = now, new_speed

    def _units_now(self) -> int:
        return self._odo_units + 2 * _fixed(self._odo_v) * (self.kernel.now - self._odo_t)

    def mileage_in(self, per_km: int) -> int:
        """The mileage now in whole 1/per_km km, to the nearest, a half up (the display point's whole metres)."""
        return (2 * self._units_now() * per_km + ODO_PER_KM) // (2 * ODO_PER_KM)

    def periods_to_repeat(self, period_us: int, per_km: int) -> int:
        """The fewest periods of `period_us` in which the train, at the speed it has now, runs a whole number of
        1/per_km km."""
        run, whole = _fixed(self._odo_v) * period_us * per_km, 3_600_000_000 << ODO_BITS
        return whole // math.gcd(run, whole)

    def reading(self, name: str) -> float:
        """Numeric readings: speed (km/h), main pipe pressure (kPa), mileage (km)."""
        if name == "mileage":
            return self._units_now() / ODO_PER_KM          # the exact quotient, rounded once
        if name in ("speed", "main pipe pressure"):
            return float(self.inputs[name])
        raise UnknownName("reading", name, ("speed", "main pipe pressure", "mileage"))

    def apply_order(self, name: str, value: str) -> None:
        if self.ordered.get(name) != value:
            self.ordered[name] = value
            self.train.emit("vehicle", "order.applied", name=name, value=value)
            self._evaluate()

    @staticmethod
    def orderable(name: str) -> tuple[str, ...] | None:
        return ORDERS.get(name.split(".", 1)[-1]) or ORDERS.get(name)

    def _spec(self, name: str) -> Spec:
        if name not in self.inputs_spec:
            raise UnknownName("vehicle input", name, self.inputs_spec)
        return self.inputs_spec[name]

    def _cancel_ramp(self, name: str) -> None:
        timer = self._ramps.pop(name, None)
        if timer is not None:
            timer.cancel()

    # -- the interlock logic --------------------------------------------------------------------
    def _evaluate(self, initial: bool = False) -> None:
        cfg, inp = self.cfg, self.inputs
        pressure, speed = inp["main pipe pressure"], inp["speed"]   # as set: what each out.change carries
        b = self.train.cfg.behaviour
        # What the interlocks measure: the pressure and speed as set, but in a freedom variant whose transducers
        # read off (by no more than the accuracy it declares).
        p_read, v_read = pressure + b.pressure_read_kpa, speed + b.speed_read_kmh
        # ILK-02 with hysteresis
        if not self.pipe_tripped and p_read < cfg.pipe_trip_kpa:
            self.pipe_tripped = True
        elif self.pipe_tripped and p_read >= cfg.pipe_reset_kpa:
            self.pipe_tripped = False
        separated = any(inp[k] == "separated" for k in self._couplers)
        self._supervise_brake_force()
        safety_trip = separated or self.pipe_tripped or self.brake_force_low          # ILK-01..03
        rapid = safety_trip if b.separation_trips_rapid else (self.pipe_tripped or self.brake_force_low)
        driver_eb = self._handle_brake() >= 8
        atp = inp["ATP brake"]
        eb_loop_open = safety_trip or driver_eb or atp == "emergency"
        # ILK-05: the doors can open only while the door-open relay acts (below 5 km/h, where the seal is long
        # off); the seal follows the doors as they are now, not as they were: doors left open at standstill
        # and the train set to 40 km/h close and are sealed in the same instant.
        relay = v_read < cfg.door_relay_kmh
        doors_open = inp["doors"] == "open" and relay
        if self.seal and (v_read < cfg.seal_off_kmh or doors_open):
            self.seal = False
        elif not self.seal and v_read > cfg.seal_on_kmh and not doors_open:
            self.seal = True
        doors = "open" if doors_open and not self.seal else "closed"
        # ILK-06
        for u in self.units:
            self._unit_protection(u)
        order = self.ordered.get
        unit_names = self._unit_names
        vcb_open = {u: "vcb" in self.unit_faults[u] or self.ns_vcb_open
                    or order(unit_names[u][0]) == "open" or order(unit_names[u][1]) == "down"
                    for u in self.units}
        # compressor governor (docs/decisions.md): start below 780 kPa, stop at 880 kPa
        if not self.compressor and p_read < cfg.compressor_start_kpa:
            self.compressor = True
        elif self.compressor and p_read >= cfg.compressor_stop_kpa:
            self.compressor = False
        out = {
            "EB valve": "de-energised" if eb_loop_open else "energised",
            "rapid-brake valve": "de-energised" if rapid else "energised",
            "emergency brake": "applied" if eb_loop_open else "released",
            "rapid brake": "commanded" if rapid else "not commanded",
            "press-seal valve": "energised" if self.seal else "de-energised",
            "door-open relay": "acting" if relay else "released",
            "doors": doors,
            "neutral section": self.ns_phase,
            "compressor": "running" if self.compressor else "stopped",
            "passenger information": order("passenger information", "none"),
        }
        for air, light in self._car_names:
            out[air] = order(air, "on")
            out[light] = order(light, "on")
        for u in self.units:
            vcb, pantograph, auxiliary = unit_names[u]
            out[vcb] = "open" if vcb_open[u] else "closed"
            out[pantograph] = order(pantograph, "up")
            # tertiary supply switching: a unit whose VCB is open takes its auxiliary supply from a unit
            # whose VCB is closed (the extension supply), if there is one
            others = [o for o in self.units if o != u and not vcb_open[o]]
            out[auxiliary] = "own" if not vcb_open[u] else ("extended" if others else "none")
        for u in self.units:
            for contactor, cut_out_name, gates in self._ci_names[u]:
                cut_out = order(cut_out_name, "in") == "cut out"
                out[cut_out_name] = "cut out" if cut_out else "in"
                cut = "converter" in self.unit_faults[u] or vcb_open[u] or cut_out
                out[contactor] = "open" if cut else "closed"
                out[gates] = "blocked" if cut else "enabled"
        out["traction"] = "permitted" if self._permitted(eb_loop_open, rapid, doors) else "blocked"
        hooks = self.train.cfg.behaviour
        for name, value in (reversed(out.items()) if hooks.outputs_logged_last_first else out.items()):
            if hooks.output_delay_us and not initial:
                if self._pending_outputs.get(name, self.outputs.get(name)) != value:
                    self._pending_outputs[name] = value
                    self.kernel.call_later(hooks.output_delay_us, self._set_late, name, value)
                continue
            if self.outputs.get(name) != value:
                self.outputs[name] = value
                if initial:
                    continue
                if hooks.rapid_brake_delay_us and name in ("rapid-brake valve", "rapid brake"):
                    self.kernel.call_later(hooks.rapid_brake_delay_us, self._log_change, name, value, speed, pressure)
                else:
                    self.train.emit(name, "out.change", value=value, speed=speed, pressure=pressure)

    def _set_late(self, name: str, value: str) -> None:
        # The change is logged with the speed and pressure of the instant the output really changes.
        if self._pending_outputs.get(name) == value:
            del self._pending_outputs[name]
        if self.outputs.get(name) != value:
            self.outputs[name] = value
            inp = self.inputs
            self.train.emit(name, "out.change", value=value, speed=inp["speed"], pressure=inp["main pipe pressure"])

    def _log_change(self, name: str, value: str, speed: float, pressure: float) -> None:
        self.train.emit(name, "out.change", value=value, speed=speed, pressure=pressure)

    def _handle_brake(self) -> int:
        ccu = self.train.commanding_ccu()
        return ccu.desk.brake if ccu else 0

    # ILK-03: brake force supervision
    def _supervise_brake_force(self) -> None:
        demand = self._handle_brake() > 0 or self.inputs["ATP brake"] != "none"
        if self.train.cfg.behaviour.brake_force_handle_only:                          # faulty variants only
            demand = self._handle_brake() > 0
        inputs, least = self.inputs, self.cfg.brake_force_min_pct
        weak = demand and any(inputs[k] < least for k in self._forces)
        if weak and self._force_timer is None and not self.brake_force_low:
            self._force_timer = self.kernel.call_later(self.cfg.brake_force_detect_us, self._brake_force_low)
        elif not weak and self._force_timer is not None:
            self._force_timer.cancel()
            self._force_timer = None

    def _brake_force_low(self) -> None:
        self._force_timer = None
        self.brake_force_low = True            # latched: the emergency brake holds until the train stops
        self.train.emit("vehicle", "brake.force_low")
        self._evaluate()
        clears_after = self.train.cfg.behaviour.brake_force_trip_clears_us
        if clears_after is not None:                                                  # faulty variants only
            self.kernel.call_later(clears_after, self._brake_force_trip_clears)

    def _brake_force_trip_clears(self) -> None:
        self.brake_force_low = False
        self._evaluate()

    # ILK-06: transformer, oil pump, oil temperature
    def _unit_protection(self, unit: int) -> None:
        inp, faults = self.inputs, self.unit_faults[unit]
        transformer = inp[f"unit{unit}.transformer"]
        if transformer != "normal":
            faults.add("vcb")                               # every listed transformer fault opens the VCB
            if transformer in OVERCURRENTS:
                faults.add("converter")                     # over-currents also cut the converters
        oil = inp[f"unit{unit}.oil pump"] == "stopped" or inp[f"unit{unit}.oil temperature"] == "over-temperature"
        if oil and self.train.cfg.behaviour.oil_protection:
            faults.add("converter")

    def _main_circuit_reset(self) -> None:
        for unit, faults in self.unit_faults.items():
            inp = self.inputs
            still = (inp[f"unit{unit}.transformer"] != "normal" or inp[f"unit{unit}.oil pump"] == "stopped"
                     or inp[f"unit{unit}.oil temperature"] == "over-temperature")
            if not still:
                faults.clear()

    # ILK-08: traction permission
    def traction_permitted(self) -> bool:
        return self.outputs.get("traction") == "permitted"

    def _permitted(self, emergency: bool, rapid: bool, doors: str) -> bool:
        ccu = self.train.commanding_ccu()
        if ccu is None or not ccu.desk.mcr:                       # (1) this cab's MCR
            return False
        inp, b = self.inputs, self.train.cfg.behaviour
        braking = ccu.desk.brake > 0 or inp["ATP brake"] != "none"
        conditions = {
            "direction": ccu.desk.direction in ("forward", "reverse"),                # (2)
            "brakes": not (emergency or rapid),                                        # (3)
            "doors": doors == "closed" or inp["door bypass"] == "on",                  # (4)
            "braking": not braking,                                                    # brake outranks traction
            "neutral section": self.ns_phase not in ("warned", "passing"),   # ILK-04: no traction into it
        }
        return all(ok for name, ok in conditions.items() if name not in b.ilk08_ignored)

    def brake_demand(self, handle: int) -> int:
        """The brake step the commands carry: the handle, raised to full service by an ATP brake."""
        return max(handle, 7) if self.inputs["ATP brake"] != "none" and handle < 8 else handle

    # ILK-04: automatic neutral-section passing
    def _ns_signal(self, signal: str) -> None:
        device = self.inputs["neutral section device"]
        self.train.emit("vehicle", "ns.signal", signal=signal, device=device)
        if device == "severe fault":
            self.ns_phase = "manual passing"               # network alarm; the driver passes by hand
            self._ns_cancel()
            return
        if signal == "warning":
            self.ns_phase = "warned"
            self.ns_vcb_open = True                        # traction off and VCB open before the section
            self._ns_arm(self.cfg.ns_entry_timeout_us, "awaiting manual entry")
        elif signal == "entry":
            # without a warning (a faulty warning signal) the network forces automatic passing here
            if self.ns_phase == "idle" and not self.train.cfg.behaviour.ns_forced_passing:
                return
            self.ns_phase = "passing"
            self.ns_vcb_open = True
            self._ns_arm(self.cfg.ns_exit_timeout_us, "awaiting manual restore")
        elif signal == "exit" and self.ns_phase in ("passing", "warned"):
            self._ns_cancel()
            self.ns_phase = "idle"
            self.ns_vcb_open = False

    def _ns_arm(self, delay: int, phase: str) -> None:
        self._ns_cancel()

        self._ns_timer = self.kernel.call_later(delay, self._ns_expire, phase)

    def _ns_expire(self, phase: str) -> None:
        self._ns_timer = None
        self.ns_phase = phase
        self._evaluate()

    def _ns_cancel(self) -> None:
        if self._ns_timer is not None:
            self._ns_timer.cancel()
            self._ns_timer = None

    def _ns_restore(self) -> None:
        if self.ns_phase in ("awaiting manual restore", "awaiting manual entry", "manual passing"):
            self._ns_cancel()
            self.ns_phase = "idle"
            self.ns_vcb_open = False

    def monitor_alarms(self) -> list[str]:
        alarms = []
        device = self.inputs["neutral section device"]
        if device == "severe fault":
            alarms.append("neutral section: severe fault, pass manually")
        elif device == "warning signal fault":
            alarms.append("neutral section: warning signal fault, forced automatic passing")
        if self.ns_phase == "awaiting manual entry":
            alarms.append("neutral section: no entry signal, enter manually")
        if self.ns_phase == "awaiting manual restore":
            alarms.append("neutral section: no exit signal, restore manually")
        for unit, faults in self.unit_faults.items():
            if faults:
                alarms.append(f"unit{unit}: main circuit protection acted")
        if self.brake_force_low:
            alarms.append("insufficient brake force")
        return alarms

