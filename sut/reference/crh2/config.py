"""Parameters of the reference train: the composition and every timing figure, in one place.

Faulty variants for the suite's own tests are built by changing these (or by small subclasses), never
by editing the model at run time. Each figure names the requirement or decision it comes from.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass, field, replace

from sut.errors import OutOfRange

MS = 1000  # microseconds per millisecond



@dataclass(frozen=True)
class Timing:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    bitrate: int = 2_500_000             # NET-07 ARCNET over fibre
    pass_through_us: int = 250           # PRO-01 per-node pass-through
    command_interval_us: int = 10 * MS   # PRO-01 minimum interval (the reference sends at the minimum)
    token_hold_us: int = 10 * MS         # PRO-04 token arrival to token arrival at the next node
    init_silence_us: int = 500 * MS      # PRO-03 no status data after power-up
    token_loss_us: int = 500 * MS        # PRO-05 no token seen
    formation_step_us: int = 20 * MS     # PRO-03 token formed at node number x 20 ms
    takeover_us: int = 50 * MS           # RED-02 system 2 silence watchdog
    block_spacing_us: int = 10 * MS      # PRO-06 consecutive block transfers
    poll_us: int = 10 * MS               # NET-09 CI/BCU polling cycle
    txc_loop_us: int = 500               # DECISIONS: TXC -> MDM8 20 mA loop transfer
    rxc_loop_us: int = 500               # DECISIONS: LCU MDM8 -> RXC 20 mA loop transfer
    rxc_fallback_us: int = 80 * MS       # DECISIONS: RXC trusts the self-diagnostic line after this silence
    command_stale_us: int = 50 * MS      # DECISIONS: MDM9 stops passing on a ring command this old
    selfdiag_bitrate: int = 38_400       # NET-10 secondary sources: HDLC at 38.4 kbit/s
    current_loop_periods_us: tuple[tuple[str, int], ...] = (("ACS", 100 * MS), ("PID", 200 * MS), ("APU", 50 * MS))


@dataclass(frozen=True)
class Behaviour:
    """Switches that only faulty variants turn off; the reference keeps every one on."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    reverse_routing: bool = True          # NET-03 broadcast both ways round the ring
    frame_check: bool = True              # NET-05 discard bad frames
    priorities: bool = True               # NET-06 queue by priority, not arrival
    token_reversal: bool = True           # PRO-04 return the token at a fault
    txc_compare: bool = True              # FS-02 both CPU groups must agree
    txc_inverted_inputs: bool = True      # FS-03 dead input reads as the safe state
    do_steps_only: bool = True            # CMD-03/04 digital outputs carry A/B steps only
    selfdiag_commands_only: bool = True   # NET-04 no status data on the self-diagnostic line
    lamps_parallel: bool = True           # RED-03 both TXCs drive the cab lamps
    cmd_bypass_cpu3: bool = True          # CMD-01 commands do not pass through CPU3
    rxc_own_supply: bool = True           # CMD-01 the RXC has its own supply, not the LCU's
    # Three that only a ring split shows (an LCU whose MDM8 lives but hears no commanding CCU):
    ring_commands_expire: bool = True     # FS-02 a ring command goes stale (50 ms), heard ring or not
    path3_steps_only: bool = True         # CMD-04 path 3 carries A/B steps, MDM8 alive or not
    standby_transmits: bool = False       # RED-02 system 2 only monitors while system 1 is healthy
    block_grant_required: bool = True     # PRO-06 no block transfer before the grant
    block_data_both_ways: bool = True     # PRO-06/NET-03 block data round the ring both ways, as any broadcast
    ilk08_ignored: tuple[str, ...] = ()   # ILK-08 conditions a faulty variant forgets to check
    separation_trips_rapid: bool = True   # ILK-01 separation applies emergency AND rapid brake
    oil_protection: bool = True           # ILK-06 oil pump / oil temperature cut the converters
    ns_forced_passing: bool = True        # ILK-04 entry without warning forces automatic passing
    mcr_exclusive: bool = True            # ILK-07 only one cab's MCR picks up
    counter_bits: int = 32                # DECISIONS: diagnostic counters are 32-bit (TST-02, 72 h)
    clock_from_us32: bool = False         # TST-02: a clock kept in 32-bit microseconds wraps at 71.6 min
    undervoltage_lockout: bool = True     # FS-02 a supply below 0.6 Un past its hold-up switches off
    restart_after_dropout: bool = True    # DECISIONS: a supply restarts once its input is back in range
    selfdiag_fcs_check: bool = True       # NET-05 the RXC discards self-diagnostic frames with a bad FCS
    packet_source_id: int | None = None   # NET-10 a fixed SID on every packet (None: the sender's own ID)
    protection_self_reset_us: int | None = None   # ILK-06 a main circuit that resets itself this long after
                                                  # its fault clears (None: only the driver's reset)
    brake_force_trip_clears_us: int | None = None  # ILK-03 a brake-force trip that clears itself (None: latched)
    waiting_key_picks_up: bool = False    # ILK-07 a cab whose key waited picks up its MCR once the active cab's drops
    regeneration_from_the_top: bool = False  # PRO-05 a token formed again ranks the nodes from the highest number
    brake_force_handle_only: bool = False  # ILK-03 the supervision counts only the brake handle as a demand
    # Freedom variants only (tests/freedom_crh2.py); the reference's values change nothing:
    record_words: tuple[tuple[str, str], ...] = ()  # a fault record's event words of its own ("failed" -> ...)
    outputs_logged_last_first: bool = False        # one evaluation's output changes logged in the other order
    rapid_brake_delay_us: int = 0                  # the rapid-brake outputs logged this much after the rest
    command_take_delay_us: int = 0                 # CI and BCU act on a command this much after it arrives
    output_delay_us: int = 0                       # the vehicle's outputs follow its inputs this much later
    display_delay_us: int = 0                      # the cab monitor shows a change this much later
    pressure_read_kpa: float = 0.0                 # the interlocks and the governor read the main pipe this
                                                   # much high (negative: low)
    speed_read_kmh: float = 0.0                    # the door interlocks read the speed this much high
    standstill_holding_brake: int = 0              # the brake step the commands carry at standstill while
                                                   # they carry no traction notch (0: none)


