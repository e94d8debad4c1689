"""The VDX emergency-brake interface of the CTCS3-300T ATP (seed 003; VDX-01..06).

The ATP opens the train's emergency-brake loop through EB1R and EB2R in series. EB2R is fed by the VDX's
fail-safe (FS) output: energised = no brake. EB1R is fed by the high-reliability (HR) output: energised =
brake. The isolation switch bypasses both contacts.

Every 5 s the VDX proves it can switch FS off: it removes one of the four excitation sources for 3 ms,
samples the output from the start of the 2nd ms, and passes if it is below 6 V; otherwise fault C019: FS off
(emergency brake), a system error, until restart. The FS output does not fall at once: the relay coil
gives back its stored energy, and a coil energised only a short time ago (a brake released just before
the test) holds the voltage up longer (VDX-05; the fall-time law is in config.Vdx). A self-test that would
come too soon after a release is postponed: 16 ms by the old firmware, 48 ms by the new (VDX-06).
"""
from __future__ import annotations

import math
from typing import Callable

from sut.reference.atp.config import POSTPONE, Vdx
from sut.reference.kernel import Kernel

LOOP_OPEN, LOOP_CLOSED = "open", "closed"


class Relay:
    """A relay with its contact timings: the NO contact opens `no_open_us` after the coil loses power and
    closes `pick_up_us` after it is powered again, so a shorter interruption never moves it (VDX-04)."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, kernel: Kernel, name: str, cfg: Vdx, on_change: Callable[[], None],
                 emit: Callable[..., None]):
        self.kernel, self.name, self.cfg = kernel, name, cfg
        self.powered = False
        self.energised = False          # its armature: NO contact closed, NC contact open
        self._timer = None
        self._on_change, self._emit = on_change, emit

    def power(self, on: bool) -> None:
        if on == self.powered:
            return
        self.powered = on
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        if on != self.energised:
            delay = self.cfg.relay_pick_up_us if on else self.cfg.relay_no_open_us
            self._timer = self.kernel.call_later(delay, self._move, on)

    def _move(self, energised: bool) -> None:
        self._timer = None
        self.energised = energised
        self._emit(self.name, "relay.change", energised=energised)
        self._on_change()


class VdxInterface:
    """Both outputs, the two relays, the loop and the FS self-test."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, kernel: Kernel, cfg: Vdx, emit: Callable[..., None],
                 on_loop: Callable[[], None] | None = None):
        self.kernel, self.cfg, self._emit = kernel, cfg, emit
        self._on_loop = on_loop
        self.supply_v = cfg.nominal_v
        self.firmware = "new"
        self.isolated = False
        self.eb_demand = True            # until the ATP has started up, the brake is applied
        self.c019 = False
        self.powered = False
        self.released_at: int | None = None      # the last FS off -> on, us
        self.testing = False
        self.eb2r = Relay(kernel, "EB2R", cfg, self._loop_changed, emit)
        self.eb1r = Relay(kernel, "EB1R", cfg, self._loop_changed, emit)
        self.loop = LOOP_OPEN
        self._test_timer = None
        self._cycle = None

    # -- power and commands ------------------------------------------------------------------------
    @property
    def supply_ok(self) -> bool:
        v = self.supply_v
        return self.cfg.supply_lo * self.cfg.nominal_v <= v <= self.cfg.supply_hi * self.cfg.nominal_v

    def power_on(self) -> None:
        self.powered = True
        self.c019 = False            # a restart clears C019 (VDX-06: recoverable by restart)
        self._cycle = self.kernel.every(self.cfg.selftest_period_us, self._selftest_due,
                                        phase=self.cfg.selftest_period_us)
        self._drive()

    def power_off(self) -> None:
        self.powered = False
        if self._cycle is not None:
            self.kernel.stop_cyclic(self._cycle)
            self._cycle = None
        if self._test_timer is not None:
            self._test_timer.cancel()
            self._test_timer = None
        self.testing = False
        self._drive()

    def set_isolation(self, on: bool) -> None:
        self.isolated = on
        self._loop_changed()

    def set_supply(self, volts: float) -> None:
        self.supply_v = volts
        self._drive()

    def command_brake(self, on: bool) -> None:
        self.eb_demand = on
        self._drive()

    @property
    def fs_on(self) -> bool:
        return self.powered and self.supply_ok and not self.eb_demand and not self.c019

    @property
    def hr_on(self) -> bool:
        return self.powered and (self.eb_demand or self.c019 or not self.supply_ok)

    def _drive(self) -> None:
        was = self.eb2r.powered
        fs = self.fs_on and not self.testing
        if fs and not was:
            self.released_at = self.kernel.now
            self._emit("VDX", "fs.on")
        elif was and not fs and not self.testing:    # a self-test's 3 ms pull-down is not a switch-off
            self._emit("VDX", "fs.off")
        # During a self-test the output is pulled low for 3 ms; the coil keeps the relay (VDX-04).
        self.eb2r.power(fs)
        self.eb1r.power(self.hr_on)
        self._loop_changed()

    def _loop_changed(self) -> None:
        closed = self.isolated and self.cfg.isolation_bypasses or (self.eb2r.energised and not self.eb1r.energised)
        state = LOOP_CLOSED if closed else LOOP_OPEN
        if state != self.loop:
            self.loop = state
            self._emit("VDX", "loop.change", state=state)
            if self._on_loop is not None:
                self._on_loop()

    # -- the FS self-test (VDX-03, VDX-05, VDX-06) --------------------------------------------------------
    def _selftest_due(self) -> None:
        if not self.fs_on or self.testing:
            return
        since = self.kernel.now - (self.released_at or 0)
        postpone = (self.cfg.postpone_us or POSTPONE)[self.firmware]
        if since < postpone:
            delay = self._postponed_by(postpone, since)
            self._emit("VDX", "selftest.postpone", by_ms=delay / 1000, since_release_ms=since / 1000)
            self._test_timer = self.kernel.call_later(delay, self._selftest)
        else:
            self._selftest()

    def _postponed_by(self, postpone: int, since: int) -> int:
        """How long a test due `since` after a release waits: until `postpone` after the release (VDX-06). A
        hook for a product that counts it from the due time (tests/freedom_atp.py)."""
        return postpone - since

    def fall_ms(self, since_release_us: int) -> float:
        cfg = self.cfg
        energy = cfg.fall_a_ms * (self.supply_v / 137.0) ** cfg.fall_v_exponent
        return cfg.fall_min_ms + energy * math.exp(-since_release_us / 1000 / cfg.fall_tau_ms)

    def voltage_during_test(self, t_us: int, fall_ms: float) -> float:
        """The FS output t_us into a self-test: a linear fall from the supply to 0 V over fall_ms."""
        return max(0.0, self.supply_v * (1 - t_us / 1000 / fall_ms))

    def _selftest(self) -> None:
        self._test_timer = None
        if not self.fs_on:
            return
        self.testing = True
        tau = self.kernel.now - (self.released_at or 0)
        fall = self.fall_ms(tau)
        sample = self.voltage_during_test(self.cfg.sample_at_us, fall)
        self._drive()
        passed = sample < self.cfg.low_threshold_v
        self._emit("VDX", "selftest", since_release_ms=tau / 1000, fall_ms=round(fall, 3),
                   sample_ms=self.cfg.sample_at_us / 1000, sample_v=round(sample, 2),
                   result="pass" if passed else "C019")
        self.kernel.call_later(self.cfg.selftest_removal_us, self._selftest_end, passed)

    def _selftest_end(self, passed: bool) -> None:
        self.testing = False
        self._emit("VDX", "selftest.end")
        if not passed:
            self.c019 = True
            self._emit("VDX", "fault.C019", text="C019: FS output did not go low in its self-test")
            if not self.cfg.c019_latches:
                self.c019 = False
            elif self.cfg.c019_self_clear_us is not None:
                self.kernel.call_later(self.cfg.c019_self_clear_us, self._c019_clears)
        self._drive()

    def _c019_clears(self) -> None:
        self.c019 = False
        self._drive()
