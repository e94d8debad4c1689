"""The metro train control and diagnosis system (seed 002): 6 cars, WTB between the units, one MVB per unit.

Read with requirements.md TCN-01..10, RED-04..07 and docs/decisions.md "Metro TCDS". In one sentence each:
- every MVB basic period (1 ms) the unit's bus master polls: the cab's two I/O modules and the train command
  port every 2 ms, and one device's status (supervisory data) per period;
- every WTB cycle (25 ms) the WTB master polls each node; a node's telegram carries the train command (from
  the unit whose cab is active), its events as numbered messages, and its acknowledgements;
- the MVB master and the WTB master are taken over by rank after silence (MVB: CCU, adjacent VCU, far VCU;
  WTB: car 1 CCU, car 2 VCU, car 3 VCU); the unit whose cab is active computes the train command;
- events go to every CCU memory (VMS) over the WTB; VCUs store nothing;
- VVVF and BECU brake the train to a stop when the train command is lost; at standstill the driver may
  switch to hard-wired emergency operation.
"""
from __future__ import annotations

import functools
from typing import Any, Callable

from sut.codecs.mvb import (SlaveFrame, check_sequence, decode_master, decode_slave, encode_master, encode_slave,
                            is_reserved, master_frame, slave_size_bits)
from sut.reference.bulk import cyclic_period_us
from sut.reference.kernel import Kernel, Timer
from sut.reference.metro import ports
from sut.reference.metro.bus import LINES, Carried, DualLineBus, FrameError
from sut.reference.metro.config import MetroConfig
from sut.reference.metro.ports import Command, IoPort
from sut.reference.metro.units import (CAB_CARS, CAB_DEVICES, MOTOR_DEVICES, UNIT_CARS, ControlUnit, Device,
                                       IoModule, Record)
from sut.eventlog import EventLog
from sut.trace import TraceEvent, new_event

FULL = 10_000          # 100 % in 0.01 % steps
MASTER_BITS = 33       # start delimiter 9 + F_code/address 16 + check 8
SLAVE_OVERHEAD_BITS = 11
REPLY_GAP_US = 4
WTB_OVERHEAD_BITS = 64   # HDLC flags, address, control, preamble


_READY_WORD = ports.READY.to_bytes(2, "big")     # a device's status answer while it works


def _nothing() -> None:
    pass