@dataclass(frozen=True)
class Interlocks:
    """Trip points and delays of the reference. The features test the requirement bands, not these."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    pipe_trip_kpa: float = 590.0        # ILK-02: (590 +/- 10) kPa
    pipe_reset_kpa: float = 620.0       # DECISIONS: hysteresis 30 kPa
    seal_on_kmh: float = 30.0           # ILK-05: press-seal valve energised above 30 km/h
    seal_off_kmh: float = 28.0          # DECISIONS: released below 28 km/h
    door_relay_kmh: float = 5.0         # ILK-05: door-open safety relay acts below 5 km/h
    brake_force_min_pct: float = 50.0   # DECISIONS: "insufficient" = below 50 % of the demand ...
    brake_force_detect_us: int = 500 * MS   # ... for 500 ms
    ns_entry_timeout_us: int = 15_000 * MS  # DECISIONS: no entry signal 15 s after the warning
    ns_exit_timeout_us: int = 10_000 * MS   # DECISIONS: no exit signal 10 s after the entry
    compressor_start_kpa: float = 780.0     # DECISIONS: compressor governor
    compressor_stop_kpa: float = 880.0


@dataclass(frozen=True)
class Environment:
    """Rated environment of the boards (hardware/software class, TST-02; docs/decisions.md "Environment").
    Voltages are fractions of Un; the features test the standards' ranges, not these figures."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    nominal_v: float = 110.0                # EN 50155 Un of the train's battery supply
    continuous_lo: float = 0.70             # EN 50155 continuous 0.7 .. 1.25 Un (VDX-02: 70 .. 125 %)
    continuous_hi: float = 1.25
    dip_lo: float = 0.60                    # EN 50155 fluctuation: 0.6 Un for 0.1 s without deviation
    dip_us: int = 100 * MS
    surge_hi: float = 1.40                  # EN 50155 fluctuation: 1.4 Un for 1 s without deviation
    surge_us: int = 1000 * MS
    hold_up_us: int = 10 * MS               # EN 50155 interruption class S2: 10 ms without reset
    restart_us: int = 300 * MS              # DECISIONS: supply soft start and board boot after a dropout
    temp_lo_c: float = -25.0                # EN 50155 operating temperature class OT3
    temp_hi_c: float = 70.0
    burst_immunity_kv: float = 2.0          # EN 50121-3-2 fast transients on signal and power ports
    contact_bridged_us: int = 1 * MS        # DECISIONS: MDM8 rides out light loss up to 1 ms (IEC 61373)
    insulation_mohm: float = 200.0          # EN 50155 insulation at 500 V DC: at least 20 MOhm
    withstand_v: float = 1500.0             # EN 50155 dielectric test of 110 V circuits: 1500 V rms, 1 min
    breakdown_v: float = 3000.0             # DECISIONS: where the reference's insulation breaks down


