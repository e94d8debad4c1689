"""The train-control interface reference (profile `atp`) behind the driver interface.

So far the VDX emergency-brake interface of the CTCS3-300T (VDX-01..06). Names:
- inputs: `ATP emergency brake` (the ATP's brake command to the VDX, bool), `ATP isolation switch` (bool),
  `VDX firmware` (`old` or `new`, before power-up);
- supplies: `VDX` (its 110 V input, which also feeds the FS output), `train 110V`;
- outputs: `EB loop` (`open` = emergency brake, `closed`), `EB1R`, `EB2R` (`energised`/`de-energised`),
  `VDX fault` (`C019` or `none`); reading `FS output voltage` (V).
A restart of the VDX is `power_off("VDX")` then `restore_power("VDX")`.
"""
from __future__ import annotations

from typing import Any, ClassVar

from sut.driver import TrainDriver
from sut.errors import OutOfRange, SutError, UnknownName
from sut.reference.atp.config import POSTPONE, AtpConfig
from sut.reference.atp.vdx import VdxInterface
from sut.reference.kernel import Kernel
from sut.trace import Trace, TraceEvent

INPUTS = ("ATP emergency brake", "ATP isolation switch", "VDX firmware")
OUTPUTS = ("EB loop", "EB1R", "EB2R", "VDX fault")
SUPPLIES = ("VDX", "train 110V")


class ReferenceAtp(TrainDriver):
    backend_name = "reference"
    PROFILES = ("atp",)
    VDX: ClassVar[dict[str, Any]] = {}

    def __init__(self) -> None:
        super().__init__()
        self._cfg = AtpConfig().with_vdx(**self.VDX)
        self.kernel = Kernel()
        self._events: list[TraceEvent] = []
        self.vdx = VdxInterface(self.kernel, self._cfg.vdx, self._emit)

    def _emit(self, source: str, kind: str, **fields: Any) -> None:
        self._events.append(TraceEvent(self.kernel.now, source, kind, fields))

    # -- life cycle and time -------------------------------------------------------------------
    def configure(self, *, sets: int = 1, cars_per_set: int = 8) -> None:
        if sets != 1:
            raise OutOfRange("train sets", sets, "1 (one ATP-equipped train)")

    def _power_on(self) -> None:
        self.vdx.power_on()

    @property
    def now_us(self) -> int:
        return self.kernel.now

    def _advance(self, us: int) -> None:
        self.kernel.run(self.kernel.now + us)

    @property
    def trace(self) -> Trace:
        return Trace(self._events)

    # -- inputs and outputs ----------------------------------------------------------------------
    def set_input(self, name: str, value: Any) -> None:
        if name in ("ATP emergency brake", "ATP isolation switch"):
            if not isinstance(value, bool):
                raise OutOfRange(name, value, "on (True) or off (False)")
            if name == "ATP emergency brake":
                self.vdx.command_brake(value)
            else:
                self.vdx.set_isolation(value)
        elif name == "VDX firmware":
            if value not in POSTPONE:
                raise OutOfRange("VDX firmware", value, " or ".join(POSTPONE))
            if self.powered:
                raise SutError("the VDX firmware is chosen before power-up")
            self.vdx.firmware = value
        else:
            raise UnknownName("input", name, INPUTS)
        self._emit("train", "in.set", name=name, value=value)

    def input(self, name: str) -> Any:
        values = {"ATP emergency brake": self.vdx.eb_demand, "ATP isolation switch": self.vdx.isolated,
                  "VDX firmware": self.vdx.firmware}
        if name not in values:
            raise UnknownName("input", name, INPUTS)
        return values[name]

    def output(self, name: str) -> str:
        vdx = self.vdx
        if name == "EB loop":
            return vdx.loop
        if name in ("EB1R", "EB2R"):
            relay = vdx.eb1r if name == "EB1R" else vdx.eb2r
            return "energised" if relay.energised else "de-energised"
        if name == "VDX fault":
            return "C019" if vdx.c019 else "none"
        raise UnknownName("output", name, OUTPUTS)

    def reading(self, name: str) -> float:
        if name != "FS output voltage":
            raise UnknownName("reading", name, ["FS output voltage"])
        return self.vdx.supply_v if self.vdx.eb2r.powered else 0.0

    # -- supply ----------------------------------------------------------------------------------
    def rated_limits(self) -> dict[str, Any]:
        v = self._cfg.vdx
        return {"supply_v": (v.supply_lo * v.nominal_v, v.supply_hi * v.nominal_v), "nominal_v": v.nominal_v}

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

    def describe(self) -> dict[str, str]:
        v = self._cfg.vdx
        return {"SUT backend": self.backend_name, "SUT class": f"{type(self).__module__}.{type(self).__qualname__}",
                "profile": "atp", "VDX": f"FS self-test every {v.selftest_period_us / 1e6:g} s, "
                                         f"{v.selftest_removal_us / 1000:g} ms, threshold {v.low_threshold_v:g} V"}
