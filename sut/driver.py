"""The one interface every SUT backend implements (python-can's `BusABC`, for a train).

Policy lives here (argument checking, time conversion, shutdown, context manager); backends give small
primitives. Steps talk to a `TrainDriver` and nothing else. What a backend does not model raises
`NotSupported`; it never pretends.

Only the life cycle, time, the trace and `describe` are abstract; the rest belongs to one train profile
or another (`PROFILES`) and raises `NotSupported` where a backend does not implement it.

Names used at this interface for a CRH2 train (a rig adapter maps them onto its wiring; metro names are
in the metro section below):
- ring nodes: `car1.CCU.sys1`, `car1.CCU.sys2`, `car3.LCU`, ...
- boards: `<node>.CPU3`, `<node>.MDM8`, `car1.CCU.sys1.TXC`, `car3.LCU.MDM9`, `car3.LCU.RXC`,
  CPU groups `...TXC.group2`, `...RXC.group2`; the line `selfdiag`
- power supplies: `car1.CCU.sys1` (CPU side of a CCU system), `car1.CCU.sys1.TXC`, `car3.LCU` (CPU side),
  `car3.LCU.RXC`, `car1.desk` (driver-desk input supply)
- devices: `car3.CI`, `car3.BCU`, `car3.ACS`, `car3.PID`, `car2.APU`, `car1.DD`, `car3.SDD`
"""
from __future__ import annotations

import abc
from typing import Any

from sut.errors import NotPoweredUp, NotSupported, OutOfRange, UnknownName
from sut.trace import Trace

DIRECTIONS = ("neutral", "forward", "reverse")