MOTOR_CARS_8 = (2, 3, 6, 7)       # CRH2A 4M4T: CI (main converter) in these cars of each set
APU_CARS_8 = (2, 4, 6)            # DECISIONS: cars with an auxiliary power unit on a 30 mA loop

TRACTION_NOTCHES = 10
BRAKE_STEPS = 7
EMERGENCY = 8


@dataclass(frozen=True)
class TrainConfig:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    sets: int = 1
    cars_per_set: int = 8
    timing: Timing = field(default_factory=Timing)
    behaviour: Behaviour = field(default_factory=Behaviour)
    interlocks: Interlocks = field(default_factory=Interlocks)
    environment: Environment = field(default_factory=Environment)

    def __post_init__(self) -> None:
        if self.sets not in (1, 2):
            raise OutOfRange("train sets", self.sets, "1..2 (NET-08 couples two sets)")
        if not 2 <= self.cars_per_set <= 16:
            raise OutOfRange("cars per set", self.cars_per_set, "2..16")

    @property
    def cars(self) -> int:
        return self.sets * self.cars_per_set

    def motor_cars(self) -> list[int]:
        per = self.cars_per_set
        local = MOTOR_CARS_8 if per == 8 else tuple(c for c in range(2, per) if c % 2 == 0)
        return [s * per + c for s in range(self.sets) for c in local]

    def apu_cars(self) -> list[int]:
        per = self.cars_per_set
        local = APU_CARS_8 if per == 8 else (2,)
        return [s * per + c for s in range(self.sets) for c in local if c <= per]

    def cab_cars(self) -> list[int]:
        per = self.cars_per_set
        return [c for s in range(self.sets) for c in (s * per + 1, s * per + per)]

    def with_timing(self, **changes) -> "TrainConfig":
        return replace(self, timing=replace(self.timing, **changes))

    def with_behaviour(self, **changes) -> "TrainConfig":
        return replace(self, behaviour=replace(self.behaviour, **changes))

    def with_interlocks(self, **changes) -> "TrainConfig":
        return replace(self, interlocks=replace(self.interlocks, **changes))

    def with_environment(self, **changes) -> "TrainConfig":
        return replace(self, environment=replace(self.environment, **changes))

    def describe(self) -> dict[str, str]:
        out = {"sets": str(self.sets), "cars per set": str(self.cars_per_set)}
        out.update({f"timing.{k}": str(v) for k, v in asdict(self.timing).items()})
        out.update({f"interlocks.{k}": str(v) for k, v in asdict(self.interlocks).items()})
        out.update({f"environment.{k}": str(v) for k, v in asdict(self.environment).items()})
        changed = {k: v for k, v in asdict(self.behaviour).items() if v != getattr(Behaviour(), k)}
        out["behaviour"] = ", ".join(f"{k}={v}" for k, v in changed.items()) or "reference"
        return out
