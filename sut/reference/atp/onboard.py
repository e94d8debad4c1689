"""The CTCS-2 200C on-board ATP functions of seed 001 (ATP-01..12), as a lab rig sees them: a signal
generator feeds the CFSK receiver (carrier, low-frequency code, amplitude), an odometry simulator gives
position and speed, and balise groups are passed with their packets.

Positions are metres along the line (the train's front); balise packet distances are absolute positions on
the same line (the model's simplification of ETCS relative distances, stated in docs/decisions.md).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

from sut.reference.atp.config import Atp
from sut.reference.kernel import Kernel

CARRIER_SETS = {"down": (1700, 2300), "up": (2000, 2600)}   # ZPW-2000: down line 1700/2300, up line 2000/2600
PERMISSIONS = ("ATO allowed", "door enable", "PSD permission")   # outputs granted or withheld (ATP-10)
KNOWN_PACKETS = ("CTCS-1", "MA", "ETCS-68", "ETCS-46", "line direction", "default", "stop point", "linking")


@dataclass
class Section:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    start_m: float
    length_m: float
    carrier: int
    end_signal: str = "block"

    @property
    def end_m(self) -> float:
        return self.start_m + self.length_m


@dataclass
class Cfsk:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    failed: bool = False
    carrier_set: str = "down"
    candidate: tuple[int, str] | None = None
    agreeing: int = 0
    confirmed: tuple[int, str] | None = None


@dataclass
class Generator:
    """What the track-circuit signal generator puts on the CFSK antenna."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    carrier: int = 0
    code: str | None = None        # None until the rig modulates one: "" is no word of the contract
    amplitude_mv: float = 0.0
    circuit_type: str = "ZPW-2000A"


@dataclass
class Linking:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    group: str
    at_m: float


@dataclass
class OnboardState:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    mode: str = "SB"
    brake: str = "none"
    sections: list[Section] = field(default_factory=list)
    eoa_m: float | None = None
    neutral: tuple[float, float] | None = None
    stop_point: tuple[float, bool] | None = None      # (position, platform screen doors)
    expected: list[Linking] = field(default_factory=list)
    diverging: bool = False
    ready: bool = False


