"""Parameters of the metro TCDS reference (seed 002, Shenzhen Metro line 3, Hyundai Rotem TCDS).

Figures from the article are marked (TCN-nn / RED-nn); the others are this reference's choices where the
article is silent, each explained in docs/decisions.md ("Metro TCDS"). Faulty variants in
tests/variants.py change one field each.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

from sut.reference.metro.ports import DEVICE_STATUS_F_CODE

MS = 1000


@dataclass(frozen=True)
class MetroTiming:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    mvb_basic_period_us: int = 1 * MS        # TCN-03
    mvb_bit_ns: int = 667                    # TCN-03: 1.5 Mbit/s
    io_period_us: int = 2 * MS               # driver's commands read from the MVB I/O modules
    command_period_us: int = 2 * MS          # train command port published on each MVB
    wtb_cycle_us: int = 25 * MS              # TCN-03: at most 25 ms
    wtb_bit_ns: int = 1000                   # TCN-03: 1 Mbit/s
    mvb_master_timeout_us: int = 16 * MS     # adjacent VCU takes the MVB (and control) after this silence
    wtb_backup_step_us: int = 75 * MS        # backup of rank r takes the WTB after r x this silence
    gateway_timeout_us: int = 250 * MS       # no train command on the WTB this long: train network failure
    sink_timeout_us: int = 100 * MS          # VVVF/BECU without a fresh command this long: brake to a stop
    message_give_up_us: int = 1000 * MS      # a message is resent this long to a silent destination
    status_silence_polls: int = 3            # device status polls unanswered before a device is reported
    brake_decel_kmh_per_s: float = 3.6       # 1.0 m/s2 at 100 % service brake
    speed_tick_us: int = 10 * MS
    # Hooks for what a product may do otherwise (tests/freedom_metro.py); the reference's values do nothing:
    actuator_latency_us: int = 0             # a VVVF/BECU applies a new effort this long after it is asked
    task_jitter_us: int = 0                  # every other MVB basic period and WTB cycle starts this late


@dataclass(frozen=True)
class MetroBehaviour:
    """Switches that faulty variants turn; the reference is the all-default instance."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    wtb_backup_ranks: tuple[str, ...] = ("car1.CCU", "car2.VCU", "car3.VCU")      # RED-04 order
    lines_sent: str = "AB"                   # RED-06: every frame on both lines
    line_switch_after: int = 1               # RED-06: bad frames on the trusted line before switching
    use_io_module_2: bool = True             # RED-07
    io_life_signal_checked: bool = True      # RED-07: module 1 used only while its life signal is set
    backup_master_stores: bool = False       # RED-04: a backup master stores nothing
    vcu_takes_control: bool = True           # RED-05: adjacent VCU takes over a failed active-cab CCU
    records_via_wtb: bool = True             # RED-04/05: events reach the other CCU's VMS over the WTB
    message_ack: bool = True                 # TCN-06: message data resent until acknowledged
    one_check_sequence: bool = False         # TCN-05: a check byte after every 64 bits, not one per frame
    network_failure_brake: bool = True       # TCN-09: brake to a stop when the train command is lost
    emergency_operation_at_speed: bool = False   # TCN-09: hard-wired operation only from standstill
    status_poll_f_code: int = DEVICE_STATUS_F_CODE   # TCN-05/06: device status request (a reserved code is ignored)
    status_polls_one_address: bool = False   # TCN-05: every status request carries the unit's first device address
    # The I/O map (TCN-07 gives channel counts only; a product wires its own, declared in its IXIT):
    di_key: int = 1                          # DI01: the cab key
    di_forward: int = 2                      # DI02: direction switch at forward
    di_reverse: int = 3                      # DI03: direction switch at reverse
    ai_traction: int = 1                     # AI1: master controller traction demand
    ai_brake: int = 2                        # AI2: master controller brake demand
    ai_full_scale: int = 10_000              # raw count for 100 % demand (0.01 % steps)
    io_port_f_code: int = 3                  # TCN-05: the I/O module port's F_code (3: 128 bits)
    standstill_holding_brake: int = 0        # 0.01 %: brake held at standstill while the active cab asks no traction
    sinks_last_first: bool = False           # a unit refreshes its VVVFs and BECUs in the reverse of their order


@dataclass(frozen=True)
class MetroConfig:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    timing: MetroTiming = MetroTiming()
    behaviour: MetroBehaviour = MetroBehaviour()

    def with_timing(self, **changes) -> "MetroConfig":
        return replace(self, timing=replace(self.timing, **changes))

    def with_behaviour(self, **changes) -> "MetroConfig":
        return replace(self, behaviour=replace(self.behaviour, **changes))
