"""Freedom variants of the atp reference (issue 30, item 4); the rules they follow are beside
tests/variants.py FREEDOM_CLASSES.

Each takes one design choice a conforming CTCS-2 200C ATP or CTCS3-300T VDX may take, by subclassing the
reference's backend and its models (never by editing them). The reference rig serves the three profiles atp,
vdx and atp-crh2, so each variant is run against all three; what it changes is said per product.
"""
from __future__ import annotations

from typing import Any, Callable

from sut.reference.atp.backend import ReferenceAtp
from sut.reference.atp.onboard import OnboardAtp
from sut.reference.atp.vdx import VdxInterface

MS = 1000


# -- task-tick (atp): the DEF and CFSK tasks on a 1 ms tick ------------------------------------------------
# Where in its 1 ms tick a task's slot lands, by slot number: a free-running task clock against the rig's
# microseconds. Always less than the tick, and repeating every four slots: the rig still repeats within its
# steady period (5 s, a whole number of four comparison periods), and no one-shot timer is left pending.
TICK_JITTER_US = (0, 700, 300, 900)


class _TickedOnboard(OnboardAtp):
    """The 200C ATP's DEF self-test and CFSK comparisons run on a 1 ms task tick: each DEF step and each
    comparison lands up to a tick after its slot (2.2 s and 50 ms apart on the slot grid, not accumulating)."""

    def power_on(self) -> None:
        self._def_t0 = self.kernel.now
        super().power_on()

    def _def_next_us(self) -> int:
        # Step k (0-based) is due at t0 + k * 2.2 s and runs on the tick after: up to 0.9 ms late.
        k = self._def_step
        return self._def_t0 + k * self.cfg.def_step_us + TICK_JITTER_US[k % 4] - self.kernel.now

    def _start_comparisons(self) -> None:
        # Comparison k runs at its slot k * 50 ms plus where the tick lands; four cyclic timers of 200 ms, one
        # per place in the jitter pattern, so nothing is a one-shot timer and the rig stays steady.
        period = self.cfg.cfsk_period_us
        for k, late in enumerate(TICK_JITTER_US):
            self.kernel.every(len(TICK_JITTER_US) * period, self._compare, phase=k * period + late)


class TaskTickAtp(ReferenceAtp):
    """Freedom (timing resolution, atp): a 200C ATP whose DEF self-test and CFSK comparisons run on a 1 ms task
    tick, each step or comparison up to 0.9 ms after its slot, declared so (timing_resolution_us 1000). ATP-08's
    2.2 s steps and 22 s and ATP-03's comparisons are met within the tick; held to 1 us, the DEF steps fail."""
    FREEDOM_CLASS = "task-tick"
    DECLARATION = "tests/declarations/task-tick-atp.yaml"
    ONBOARD = _TickedOnboard


# -- actuator-latency (vdx): the ATP's brake reaches the FS output later ----------------------------------
FS_LATENCY_US = 4 * MS