class TrainDriver(abc.ABC):
    """A train under test: inputs, faults, time, observations."""

    backend_name = "abstract"
    # The train profiles this backend implements (features carry @profile:<name>); a scenario of a profile
    # its SUT does not declare is skipped with that reason, never run and never passed.
    PROFILES: tuple[str, ...] = ()
    # Whether the same calls from open() always give the same states, traces and answers (a simulation, not
    # a rig or a train behind a socket). Only then may a run reuse what one scenario computed for another
    # (sut/snapshot.py); a backend that is not, or does not say so, is simply driven call by call.
    DETERMINISTIC: bool = False
    # The backend's implementation declaration (sut/contract/declaration.py: options it implements, the
    # parameters and texts the suite tests it by), a path from the project root; `--declaration FILE`
    # names one for a backend that has none (a remote SUT) or overrides it.
    DECLARATION: str | None = None

    def __init__(self) -> None:
        self._powered = False
        self._shut_down = False

    @classmethod
    def open(cls, profile: str | None = None) -> "TrainDriver":
        """A driver for a train of `profile` (None: the first declared). A backend of several profiles
        returns the driver of that profile's train (python-can's `Bus(interface=...)` picks the class)."""
        if profile is not None and profile not in cls.PROFILES:
            raise UnknownName(f"profile of {cls.__qualname__}", profile, cls.PROFILES)
        return cls()

    # -- composition and life cycle ------------------------------------------------------------
    @abc.abstractmethod
    def configure(self, *, sets: int = 1, cars_per_set: int = 8) -> None:
        """Choose the composition before power-up (NET-08: two sets coupled)."""

    @property
    def powered(self) -> bool:
        return self._powered

    def power_on(self) -> None:
        if self._powered:
            return
        self._power_on()
        self._powered = True

    @abc.abstractmethod
    def _power_on(self) -> None: ...

    def shutdown(self) -> None:
        """Idempotent; a backend releases what it holds."""
        if not self._shut_down:
            self._shut_down = True
            self._shutdown()

    def _shutdown(self) -> None:
        pass

    def __enter__(self) -> "TrainDriver":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.shutdown()

    def _unsupported(self, method: str) -> NotSupported:
        return NotSupported(f"{self.backend_name} ({', '.join(self.PROFILES) or 'no profile'}) does not "
                            f"implement {method}()")

    def _require_power(self) -> None:
        if not self._powered:
            raise NotPoweredUp("the train is not powered up yet (a Given step must power it up first)")

    # -- snapshots (sut/snapshot.py) -----------------------------------------------------------
    def snapshot(self) -> bytes:
        """This train's whole state, from which `from_snapshot` makes an independent train in this
        process: the same state, none of the same objects (but events of its trace, which no one changes:
        PickledState shares the trace up to the snapshot). A backend whose state is more than its own
        objects (a rig, a remote train) raises NotSupported, and its scenarios simply simulate."""
        raise NotSupported(f"{self.backend_name} cannot snapshot its state")

    @classmethod
    def from_snapshot(cls, data: bytes) -> "TrainDriver":
        raise NotSupported(f"{cls.backend_name} cannot restore a snapshot")

    # -- virtual time --------------------------------------------------------------------------
    @property
    @abc.abstractmethod
    def now_us(self) -> int: ...

    def advance(self, us: int) -> None:
        """Let `us` microseconds of train time pass."""
        self.check_us("time step", us, 0)
        self._require_power()
        self._advance(us)

    def advance_ms(self, ms: float) -> None:
        us = round(ms * 1000)
        if abs(us - ms * 1000) > 1e-6:
            raise OutOfRange("time step", ms, "whole microseconds")
        self.advance(us)

    @abc.abstractmethod
    def _advance(self, us: int) -> None: ...

    # -- long runs (continuous power-on, TST-02) -----------------------------------------------
    def soak(self, us: int, *, sample_every_us: int | None = None) -> None:
        """Let `us` of train time pass in one long run (72 h of continuous power-on).

        The result must be what `advance(us)` gives. A backend may skip steady traffic in closed form
        (the reference does: sut/reference/bulk.py), but then the trace must still hold the traffic of one
        steady sample after every `sample_every_us` and of the end of the run, and the `counters` must
        count everything, skipped or not. A rig simply waits."""
        self.check_us("time step", us, 0)
        if sample_every_us is not None and (not isinstance(sample_every_us, int) or sample_every_us <= 0):
            raise OutOfRange("sample interval", sample_every_us, "a whole number of microseconds > 0")
        self._require_power()
        self._soak(us, sample_every_us)

    def _soak(self, us: int, sample_every_us: int | None) -> None:
        self._advance(us)

    def counters(self, node: str) -> dict[str, int]:
        """A ring node's diagnostic counters: 'status sent', 'tokens received', 'token initialisations',
        'frames discarded'; a CCU system adds 'commands sent', an LCU 'commands received' and 'clock ms'
        (the clock the CCU's clock correction set, ms since power-up)."""
        raise NotSupported(f"{self.backend_name} keeps no diagnostic counters")

    # -- driver desk (CMD-05) ------------------------------------------------------------------
    def insert_key(self, cab: int) -> None:
        raise self._unsupported("insert_key")

    def remove_key(self, cab: int) -> None:
        raise self._unsupported("remove_key")

    def set_direction(self, cab: int, direction: str) -> None:
        raise self._unsupported("set_direction")

    def set_traction(self, cab: int, notch: int) -> None:
        raise self._unsupported("set_traction")

    def set_brake(self, cab: int, step: int) -> None:
        raise self._unsupported("set_brake")

    # -- faults --------------------------------------------------------------------------------
    def cut_link(self, a: str, b: str) -> None:
        """Cut the ring span between adjacent nodes a and b (both fibres)."""
        raise self._unsupported("cut_link")

    def restore_link(self, a: str, b: str) -> None:
        raise self._unsupported("restore_link")

    def cut_ring(self) -> None:
        """Cut every span of the ring (NET-04: the whole ring down)."""
        nodes = self.ring_nodes()
        for a, b in zip(nodes, nodes[1:] + nodes[:1]):
            self.cut_link(a, b)

    def corrupt_frames(self, a: str, b: str, kind: str, count: int = 1) -> None:
        """Corrupt the next `count` frames of `kind` going from node a to node b (one bit flipped)."""
        raise self._unsupported("corrupt_frames")

    def fail(self, board: str) -> None:
        raise self._unsupported("fail")

    def repair(self, board: str) -> None:
        raise self._unsupported("repair")

    def power_off(self, supply: str) -> None:
        raise self._unsupported("power_off")

    def restore_power(self, supply: str) -> None:
        raise self._unsupported("restore_power")

    # -- the vehicle around the network (ILK): named inputs and outputs ------------------------
    def set_input(self, name: str, value: Any) -> None:
        """Set a vehicle input (speed, main pipe pressure, doors, ATP brake, a fault state, ...)."""
        raise NotSupported(f"{self.backend_name} has no vehicle inputs")

    def ramp_input(self, name: str, to: float, per_s: float) -> None:
        """Move a numeric input linearly to `to` at `per_s` units per second of train time."""
        raise NotSupported(f"{self.backend_name} cannot ramp vehicle inputs")

    def input(self, name: str) -> Any:
        raise NotSupported(f"{self.backend_name} has no vehicle inputs")

    def output(self, name: str) -> str:
        """A vehicle output: a valve, relay, breaker or contactor state, the doors, traction permission."""
        raise NotSupported(f"{self.backend_name} has no vehicle outputs")

    def reading(self, name: str) -> float:
        """A numeric reading of the train: speed (km/h), main pipe pressure (kPa), mileage (km)."""
        raise NotSupported(f"{self.backend_name} has no readings")

    def monitor_order(self, cab: int, name: str, value: str) -> None:
        """The driver orders equipment from the cab monitor (service equipment, remote cut-out, VCB, ...)."""
        raise NotSupported(f"{self.backend_name} takes no monitor orders")

    def vehicle_names(self) -> dict[str, list[str]]:
        return {"inputs": [], "outputs": []}

    # -- environment (hardware/software class, TST-02) -----------------------------------------
    # Names: a supply as above or `train 110V` (the train supply feeding all of them); a unit is a ring
    # node or `train`; a line is a ring link `a~b` (adjacent nodes) or `selfdiag`; a connector is a
    # supply (its power contacts) or a ring link (its optical connectors). Times in microseconds.
    def rated_limits(self) -> dict[str, Any]:
        """The environment the SUT declares it works in (supply, temperature, bursts, insulation, ...)."""
        raise NotSupported(f"{self.backend_name} declares no rated environment")

    def set_supply_voltage(self, supply: str, volts: float) -> None:
        """Feed `supply` (or every supply, `train 110V`) with `volts` from now on."""
        raise NotSupported(f"{self.backend_name} cannot vary its supply voltage")

    def interrupt_supply(self, supply: str, duration_us: int) -> None:
        """Interrupt the input of `supply` (or `train 110V`) for `duration_us`, starting now."""
        raise NotSupported(f"{self.backend_name} cannot interrupt its supply")

    def set_temperature(self, unit: str, celsius: float) -> None:
        """Bring a unit (ring node) or the whole `train` to `celsius` from now on."""
        raise NotSupported(f"{self.backend_name} has no climatic chamber")

    def interfere(self, line: str, level_kv: float, duration_us: int) -> None:
        """Fast-transient bursts of `level_kv` coupled into a ring link `a~b` or `selfdiag` for `duration_us`."""
        raise NotSupported(f"{self.backend_name} cannot inject interference")

    def vibrate(self, connector: str, interruption_us: int, count: int, period_us: int) -> None:
        """Vibration shakes `connector` open `count` times, `interruption_us` each, one every `period_us`."""
        raise NotSupported(f"{self.backend_name} has no vibration table")

    def withstand_test(self, unit: str, volts_rms: float, duration_us: int) -> None:
        """Apply the dielectric test voltage to a unit, disconnected (unpowered) for the test's duration."""
        raise NotSupported(f"{self.backend_name} cannot run withstand-voltage tests")

    def insulation_resistance(self, unit: str) -> float:
        """A unit's insulation resistance in MOhm, measured at 500 V DC."""
        raise NotSupported(f"{self.backend_name} cannot measure insulation")

    # -- metro TCN (profile metro-tcn): dual-line buses and the units on them ----------------------
    # Buses: `WTB`, `unit1.MVB` (cars 1-3), `unit2.MVB` (cars 4-6); lines `A` and `B`. Units: `car1.CCU`,
    # `car2.VCU` .. `car5.VCU`, `car6.CCU`; MVB I/O modules `car1.IO1`, `car1.IO2`, `car6.IO1`, `car6.IO2`;
    # devices `car2.VVVF`, `car3.BECU`, `car1.DU`, ... (`devices(car)`). `fail`/`repair` take any of them
    # or a board (`car1.CCU.VMS`).
    def cut_line(self, bus: str, line: str) -> None:
        """Cut line A or B of a bus (its whole length): frames on that line are lost."""
        raise self._unsupported("cut_line")

    def restore_line(self, bus: str, line: str) -> None:
        raise self._unsupported("restore_line")

    def disturb_line(self, bus: str, line: str, count: int = 1) -> None:
        """Flip one bit in each of the next `count` frames on one line of a bus."""
        raise self._unsupported("disturb_line")

    def tap_bus(self, bus: str) -> None:
        """Attach an analyser to a bus: every frame on it appears in the trace as `bus.frame` with its
        `type` (master/slave) and body as `hex` (between the delimiters, MSB first)."""
        raise self._unsupported("tap_bus")

    def records(self, unit: str) -> list[str]:
        """The event records stored in a unit's memory (VMS), oldest first, as `t_ms origin: text`."""
        raise self._unsupported("records")

    # -- on-board ATP (profile atp) ---------------------------------------------------------------
    def pass_balise(self, group: str, packets: list[dict[str, Any]]) -> None:
        """The train passes balise group `group` (e.g. `70-2-4-15`) now, at its present position. `packets`
        is a list of dicts, each with `type` and that type's fields, exactly as the steps send them:
        - `CTCS-1`: `sections`, a list of (start m, length m, carrier Hz) triples (float, float, int), the
          track circuits in line order (no end-signal type is sent); the steps send it with an `MA`;
        - `MA`: `end_m` (float), the end of authority;
        - `ETCS-68`: `start_m` and `length_m` (float), a neutral section;
        - `ETCS-46`: no other field;
        - `line direction`: `direction`, `up` or `down` (switches the CFSK carrier set);
        - `default`: `side_line` True, the default telegram of a side-line balise;
        - `stop point`: `at_m` (float) and `psd` (bool: the platform has screen doors);
        - `linking`: `next`, a list of (group, at m) pairs, the groups the train must pass next.
        Any other `type` (e.g. `ETCS-99`, with no other field) is a packet the ATP does not know: a balise
        information error. Positions are absolute metres along the line, as the train's `position`."""
        raise self._unsupported("pass_balise")

    # -- traffic -------------------------------------------------------------------------------
    def request_block_transfer(self, node: str, data: bytes) -> None:
        """Give `node` a record to send as block data (PRO-06)."""
        raise self._unsupported("request_block_transfer")

    def tap_link(self, a: str, b: str) -> None:
        """Attach an analyser to span a-b: frames crossing it appear in the trace as `link.tx`."""
        raise self._unsupported("tap_link")

    # -- observations --------------------------------------------------------------------------
    @property
    @abc.abstractmethod
    def trace(self) -> Trace: ...

    def _trace_view(self, events: list) -> Trace:
        """One Trace per event list, so that its index of kinds and sources is built once, not per query."""
        view = self.__dict__.get("_view")
        if view is None or view._events is not events:
            view = self._view = Trace(events)
        return view

    def ring_nodes(self) -> list[str]:
        """Node names in ring order (node number = position + 1)."""
        raise self._unsupported("ring_nodes")

    def boards(self, unit: str) -> list[str]:
        """Board names of a unit, e.g. boards('car3.LCU') -> ['CPU3', 'MDM8', 'MDM9', 'RXC']."""
        raise self._unsupported("boards")

    def devices(self, car: int) -> list[str]:
        raise self._unsupported("devices")

    def supplies(self) -> list[str]:
        """The power supplies `power_off` can switch off, e.g. 'car3.LCU' (the unit's own) and 'car3.LCU.RXC'
        (a command board's own supply, CMD-01); with the boards and the ring's spans, the single faults a
        campaign runs through (outline/campaigns/campaign.py)."""
        raise self._unsupported("supplies")

    def token_holder(self) -> list[str]:
        """Nodes holding a token now (one per connected segment in a healthy protocol)."""
        raise self._unsupported("token_holder")

    def monitor(self, cab: int) -> dict[str, Any]:
        """The cab monitor: {'status': {node: age_us or None}, 'faults': [text, ...]}."""
        raise self._unsupported("monitor")

    def watch_monitor(self, cab: int, us: int, step_us: int) -> list[tuple[int, list[str]]]:
        """Let `us` pass while looking at the cab monitor's faults every `step_us`, as a tester watching
        the screen notes what it shows: [(t_us, faults), ...] from now to now + us, both included.

        The same as `monitor` between `advance` calls (that is this default); one call so that a backend
        can watch without a round trip per look (the features look every 1 ms for seconds)."""
        self.check_us("watch", us, 0)
        self.check_us("watch step", step_us)
        self._require_power()
        end = self.now_us + us
        samples = []
        while True:
            samples.append((self.now_us, self._monitor_faults(cab)))
            if self.now_us >= end:
                return samples
            self.advance(min(step_us, end - self.now_us))

    def _monitor_faults(self, cab: int) -> list[str]:
        return list(self.monitor(cab)["faults"])

    def status_table(self, node: str) -> dict[str, int | None]:
        """Age in us of the last status data `node` received from every other node (None: never)."""
        raise self._unsupported("status_table")

    def lamp(self, cab: int, name: str) -> bool:
        raise self._unsupported("lamp")

    def block_store(self, node: str) -> dict[str, list[bytes]]:
        """Complete records received as block data at `node`, by sending node, oldest first (236-byte
        blocks, so a record is padded with zero bytes to whole blocks)."""
        raise self._unsupported("block_store")

    @abc.abstractmethod
    def describe(self) -> dict[str, str]:
        """Parameters shown as the report's environment."""

    # -- shared argument checks ----------------------------------------------------------------
    @staticmethod
    def check_us(what: str, value: Any, lo: int = 1) -> int:
        """A duration or time step: a whole number of microseconds, at least `lo`."""
        if isinstance(value, bool) or not isinstance(value, int) or value < lo:
            raise OutOfRange(what, value, f"a whole number of microseconds >= {lo}")
        return value

    @staticmethod
    def check_direction(direction: str) -> str:
        if direction not in DIRECTIONS:
            raise OutOfRange("direction", direction, ", ".join(DIRECTIONS))
        return direction
