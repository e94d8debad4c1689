"""The train-control interface reference (profile `atp`) behind the driver interface.

Two parts, as on a lab rig: the CTCS-2 200C on-board functions (ATP-01..12, `onboard.py`) and the VDX
emergency-brake interface of the CTCS3-300T (VDX-01..06, `vdx.py`). Names:
- ATP inputs: `position` (m, the odometry simulator), `speed` (km/h), the track-circuit signal generator
  `carrier` (Hz), `low frequency code`, `amplitude` (mV), `track circuit type`; `sleep`, `ATO start`,
  `cab signal mode` (bool); DMI order (`monitor_order`) `carrier set` = `up`/`down`; balises through
  `pass_balise`; boards `CFSK`, `MTORE` (`fail`/`repair`);
- ATP outputs: `ATP mode` (SB FS PS CS SL AM), `ATP brake` (none, max service, emergency), `ATO allowed`,
  `door enable`, `PSD permission` (granted/withheld), `neutral section` (passing/none), `CFSK carrier set`;
  `records("ATP")` the CFSK records; `monitor(1)` the DMI messages (no `rated_limits()`: the ATP's figures
  are its declaration's, sut/reference/declaration.yaml, which the atp contract does not ask it to repeat);
- VDX inputs: `ATP emergency brake` (the ATP's brake command to the VDX, bool), `ATP isolation switch`
  (bool), `VDX firmware` (`old` or `new`, before power-up);
- supplies: `VDX` (its 110 V input, which also feeds the FS output), `train 110V`;
- outputs: `EB loop` (`open` = emergency brake, `closed`), `EB1R`, `EB2R` (`energised`/`de-energised`),
  `VDX fault` (`C019` or `none`); reading `FS output voltage` (V).
A restart of the VDX is `power_off("VDX")` then `restore_power("VDX")`.

Fitted to a train (`configure(cars_per_set=8)`), the rig drives an embedded CRH2 train set on the same
virtual clock: the ATP's brake reaches it as its `ATP brake` input (ILK-08: maximum service brake ->
`service`, an open emergency-brake loop or an ATP emergency brake -> `emergency`), `speed` is the train's
speed for both, and the desk, the ring and the vehicle's other inputs and outputs are the train's.
"""
from __future__ import annotations

from typing import Any, ClassVar

from sut.driver import TrainDriver
from sut.snapshot import PickledState
from sut.errors import OutOfRange, SutError, UnknownName
from sut.reference.atp.config import POSTPONE, AtpConfig
from sut.reference.atp.onboard import CARRIER_SETS, PERMISSIONS, OnboardAtp
from sut.reference.atp.vdx import VdxInterface
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference import bulk
from sut.reference.bulk import cyclic_period_us
from sut.reference.kernel import Kernel
from sut.eventlog import EventLog
from sut.trace import Trace, TraceEvent, new_event

INPUTS = ("ATP emergency brake", "ATP isolation switch", "VDX firmware", "position", "speed", "carrier",
          "low frequency code", "amplitude", "track circuit type", "sleep", "ATO start", "cab signal mode")
OUTPUTS = ("EB loop", "EB1R", "EB2R", "VDX fault", "ATP mode", "ATP brake", "ATO allowed", "door enable",
           "PSD permission", "neutral section", "CFSK carrier set")
BOARDS = ("CFSK", "MTORE")
SUPPLIES = ("VDX", "train 110V")