class OnboardAtp:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, kernel: Kernel, cfg: Atp, emit: Callable[..., None],
                 on_brake: Callable[[], None] | None = None):
        self.kernel, self.cfg, self._emit = kernel, cfg, emit
        self._on_brake = on_brake
        self.s = OnboardState()
        self.cfsk = Cfsk()
        self.gen = Generator()
        self.position_m = 0.0
        self.speed_kmh = 0.0
        self.inputs = {"sleep": False, "ATO start": False, "cab signal mode": False}
        self.mtore_failed = False
        self.neutral_command = False
        self.dmi: list[str] = []
        self.records: list[str] = []
        self._def_step = 0

    # -- start-up: the DEF train-interface self-test (ATP-08) -----------------------------------------
    def power_on(self) -> None:
        self._def_step = 0
        self.kernel.call_later(0, self._def)
        self._start_comparisons()
        self.kernel.every(self.cfg.tick_us, self._tick)

    def _start_comparisons(self) -> None:
        """One CFSK comparison every cfsk_period_us from power-up. A hook for a product whose CFSK task runs on
        a task tick (tests/freedom_atp.py)."""
        self.kernel.every(self.cfg.cfsk_period_us, self._compare)

    def _def(self) -> None:
        step = self._def_step
        if step == self.cfg.def_steps:
            self.s.ready = True
            self._emit("ATP", "def.done", steps=step)
            self._set_mode("SB")
            return
        # Each step changes one train-interface output and reads it back one step later.
        readback = not self.mtore_failed
        self._emit("ATP", "def.step", step=step + 1, readback="ok" if readback else "wrong")
        if not readback:
            self._message("DEF fault: train interface output not read back")
            self._set_brake("emergency")
            return
        self._def_step += 1
        self.kernel.call_later(self._def_next_us(), self._def)

    def _def_next_us(self) -> int:
        """How long after this DEF step the next one runs: one step every def_step_us (ATP-08). A hook for a
        product whose DEF task runs on a task tick (tests/freedom_atp.py)."""
        return self.cfg.def_step_us

    # -- motion ------------------------------------------------------------------------------------------
    def _tick(self) -> None:
        dt_s = self.cfg.tick_us / 1e6
        self.position_m += self.speed_kmh / 3.6 * dt_s
        if not self.s.ready:
            return
        self._supervise()

    def _supervise(self) -> None:
        s, p = self.s, self.position_m
        # Automatic neutral-section passing (ATP-11): the command holds over the section.
        if s.neutral is not None:
            start, end = s.neutral
            inside = start <= p < end
            if inside != self.neutral_command:
                self.neutral_command = inside
                self._emit("ATP", "neutral.command", state="passing" if inside else "none", at_m=round(p, 3))
        # FS -> PS near the end of authority (ATP-06)
        if s.mode == "FS" and s.eoa_m is not None and s.eoa_m - p <= self.cfg.fs_to_ps_m:
            self._message(f"PS: {s.eoa_m - p:.1f} m to the end of authority")
            self._set_mode("PS")
        # Default telegram on a diverging entry (ATP-07): PS and line data deleted below 45 km/h
        if s.diverging and self.speed_kmh < self.cfg.default_ps_kmh:
            s.diverging = False
            self._delete_line_data("default telegram on diverging entry")
            self._set_mode("PS")
            self._set_brake("none")
        # Balise linking (ATP-12)
        for link in list(s.expected):
            if p > link.at_m + self.cfg.linking_window_m:
                s.expected.remove(link)
                if link.group in self.cfg.no_reaction_groups:
                    self._emit("ATP", "linking.missing", group=link.group, reaction="none")
                else:
                    self._emit("ATP", "linking.missing", group=link.group, reaction="max service")
                    self._message(f"balise group {link.group} missing")
                    self._set_brake("max service")
        # Carrier consistency on every position update once a carrier is confirmed (ATP-02)
        if self.cfsk.confirmed is not None and s.sections and self.s.mode in ("FS", "PS", "AM"):
            self._check_carrier()

    # -- CFSK (ATP-01, ATP-03, ATP-04, ATP-05) ------------------------------------------------------------
    def _compare(self) -> None:
        if not self.s.ready:
            return
        c = self.cfsk
        if c.failed and self.cfg.fault_stops_decoding:
            return
        heard = (self.gen.carrier, self.gen.code)
        if heard[0] not in CARRIER_SETS[c.carrier_set]:
            heard = None
        if heard == c.candidate:
            c.agreeing += 1
        else:
            c.candidate, c.agreeing = heard, 1
        self._emit("CFSK", "cfsk.compare", heard=list(heard) if heard else None, agreeing=c.agreeing)
        if heard is not None and c.agreeing >= self.cfg.cfsk_confirmations and heard != c.confirmed:
            c.confirmed = heard
            self._emit("CFSK", "cfsk.report", carrier=heard[0], code=heard[1])
            self._record()
            self._check_carrier()

    def fail_cfsk(self, failed: bool) -> None:
        self.cfsk.failed = failed
        if failed:
            self.cfsk.confirmed = None
            self._emit("CFSK", "cfsk.fault", text="CFSK board fault")
            self._message("CFSK fault")
            self._record()

    def _record(self) -> None:
        c, g = self.cfsk, self.gen
        carrier, code = c.confirmed or (0, "")
        self.records.append(f"{self.kernel.now / 1000:.3f} CFSK code={code or '-'} carrier={carrier} "
                            f"amplitude={g.amplitude_mv:g}mV state={'fault' if c.failed else 'ok'} "
                            f"type={g.circuit_type}")

    def select_carrier_set(self, which: str, by: str) -> None:
        if which != self.cfsk.carrier_set:
            self.cfsk.carrier_set = which
            self.cfsk.candidate, self.cfsk.agreeing = None, 0
            self._emit("CFSK", "cfsk.carrier_set", set=which, by=by)

    # -- carrier consistency (ATP-02) -------------------------------------------------------------------
    def receiver_range(self) -> tuple[float, float]:
        """[Dmin, Dmax] where the CFSK receiver can have been when it decoded: from the minimum and maximum
        safe front positions, less the receiver's distance behind the front, and widened to the rear by the
        distance run during the decode delay."""
        cfg, p = self.cfg, self.position_m
        v_ms = self.speed_kmh / 3.6
        widening = v_ms * cfg.decode_delay_us / 1e6 if cfg.widen_rear else 0.0
        d_min = p - cfg.position_uncertainty_m - cfg.d_sen_m - widening
        d_max = p + cfg.position_uncertainty_m - cfg.d_sen_m
        return d_min, d_max

    def _check_carrier(self) -> None:
        if self.cfsk.confirmed is None or not self.s.sections:
            return
        d_min, d_max = self.receiver_range()
        allowed = sorted({sec.carrier for sec in self.s.sections if sec.start_m <= d_max and sec.end_m >= d_min})
        f0 = self.cfsk.confirmed[0]
        if f0 not in allowed:
            self._emit("ATP", "carrier.inconsistent", f0=f0, allowed=allowed, d_min=round(d_min, 3),
                       d_max=round(d_max, 3), at_m=round(self.position_m, 3))
            self._message("carrier inconsistent")
            self._delete_line_data("carrier inconsistent")
            self._set_brake("max service")

    # -- balises -------------------------------------------------------------------------------------------
    def pass_balise(self, group: str, packets: list[dict[str, Any]]) -> None:
        s = self.s
        self._emit("ATP", "balise", group=group, packets=[pk["type"] for pk in packets], at_m=round(self.position_m, 3))
        s.expected = [link for link in s.expected if link.group != group]
        for pk in packets:
            kind = pk["type"]
            if kind == "ETCS-46" and not self.cfg.parses_etcs46 or kind not in KNOWN_PACKETS:
                self._message(f"balise information error: packet {kind} in group {group}")
                self._set_brake("max service")
                continue
            if kind == "CTCS-1":
                s.sections = [Section(*sec) for sec in pk["sections"]]
            elif kind == "MA":
                s.eoa_m = float(pk["end_m"])
            elif kind == "ETCS-68":
                s.neutral = (float(pk["start_m"]), float(pk["start_m"]) + float(pk["length_m"]))
            elif kind == "line direction" and self.cfg.balise_switches_carrier_set:
                self.select_carrier_set(pk["direction"], by=f"balise {group}")
            elif kind == "default":
                if pk.get("side_line") and self.s.mode in ("FS", "AM"):
                    s.diverging = True
                    self._message(f"default telegram from side-line balise {group}")
                    self._set_brake("max service")
            elif kind == "stop point":
                s.stop_point = (float(pk["at_m"]), bool(pk.get("psd", False)))
            elif kind == "linking":
                s.expected = [Linking(g, float(at)) for g, at in pk["next"]]
        if s.sections and s.eoa_m is not None and s.mode in ("SB", "PS", "CS") and s.eoa_m - self.position_m > \
                self.cfg.fs_to_ps_m and not s.diverging and s.brake == "none":
            self._set_mode("FS")

    # -- modes, permissions (ATP-10) ---------------------------------------------------------------------
    def set_mode_input(self, name: str, value: bool) -> None:
        self.inputs[name] = value
        s = self.s
        if name == "sleep":
            self._set_mode("SL" if value else "SB")
        elif name == "ATO start" and value and self.permission("ATO allowed"):
            self._set_mode("AM")
        elif name == "cab signal mode" and value and not s.sections and s.mode in ("SB", "PS"):
            self._set_mode("CS")

    def permission(self, name: str) -> bool:
        """One of PERMISSIONS; another name is a KeyError of the lookup (the backend asks only these)."""
        s = self.s
        in_window = self.in_stop_window()
        return {"ATO allowed": s.mode in ("FS", "AM") and s.brake == "none",
                "door enable": in_window,
                "PSD permission": in_window and s.stop_point is not None and s.stop_point[1]}[name]

    def in_stop_window(self) -> bool:
        sp = self.s.stop_point
        if sp is None or self.speed_kmh != 0:
            return False
        return -self.cfg.stop_window_m <= self.position_m - sp[0] <= self.cfg.stop_window_m

    def _set_mode(self, mode: str) -> None:
        if mode != self.s.mode:
            self.s.mode = mode
            self._emit("ATP", "mode.change", mode=mode, at_m=round(self.position_m, 3))

    def _set_brake(self, brake: str) -> None:
        if brake != self.s.brake:
            self.s.brake = brake
            self._emit("ATP", "brake.change", brake=brake, at_m=round(self.position_m, 3))
            if self._on_brake is not None:
                self._on_brake()

    def _delete_line_data(self, why: str) -> None:
        if self.s.sections or self.s.eoa_m is not None:
            self.s.sections, self.s.eoa_m = [], None
            self._emit("ATP", "linedata.delete", reason=why)

    def _message(self, text: str) -> None:
        self.dmi.append(text)
        self._emit("DMI", "dmi.message", text=text)
