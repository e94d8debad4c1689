"""Figures of the ATP reference. Marked with the requirement they come from; the rest are this reference's
choices, explained in docs/decisions.md ("VDX emergency-brake interface"). Faulty variants in
tests/variants.py change one field each.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

MS = 1000


@dataclass(frozen=True)
class Vdx:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    nominal_v: float = 110.0                  # VDX-02
    supply_lo: float = 0.70                   # VDX-02: 70 % .. 125 % of 110 V
    supply_hi: float = 1.25
    selftest_period_us: int = 5000 * MS       # VDX-03: every 5 s
    selftest_removal_us: int = 3 * MS         # VDX-03: one excitation source removed for 3 ms
    sample_at_us: int = 1 * MS                # VDX-03: sampled from the start of the 2nd ms
    low_threshold_v: float = 6.0              # VDX-03: below 6 V passes
    postpone_us: dict | None = None           # VDX-06: per firmware, see POSTPONE
    c019_latches: bool = True                 # VDX-03/06: FS stays off until restart
    c019_self_clear_us: int | None = None     # faulty variants only: a "latched" C019 that clears itself
    relay_no_open_us: int = 5 * MS            # VDX-04: EB2R NO contact opens < 6 ms after its coil loses power
    relay_nc_close_us: int = 12 * MS          # VDX-04: EB2R NC contact closes < 15 ms after
    relay_pick_up_us: int = 8 * MS
    isolation_bypasses: bool = True           # VDX-01
    # VDX-05, the coil's stored energy: the FS output falls to 0 V in  fall_min + fall_a * (V/137)^2 *
    # exp(-tau / fall_tau)  ms, tau = ms from the release to the self-test. Fitted to the article's two
    # oscilloscope readings at 137 V (19.795 ms -> 2.102 ms, 35.75 ms -> 0.797 ms).
    fall_min_ms: float = 0.3
    fall_a_ms: float = 8.90
    fall_tau_ms: float = 12.39
    fall_v_exponent: float = 2.0


POSTPONE = {"old": 16 * MS, "new": 48 * MS}   # VDX-06


@dataclass(frozen=True)
class Atp:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    cfsk_period_us: int = 50 * MS             # one CFSK comparison every 50 ms
    cfsk_confirmations: int = 3               # ATP-03
    decode_delay_us: int = 150 * MS           # ATP-02 dt: three comparisons
    d_sen_m: float = 3.0                      # ATP-02 D_Sen: CFSK antenna behind the front
    position_uncertainty_m: float = 5.0       # ATP-02: min/max safe front = position -/+ this
    tick_us: int = 10 * MS                    # odometry and supervision
    def_steps: int = 10                       # ATP-08
    def_step_us: int = 2200 * MS              # ATP-08 (was 2.5 s)
    fs_to_ps_m: float = 150.0                 # ATP-06 (was 300 m)
    default_ps_kmh: float = 45.0              # ATP-07
    stop_window_m: float = 0.5                # ATP-09
    linking_window_m: float = 20.0            # a linked group not found 20 m past its place is missing
    no_reaction_groups: tuple[str, ...] = ("70-2-4-15", "70-2-4-16")   # ATP-12
    parses_etcs46: bool = True                # ATP-11
    widen_rear: bool = True                   # ATP-02: the range reaches v*dt further to the rear
    balise_switches_carrier_set: bool = True  # ATP-04
    fault_stops_decoding: bool = True         # ATP-01: a faulty CFSK sends fault information, not results


@dataclass(frozen=True)
class AtpConfig:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    vdx: Vdx = Vdx()
    atp: Atp = Atp()

    def with_vdx(self, **changes) -> "AtpConfig":
        return replace(self, vdx=replace(self.vdx, **changes))

    def with_atp(self, **changes) -> "AtpConfig":
        return replace(self, atp=replace(self.atp, **changes))