class ReferenceAtp(PickledState, TrainDriver):
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    backend_name = "reference"
    # One rig, three products' views of it: the 200C ATP alone (`atp`), the 300T VDX interface alone (`vdx`)
    # and the 200C ATP fitted to a CRH2 set (`atp-crh2`, ILK-08). A vendor of one declares only its own.
    PROFILES = ("atp", "vdx", "atp-crh2")
    DETERMINISTIC = True           # virtual time, no randomness, nothing outside the model
    DECLARATION = "sut/reference/declaration.yaml"
    VDX: ClassVar[dict[str, Any]] = {}
    ATP: ClassVar[dict[str, Any]] = {}
    # The CRH2 set the ATP is fitted to (atp-crh2): a faulty variant fits one of the train's own variants.
    TRAIN: ClassVar[type[ReferenceTrain]] = ReferenceTrain
    # The two parts, as classes a variant may subclass (tests/variants.py): built once, by _build.
    VDX_INTERFACE: ClassVar[type[VdxInterface]] = VdxInterface
    ONBOARD: ClassVar[type[OnboardAtp]] = OnboardAtp

    def __init__(self) -> None:
        super().__init__()
        self._cfg = AtpConfig().with_vdx(**self.VDX).with_atp(**self.ATP)
        self.kernel = Kernel()
        self._events: EventLog = EventLog()
        self._crh2: ReferenceTrain | None = None
        self._train_brake = "none"
        self._build()

    def _build(self) -> None:
        self.vdx = self.VDX_INTERFACE(self.kernel, self._cfg.vdx, self._emit, on_loop=self._brake_to_train)
        self.atp = self.ONBOARD(self.kernel, self._cfg.atp, self._emit, on_brake=self._brake_to_train)

    def _brake_to_train(self) -> None:
        """ILK-08: the ATP's brake as the CRH2 train's `ATP brake` input."""
        if self._crh2 is None:
            return
        if self.vdx.loop == "open" or self.atp.s.brake == "emergency":
            brake = "emergency"
        else:
            brake = "service" if self.atp.s.brake == "max service" else "none"
        if brake != self._train_brake:
            self._train_brake = brake
            self._crh2.set_input("ATP brake", brake)

    def _emit(self, source: str, kind: str, **fields: Any) -> None:
        self._events.append(new_event(TraceEvent, (self.kernel.now, source, kind, fields)))

    # -- long runs: bulk advance (sut/reference/bulk.py) reads the rig itself as its model --------------
    BULK_SKIP = ("_events", "_view")          # the trace and the index of it a step built are history, not state

    @property
    def events(self) -> EventLog:
        return self._events

    @property
    def free_marks(self) -> list[int] | None:
        """Where the fitted train's metronomes' events are in the shared trace (bulk.py); the rig has none."""
        return self._crh2.train.free_marks if self._crh2 is not None else None

    def emit(self, source: str, kind: str, /, **fields: Any) -> None:
        self._emit(source, kind, **fields)

    def bulk_period_us(self) -> int:
        """The steady period: every cyclic activity (CFSK comparisons, the VDX self-test every 5 s) and, when
        fitted to a CRH2 set, the train's own (its token rotation)."""
        return cyclic_period_us(self.kernel, *([self._crh2.train.bulk_period_us()] if self._crh2 else []))

    def _soak(self, us: int, sample_every_us: int | None) -> None:
        bulk.soak(self, us, sample_every_us)

    # -- life cycle and time -------------------------------------------------------------------
    def configure(self, *, sets: int = 1, cars_per_set: int | None = None) -> None:
        """One ATP on the rig; with `cars_per_set`, fitted to a CRH2 train set of that many cars."""
        if sets != 1:
            raise OutOfRange("train sets", sets, "1 (one ATP-equipped train)")
        if cars_per_set is None:
            return
        # The fitted profile (atp-crh2) declares an 8-car set only: a 16-car fit is a train this rig does not
        # model (one ATP, cab 1's desk), so it is refused rather than built as something else.
        if cars_per_set != 8:
            raise OutOfRange("cars per set of the fitted train", cars_per_set, "8 (atp-crh2: an 8-car CRH2 set)")
        if self.powered or self._crh2 is not None:
            raise SutError("fit the ATP to a train before anything else is done")
        crh2 = self.TRAIN()
        crh2.configure(sets=1, cars_per_set=cars_per_set)
        self._crh2 = crh2
        self.kernel = crh2.train.kernel          # one clock for the ATP and the train
        self._events = crh2.train.events         # and one trace
        self._build()

    def _power_on(self) -> None:
        if self._crh2 is not None:
            self._crh2.power_on()
        self.vdx.power_on()
        self.atp.power_on()
        self._brake_to_train()

    def _train(self) -> ReferenceTrain:
        if self._crh2 is None:
            raise SutError("the ATP is on the test rig, not fitted to a train (configure cars_per_set)")
        return self._crh2

    # The desk and the ring are the train's.
    def insert_key(self, cab: int) -> None:
        self._train().insert_key(cab)

    def remove_key(self, cab: int) -> None:
        self._train().remove_key(cab)

    def set_direction(self, cab: int, direction: str) -> None:
        self._train().set_direction(cab, direction)

    def set_traction(self, cab: int, notch: int) -> None:
        self._train().set_traction(cab, notch)

    def set_brake(self, cab: int, step: int) -> None:
        self._train().set_brake(cab, step)

    def ring_nodes(self) -> list[str]:
        return self._train().ring_nodes()

    def devices(self, car: int) -> list[str]:
        return self._train().devices(car)

    @property
    def now_us(self) -> int:
        return self.kernel.now

    def _advance(self, us: int) -> None:
        bulk.advance(self, self.kernel.now + us)                    # steady periods skipped, trace and all

    @property
    def trace(self) -> Trace:
        return self._trace_view(self._events)

    # -- inputs and outputs ----------------------------------------------------------------------
    def set_input(self, name: str, value: Any) -> None:
        atp = self.atp
        if name in ("ATP emergency brake", "ATP isolation switch", "sleep", "ATO start", "cab signal mode"):
            if not isinstance(value, bool):
                raise OutOfRange(name, value, "on (True) or off (False)")
            if name == "ATP emergency brake":
                self.vdx.command_brake(value)
            elif name == "ATP isolation switch":
                self.vdx.set_isolation(value)
            else:
                atp.set_mode_input(name, value)
        elif name == "VDX firmware":
            if value not in POSTPONE:
                raise OutOfRange("VDX firmware", value, " or ".join(POSTPONE))
            if self.powered:
                raise SutError("the VDX firmware is chosen before power-up")
            self.vdx.firmware = value
        elif name in ("position", "speed", "amplitude"):
            limits = {"position": (-1e6, 1e6), "speed": (0, 350), "amplitude": (0, 10_000)}[name]
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not limits[0] <= value <= limits[1]:
                raise OutOfRange(name, value, f"{limits[0]:g}..{limits[1]:g}")
            if name == "position":
                atp.position_m = float(value)
            elif name == "speed":
                atp.speed_kmh = float(value)
            else:
                atp.gen.amplitude_mv = float(value)
        elif name == "carrier":
            allowed = sorted({f for fs in CARRIER_SETS.values() for f in fs})
            if value not in allowed and value != 0:
                raise OutOfRange("carrier", value, f"{', '.join(map(str, allowed))} Hz or 0 (none)")
            atp.gen.carrier = value
        elif name in ("low frequency code", "track circuit type"):
            if not isinstance(value, str) or not value:
                raise OutOfRange(name, value, "a name such as L, U, HU or ZPW-2000")
            if name == "low frequency code":
                atp.gen.code = value
            else:
                atp.gen.circuit_type = value
        elif self._crh2 is not None:
            self._crh2.set_input(name, value)
            return
        else:
            raise UnknownName("input", name, INPUTS)
        if name == "speed" and self._crh2 is not None:
            self._crh2.set_input("speed", value)
        self._emit("train", "in.set", name=name, value=value)

    def input(self, name: str) -> Any:
        atp = self.atp
        values = {"ATP emergency brake": self.vdx.eb_demand, "ATP isolation switch": self.vdx.isolated,
                  "VDX firmware": self.vdx.firmware, "position": atp.position_m, "speed": atp.speed_kmh,
                  "carrier": atp.gen.carrier, "low frequency code": atp.gen.code,
                  "amplitude": atp.gen.amplitude_mv, "track circuit type": atp.gen.circuit_type, **atp.inputs}
        if name not in values:
            raise UnknownName("input", name, INPUTS)
        return values[name]

    def output(self, name: str) -> str:
        vdx, atp = self.vdx, self.atp
        if name == "EB loop":
            return vdx.loop
        if name in ("EB1R", "EB2R"):
            relay = vdx.eb1r if name == "EB1R" else vdx.eb2r
            return "energised" if relay.energised else "de-energised"
        if name == "VDX fault":
            return "C019" if vdx.c019 else "none"
        if name == "ATP mode":
            return atp.s.mode
        if name == "ATP brake":
            return atp.s.brake
        if name in PERMISSIONS:
            return "granted" if atp.permission(name) else "withheld"
        if name == "neutral section":
            return "passing" if atp.neutral_command else "none"
        if name == "CFSK carrier set":
            return atp.cfsk.carrier_set
        if self._crh2 is not None:
            return self._crh2.output(name)
        raise UnknownName("output", name, OUTPUTS)

    def reading(self, name: str) -> float:
        if name == "FS output voltage":
            return self.vdx.supply_v if self.vdx.eb2r.powered else 0.0
        raise UnknownName("reading", name, ["FS output voltage"])

    # -- the ATP's faults, balises, DMI and records ---------------------------------------------------
    def fail(self, board: str) -> None:
        self._board(board, True)

    def repair(self, board: str) -> None:
        self._board(board, False)

    def _board(self, board: str, failed: bool) -> None:
        if board == "CFSK":
            self.atp.fail_cfsk(failed)
        elif board == "MTORE":
            self.atp.mtore_failed = failed
        else:
            raise UnknownName("board", board, BOARDS)
        self._emit(board, "fault.fail" if failed else "fault.repair")

    def pass_balise(self, group: str, packets: list[dict[str, Any]]) -> None:
        self._require_power()
        for pk in packets:
            if not isinstance(pk, dict) or "type" not in pk:
                raise OutOfRange(f"packet of balise group {group}", pk, "a dict with a 'type'")
        self.atp.pass_balise(group, packets)

    def monitor_order(self, cab: int, name: str, value: str) -> None:
        if name != "carrier set":
            raise UnknownName("DMI order", name, ["carrier set"])
        if value not in CARRIER_SETS:
            raise OutOfRange("carrier set", value, " or ".join(CARRIER_SETS))
        self.atp.select_carrier_set(value, by="driver at the DMI")

    def monitor(self, cab: int) -> dict[str, Any]:
        # The DMI's messages only: the contract's monitor lists no more, and the mode is the output "ATP mode".
        return {"faults": list(self.atp.dmi)}

    def records(self, unit: str) -> list[str]:
        if unit != "ATP":
            raise UnknownName("recording unit", unit, ["ATP"])
        return list(self.atp.records)

    # -- supply ----------------------------------------------------------------------------------
    def set_supply_voltage(self, supply: str, volts: float) -> None:
        if supply not in SUPPLIES:
            raise UnknownName("supply", supply, SUPPLIES)
        if isinstance(volts, bool) or not isinstance(volts, (int, float)) or not 0 <= volts <= 200:
            raise OutOfRange("supply voltage", volts, "0-200 V")
        self._emit(supply, "env.supply", volts=volts)
        self.vdx.set_supply(float(volts))

    def power_off(self, supply: str) -> None:
        if supply != "VDX":
            raise UnknownName("supply", supply, ["VDX"])
        self._emit("VDX", "supply.off")
        self.vdx.power_off()

    def restore_power(self, supply: str) -> None:
        if supply != "VDX":
            raise UnknownName("supply", supply, ["VDX"])
        self._emit("VDX", "supply.on")
        self.vdx.power_on()

    @classmethod
    def open(cls, profile: str | None = None) -> "ReferenceAtp":
        driver = super().open(profile)
        driver.profile = profile or cls.PROFILES[0]       # what the report files its description under
        return driver

    def describe(self) -> dict[str, str]:
        v = self._cfg.vdx
        return {"SUT backend": self.backend_name, "SUT class": f"{type(self).__module__}.{type(self).__qualname__}",
                "profile": getattr(self, "profile", "atp"), "VDX": f"FS self-test every {v.selftest_period_us / 1e6:g} s, "
                                         f"{v.selftest_removal_us / 1000:g} ms, threshold {v.low_threshold_v:g} V"}