class _LateFsVdx(VdxInterface):
    """The ATP's emergency-brake command reaches the FS output 4 ms later (an input filter and a task cycle);
    a release at once. VDX-04 bounds the relay from its coil, so the loop still opens within 6 ms of the FS
    output going off, 9 ms after the command."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._late = None

    def command_brake(self, on: bool) -> None:
        if self._late is not None:                 # a release before the brake took effect cancels it
            self._late.cancel()
            self._late = None
        if on and not self.eb_demand:
            self._late = self.kernel.call_later(FS_LATENCY_US, self._brake_reaches_fs)
        else:
            super().command_brake(on)

    def _brake_reaches_fs(self) -> None:
        self._late = None
        super().command_brake(True)


class LateFsVdx(ReferenceAtp):
    """Freedom (actuator latency, vdx): the ATP's emergency brake reaches the VDX's FS output 4 ms after the
    command; EB2R still opens the loop within VDX-04's 6 ms of its coil losing power. Nothing is declared: the
    features measure the relay from the FS output going off, not from the command."""
    FREEDOM_CLASS = "actuator-latency"
    EXERCISED_BY = "F-ATP-04"
    VDX_INTERFACE = _LateFsVdx


# -- range-edge-tolerance (vdx): a supply measurement 0.3 % high -------------------------------------------
SUPPLY_READS_HIGH = 1.003


class SupplyToleranceVdx(ReferenceAtp):
    """Freedom (measurement tolerance at range edges, vdx): the VDX measures its supply 0.3 % high, so it takes
    137.1 V for out of range (a little inside VDX-02's 137.5 V) and still works at 76.8 V (a little outside 77 V).
    It declares its measurement accurate to 0.5 % (supply_accuracy_pct), and the features feed the edges moved
    inside by that; held to the reference's 0 %, 137.5 V brakes it."""
    FREEDOM_CLASS = "range-edge-tolerance"
    DECLARATION = "tests/declarations/supply-tolerance-vdx.yaml"
    VDX = {"supply_lo": 0.70 / SUPPLY_READS_HIGH, "supply_hi": 1.25 / SUPPLY_READS_HIGH}


# -- record-wording (atp): the CFSK records in Chinese, fields in another order -----------------------------
class CfskRecordsInChineseAtp(ReferenceAtp):
    """Freedom (record wording, atp): the ATP writes its CFSK records in Chinese, the ATP-05 fields in another
    order and words (`12345.000 CFSK记录 轨道电路类型=ZPW-2000A 状态=正常 信号幅度=420mV 载频=2300Hz 低频码=LU`),
    in the documented shape (a ms stamp, one word per field) and declared by text identifier."""
    FREEDOM_CLASS = "record-wording"
    DECLARATION = "tests/declarations/cfsk-records-zh-atp.yaml"
    STATES = {"ok": "正常", "fault": "故障"}

    def records(self, unit: str) -> list[str]:
        out = []
        for record in super().records(unit):
            stamp, marker, *words = record.split()
            if marker != "CFSK":
                out.append(record)
                continue
            f = dict(word.split("=", 1) for word in words)
            out.append(f"{stamp} CFSK记录 轨道电路类型={f['type']} 状态={self.STATES[f['state']]} "
                       f"信号幅度={f['amplitude']} 载频={f['carrier']}Hz 低频码={f['code']}")
        return out


# -- simultaneous-ordering (atp, vdx): the events of one instant logged in reverse ---------------------------
class _ReversedInstant:
    """A model whose event logger writes what one action emits at one instant in the reverse order (events of
    the same microsecond have no order a requirement gives). The actions named in BATCHED collect their
    events and hand them on last first."""
    BATCHED: tuple[str, ...] = ()

    def _reversed_emit_init(self) -> None:
        self._emit_now: Callable[..., None] = self._emit
        self._emit = self._collect
        self._batch: list | None = None

    def _collect(self, *args: Any, **fields: Any) -> None:
        if self._batch is None:
            self._emit_now(*args, **fields)
        else:
            self._batch.append((args, fields))

    def _batched(self, action: Callable[..., Any], *args: Any) -> Any:
        if self._batch is not None:                # inside another action of the same instant
            return action(*args)
        self._batch = []
        try:
            return action(*args)
        finally:
            batch, self._batch = self._batch, None
            for event_args, fields in reversed(batch):
                self._emit_now(*event_args, **fields)


class _ReversedOnboard(_ReversedInstant, OnboardAtp):
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._reversed_emit_init()

    def _compare(self) -> None:
        self._batched(super()._compare)

    def _tick(self) -> None:
        self._batched(super()._tick)

    def _def(self) -> None:
        self._batched(super()._def)

    def pass_balise(self, group: str, packets: list[dict[str, Any]]) -> None:
        self._batched(super().pass_balise, group, packets)

    def fail_cfsk(self, failed: bool) -> None:
        self._batched(super().fail_cfsk, failed)


class _ReversedVdx(_ReversedInstant, VdxInterface):
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._reversed_emit_init()

    def _selftest_due(self) -> None:
        self._batched(super()._selftest_due)

    def _selftest_end(self, passed: bool) -> None:
        self._batched(super()._selftest_end, passed)

    def command_brake(self, on: bool) -> None:
        self._batched(super().command_brake, on)

    def set_supply(self, volts: float) -> None:
        self._batched(super().set_supply, volts)


class ReversedInstantAtp(ReferenceAtp):
    """Freedom (simultaneous ordering, atp): the ATP logs the events of one decision at one microsecond in the
    reverse order (the brake before the inconsistency that caused it, the report before its comparison)."""
    FREEDOM_CLASS = "simultaneous-ordering"
    EXERCISED_BY = "F-ATP-08"
    ONBOARD = _ReversedOnboard


class ReversedInstantVdx(ReferenceAtp):
    """Freedom (simultaneous ordering, vdx): the VDX logs the events of one instant in the reverse order (the
    FS output off before the C019 and the self-test's end that raised it)."""
    FREEDOM_CLASS = "simultaneous-ordering"
    EXERCISED_BY = "F-ATP-05"
    VDX_INTERFACE = _ReversedVdx


# -- optional-feature (atp): a DMI that announces each mode change ------------------------------------------
class _AnnouncingOnboard(OnboardAtp):
    def _set_mode(self, mode: str) -> None:
        changed = mode != self.s.mode
        super()._set_mode(mode)
        if changed:
            self._message(f"模式 {mode}")


class ModeAnnouncingDmiAtp(ReferenceAtp):
    """Freedom (optional feature, atp): the DMI also announces every mode change (`模式 FS`), a message no
    requirement asks for and none forbids; the features look for the messages they name, not for a DMI that
    shows nothing else."""
    FREEDOM_CLASS = "optional-feature"
    EXERCISED_BY = "F-ATP-11"
    ONBOARD = _AnnouncingOnboard


# -- optional-feature (vdx): the VDX reads the isolation switch and brakes its own outputs while isolated ---------
class _IsolationReadingVdx(VdxInterface):
    """An isolated ATP supervises nothing, so its VDX says brake: FS off and HR on while the switch is on (its
    self-test pauses with the FS output); the switch's contact keeps the loop closed all the while."""

    @property
    def fs_on(self) -> bool:
        return super().fs_on and not self.isolated

    @property
    def hr_on(self) -> bool:
        return super().hr_on or (self.powered and self.isolated)

    def set_isolation(self, on: bool) -> None:
        self.isolated = on
        self._drive()


class BrakesWhileIsolatedVdx(ReferenceAtp):
    """Freedom (optional feature, vdx): the VDX also reads the ATP isolation switch and, while it is on, holds
    both its outputs at brake (EB2R de-energised, EB1R energised) whatever the ATP commands, and pauses its FS
    self-test. VDX-01 gives the switch's bypass, not what the relays behind it do; the loop stays closed through
    the bypass. Nothing is declared; F-ATP-04's release-then-isolate scenario shows the relays drop at the
    isolation, not at the ATP's later brake."""
    FREEDOM_CLASS = "optional-feature"
    EXERCISED_BY = "F-ATP-04"
    VDX_INTERFACE = _IsolationReadingVdx


# -- product-choice (atp, atp-crh2): which brake holds the train after a failed DEF self-test -------------------
class _ServiceBrakeOnDefFault(OnboardAtp):
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def _set_brake(self, brake: str) -> None:
        # Before its DEF self-test is done, the only emergency this ATP commands is a failed step's.
        super()._set_brake("max service" if brake == "emergency" and not self.s.ready else brake)


class DefFaultServiceBrakeAtp(ReferenceAtp):
    """Freedom (a product's choice, atp and atp-crh2): after a failed DEF self-test this 200C ATP holds the train
    with its maximum service brake, not the emergency brake (docs/decisions.md "A failed DEF self-test": which
    brake is the product's). F-ATP-10 and F-ATP-16 accept it: on the fitted train every BCU then receives full
    service, and the train's emergency brake stays released."""
    FREEDOM_CLASS = "product-choice"
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)
    EXERCISED_BY = "F-ATP-16"

    def _build(self) -> None:
        super()._build()
        self.atp.__class__ = _ServiceBrakeOnDefFault


# -- product-choice (vdx): VDX-06's postponement counted from when the test was due ------------------------------
class _PostponeFromDue(VdxInterface):
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def _postponed_by(self, postpone: int, since: int) -> int:
        return postpone


class PostponeFromDueVdx(ReferenceAtp):
    """Freedom (a reading the article leaves to the product, vdx): "postpones a self-test that coincides with a
    release by 16 ms" (VDX-06) read as 16 ms (48 ms) after the test was due, not after the release as the
    reference reads it. F-ATP-06 takes either: from the postponement after the release to the due time plus
    the postponement."""
    FREEDOM_CLASS = "product-choice"
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)
    EXERCISED_BY = "F-ATP-06"

    def _build(self) -> None:
        super()._build()
        self.vdx.__class__ = _PostponeFromDue


FREEDOM: list[type] = [TaskTickAtp, LateFsVdx, SupplyToleranceVdx, CfskRecordsInChineseAtp, ReversedInstantAtp,
                       ReversedInstantVdx, ModeAnnouncingDmiAtp, BrakesWhileIsolatedVdx, DefFaultServiceBrakeAtp,
                       PostponeFromDueVdx]