@functools.lru_cache(maxsize=None)
def _message_us(f_code: int, bit_ns: int) -> int:
    """A poll's time on the bus: master frame, the slave frame answering it, the gap before the next."""
    bits = MASTER_BITS
    if not is_reserved(f_code):          # no slave frame answers a reserved F_code
        bits += slave_size_bits(f_code) + 8 * max(1, slave_size_bits(f_code) // 64) + SLAVE_OVERHEAD_BITS
    return DualLineBus.frame_us(bits, bit_ns) + REPLY_GAP_US


def _one_check_encode(data: bytes) -> bytes:
    # The faulty layout of a variant: one check byte at the end of a long frame (TCN-05 wants one per 64 bits).
    return data + bytes([check_sequence(data)])


def _one_check_decode(raw: bytes, size_bits: int) -> SlaveFrame:
    if len(raw) != size_bits // 8 + 1 or raw[-1] != check_sequence(raw[:-1]):
        raise FrameError("slave frame check failed")
    return SlaveFrame(raw[:-1])


class MvbSegment:
    """One unit's MVB: its bus, its master and what the master has read."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, unit: int, bus: DualLineBus, ranks: tuple[str, ...], devices: list[Device],
                 ios: list[IoModule]):
        self.unit = unit
        self.bus = bus
        self.ranks = ranks
        self.master: str = ranks[0]     # the last node to master the bus: never None
        self.last_master_t = 0
        self.devices = devices
        self.sinks = [d for d in devices if d.sink]    # VVVF and BECU: what takes the train command
        self.ios = ios
        self.io_data: dict[str, tuple[IoPort, int]] = {}
        self.io_used: str | None = None
        self.status_missing = {d.name: 0 for d in devices}
        self.status_reported: set[str] = set()
        self.cmd: Command | None = None
        self.cmd_t = -1
        self.stale = True
        self.sink_timer = None
        self.cmd_seq = 0


class MetroTrain:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    def __init__(self, cfg: MetroConfig):
        self.cfg = cfg
        t, b = cfg.timing, cfg.behaviour
        self.kernel = Kernel()
        self.events: EventLog = EventLog()
        self.tapped: set[str] = set()
        self.nodes: dict[str, ControlUnit] = {}
        for car in range(1, 7):
            kind = "CCU" if car in CAB_CARS else "VCU"
            self.nodes[f"car{car}.{kind}"] = ControlUnit(f"car{car}.{kind}", car, kind)
        self.devices: dict[str, Device] = {}
        self.ios: dict[str, IoModule] = {}
        for car in range(1, 7):
            for kind in (CAB_DEVICES if car in CAB_CARS else MOTOR_DEVICES):
                name = f"car{car}.{kind}"
                if kind.startswith("IO"):
                    self.ios[name] = IoModule(name, car)
                else:
                    self.devices[name] = Device(name, car, kind)
        # Device address on its MVB: car number x 16 + place in the car (12-bit logical addresses).
        self.device_addresses = {}
        placed: dict[int, int] = {}
        for d in self.devices.values():
            place = placed.get(d.car, 0)
            self.device_addresses[d.name] = d.car * 16 + place
            placed[d.car] = place + 1
        self.segments: dict[int, MvbSegment] = {}
        for unit, cars in UNIT_CARS.items():
            cab = cars[0] if unit == 1 else cars[-1]
            near, far = (cars[1], cars[2]) if unit == 1 else (cars[1], cars[0])
            ranks = (f"car{cab}.CCU", f"car{near}.VCU", f"car{far}.VCU")
            self.segments[unit] = MvbSegment(
                unit, DualLineBus(f"unit{unit}.MVB", b.lines_sent, b.line_switch_after), ranks,
                [d for d in self.devices.values() if d.car in cars],
                [m for m in self.ios.values() if m.car in cars])
        self.wtb = DualLineBus("WTB", b.lines_sent, b.line_switch_after)
        self.wtb_master: str | None = b.wtb_backup_ranks[0]
        self.wtb_last_master_t = 0
        self.wtb_missing = {n: 0 for n in self.nodes}
        self.wtb_reported: set[str] = set()
        self.wtb_answered_at = {n: 0 for n in self.nodes}
        self._give_up_marks: dict[str, Timer] = {}
        self.desk = {cab: {"key": False, "direction": "neutral", "traction": 0, "brake": 0} for cab in CAB_CARS}
        self.emergency_switch = False
        self.emergency_mode = False
        self.speed_kmh = 0.0
        self.modes = {1: "power-up", 2: "power-up"}
        self.started = False
        self.pending_effort: dict[str, int] = {}     # device -> effort it is about to apply (actuator latency)

    # -- trace ------------------------------------------------------------------------------------
    def emit(self, source: str, kind: str, **fields: Any) -> None:
        self.events.append(new_event(TraceEvent, (self.kernel.now, source, kind, fields)))

    # -- bulk advance (sut/reference/bulk.py) -------------------------------------------------------
    BULK_SKIP = ("events",)           # the trace is history, not state

    def bulk_period_us(self) -> int:
        """The steady period: every cyclic activity and each unit's round of device status polls (one device
        per basic period), stretched if need be so that the two periods bulk.py checks outlast the longest
        time the model compares with: a state that only waits for such a time to run out would look steady."""
        t = self.cfg.timing
        rounds = [len(seg.devices) * t.mvb_basic_period_us for seg in self.segments.values() if seg.devices]
        period = cyclic_period_us(self.kernel, *rounds, t.io_period_us, t.command_period_us)
        # (message_give_up_us is longer, but marked by a timer: _mark_give_up)
        longest = max(t.gateway_timeout_us, t.sink_timeout_us, t.mvb_master_timeout_us * 2,
                      t.wtb_backup_step_us * len(self.cfg.behaviour.wtb_backup_ranks))
        return period * (longest // (2 * period) + 1)

    # -- life cycle -------------------------------------------------------------------------------
    def start(self) -> None:
        t = self.cfg.timing
        self.started = True
        # Without a task jitter (the reference) every period's task starts on time: no late start to work out.
        on_time = not t.task_jitter_us
        for unit in self.segments:
            self.kernel.every(t.mvb_basic_period_us, self._mvb_period_now if on_time else self._mvb_period,
                              args=(unit,))
        self.kernel.every(t.wtb_cycle_us, self._wtb_cycle_now if on_time else self._wtb_cycle)
        self.kernel.every(t.mvb_basic_period_us, self._watch_masters, phase=t.mvb_basic_period_us // 2)
        self.kernel.every(t.speed_tick_us, self._speed_tick)
        for name in self.nodes:
            self._mark_give_up(name)
        for unit in self.segments:
            self._apply(unit)

    # -- MVB --------------------------------------------------------------------------------------
    def _late_start(self, period_us: int) -> int:
        """How late this period's task starts: 0 in the reference; with a task jitter (MetroTiming,
        tests/freedom_metro.py) every other period starts that late, a pattern that repeats every 2 periods."""
        jitter = self.cfg.timing.task_jitter_us
        return jitter if jitter and (self.kernel.now // period_us) % 2 else 0

    def _mvb_period(self, unit: int) -> None:
        late = self._late_start(self.cfg.timing.mvb_basic_period_us)
        if late:
            self.kernel.call_later(late, self._mvb_period_now, unit)
        else:
            self._mvb_period_now(unit)

    def _mvb_period_now(self, unit: int) -> None:
        seg = self.segments[unit]
        master = self.nodes[seg.master]
        if not master.masters_mvb:
            return
        t, b = self.cfg.timing, self.cfg.behaviour
        basic, bit_ns, name = t.mvb_basic_period_us, t.mvb_bit_ns, master.name
        schedule, message = self.kernel.schedule, self._mvb_message
        k = self.kernel.now // basic
        # The whole message is taken at its master frame's instant, which is what an analyser logs; the polls
        # of one period go out in this order (I/O modules, train command, one device's status), back to back.
        offset = 0
        if k % (t.io_period_us // basic) == 0:
            f_code = b.io_port_f_code
            for module in seg.ios:
                schedule(offset, message, unit, name, "io", module, f_code)
                offset += _message_us(f_code, bit_ns)
        if k % (t.command_period_us // basic) == 0:
            schedule(offset, message, unit, name, "cmd", None, ports.COMMAND_F_CODE)
            offset += _message_us(ports.COMMAND_F_CODE, bit_ns)
        schedule(offset, message, unit, name, "status", seg.devices[k % len(seg.devices)], b.status_poll_f_code)

    def _address(self, unit: int, what: str, target: Any) -> int:
        if what == "io":
            return ports.IO_ADDRESSES[target.name.split(".")[1]]
        if what == "cmd":
            return ports.COMMAND_ADDRESS
        return self.device_addresses[target.name]

    def _mvb_message(self, unit: int, master_name: str, what: str, target: Any, f_code: int) -> None:
        seg = self.segments[unit]
        master = self.nodes[master_name]
        if seg.master != master_name or not master.masters_mvb:
            return
        bus = seg.bus
        address = self._address(unit, what, target)
        if what == "status" and self.cfg.behaviour.status_polls_one_address:
            address = min(self.device_addresses[device.name] for device in seg.devices)
        # On whole lines, untapped, a frame arrives as it was sent: what it decodes to is the frame the sender
        # encoded (tests/test_mvb.py holds decode to undo encode), so the bus is handed that, not its bits.
        # Several thousand frames a simulated second; a damaged or tapped bus takes every frame bit by bit.
        as_sent = bus.whole and bus.name not in self.tapped
        if as_sent:
            got = bus.carry_as_sent(master_frame(f_code, address))
        else:
            got = self._carry(bus, "master", encode_master(f_code, address), decode_master)
        if got.data is None:
            self.emit(bus.name, "mvb.msg", master=master_name, f_code=f_code, address=address, line=None,
                      responder=None, lost=True)
            self._diagnose_lines(bus, master)
            return
        seg.last_master_t = self.kernel.now
        # IEC 61375-3-1 assigns no slave frame to F_code 5-7 and 10-11: a device ignores such a master frame
        # (docs/decisions.md), so a poll with one goes unanswered.
        source, data = (target.name if target is not None else master.name, None) if got.data.reserved \
            else self._answer(seg, master, what, target)
        line, master_line = None, got.line
        if data is not None:
            size = slave_size_bits(f_code)
            long_one = self.cfg.behaviour.one_check_sequence and size > 64
            if as_sent and not long_one and len(data) * 8 == size and bus.whole:
                got = bus.carry_as_sent(data)       # (answering may have changed the bus: asked again)
                line = got.line
                self._deliver(seg, master, what, target, data)
            else:
                wire = _one_check_encode(data) if long_one else encode_slave(data)
                decode: Callable = ((lambda raw: _one_check_decode(raw, size)) if long_one
                                    else (lambda raw: decode_slave(raw, size)))
                got = self._carry(bus, "slave", wire, decode)
                if got.data is not None:
                    line = got.line
                    self._deliver(seg, master, what, target, got.data.data)
        if what == "status":
            self._diagnose_device(seg, master, target, answered=line is not None)
        self.emit(bus.name, "mvb.msg", master=master_name, f_code=f_code, address=address, line=master_line,
                  responder=source if line else None, lost=data is not None and line is None)
        self._diagnose_lines(bus, master)

    def _answer(self, seg: MvbSegment, master: ControlUnit, what: str, target: Any) -> tuple[str, bytes | None]:
        if what == "io":
            data = self._io_port(target).encode()          # padded to the port's size (F_code), spare bits 0
            return target.name, data + bytes(slave_size_bits(self.cfg.behaviour.io_port_f_code) // 8 - len(data))
        if what == "cmd":
            cmd = self._command(seg, master)
            return master.name, cmd.encode() if cmd is not None else None
        if target.failed:
            return target.name, None
        return target.name, _READY_WORD

    def _io_port(self, module: IoModule) -> IoPort:
        if module.failed:
            di, ai = module.frozen or (0, (0, 0, 0))
            return IoPort(di, ai, 0)
        desk, b = self.desk[module.car], self.cfg.behaviour
        di = (desk["key"] << (b.di_key - 1)) | ((desk["direction"] == "forward") << (b.di_forward - 1)) \
            | ((desk["direction"] == "reverse") << (b.di_reverse - 1))
        ai = [0, 0, 0]
        ai[b.ai_traction - 1] = desk["traction"] * b.ai_full_scale // 100
        ai[b.ai_brake - 1] = desk["brake"] * b.ai_full_scale // 100
        for name, value in module.forced.items():
            n = int(name[2:])
            if name.startswith("DI"):
                di = (di & ~(1 << (n - 1))) | (bool(value) << (n - 1))
            else:
                ai[n - 1] = int(value)
        # The module counts its refreshes without bound (a bulk advance carries a count over a jump, not a
        # wrap); the wire carries 1..65535, and 0 means "not alive".
        module.life += 1
        return IoPort(di, (ai[0], ai[1], ai[2]), (module.life - 1) % 0xFFFF + 1)

    def _deliver(self, seg: MvbSegment, master: ControlUnit, what: str, target: Any, data: bytes) -> None:
        now = self.kernel.now
        if what == "io":
            # Of the life signal the master keeps whether it is set (RED-07), not the count: the count wraps
            # with the wire's 16 bits, and a kept value that wraps cannot be carried over a bulk jump.
            port = IoPort.decode(data[:16])           # the port's first 128 bits; the rest spare
            seg.io_data[target.name] = (IoPort(port.di, port.ai, 1 if port.life else 0), now)
        elif what == "cmd":
            # What the command says, not its number, as the life signal above: nothing reads the number
            # here, and one that wraps with the wire's 16 bits could not be carried over a bulk jump.
            sent = Command.decode(data)
            cmd = Command(sent.mode, sent.direction, sent.traction, sent.brake, 0)
            seg.cmd, seg.cmd_t = cmd, now
            # put off, not replaced: every command (each 2 ms) re-arms it (Kernel.put_off)
            seg.sink_timer = self.kernel.put_off(seg.sink_timer, self.cfg.timing.sink_timeout_us, self._sink_timeout,
                                                 seg.unit)
            if seg.stale:
                seg.stale = False
                self.emit(seg.bus.name, "pd.fresh", port="train command")
            self._apply(seg.unit)

    def _sink_timeout(self, unit: int) -> None:
        seg = self.segments[unit]
        seg.stale = True
        seg.sink_timer = None
        self.emit(seg.bus.name, "pd.stale", port="train command", last_ms=seg.cmd_t / 1000)
        self._apply(unit)

    # -- the train command (traction/brake control, TCN-08) ------------------------------------------
    def _inputs(self, seg: MvbSegment, master: ControlUnit) -> IoPort | None:
        """The cab's inputs as the unit's master reads them: module 1 while its life signal is set, else
        module 2 (RED-07)."""
        b, t = self.cfg.behaviour, self.cfg.timing
        oldest = self.kernel.now - 3 * t.io_period_us

        def alive(module: IoModule) -> bool:
            port, at = seg.io_data.get(module.name, (None, -1))
            return port is not None and at >= oldest and (b.use_io_module_2 or not module.name.endswith("IO2")) \
                and (port.life != 0 or not b.io_life_signal_checked)

        # The first alive in rank order (a first-match search: a module passed over does not end it).
        chosen = next((module.name for module in seg.ios if alive(module)), None)
        if chosen != seg.io_used and seg.ios:
            before, seg.io_used = seg.io_used, chosen
            self.emit(master.name, "io.select", module=chosen)
            if before is not None:
                self._raise(master, f"inputs from {chosen}" if chosen else "no MVB I/O module alive")
        return seg.io_data[chosen][0] if chosen else None

    def _command(self, seg: MvbSegment, master: ControlUnit) -> Command | None:
        seg.cmd_seq += 1
        inputs = self._inputs(seg, master) if seg.ios else None
        b = self.cfg.behaviour
        if inputs is not None and inputs.input(b.di_key):
            if master.kind == "VCU" and not b.vcu_takes_control:
                return None
            direction = ("forward" if inputs.input(b.di_forward)
                         else "reverse" if inputs.input(b.di_reverse) else "neutral")
            traction = min(inputs.ai[b.ai_traction - 1] * FULL // b.ai_full_scale, FULL)
            brake = min(inputs.ai[b.ai_brake - 1] * FULL // b.ai_full_scale, FULL)
            return Command("normal", direction, traction, brake, seg.cmd_seq)
        if master.wtb_cmd is not None and self.kernel.now - master.wtb_cmd_t <= self.cfg.timing.gateway_timeout_us:
            relayed: Command = master.wtb_cmd           # the active cab's command, through the gateway
            return Command(relayed.mode, relayed.direction, relayed.traction, relayed.brake, seg.cmd_seq)
        if master.wtb_cmd_t < 0 and self.kernel.now <= self.cfg.timing.gateway_timeout_us:
            return Command("no cab", "neutral", 0, FULL, seg.cmd_seq)      # just powered up, nothing heard yet
        return Command("network failure", "neutral", 0, FULL, seg.cmd_seq)

    # -- VVVF and BECU: what they apply ----------------------------------------------------------------
    def refresh_outputs(self) -> None:
        """After a desk change or a fault: what VVVF and BECU apply (in emergency operation the desk acts
        through hard wires, not through the network)."""
        if self.started:
            for unit in self.segments:
                self._apply(unit)

    def fail_io(self, module: IoModule) -> None:
        """A failed module keeps answering: life signal 0 and the inputs it read last."""
        if not module.failed:
            port = self._io_port(module)
            module.frozen = (port.di, port.ai)
        module.failed = True

    def _apply(self, unit: int) -> None:
        self._apply_unit(unit)
        if self.cfg.behaviour.standstill_holding_brake:
            # The hold follows the active cab's command: every unit at once (idempotent for all else).
            for other in self.segments:
                if other != unit:
                    self._apply_unit(other)

    def _apply_unit(self, unit: int) -> None:
        seg = self.segments[unit]
        cmd = seg.cmd
        failure = seg.stale or cmd is None or cmd.mode != "normal"
        mode = "emergency operation" if self.emergency_mode else (
            "normal" if not failure else ("no cab" if cmd is not None and cmd.mode == "no cab" and not seg.stale
                                          else "train network failure"))
        if mode != self.modes[unit]:
            before, self.modes[unit] = self.modes[unit], mode
            self.emit(f"unit{unit}", "mode.change", mode=mode)
            if mode == "train network failure" and before != "power-up":
                master = self.nodes[seg.master]
                if master.alive:
                    self._raise(master, "train network failure: braking to a stop")
        active = next((c for c in CAB_CARS if self.desk[c]["key"]), None)
        # The order within one instant is the product's (MetroBehaviour.sinks_last_first, tests/freedom_metro.py).
        for dev in (seg.sinks[::-1] if self.cfg.behaviour.sinks_last_first else seg.sinks):
            if dev.failed:
                value = 0
            elif self.emergency_mode:
                desk = self.desk[active] if active else None
                if desk is None:
                    value = 0 if dev.kind == "VVVF" else FULL
                elif dev.kind == "VVVF":
                    value = desk["traction"] * 100 if desk["direction"] != "neutral" else 0
                else:
                    value = desk["brake"] * 100
            elif failure:
                if not self.cfg.behaviour.network_failure_brake and cmd is not None and cmd.mode == "normal":
                    value = dev.applied
                else:
                    value = 0 if dev.kind == "VVVF" else FULL
            elif dev.kind == "VVVF":
                value = cmd.traction if cmd.direction != "neutral" else 0
            else:
                value = cmd.brake
            self._set_effort(dev, self._effort(seg, dev, mode, value))

    def _set_effort(self, dev: Device, value: int) -> None:
        """`dev` is to apply `value` (0.01 %) from now on, called at every refresh. The reference's devices
        apply it at once; with an actuator latency (MetroTiming, tests/freedom_metro.py) a device applies it
        that much later, and drops a change asked back meanwhile."""
        latency = self.cfg.timing.actuator_latency_us
        if latency:
            if value == self.pending_effort.get(dev.name, dev.applied):
                return
            if value == dev.applied:
                self.pending_effort.pop(dev.name, None)
                return
            self.pending_effort[dev.name] = value
            self.kernel.call_later(latency, self._late_effort, dev.name, value)
            return
        if value != dev.applied:
            dev.applied = value
            self.emit(dev.name, "pd.change", value=value / 100)

    def _late_effort(self, name: str, value: int) -> None:
        if self.pending_effort.get(name) == value:
            del self.pending_effort[name]
            dev = self.devices[name]
            dev.applied = value
            self.emit(name, "pd.change", value=value / 100)

    def _effort(self, seg: MvbSegment, dev: Device, mode: str, value: int) -> int:
        """What `dev` applies, given `value` (0.01 %), the effort the unit's train command (or the hard wires)
        asks of it in `mode`. The reference applies exactly what is asked; with a standstill holding brake
        (MetroBehaviour, a product's option: tests/freedom_metro.py) every BECU holds at least that while the
        train stands in normal mode and the active cab's command asks no traction."""
        hold = self.cfg.behaviour.standstill_holding_brake
        if hold and dev.kind == "BECU" and mode == "normal" and not dev.failed and self._holding():
            return max(value, hold)
        return value

    def _holding(self) -> bool:
        """The train stands and the active cab's train command, as its unit's master reads it, asks no
        traction: a train-wide function of the active cab, so every BECU takes the hold off at the instant that
        command asks traction."""
        if self.speed_kmh > 0 or self.emergency_mode:
            return False
        active = next((c for c in CAB_CARS if self.desk[c]["key"]), None)
        if active is None:
            return False
        seg = self.segments[1 if active == 1 else 2]
        cmd = seg.cmd
        if seg.stale or cmd is None or cmd.mode != "normal":
            return False
        return cmd.traction == 0 or cmd.direction == "neutral"

    def _speed_tick(self) -> None:
        if self.emergency_switch and not self.emergency_mode and (
                self.speed_kmh == 0 or self.cfg.behaviour.emergency_operation_at_speed):
            self.emergency_mode = True
            for unit in self.segments:
                self._apply(unit)
        if self.speed_kmh <= 0:
            return
        becus = [d for d in self.devices.values() if d.kind == "BECU"]
        mean = sum(d.applied for d in becus) / len(becus) / FULL
        if mean <= 0:
            return
        dt_s = self.cfg.timing.speed_tick_us / 1e6
        self.speed_kmh = max(0.0, self.speed_kmh - self.cfg.timing.brake_decel_kmh_per_s * mean * dt_s)
        if self.speed_kmh == 0:
            self.emit("train", "train.stop")

    # -- masters by rank after silence (RED-04, RED-05) ------------------------------------------------
    def _watch_masters(self) -> None:
        t = self.cfg.timing
        now = self.kernel.now
        for seg in self.segments.values():
            name = self._successor(seg.ranks, seg.master, seg.last_master_t, t.mvb_master_timeout_us,
                                  "masters_mvb")
            if name is not None:
                before, seg.master, seg.last_master_t = seg.master, name, now
                self.emit(name, "master.take", bus=seg.bus.name, after=before)
                self._raise(self.nodes[name], f"MVB master of unit {seg.unit} ({before} silent)")
        name = self._successor(self.cfg.behaviour.wtb_backup_ranks, self.wtb_master, self.wtb_last_master_t,
                               t.wtb_backup_step_us, "on_wtb")
        if name is not None:
            before, self.wtb_master, self.wtb_last_master_t = self.wtb_master, name, now
            self.emit(name, "master.take", bus="WTB", after=before)
            self._raise(self.nodes[name], f"WTB master ({before} silent)")

    def _successor(self, ranks: tuple[str, ...], master: str | None, last_frame_us: int, step_us: int,
                   up: str) -> str | None:
        """Who takes a bus whose master is down: the first of the others, in rank order, that is up (`up`:
        the unit attribute that says so) and whose place x `step_us` of silence has passed; None if nobody."""
        current = self.nodes.get(master) if master else None
        if current is not None and getattr(current, up):
            return None
        silent = self.kernel.now - last_frame_us
        waiting = [n for n in ranks if n != master]
        for position, name in enumerate(waiting, start=1):
            if getattr(self.nodes[name], up) and silent >= position * step_us:
                return name
        return None

    # -- WTB --------------------------------------------------------------------------------------
    def _wtb_cycle(self) -> None:
        late = self._late_start(self.cfg.timing.wtb_cycle_us)
        if late:
            self.kernel.call_later(late, self._wtb_cycle_now)
        else:
            self._wtb_cycle_now()

    def _wtb_cycle_now(self) -> None:
        master = self.nodes.get(self.wtb_master) if self.wtb_master else None
        if master is None or not master.on_wtb:
            return
        t = self.cfg.timing
        offset = 0
        for name in self.nodes:
            # Frame time from a size estimate: building the telegram now would send its messages early.
            bits = WTB_OVERHEAD_BITS * 2 + 8 * (80 + 48 * len(self.nodes[name].outbox))
            self.kernel.call_later(offset, self._wtb_message, master.name, name)
            offset += DualLineBus.frame_us(bits, t.wtb_bit_ns)

    def _telegram(self, node: ControlUnit) -> dict | None:
        if not node.on_wtb:
            return None
        seg = self.segments[node.unit]
        cmd = None
        if seg.master == node.name and seg.ios and seg.cmd is not None and seg.cmd.mode == "normal" \
                and not seg.stale and self._key_seen(seg):
            cmd = seg.cmd.as_json()
        elif seg.master == node.name and seg.ios and seg.io_used is not None and not self._key_seen(seg):
            cmd = ["no cab", "neutral", 0, FULL]
        # A destination silent on the WTB for longer than the give-up time is no longer waited for.
        limit = self.kernel.now - self.cfg.timing.message_give_up_us
        gone = {d for d, at in self.wtb_answered_at.items() if at < limit}
        for record in node.outbox:
            node.awaiting[record.seq] -= gone
        for record in [r for r in node.outbox if not node.awaiting[r.seq]]:
            node.awaiting.pop(record.seq)
        node.outbox = [r for r in node.outbox if r.seq in node.awaiting]
        events = [[r.seq, r.t_us, r.text] for r in node.outbox]
        if not self.cfg.behaviour.message_ack:
            node.outbox = []                            # sent once, lost if the telegram is
            node.awaiting.clear()
        acks = {origin: seq for origin, seq in node.stored_upto.items()}
        return {"n": node.name, "cmd": cmd, "ev": events, "ack": acks}

    def _key_seen(self, seg: MvbSegment) -> bool:
        if seg.io_used is None:
            return False
        port, _ = seg.io_data[seg.io_used]
        return port.input(self.cfg.behaviour.di_key)

    def _wtb_message(self, master_name: str, polled: str) -> None:
        master = self.nodes[master_name]
        if self.wtb_master != master_name or not master.on_wtb:
            return
        bus = self.wtb
        wire = ports.wtb_encode({"poll": polled, "m": master_name})
        got = self._carry(bus, "master", wire, ports.wtb_decode)
        if got.data is None:
            self.emit("WTB", "wtb.msg", master=master_name, polled=polled, line=None, answered=False, lost=True)
            self._diagnose_lines(bus, master)
            return
        self.wtb_last_master_t = self.kernel.now
        node = self.nodes[polled]
        telegram = self._telegram(node)
        line, master_line = None, got.line
        if telegram is not None:
            wire = ports.wtb_encode(telegram)
            got = self._carry(bus, "slave", wire, ports.wtb_decode)
            if got.data is not None:
                line = got.line
                for receiver in self.nodes.values():
                    if receiver is not node and receiver.on_wtb:
                        self._receive_telegram(receiver, got.data)
        self.emit("WTB", "wtb.msg", master=master_name, polled=polled, line=master_line, answered=line is not None,
                  lost=telegram is not None and line is None)
        self._diagnose_wtb_node(master, polled, answered=line is not None)
        self._diagnose_lines(bus, master)

    def _receive_telegram(self, receiver: ControlUnit, telegram: dict) -> None:
        now = self.kernel.now
        origin = telegram["n"]
        if telegram["cmd"] is not None and self.nodes[origin].unit != receiver.unit:
            # Every gateway keeps the other unit's train command, so a standby that takes its unit's MVB has
            # it at once. Its own unit's command comes from its own cab's I/O modules, never over the WTB.
            # It numbers what it relays itself, so it keeps no number (one that wraps could not be carried
            # over a bulk jump).
            receiver.wtb_cmd, receiver.wtb_cmd_t = Command.from_json(telegram["cmd"]), now
        takes_records = receiver.has_memory or (self.cfg.behaviour.backup_master_stores
                                                and self.wtb_master == receiver.name)
        if self.cfg.behaviour.records_via_wtb:
            for seq, t_us, text in telegram["ev"]:
                if seq <= receiver.stored_upto.get(origin, 0):
                    continue                           # a resent message already taken in
                receiver.stored_upto[origin] = seq
                record = Record(t_us, origin, seq, text)
                receiver.known.append(record)
                if takes_records:
                    receiver.store.append(record)
                    self.emit(receiver.name, "record.store", origin=origin, text=text)
        for dest_origin, seq in telegram["ack"].items():
            if dest_origin == receiver.name:
                self._acknowledged(receiver, origin, seq)

    def _acknowledged(self, node: ControlUnit, by: str, upto: int) -> None:
        keep = []
        for record in node.outbox:
            waiting = node.awaiting.get(record.seq, set())
            if record.seq <= upto:
                waiting.discard(by)
            if waiting:
                keep.append(record)
            else:
                node.awaiting.pop(record.seq, None)
        node.outbox = keep

    # -- events and records (TCN-08, RED-04, RED-05) ----------------------------------------------------
    def _raise(self, node: ControlUnit, text: str) -> None:
        node.seq += 1
        record = Record(self.kernel.now, node.name, node.seq, text)
        self.emit(node.name, "event.raise", text=text)
        node.known.append(record)
        if node.has_memory or (self.cfg.behaviour.backup_master_stores and self.wtb_master == node.name):
            node.store.append(record)
            self.emit(node.name, "record.store", origin=node.name, text=text)
        # Numbered messages to every other CCU, resent until each acknowledges (TCN-06 message data).
        dests = {n.name for n in self.nodes.values() if n.kind == "CCU" and n is not node}
        node.outbox.append(record)
        node.awaiting[record.seq] = dests

    def _diagnose_device(self, seg: MvbSegment, master: ControlUnit, device: Device, answered: bool) -> None:
        if answered:
            seg.status_missing[device.name] = 0
            if device.name in seg.status_reported:
                seg.status_reported.discard(device.name)
                self._raise(master, f"{device.name}: answering again")
            return
        seg.status_missing[device.name] += 1
        if seg.status_missing[device.name] >= self.cfg.timing.status_silence_polls \
                and device.name not in seg.status_reported:
            seg.status_reported.add(device.name)
            self._raise(master, f"{device.name}: no status data")

    def _mark_give_up(self, name: str) -> None:
        """A timer at the moment messages to `name` stop being resent if it stays silent (the give-up itself
        is decided when the next telegram is built): it does nothing, but it tells a bulk jump that something
        will change then (bulk.fixed_timer_limit), as the comparison alone cannot."""
        at = self.wtb_answered_at[name] + self.cfg.timing.message_give_up_us + 1
        # put off, not replaced: every answer on the WTB (each 25 ms) moves it (Kernel.put_off)
        self._give_up_marks[name] = self.kernel.put_off(self._give_up_marks.get(name), at - self.kernel.now,
                                                        _nothing)

    def _diagnose_wtb_node(self, master: ControlUnit, polled: str, answered: bool) -> None:
        if answered:
            self.wtb_answered_at[polled] = self.kernel.now
            self._mark_give_up(polled)
            self.wtb_missing[polled] = 0
            if polled in self.wtb_reported:
                self.wtb_reported.discard(polled)
                self._raise(master, f"{polled}: answering on WTB again")
            return
        self.wtb_missing[polled] += 1
        if self.wtb_missing[polled] >= self.cfg.timing.status_silence_polls and polled not in self.wtb_reported:
            self.wtb_reported.add(polled)
            self._raise(master, f"{polled}: no answer on WTB")

    def _diagnose_lines(self, bus: DualLineBus, master: ControlUnit) -> None:
        for ln in LINES:
            line = bus.lines[ln]
            if line.bad_run >= 3 and not line.reported and ln in self.cfg.behaviour.lines_sent:
                line.reported = True
                self._raise(master, f"{bus.name} line {ln}: fault")
            elif line.bad_run == 0 and line.reported:
                line.reported = False
                self._raise(master, f"{bus.name} line {ln}: restored")

    def _carry(self, bus: DualLineBus, frame_type: str, wire: bytes, decode: Callable[[bytes], Any]) -> Carried:
        """One frame over both lines, as the analyser, the receivers and the diagnosis see it."""
        if bus.name in self.tapped:
            self.emit(bus.name, "bus.frame", type=frame_type, hex=wire.hex())
        got = bus.carry(wire, decode,
                        lambda frm, to, why: self.emit(bus.name, "line.switch", frm=frm, to=to, reason=why))
        for error in got.errors:
            self.emit(bus.name, "frame.discard", error=error)
        return got
