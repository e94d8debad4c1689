"""Variants of the reference train for the suite's own tests (DEVELOPERS.md: "that pair is how we know a
feature specifies the right thing").

Faulty variants break exactly one requirement each; the features must reject them. In-band variants differ
from the reference only where the requirements leave room; the features must accept them. Each is a
subclass that changes parameters: the reference's code is never edited at run time.
"""
from __future__ import annotations

import heapq
import math
import re

from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.crh2.ccu import Ccu
from sut.reference.crh2.lcu import Rxc
from sut.reference.crh2.train import Train
from sut.reference.crh2.ring import Ring
from sut.reference.crh2.vehicle import Vehicle
from tests.wording import reword
from sut.reference.atp.backend import ReferenceAtp
from sut.reference.atp.onboard import OnboardAtp
from sut.reference.atp.config import POSTPONE
from sut.reference.atp.vdx import VdxInterface
from sut.reference.metro.backend import ReferenceMetro
from sut.reference.metro.ports import DI_KEY, Command, IoPort
from sut.reference.metro.tcds import MetroTrain
from sut.reference.metro.units import ControlUnit

MS = 1000


# -- faulty: (requirement broken, test item that must catch it) -------------------------------------
class SlowTakeover(ReferenceTrain):
    """RED-02: system 2 waits 100 ms, not 50 ms, before it takes over."""
    TIMING = {"takeover_us": 100 * MS}


class StandbyTransmits(ReferenceTrain):
    """RED-02: system 2 transmits although system 1 is healthy."""
    BEHAVIOUR = {"standby_transmits": True}


class LongTokenHold(ReferenceTrain):
    """PRO-04: each node holds the token 20 ms."""
    TIMING = {"token_hold_us": 20 * MS}


class NoTokenReversal(ReferenceTrain):
    """PRO-04: the node at a fault passes the token into the fault instead of sending it back."""
    BEHAVIOUR = {"token_reversal": False}


class FullNotchesOnDigitalOutputs(ReferenceTrain):
    """CMD-03: the RXC's digital outputs carry full notches on paths 2 and 3."""
    BEHAVIOUR = {"do_steps_only": False}


class NoReverseRouting(ReferenceTrain):
    """NET-03: broadcasts go one way round the ring only, so one cut strands the nodes behind it."""
    BEHAVIOUR = {"reverse_routing": False}


class TxcWithoutCompare(ReferenceTrain):
    """FS-02: the TXC transmits although its CPU groups disagree."""
    BEHAVIOUR = {"txc_compare": False}


class StatusOnSelfDiagnosticLine(ReferenceTrain):
    """NET-04: nodes cut off from the ring send their status data on the self-diagnostic line."""
    BEHAVIOUR = {"selfdiag_commands_only": False}


class NoFrameCheck(ReferenceTrain):
    """NET-05: nodes forward and use frames with a bad check sequence."""
    BEHAVIOUR = {"frame_check": False}


class FifoQueues(ReferenceTrain):
    """NET-06: frames leave a node in arrival order, commands queue behind status and block data."""
    BEHAVIOUR = {"priorities": False}


class DeadInputReleasesBrake(ReferenceTrain):
    """FS-03: TXC inputs in plain logic: a dead desk input reads as 'no brake'."""
    BEHAVIOUR = {"txc_inverted_inputs": False}


class RxcOnTheLcuSupply(ReferenceTrain):
    """CMD-01: the RXC is fed from its LCU's supply, so losing that supply silences the car's paths 2 and 3
    (F-NET-16 checks one LCU so; the single-fault campaign every one of them)."""
    BEHAVIOUR = {"rxc_own_supply": False}


# -- faulty only under double faults: an LCU whose MDM8 lives but hears no commanding CCU (a split ring) -------
class StaleCommandsWhileTheRingIsHeard(ReferenceTrain):
    """FS-02: an LCU whose MDM8 lives keeps handing CI and BCU its last ring command however old, as if a
    live modem meant a live command: it talks stale on path 1 while its car should be on path 3."""
    BEHAVIOUR = {"ring_commands_expire": False}


class FullNotchesOnPath3WithALiveModem(ReferenceTrain):
    """CMD-04: the RXC drives full notches on path 3 when its LCU's MDM8 lives (taking the ring's silence for a
    moment's gap): more than the A/B steps on the backup path."""
    BEHAVIOUR = {"path3_steps_only": False}


class _RepeatingRxc(Rxc):
    BULK_READABLE = True         # its one field is a ring command, a plain dict (sut/reference/bulk.py)
    last_ring: dict | None = None

    # _checked() first, as the reference's handlers do (a second call in them finds the same and says nothing).
    def from_loop(self, fields: dict, mdm9_ok: bool) -> None:
        if self._checked():
            self.last_ring = fields
        super().from_loop(fields, mdm9_ok)

    def from_selfdiag(self, fields: dict) -> None:
        if (self._checked() and self.last_ring is not None and self.lcu.mdm8.alive
                and self.train.kernel.now - self.last_ring_us >= self.train.cfg.timing.rxc_fallback_us):
            self._drive(self.last_ring, path=2)      # the last ring command again
            return
        super().from_selfdiag(fields)


class _TrainOfRepeatingRxcs(Train):
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def __init__(self, cfg) -> None:
        super().__init__(cfg)
        for lcu in self.lcus:
            lcu.rxc.__class__ = _RepeatingRxc


class RxcRepeatsTheRing(ReferenceTrain):
    """CMD-04: on a silent ring, an RXC whose MDM8 lives answers every self-diagnostic command with the last
    ring command again (over path 2) instead of taking the line's."""
    TRAIN = _TrainOfRepeatingRxcs


class BlockDataTheShortWayOnly(ReferenceTrain):
    """PRO-06: block data goes to the master only the shorter way round the ring, so a cut on that way loses a
    fault record (an intact ring, all a single board fault leaves, always carries it)."""
    BEHAVIOUR = {"block_data_both_ways": False}


class LampsFromOneTxc(ReferenceTrain):
    """RED-03: only system 1's TXC drives the cab lamps."""
    BEHAVIOUR = {"lamps_parallel": False}


class CommandsThroughCpu3(ReferenceTrain):
    """CMD-01: the LCU hands commands on through CPU3, so a dead CPU3 stops them."""
    BEHAVIOUR = {"cmd_bypass_cpu3": False}


class BlocksWithoutGrant(ReferenceTrain):
    """PRO-06: a node sends its blocks as soon as it has them, without waiting for the grant."""
    BEHAVIOUR = {"block_grant_required": False}


class CrowdedBlocks(ReferenceTrain):
    """PRO-06: consecutive blocks 5 ms apart."""
    TIMING = {"block_spacing_us": 5 * MS}


class LateTokenInit(ReferenceTrain):
    """PRO-03: nodes wait 1 s of silence after power-up before the token initialisation."""
    TIMING = {"init_silence_us": 1000 * MS}


class SlowFormation(ReferenceTrain):
    """PRO-03: token formed at node number x 40 ms."""
    TIMING = {"formation_step_us": 40 * MS}


class LateRegeneration(ReferenceTrain):
    """PRO-05: a node waits 1 s without a token before it re-initialises."""
    TIMING = {"token_loss_us": 1000 * MS}


class SlowPassThrough(ReferenceTrain):
    """PRO-01: each node holds a frame 0.5 ms on its way."""
    TIMING = {"pass_through_us": 500}


class HurriedCommands(ReferenceTrain):
    """PRO-01: commands every 5 ms, below the 10 ms minimum interval."""
    TIMING = {"command_interval_us": 5 * MS}


class SlowPolling(ReferenceTrain):
    """NET-09: CI and BCU polled every 20 ms."""
    TIMING = {"poll_us": 20 * MS}


class HalfRateRing(ReferenceTrain):
    """NET-07: the ring runs at 1.25 Mbit/s."""
    TIMING = {"bitrate": 1_250_000}


class NoSelfDiagnosticFallback(ReferenceTrain):
    """CMD-04: the RXC never trusts the self-diagnostic line (its fallback never comes in a run)."""
    TIMING = {"rxc_fallback_us": 3_600_000 * MS}


# -- faulty interlocks (ILK) ------------------------------------------------------------------------
class PipeTripTooLow(ReferenceTrain):
    """ILK-02: trips at 570 kPa, below the (590 +/- 10) kPa band."""
    INTERLOCKS = {"pipe_trip_kpa": 570.0}


class PipeTripTooHigh(ReferenceTrain):
    """ILK-02: trips at 605 kPa, above the band."""
    INTERLOCKS = {"pipe_trip_kpa": 605.0, "pipe_reset_kpa": 630.0}


class PipeWithoutHysteresis(ReferenceTrain):
    """ILK-02: releases as soon as the pressure is back at the trip point: chatters inside the band."""
    INTERLOCKS = {"pipe_reset_kpa": 590.0}


class SeparationWithoutRapidBrake(ReferenceTrain):
    """ILK-01: separation applies the emergency brake only."""
    BEHAVIOUR = {"separation_trips_rapid": False}


class BlindBrakeForceSupervision(ReferenceTrain):
    """ILK-03: 'insufficient' only below 20 % of the demand."""
    INTERLOCKS = {"brake_force_min_pct": 20.0}


class NoForcedNeutralSectionPassing(ReferenceTrain):
    """ILK-04: an entry signal without a warning does nothing."""
    BEHAVIOUR = {"ns_forced_passing": False}


class EarlyPressSeal(ReferenceTrain):
    """ILK-05: the press-seal valve energises above 25 km/h."""
    INTERLOCKS = {"seal_on_kmh": 25.0, "seal_off_kmh": 23.0}


class DoorRelayAt10(ReferenceTrain):
    """ILK-05: the door-open safety relay acts below 10 km/h."""
    INTERLOCKS = {"door_relay_kmh": 10.0}


class OilFaultsIgnored(ReferenceTrain):
    """ILK-06: a stopped oil pump or hot oil leaves the converters running."""
    BEHAVIOUR = {"oil_protection": False}


class TwoMasterControllers(ReferenceTrain):
    """ILK-07: both cabs' MCRs pick up."""
    BEHAVIOUR = {"mcr_exclusive": False}


class LateCompressor(ReferenceTrain):
    """Control: the compressor starts only below 700 kPa (the governor's 780 kPa is a project decision)."""
    INTERLOCKS = {"compressor_start_kpa": 700.0}


class TractionInNeutral(ReferenceTrain):
    """ILK-08: the direction switch is not part of the traction permission."""
    BEHAVIOUR = {"ilk08_ignored": ("direction",)}


class TractionThroughEmergencyBrake(ReferenceTrain):
    """ILK-08: traction stays permitted while the emergency and rapid brakes act."""
    BEHAVIOUR = {"ilk08_ignored": ("brakes",)}


class TractionWithDoorsOpen(ReferenceTrain):
    """ILK-08: open doors do not block traction."""
    BEHAVIOUR = {"ilk08_ignored": ("doors",)}


class TractionWhileBraking(ReferenceTrain):
    """ILK-08: a brake command does not suppress traction."""
    BEHAVIOUR = {"ilk08_ignored": ("braking",)}


# -- faulty environment (hardware/software class, TST-02) ----------------------------------------------
class NarrowDeclaredTemperature(ReferenceTrain):
    """TST-02 characteristics: rated -10 .. +55 degC only, short of class OT3."""
    ENVIRONMENT = {"temp_lo_c": -10.0, "temp_hi_c": 55.0}


class LockoutAt80Percent(ReferenceTrain):
    """TST-02 supply voltage: the undervoltage lockout acts at 0.8 Un, inside EN 50155's continuous range."""
    ENVIRONMENT = {"continuous_lo": 0.80}


class TalksWrongBelow60Percent(ReferenceTrain):
    """FS-02: no undervoltage lockout; below 0.6 Un the boards run on and send damaged frames."""
    BEHAVIOUR = {"undervoltage_lockout": False}


class ResetsOn10msInterruption(ReferenceTrain):
    """TST-02 interruption class S2: the hold-up bridges only 5 ms, so a 10 ms interruption resets."""
    ENVIRONMENT = {"hold_up_us": 5 * MS}


class NeverRestarts(ReferenceTrain):
    """TST-02: a supply that dropped out stays off after its input is back in range."""
    BEHAVIOUR = {"restart_after_dropout": False}


class HotLimitAt60(ReferenceTrain):
    """TST-02 temperature: the boards shut down above +60 degC, inside class OT3."""
    ENVIRONMENT = {"temp_hi_c": 60.0}


class LowBurstImmunity(ReferenceTrain):
    """TST-02 interference: immune to 1 kV bursts only, EN 50121-3-2 asks 2 kV."""
    ENVIRONMENT = {"burst_immunity_kv": 1.0}


class SelfDiagWithoutFcsCheck(ReferenceTrain):
    """NET-05: the RXC acts on self-diagnostic frames damaged by bursts (no frame check sequence test)."""
    BEHAVIOUR = {"selfdiag_fcs_check": False}


class ChatterResets(ReferenceTrain):
    """TST-02 vibration: supply contact chatter of 1 ms resets the board (no hold-up at all)."""
    ENVIRONMENT = {"hold_up_us": 0}


class LightLossIsLinkFault(ReferenceTrain):
    """TST-02 vibration: every light loss, however short, is a link fault (the MDM8 rides out nothing)."""
    ENVIRONMENT = {"contact_bridged_us": 0}


class LowInsulation(ReferenceTrain):
    """TST-02 withstand voltage: 10 MOhm of insulation resistance, EN 50155 asks 20 MOhm."""
    ENVIRONMENT = {"insulation_mohm": 10.0}


class WeakInsulation(ReferenceTrain):
    """TST-02 withstand voltage: the insulation breaks down at 1200 V rms, below the 1500 V test."""
    ENVIRONMENT = {"breakdown_v": 1200.0}


# -- in band: differ only where the requirements leave room ------------------------------------------
class HoldCountedToSend(ReferenceTrain):
    """Holds 10 ms from receiving the token to sending it: the neighbour has it 10.25 ms later."""
    TIMING = {"token_hold_us": 10 * MS + 250}


class FasterNodes(ReferenceTrain):
    """Pass-through 0.2 ms and a 0.2 ms TXC loop: faster than the articles require."""
    TIMING = {"pass_through_us": 200, "txc_loop_us": 200, "rxc_loop_us": 200}


class CommandsEvery12ms(ReferenceTrain):
    """Commands every 12 ms: above the 10 ms minimum; the takeover band follows the interval."""
    TIMING = {"command_interval_us": 12 * MS}


class EarlierFallback(ReferenceTrain):
    """The RXC trusts the self-diagnostic line after 60 ms without ring commands (a project decision)."""
    TIMING = {"rxc_fallback_us": 60 * MS}


class StatusCounter16(ReferenceTrain):
    """TST-02: diagnostic counters kept in 16 bits wrap within 72 h (65,536 status frames = 2.2 h)."""
    BEHAVIOUR = {"counter_bits": 16}


class ClockInMicroseconds32(ReferenceTrain):
    """TST-02: the clock correction counts microseconds in 32 bits, which wrap after 71.6 min."""
    BEHAVIOUR = {"clock_from_us32": True}


FAULTY = [
    (StatusCounter16, "TST-02", "H-CPO-01"),
    (ClockInMicroseconds32, "TST-02", "H-CPO-02"),
    # (variant, requirement it breaks, test item that must reject it)
    (SlowTakeover, "RED-02", "F-NET-17"),
    (StandbyTransmits, "RED-02", "F-NET-17"),
    (LongTokenHold, "PRO-04", "F-NET-13"),
    (NoTokenReversal, "PRO-04", "F-NET-13"),
    (FullNotchesOnDigitalOutputs, "CMD-03", "F-NET-16"),
    (NoReverseRouting, "NET-03", "F-NET-02"),
    (TxcWithoutCompare, "FS-02", "F-NET-19"),
    (StatusOnSelfDiagnosticLine, "NET-04", "F-NET-04"),
    (NoFrameCheck, "NET-05", "F-NET-05"),
    (FifoQueues, "NET-06", "F-NET-06"),
    (DeadInputReleasesBrake, "FS-03", "F-NET-19"),
    (LampsFromOneTxc, "RED-03", "F-NET-18"),
    (CommandsThroughCpu3, "CMD-01", "F-NET-16"),
    (RxcOnTheLcuSupply, "CMD-01", "F-NET-30"),
    (BlocksWithoutGrant, "PRO-06", "F-NET-15"),
    (CrowdedBlocks, "PRO-06", "F-NET-15"),
    (LateTokenInit, "PRO-03", "F-NET-12"),
    (SlowFormation, "PRO-03", "F-NET-12"),
    (LateRegeneration, "PRO-05", "F-NET-14"),
    (SlowPassThrough, "PRO-01", "F-NET-10"),
    (HurriedCommands, "PRO-01", "F-NET-10"),
    (SlowPolling, "NET-09", "F-NET-09"),
    (HalfRateRing, "NET-07", "F-NET-07"),
    (NoSelfDiagnosticFallback, "CMD-04", "F-NET-04"),
    (PipeTripTooLow, "ILK-02", "F-ILK-02"),
    (PipeTripTooHigh, "ILK-02", "F-ILK-02"),
    (PipeWithoutHysteresis, "ILK-02", "F-ILK-02"),
    (SeparationWithoutRapidBrake, "ILK-01", "F-ILK-01"),
    (BlindBrakeForceSupervision, "ILK-03", "F-ILK-03"),
    (NoForcedNeutralSectionPassing, "ILK-04", "F-ILK-04"),
    (EarlyPressSeal, "ILK-05", "F-ILK-05"),
    (DoorRelayAt10, "ILK-05", "F-ILK-05"),
    (OilFaultsIgnored, "ILK-06", "F-ILK-06"),
    (TwoMasterControllers, "ILK-07", "F-ILK-07"),
    (LateCompressor, "TST-05", "F-CTL-09"),
    (TractionInNeutral, "ILK-08", "F-ILK-08"),
    (TractionThroughEmergencyBrake, "ILK-08", "F-ILK-08"),
    (TractionWithDoorsOpen, "ILK-08", "F-ILK-08"),
    (TractionWhileBraking, "ILK-08", "F-ILK-09"),
    (NarrowDeclaredTemperature, "TST-02", "H-CHR-03"),
    (LockoutAt80Percent, "TST-02", "H-VLT-01"),
    (TalksWrongBelow60Percent, "FS-02", "H-VLT-02"),
    (ResetsOn10msInterruption, "TST-02", "H-PWR-01"),
    (NeverRestarts, "TST-02", "H-PWR-02"),
    (HotLimitAt60, "TST-02", "H-TMP-01"),
    (LowBurstImmunity, "TST-02", "H-EMC-01"),
    (SelfDiagWithoutFcsCheck, "NET-05", "H-EMC-03"),
    (ChatterResets, "TST-02", "H-VIB-01"),
    (LightLossIsLinkFault, "TST-02", "H-VIB-02"),
    (LowInsulation, "TST-02", "H-WSV-01"),
    (WeakInsulation, "TST-02", "H-WSV-02"),
]

class PipeTripAt585(ReferenceTrain):
    """Trips at 585 kPa, releases at 610 kPa: inside ILK-02's band and the hysteresis rule."""
    INTERLOCKS = {"pipe_trip_kpa": 585.0, "pipe_reset_kpa": 610.0}


class DoorBandsNarrow(ReferenceTrain):
    """Press-seal at 31 km/h, door-open relay below 4.5 km/h: inside ILK-05's bands."""
    INTERLOCKS = {"seal_on_kmh": 31.0, "seal_off_kmh": 29.0, "door_relay_kmh": 4.5}


class RuggedBoards(ReferenceTrain):
    """Rated beyond the standards: 20 ms hold-up, -40 .. +85 degC, a 150 ms restart."""
    ENVIRONMENT = {"hold_up_us": 20 * MS, "temp_lo_c": -40.0, "temp_hi_c": 85.0, "restart_us": 150 * MS}


# Faulty under double faults only (issue 16): the single-fault campaigns pass them, the double-fault one
# (F-NET-32, run on request) must reject them: tests/test_campaign.py.
DOUBLE_ONLY = [StaleCommandsWhileTheRingIsHeard, FullNotchesOnPath3WithALiveModem, RxcRepeatsTheRing,
               BlockDataTheShortWayOnly]

# A CRH2 cab monitor that speaks Chinese: its fault texts and the lines of its maintenance view, by the English
# text's pattern (<name>: a name it keeps as it is). It declares what it shows for each message the features name
# (tests/declarations/chinese-monitor-crh2.yaml). The fault records themselves (block data, `F|<t ms>|<node>|...`)
# keep their documented ASCII format: that is a record format, not a display text.
CRH2_FAULTS_ZH = {"no status data from <node>": "<node>无状态数据",
                  "optical transmission fault between <node> and <neighbour>": "<node>与<neighbour>间光传输故障",
                  "<board> failure": "<board>故障",
                  "<unit>: main circuit protection acted": "<unit>：主电路保护动作",
                  "insufficient brake force": "制动力不足",
                  "neutral section: severe fault, pass manually": "过分相装置严重故障，请手动过分相",
                  "neutral section: warning signal fault, forced automatic passing": "过分相预告信号故障，强制自动过分相",
                  "neutral section: no entry signal, enter manually": "过分相无进入信号，请手动进入",
                  "neutral section: no exit signal, restore manually": "过分相无退出信号，请手动恢复"}
CRH2_RECORDS_ZH = {"<board> failed": "<board>发生故障", "<board> recovered": "<board>恢复正常",
                   **{f"<node>.supply restarted after {reason}": f"<node>电源因{zh}重启" for reason, zh in
                      {"over-temperature": "过温", "under-temperature": "低温", "overvoltage": "过压",
                       "undervoltage": "欠压", "interruption": "断电", "withstand test": "耐压试验"}.items()}}
MAINTENANCE_LINE = re.compile(r"(\d+ ms )(.*)")


def _localized(text: str, table: dict[str, str]) -> str:
    """`text` in the words of `table` (English identifier -> the monitor's words) if it is one of its messages
    with names filled in, else unchanged."""
    for english, words in table.items():
        parts = re.split(r"(<\w+>)", english)
        rx = "".join(f"(?P<{p[1:-1]}>[A-Za-z0-9_.]+)" if p.startswith("<") else re.escape(p) for p in parts)
        found = re.fullmatch(rx, text)
        if found:
            return re.sub(r"<(\w+)>", lambda n: found.group(n.group(1)), words)
    return text


class ChineseMonitorCrh2(ReferenceTrain):
    """Freedom (localized display): the cab monitors show their fault texts and maintenance view in Chinese,
    declared by message identifier; the displayed values (value words) and the fault records are as the
    reference's."""
    DECLARATION = "tests/declarations/chinese-monitor-crh2.yaml"

    def monitor(self, cab: int) -> dict:
        shown = super().monitor(cab)
        lines = [MAINTENANCE_LINE.fullmatch(line) for line in shown["maintenance"]]
        return {**shown, "faults": [_localized(f, CRH2_FAULTS_ZH) for f in shown["faults"]],
                "maintenance": [m.group(1) + _localized(m.group(2), CRH2_RECORDS_ZH) if m else line
                                for m, line in zip(lines, shown["maintenance"])]}

    def _monitor_faults(self, cab: int) -> list[str]:
        # watch_monitor looks at the screen alone (the reference's shortcut past monitor()): the same words.
        return [_localized(f, CRH2_FAULTS_ZH) for f in super()._monitor_faults(cab)]


IN_BAND = [HoldCountedToSend, FasterNodes, CommandsEvery12ms, EarlierFallback, PipeTripAt585, DoorBandsNarrow,
           RuggedBoards]


# -- metro TCDS (profile metro-tcn, issue 6) ----------------------------------------------------------
class SkippedFallback(ReferenceMetro):
    """RED-04: the car 3 VCU, not the car 2 VCU, takes the WTB from a failed car 1 CCU."""
    BEHAVIOUR = {"wtb_backup_ranks": ("car1.CCU", "car3.VCU", "car2.VCU")}


class CarSixMastersWtb(ReferenceMetro):
    """RED-04: the car 6 CCU is a WTB backup master."""
    BEHAVIOUR = {"wtb_backup_ranks": ("car1.CCU", "car6.CCU", "car2.VCU", "car3.VCU")}


class BackupMasterStores(ReferenceMetro):
    """RED-04: a VCU acting as WTB master stores the records itself."""
    BEHAVIOUR = {"backup_master_stores": True}


class VcuKeepsOutOfControl(ReferenceMetro):
    """RED-05: the adjacent VCU takes the MVB of a failed active-cab CCU but computes no train command."""
    BEHAVIOUR = {"vcu_takes_control": False}


class SlowMvbTakeover(ReferenceMetro):
    """RED-05: the adjacent VCU waits 150 ms before it takes the MVB (the command is lost meanwhile)."""
    TIMING = {"mvb_master_timeout_us": 150 * MS}


class RecordsStayInTheirUnit(ReferenceMetro):
    """RED-05: events are not sent over the WTB, so each CCU records only its own unit."""
    BEHAVIOUR = {"records_via_wtb": False}


class SingleLine(ReferenceMetro):
    """RED-06: frames go on line A only."""
    BEHAVIOUR = {"lines_sent": "A"}


class LineSwitchAfterThreeFrames(ReferenceMetro):
    """RED-06: receivers switch lines only after three bad frames, losing the first two."""
    BEHAVIOUR = {"line_switch_after": 3}


class ModuleTwoNeverUsed(ReferenceMetro):
    """RED-07: the inputs of MVB I/O module 2 are never used."""
    BEHAVIOUR = {"use_io_module_2": False}


class LifeSignalIgnored(ReferenceMetro):
    """RED-07: module 1's inputs are used while it answers, whatever its life signal says."""
    BEHAVIOUR = {"io_life_signal_checked": False}


class OneCheckSequence(ReferenceMetro):
    """TCN-05: one check byte at the end of a 128/256-bit slave frame instead of one per 64 bits."""
    BEHAVIOUR = {"one_check_sequence": True}


class SlowWtbCycle(ReferenceMetro):
    """TCN-03: a WTB cycle of 30 ms."""
    TIMING = {"wtb_cycle_us": 30 * MS}


class MvbBasicPeriod2ms(ReferenceMetro):
    """TCN-03: an MVB basic period of 2 ms."""
    TIMING = {"mvb_basic_period_us": 2 * MS}


class DevicesNeverReported(ReferenceMetro):
    """TCN-04: a device that stops answering is never reported."""
    TIMING = {"status_silence_polls": 1_000_000}


class EventsSentOnce(ReferenceMetro):
    """TCN-06: event messages are sent once, never acknowledged, so a lost telegram loses the record."""
    BEHAVIOUR = {"message_ack": False}


class NoBrakeOnNetworkFailure(ReferenceMetro):
    """TCN-09: the VVVF and BECU hold the last command when the train command is lost."""
    BEHAVIOUR = {"network_failure_brake": False}


class EmergencyOperationAtSpeed(ReferenceMetro):
    """TCN-09: hard-wired emergency operation is taken at speed, without braking to a stop first."""
    BEHAVIOUR = {"emergency_operation_at_speed": True}


class PacketsFromNodeOne(ReferenceTrain):
    """NET-10: every packet on the ring carries node 1's ID as its source; the layout and CRC are right and
    the nodes understand each other (they read the sender from the exchange), but the wire misnames it."""
    BEHAVIOUR = {"packet_source_id": 1}


class MainCircuitResetsItself(ReferenceTrain):
    """ILK-06 (the project's latching decision): an opened VCB closes again by itself one minute after the
    transformer fault clears, without the driver's reset; the 500 ms watch of F-VSD-02 let it pass."""
    BEHAVIOUR = {"protection_self_reset_us": 60_000_000}


class BrakeForceTripClearsItself(ReferenceTrain):
    """ILK-03 (latched trip, docs/decisions.md): the emergency brake for insufficient brake force releases by
    itself two minutes after it tripped."""
    BEHAVIOUR = {"brake_force_trip_clears_us": 120_000_000}


class StatusPolledAtOneAddress(ReferenceMetro):
    """TCN-05: every device status request carries the first device's address; the devices still answer in
    turn, so the frames decode and the log agrees with them, but the wire names the wrong device."""
    BEHAVIOUR = {"status_polls_one_address": True}


class StatusPolledWithReservedCode(ReferenceMetro):
    """TCN-05: device status is requested with F_code 10, which IEC 61375-3-1 reserves (devices ignore it)."""
    BEHAVIOUR = {"status_poll_f_code": 10}


class _BackupStartsFromTheCcuCommand(MetroTrain):
    """The train of BackupVcuHoldsTheCcuCommand: a subclass, so the reference's code is not edited."""

    def __init__(self, cfg) -> None:
        super().__init__(cfg)
        self.held: dict[int, tuple] = {}     # unit -> (the cab's inputs at takeover, the CCU's last command or None)
        self.sent: dict[int, Command | None] = {}   # unit -> the last command its master put on the port

    def _command(self, seg, master):
        last = self.sent.get(seg.unit)       # what the failed CCU last put on the port
        cmd = self.sent[seg.unit] = super()._command(seg, master)
        inputs = seg.io_data[seg.io_used][0] if seg.io_used else None
        if master.kind != "VCU" or cmd is None or inputs is None or not inputs.input(DI_KEY):
            self.held.pop(seg.unit, None)
            return cmd
        seen = (inputs.di, inputs.ai)
        if seg.unit not in self.held:
            start = (last.mode, last.direction, last.traction, last.brake) if last is not None else None
            self.held[seg.unit] = (seen, start)
        at_takeover, start = self.held[seg.unit]
        if start is None or seen != at_takeover:
            self.held[seg.unit] = (seen, None)          # the inputs moved: from now on computed from them
            return cmd
        return Command(*start, cmd.seq)


class BackupVcuHoldsTheCcuCommand(ReferenceMetro):
    """RED-05: the VCU that takes over a failed keyed-cab CCU starts from the train command the CCU last sent
    and computes a new one only when the cab's inputs change after it took over. The hand-written items move
    the controller long after the takeover (the VCU follows) or not at all (the held command is right); a
    controller moved at the instant of the failure is never followed: only the campaign (F-NET-34) sees it."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _BackupStartsFromTheCcuCommand(self._train.cfg)


class _KeepsTheMvbWithoutAGateway(ControlUnit):
    """A CCU or VCU that masters its unit's MVB while it lives, gateway or not."""

    @property
    def masters_mvb(self) -> bool:
        return self.alive


class GatewaylessCcuKeepsItsMvb(ReferenceMetro):
    """RED-05 (docs/decisions.md "Gateway failure"): a CCU whose gateway failed keeps mastering its unit's MVB,
    so the unit is cut off from the train's command; in the other unit the command stops and the train
    brakes. No hand-written item fails a gateway alone for long: only the campaign (F-NET-34) sees it."""

    def __init__(self) -> None:
        super().__init__()
        for node in self._train.nodes.values():
            node.__class__ = _KeepsTheMvbWithoutAGateway


class DisplayShowsASilentBus(ReferenceMetro):
    """TCN-08 (docs/decisions.md, "A display whose bus master is silent"): a DU whose unit has no live bus
    master keeps showing what the last one knew, mode and WTB master as if the train were still so."""

    def monitor(self, cab: int) -> dict:
        train = self._train
        seg = train.segments[1 if cab == 1 else 2]
        master = train.nodes[seg.master]
        if train.devices[f"car{cab}.DU"].failed or master.alive:
            return super().monitor(cab)
        return {"faults": [r.text for r in master.known], "mode": train.modes[seg.unit],
                "WTB master": train.wtb_master, "blank": False}


class _LifeWrapsThroughZero(MetroTrain):
    def _io_port(self, module):
        port = super()._io_port(module)
        return port if module.failed else IoPort(port.di, port.ai, module.life % 0x10000)


class LifeSignalWrapsThroughZero(ReferenceMetro):
    """RED-07: module 1's life signal counts 1..65535 and then 0, so every 65536th refresh says "not alive"
    and the unit's master loses module 1 for a period: the drives drop to 0 % traction and full brake for
    2 ms. A bulk advance carries the count over a jump without encoding it, so only a frame-by-frame run past
    the wrap sees this, as a rig would: the train class declares no bulk (BULK_READABLE), so it runs so, and
    F-CTL-16's 18 minutes cost about three minutes of wall time."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _LifeWrapsThroughZero(self._train.cfg)


class BriskMetro(ReferenceMetro):
    """In band: a 20 ms WTB cycle, quicker takeovers, I/O and command ports every 4 ms, longer sink and
    gateway supervision."""
    TIMING = {"wtb_cycle_us": 20 * MS, "mvb_master_timeout_us": 8 * MS, "wtb_backup_step_us": 60 * MS,
              "io_period_us": 4 * MS, "command_period_us": 4 * MS, "sink_timeout_us": 150 * MS,
              "gateway_timeout_us": 300 * MS}


FAULTY += [
    (SkippedFallback, "RED-04", "F-NET-22"),
    (CarSixMastersWtb, "RED-04", "F-NET-22"),
    (BackupMasterStores, "RED-04", "F-NET-22"),
    (VcuKeepsOutOfControl, "RED-05", "F-CTL-15"),
    (SlowMvbTakeover, "RED-05", "F-CTL-15"),
    (RecordsStayInTheirUnit, "RED-05", "F-REC-04"),
    (SingleLine, "RED-06", "F-NET-23"),
    (LineSwitchAfterThreeFrames, "RED-06", "F-NET-23"),
    (ModuleTwoNeverUsed, "RED-07", "F-CTL-16"),
    (LifeSignalIgnored, "RED-07", "F-CTL-16"),
    (OneCheckSequence, "TCN-05", "F-NET-24"),
    (SlowWtbCycle, "TCN-03", "F-NET-21"),
    (MvbBasicPeriod2ms, "TCN-03", "F-NET-21"),
    (DevicesNeverReported, "TCN-04", "F-DIA-04"),
    (EventsSentOnce, "TCN-06", "F-REC-04"),
    (NoBrakeOnNetworkFailure, "TCN-09", "F-NET-25"),
    (EmergencyOperationAtSpeed, "TCN-09", "F-NET-25"),
    (StatusPolledWithReservedCode, "TCN-05", "F-NET-24"),
    (StatusPolledAtOneAddress, "TCN-05", "F-NET-24"),
    (BackupVcuHoldsTheCcuCommand, "RED-05", "F-NET-34"),
    (GatewaylessCcuKeepsItsMvb, "RED-05", "F-NET-34"),
    (DisplayShowsASilentBus, "TCN-08", "F-DSP-05"),
    (LifeSignalWrapsThroughZero, "RED-07", "F-CTL-16"),
    (PacketsFromNodeOne, "NET-10", "F-NET-26"),
    (MainCircuitResetsItself, "ILK-06", "F-VSD-02"),
    (BrakeForceTripClearsItself, "ILK-03", "F-ILK-03"),
]
IN_BAND += [BriskMetro]


# -- three capabilities held-out faults found missing (issue 31, item 4) ----------------------------------
class SecondKeyTakesOver(ReferenceTrain):
    """ILK-07 (docs/decisions.md, "ILK-07"): a key left in cab 8 while cab 1 drives picks cab 8's MCR up the
    moment cab 1's key comes out, so what was set in cab 8 while it was void (direction, notch 9) commands
    the train with nobody acting in cab 8. The other items take the first key out with no second key in.
    Rejected by F-ILK-07's "Taking cab 1's key out while a key waits in cab 8 picks nothing up"."""
    BEHAVIOUR = {"waiting_key_picks_up": True}


class RegenerationHighestFirst(ReferenceTrain):
    """PRO-05: the token is formed after power-up as PRO-03 says, but formed again after a loss the way
    ARCNET's own reconfiguration does it, the highest node number first (each node waits (N + 1 - number) x
    20 ms): the ring's last node forms it 20 ms after the initialisation, not node 1. A token circulates
    again as soon as with the reference, which is all F-NET-14 asked before. Rejected by F-NET-14's "After a
    loss node 1 forms the new token 20 ms after the initialisation"."""
    BEHAVIOUR = {"regeneration_from_the_top": True}


class BrakeForceBlindToAtp(ReferenceTrain):
    """ILK-03: the brake-force supervision counts only the brake handle as a demand, so a car short of brake
    force under an ATP brake, with the handle at 0, trips nothing (F-ILK-03 braked with the handle only).
    Rejected by F-ILK-03's "Under an ATP brake with the handle at 0 a car braking at 30 % of its demand
    trips the emergency brake"."""
    BEHAVIOUR = {"brake_force_handle_only": True}


FAULTY += [
    (SecondKeyTakesOver, "ILK-07", "F-ILK-07"),
    (RegenerationHighestFirst, "PRO-05", "F-NET-14"),
    (BrakeForceBlindToAtp, "ILK-03", "F-ILK-03"),
]


class _ForwardOnlyTraction(Vehicle):
    """The vehicle of ReverseRefused."""
    BULK_READABLE = True         # no state of its own: a 72 h soak need not run frame by frame (sut/reference/bulk.py)

    def _permitted(self, emergency: bool, rapid: bool, doors: str) -> bool:
        ccu = self.train.commanding_ccu()
        return super()._permitted(emergency, rapid, doors) and (ccu is None or ccu.desk.direction == "forward")


class _OwnParts(ReferenceTrain):
    """A CRH2 train whose vehicle is of the class VEHICLE and whose ring of the class RING (subclasses of the
    reference's), from when the train is built: the reference's code is not edited."""
    VEHICLE: type[Vehicle] = Vehicle
    RING: type[Ring] = Ring

    @property
    def train(self) -> Train:
        fresh = self._train is None
        train = super().train
        if fresh:
            train.vehicle.__class__ = self.VEHICLE
            train.ring.__class__ = self.RING
        return train


class _EagerRing(Ring):
    def _enqueue(self, link, frame, hops):
        # Every frame goes through the queue, served when the link frees (at once if it is free); but one that
        # comes while the queue waits for that service, the link already free, takes the link first.
        if link.queue and link.busy_until <= self.kernel.now:
            self._start(link, frame, hops)
            return
        self._order += 1
        heapq.heappush(link.queue, (frame.prio if self.by_priority else 0, self._order, frame, hops))
        if link.timer is None:
            link.timer = self.kernel.call_at(max(link.busy_until, self.kernel.now), self._link_free, link)


class NewcomerAtTheFreeInstant(_OwnParts):
    """NET-06, NET-07: every frame is queued and served when the link frees, but one that reaches a node at
    the instant its outgoing fibre frees, while the queue there waits for that service, starts at once, and
    the queue is served at the same instant: a status frame goes out on top of a command that was waiting
    (the `_enqueue` mutant of seed 16). Rejected by F-NET-06's analysers on both sides of
    car 1's LCU: one frame at a time, and the command first."""
    RING = _EagerRing


class ReverseRefused(_OwnParts):
    """ILK-08 (issue 31, item 4: a held-out fault, described): the direction condition reads "forward", not
    "forward or reverse", so with the direction switch at reverse traction is blocked and no notch reaches a
    CI. Before, only F-CTL-11's "In reverse the driver's notch reaches every CI" (tagged CMD-05) drove in
    reverse: `--req ILK-08` passed it. Rejected by F-ILK-08's "The direction switch at reverse permits
    traction as forward does"."""
    VEHICLE = _ForwardOnlyTraction


FAULTY += [(ReverseRefused, "ILK-08", "F-ILK-08"), (NewcomerAtTheFreeInstant, "NET-06", "F-NET-06")]


class _GrantLeftAtNode1(Train):
    """The train of GrantLeftStanding."""
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def block_master_saw_status(self, node, fields: dict, src: int) -> None:
        released = node is self.block_master() and src == self.block_granted and not fields["block_request"]
        super().block_master_saw_status(node, fields, src)
        if released:
            self.block_granted = 1


class GrantLeftStanding(ReferenceTrain):
    """PRO-06: when a node's transfer ends, the master's grant moves to node 1, which never asked; the queued
    nodes wait until node 1's own status data say it asks for nothing, and for ever if node 1 is silent (make
    mutate seed 11's survivor of train.py:188). Rejected by F-NET-15's scenario with system 1 switched off."""
    TRAIN = _GrantLeftAtNode1


FAULTY += [(GrantLeftStanding, "PRO-06", "F-NET-15")]


class _BlamesUnheardFields(Ccu):
    """The cab's CCU of ReportsBoardsItHasNoStatusFor."""
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def monitor_view(self, stale_us: int) -> dict:
        view = super().monitor_view(stale_us)
        source = self.monitor_source()
        if source is not None:
            blamed = {f"{node.name}.CPU3 failure" for node in self.train.ring.nodes
                      if node is not source and node.number in source.heard and node.number not in source.last_status}
            view["faults"] = sorted(set(view["faults"]) | blamed)
        return view


class _TrainBlamingUnheardFields(Train):
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def __init__(self, cfg) -> None:
        super().__init__(cfg)
        for ccu in self.ccus.values():
            ccu.__class__ = _BlamesUnheardFields


class ReportsBoardsItHasNoStatusFor(ReferenceTrain):
    """PRO-02: a monitor fed by a system that has heard a node but holds none of its status fields (its own
    CPU3 was down when they came) reports that node's boards failed until their next status data (make mutate
    seed 12's survivors of ccu.py:260/264, which took None for the missing fields and crashed). Rejected by
    F-DSP-01's "A system silent since power-up ...": no node is blamed once it is repaired."""
    TRAIN = _TrainBlamingUnheardFields


FAULTY += [(ReportsBoardsItHasNoStatusFor, "PRO-02", "F-DSP-01")]


class AtpEmergencyOnlyThroughTheLoop(ReferenceAtp):
    """ILK-08: fitted to a CRH2 set, the ATP's own emergency brake (a failed DEF self-test) reaches the train
    only while the VDX holds the loop open; with the rig's command to the VDX released, the train runs
    unbraked though the ATP still brakes (make mutate seed 12's survivor of atp/backend.py:79). Rejected by
    F-ATP-16's scenario with the emergency-brake command to the VDX released."""

    def _brake_to_train(self) -> None:
        state = self.atp.s
        if state.brake != "emergency" or self.vdx.loop == "open":
            super()._brake_to_train()
            return
        state.brake = "none"                 # the ATP's own emergency, seen as no brake while the loop is closed
        try:
            super()._brake_to_train()
        finally:
            state.brake = "emergency"


FAULTY += [(AtpEmergencyOnlyThroughTheLoop, "ILK-08", "F-ATP-16")]


class _LastKeyedCommand(MetroTrain):
    """The train of KeyRemovalIgnored: a subclass, so the reference's code is not edited."""

    def __init__(self, cfg) -> None:
        super().__init__(cfg)
        self.keyed: dict[int, tuple] = {}     # unit -> the last command its cab's key was in for (mode .. brake)

    def _command(self, seg, master):
        cmd = super()._command(seg, master)
        inputs = seg.io_data[seg.io_used][0] if seg.io_used else None
        if inputs is not None and inputs.input(self.cfg.behaviour.di_key):
            if cmd is not None:
                self.keyed[seg.unit] = (cmd.mode, cmd.direction, cmd.traction, cmd.brake)
            return cmd
        last = self.keyed.get(seg.unit)
        return cmd if last is None or cmd is None else Command(*last, cmd.seq)


class KeyRemovalIgnored(ReferenceMetro):
    """TCN-08: a cab whose key is taken out stays the active cab: its CCU keeps sending the train command it
    computed last, so its unit runs on without a driver's cab (the other unit, told "no cab", brakes). The
    hand-written items take a key out only in emergency operation (F-NET-25), where the desk acts through hard
    wires; F-NET-35's "every VVVF and BECU follows the active cab, through a CCU failure" finds it."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _LastKeyedCommand(self._train.cfg)


FAULTY += [(KeyRemovalIgnored, "TCN-08", "F-NET-35")]


class _LateLifeSignal(MetroTrain):
    """The train of LateLifeSignalCheck: a subclass, so the reference's code is not edited."""
    LATE_US = 300 * MS
    BULK_READABLE = True         # its moment comes by a timer, which bulk advance never jumps over

    def __init__(self, cfg) -> None:
        super().__init__(cfg)
        self.noticed_dead: set[str] = set()        # modules whose life signal 0 the masters have taken in
        self.noticing: dict[str, object] = {}      # module -> the timer that takes it in

    def _deliver(self, seg, master, what, target, data) -> None:
        super()._deliver(seg, master, what, target, data)
        if what != "io":
            return
        name = target.name
        port, at = seg.io_data[name]
        if port.life:
            self.noticed_dead.discard(name)
            timer = self.noticing.pop(name, None)
            if timer is not None:
                timer.cancel()
        elif name not in self.noticed_dead:
            # A timer, not a comparison with the time: a bulk advance must not jump over the moment.
            if name not in self.noticing:
                self.noticing[name] = self.kernel.call_later(self.LATE_US, self._notice, name)
            seg.io_data[name] = (IoPort(port.di, port.ai, 1), at)

    def _notice(self, name: str) -> None:
        self.noticing.pop(name, None)
        self.noticed_dead.add(name)


class LateLifeSignalCheck(ReferenceMetro):
    """TCN-06 (issue 31, item 4: a held-out fault, described): the I/O modules' ports are process data, of
    bounded latency, but the masters take in a module's life signal 0 only after it has read 0 for 300 ms, so
    for 300 ms a dead module 1's frozen inputs drive the train. Before, only F-CTL-16's "Module 1's life signal
    drops" (tagged RED-07) timed the switch to module 2: `--req TCN-06` passed it. Rejected by F-CTL-16's
    "Module 1's life signal drops: the inputs of module 2 are used" (now tagged TCN-06 too)."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _LateLifeSignal(self._train.cfg)


FAULTY += [(LateLifeSignalCheck, "TCN-06", "F-CTL-16")]


# A metro display unit that speaks Chinese: its modes, and its event texts on the displays and in the records,
# by the English text's pattern (<name>: a name it keeps as it is). It declares what it shows for each message
# the features name (tests/declarations/chinese-display-metro.yaml); the texts no feature names it need not.
METRO_MODES_ZH = {"normal": "正常", "no cab": "无激活司机室", "train network failure": "列车网络故障",
                  "emergency operation": "紧急运行", "power-up": "上电"}
METRO_TEXTS_ZH = {"<device>: no status data": "<device>：无状态数据",
                  "<device>: answering again": "<device>：恢复应答",
                  "<node>: no answer on WTB": "<node>：WTB无应答",
                  "<node>: answering on WTB again": "<node>：WTB恢复应答",
                  "WTB master (<node> silent)": "WTB主控转移（<node>无响应）",
                  "MVB master of unit <unit> (<node> silent)": "单元<unit> MVB主控转移（<node>无响应）",
                  "inputs from <module>": "采用<module>的输入",
                  "no MVB I/O module alive": "无可用MVB I/O模块",
                  "<bus> line <line>: fault": "<bus> <line>线故障",
                  "<bus> line <line>: restored": "<bus> <line>线恢复",
                  "train network failure: braking to a stop": "列车网络故障，制动停车"}


def _in_chinese(text: str) -> str:
    return reword(text, METRO_TEXTS_ZH)


class ChineseDisplayMetro(ReferenceMetro):
    """Freedom (localized display): the cab displays show their modes and events in Chinese, and the CCU
    memories record the events so, declared by message identifier."""
    DECLARATION = "tests/declarations/chinese-display-metro.yaml"

    def monitor(self, cab: int) -> dict:
        shown = super().monitor(cab)
        return {**shown, "mode": METRO_MODES_ZH.get(shown["mode"], shown["mode"]),
                "faults": [_in_chinese(f) for f in shown["faults"]]}

    def records(self, unit: str) -> list[str]:
        return [_in_chinese(r) for r in super().records(unit)]


# -- VDX emergency-brake interface (profile atp, issue 7) -----------------------------------------------
class NewFirmwarePostpones16ms(ReferenceAtp):
    """VDX-06: the new firmware still postpones a self-test only 16 ms after a release."""
    VDX = {"postpone_us": {"old": 16 * MS, "new": 16 * MS}}


class Threshold12V(ReferenceAtp):
    """VDX-03: the self-test passes below 12 V instead of 6 V."""
    VDX = {"low_threshold_v": 12.0}


class SampledAtOnce(ReferenceAtp):
    """VDX-03: the FS output is sampled as the excitation is removed, not from the 2nd ms."""
    VDX = {"sample_at_us": 0}


class SelfTestEvery10s(ReferenceAtp):
    """VDX-03: the FS self-test every 10 s."""
    VDX = {"selftest_period_us": 10_000 * MS}


class C019Clears(ReferenceAtp):
    """VDX-03: after C019 the FS output comes back without a restart."""
    VDX = {"c019_latches": False}


class C019ClearsAfterTenMinutes(ReferenceAtp):
    """VDX-03: C019 holds the FS output off for 10 minutes, then lets it come back without a restart."""
    VDX = {"c019_self_clear_us": 10 * 60 * 1000 * MS}


class RelayDropsIn2ms(ReferenceAtp):
    """VDX-04: EB2R drops 2 ms after its coil loses power, so every 3 ms self-test brakes the train."""
    VDX = {"relay_no_open_us": 2 * MS}


class SlowRelay(ReferenceAtp):
    """VDX-04: EB2R opens the loop 7 ms after its coil loses power."""
    VDX = {"relay_no_open_us": 7 * MS}


class NarrowSupply(ReferenceAtp):
    """VDX-02: works only from 80 % of 110 V."""
    VDX = {"supply_lo": 0.80}


class IsolationIgnored(ReferenceAtp):
    """VDX-01: the isolation switch does not bypass the relay contacts."""
    VDX = {"isolation_bypasses": False}


class AnotherCoil(ReferenceAtp):
    """In band: a coil that gives back its energy more slowly (C019 window 33.7 ms at 137 V, inside the
    article's 30..36 ms) and a quicker relay (4 ms to drop, 6 ms to pick up)."""
    VDX = {"fall_min_ms": 0.2, "fall_a_ms": 8.0, "fall_tau_ms": 15.0, "relay_no_open_us": 4 * MS,
           "relay_pick_up_us": 6 * MS}


class FsToPsAt300m(ReferenceAtp):
    """ATP-06: FS turns into PS 300 m before the end of authority (the old value)."""
    ATP = {"fs_to_ps_m": 300.0}


class StopWindow1m(ReferenceAtp):
    """ATP-09: the stop window is -1 m .. +1 m."""
    ATP = {"stop_window_m": 1.0}


class CarrierAfterOneComparison(ReferenceAtp):
    """ATP-03: the CFSK reports a new carrier after one comparison."""
    ATP = {"cfsk_confirmations": 1}


class DefSteps2500ms(ReferenceAtp):
    """ATP-08: DEF steps of 2.5 s (25 s in all)."""
    ATP = {"def_step_us": 2500 * MS}


class NoRearWidening(ReferenceAtp):
    """ATP-02: the receiver range is not widened by v*dt to the rear (false carrier alarms at speed)."""
    ATP = {"widen_rear": False}


class DefaultPsBelow50(ReferenceAtp):
    """ATP-07: PS after a default telegram already below 50 km/h."""
    ATP = {"default_ps_kmh": 50.0}


class CarrierSetFixed(ReferenceAtp):
    """ATP-04: balise up/down-line information does not switch the carrier set."""
    ATP = {"balise_switches_carrier_set": False}


class FaultyCfskDecodes(ReferenceAtp):
    """ATP-01: a faulty CFSK keeps sending decoded results."""
    ATP = {"fault_stops_decoding": False}


class Etcs46Unknown(ReferenceAtp):
    """ATP-11: ETCS-46 packets give a balise information error (the bug the article fixed)."""
    ATP = {"parses_etcs46": False}


class NoLinkingException(ReferenceAtp):
    """ATP-12: missing groups 70-2-4-15/16 brake like any other."""
    ATP = {"no_reaction_groups": ()}


FAULTY += [
    (FsToPsAt300m, "ATP-06", "F-ATP-09"),
    (StopWindow1m, "ATP-09", "F-ATP-11"),
    (CarrierAfterOneComparison, "ATP-03", "F-ATP-07"),
    (DefSteps2500ms, "ATP-08", "F-ATP-10"),
    (NoRearWidening, "ATP-02", "F-ATP-08"),
    (DefaultPsBelow50, "ATP-07", "F-ATP-09"),
    (CarrierSetFixed, "ATP-04", "F-ATP-07"),
    (FaultyCfskDecodes, "ATP-01", "F-ATP-07"),
    (Etcs46Unknown, "ATP-11", "F-ATP-12"),
    (NoLinkingException, "ATP-12", "F-ATP-12"),
    (NewFirmwarePostpones16ms, "VDX-06", "F-ATP-06"),
    (Threshold12V, "VDX-03", "F-ATP-06"),
    (SampledAtOnce, "VDX-03", "F-ATP-05"),
    (SelfTestEvery10s, "VDX-03", "F-ATP-05"),
    (C019Clears, "VDX-03", "F-ATP-05"),
    (C019ClearsAfterTenMinutes, "VDX-03", "F-ATP-05"),
    (RelayDropsIn2ms, "VDX-04", "F-ATP-05"),
    (SlowRelay, "VDX-04", "F-ATP-04"),
    (NarrowSupply, "VDX-02", "F-ATP-04"),
    (IsolationIgnored, "VDX-01", "F-ATP-04"),
]


class _RecordsOneFaultAWhile(OnboardAtp):
    """The ATP of CfskFaultsRecordedOnceAWhile."""
    QUIET_US = 10_000 * MS

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.fault_recorded_at: int | None = None

    def fail_cfsk(self, failed: bool) -> None:
        last = self.fault_recorded_at
        quiet = failed and last is not None and self.kernel.now - last < self.QUIET_US
        kept = list(self.records)
        super().fail_cfsk(failed)
        if quiet:
            self.records[:] = kept                  # the fault information went out, the record did not
        elif failed:
            self.fault_recorded_at = self.kernel.now


class CfskFaultsRecordedOnceAWhile(ReferenceAtp):
    """ATP-05: a CFSK fault within 10 s of the last one recorded is not recorded (its fault information still
    reaches the safety computer and the DMI): two faults close together leave one record. F-ATP-15's "a faulty
    CFSK is recorded and sends no decoded result" finds it, and F-ATP-07's "Two CFSK faults a second apart are
    both recorded" (before it, F-ATP-07 failed the CFSK once only)."""
    ONBOARD = _RecordsOneFaultAWhile


FAULTY += [(CfskFaultsRecordedOnceAWhile, "ATP-05", "F-ATP-15")]


class _RecordsTheLastCarrier(OnboardAtp):
    """The ATP of FaultRecordNamesTheLastCarrier."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.last_carrier: tuple[int, str] | None = None

    def fail_cfsk(self, failed: bool) -> None:
        self.last_carrier = self.cfsk.confirmed
        super().fail_cfsk(failed)

    def _record(self) -> None:
        c = self.cfsk
        if c.failed and c.confirmed is None and self.last_carrier:
            c.confirmed = self.last_carrier           # the carrier heard before the fault, as if still decoded
            try:
                super()._record()
            finally:
                c.confirmed = None
            return
        super()._record()


class FaultRecordNamesTheLastCarrier(ReferenceAtp):
    """ATP-05 with ATP-01: the record of a CFSK fault names the carrier confirmed before it failed, as if the
    failed board still decoded it (make mutate seed 13's survivor of atp/onboard.py:199 named a carrier of 1 Hz).
    Rejected by F-ATP-07's "A failed CFSK's record names no carrier" (a project decision: docs/decisions.md)."""
    ONBOARD = _RecordsTheLastCarrier


FAULTY += [(FaultRecordNamesTheLastCarrier, "ATP-05", "F-ATP-07")]


class AtpOnABrakeForceBlindTrain(ReferenceAtp):
    """ILK-03 in the fitted train (atp-crh2): the ATP is the reference's, the CRH2 set it brakes is
    BrakeForceBlindToAtp, whose supervision ignores the ATP's maximum service brake. Rejected by F-ATP-13's
    "The ATP's maximum service brake with the handle at 0: a car short of brake force trips the emergency
    brake"."""
    TRAIN = BrakeForceBlindToAtp


FAULTY += [(AtpOnABrakeForceBlindTrain, "ILK-03", "F-ATP-13")]


# Issue 31, item 4: two close CFSK faults in the hand-written item too, and `--req VDX-06` catching a C019 that
# clears itself (VDX-06: C019 is recovered by a restart; F-ATP-05's "stays until restart" scenarios carry it).
FAULTY += [
    (CfskFaultsRecordedOnceAWhile, "ATP-05", "F-ATP-07"),
    (C019Clears, "VDX-06", "F-ATP-05"),
    (C019ClearsAfterTenMinutes, "VDX-06", "F-ATP-05"),
]


class AnotherAtpRig(ReferenceAtp):
    """In band: another installation and CFSK: antenna 4.5 m behind the front, +-8 m odometry, comparisons
    every 40 ms (so a 120 ms decode delay). The features compute their edges from what it declares."""
    ATP = {"d_sen_m": 4.5, "position_uncertainty_m": 8.0, "cfsk_period_us": 40 * MS,
           "decode_delay_us": 120 * MS}
    DECLARATION = "tests/declarations/another-atp-rig.yaml"


# The DMI of a CTCS-2 train speaks Chinese; what it shows for each message the features name is declared.
DMI_ZH = {"CFSK fault": "CFSK故障", "carrier inconsistent": "载频不一致", "default telegram": "默认报文",
          "balise information error": "应答器信息错误", "DEF fault": "DEF故障"}


class ChineseDmiAtp(ReferenceAtp):
    """Freedom (localized display): the DMI shows its messages in Chinese, declared by message identifier."""
    DECLARATION = "tests/declarations/chinese-dmi-atp.yaml"

    def monitor(self, cab: int) -> dict:
        shown = super().monitor(cab)
        faults = []
        for text in shown["faults"]:
            for english, chinese in DMI_ZH.items():
                text = text.replace(english, chinese)
            faults.append(text)
        return {**shown, "faults": faults}


class FarDeclaredAtp(ReferenceAtp):
    """Freedom (declared parameters): an installation and a CFSK far from the reference's, inside the form's
    ranges: antenna 10 m behind the front, +-20 m odometry, comparisons every 100 ms, a 300 ms decode delay.
    Every edge and wait of the features must come from what it declares (a fixed 6 s wait failed it)."""
    ATP = {"d_sen_m": 10.0, "position_uncertainty_m": 20.0, "cfsk_period_us": 100 * MS, "decode_delay_us": 300 * MS}
    DECLARATION = "tests/declarations/far-declared-atp.yaml"


class TaskTickVdx(ReferenceAtp):
    """Freedom (timing resolution): a VDX on a 1 ms task tick with jitter, declared so: its self-test comes
    every 5000.7 ms and pulls the output low for 3.4 ms, each less than a tick off VDX-03; it samples on the
    tick, 1 ms in (a later sample sees the coil further decayed: VDX-05's 30 ms C019 window is the article's
    measurement at that sample point, docs/assertion-audit.md)."""
    VDX = {"selftest_period_us": 5000 * MS + 700, "selftest_removal_us": 3 * MS + 400}
    DECLARATION = "tests/declarations/task-tick-vdx.yaml"


class _HalfOpenRange(OnboardAtp):
    """The ATP of TouchingSectionOutsideTheRange."""
    BULK_READABLE = True          # no state of its own: bulk.py reads it as it reads its base

    def receiver_range(self) -> tuple[float, float]:
        d_min, d_max = super().receiver_range()
        return d_min, math.nextafter(d_max, -math.inf)


class TouchingSectionOutsideTheRange(ReferenceAtp):
    """In band: a track circuit that starts exactly at Dmax does not overlap the receiver range (ATP-02 says
    "overlapping" and leaves a touching section open; seed 18's `start_m < d_max`). The features test the edge
    0.1 m either side (F-ATP-08), not the one point where the two readings differ."""
    BULK_READABLE = True
    ONBOARD = _HalfOpenRange


IN_BAND += [AnotherCoil, AnotherAtpRig, TouchingSectionOutsideTheRange]
# Design freedoms a conforming product may take (issue 30), each with its own declaration: the whole suite
# must accept them, as the in-band variants.
FREEDOM = [ChineseDmiAtp, TaskTickVdx, ChineseDisplayMetro, ChineseMonitorCrh2, FarDeclaredAtp]
# The classes of design freedom issue 30 names, by the key a variant's FREEDOM_CLASS gives. Each freedom variant
# takes one design choice a conforming product may take; the whole suite must accept it
# (tests/test_faulty_variants.py). One with its own declaration must be rejected when held to the reference's;
# one without (a choice nothing declares, such as the order of simultaneous events) names in EXERCISED_BY the
# item whose trace shows it differing from the reference's.
FREEDOM_CLASSES = {
    "task-tick": "a task tick with jitter, within the declared timing resolution",
    "declared-parameters": "parameters declared away from the reference's values",
    "localized-texts": "localized display and DMI texts",
    "actuator-latency": "latency inside a bound, measured at the actuator",
    "range-edge-tolerance": "measurement tolerance at range edges",
    "simultaneous-ordering": "another ordering of simultaneous events",
    "record-wording": "another record wording in the documented shape",
    "io-map": "another I/O map and port layout",
    "optional-feature": "an optional feature a product may add (a standstill holding brake)",
    "product-choice": "a choice the articles or a project decision leave to the product (which brake a failed DEF "
                      "test holds; from when VDX-06's postponement counts)",
}
for _variant, _freedom in ((ChineseDmiAtp, "localized-texts"), (TaskTickVdx, "task-tick"),
                           (ChineseDisplayMetro, "localized-texts"), (ChineseMonitorCrh2, "localized-texts"),
                           (FarDeclaredAtp, "declared-parameters")):
    _variant.FREEDOM_CLASS = _freedom

# The freedom variants kept per profile; each is reachable as tests.variants:<Name> (--sut) like the others.
from tests import freedom_atp, freedom_crh2, freedom_metro  # noqa: E402  (they import nothing from here)

for _module in (freedom_atp, freedom_crh2, freedom_metro):
    for _variant in _module.FREEDOM:
        globals()[_variant.__name__] = _variant
    FREEDOM += _module.FREEDOM


# -- the contract's event entries (issue 31: the checker's overturned marks) ---------------------------------
# An event a step is handed must come from a source its kind's contract entry names and carry every field the
# entry requires (sut/contract/catalogue.py, check_event), whatever the step then reads: a step that selects
# by kind alone would take a mis-sourced event, and a field nobody reads could be left out unseen.
class LoopReportedByAnotherSource(ReferenceAtp):
    """VDX-04 (contract vdx.yaml, loop.change: source VDX): the loop's changes are reported as the lower-case
    `vdx`, a source the contract does not name (the checker's overturned marks of vdx.py:139)."""

    def _emit(self, source, kind, **fields):  # noqa: ANN001, ANN202
        super()._emit("vdx" if kind == "loop.change" else source, kind, **fields)


class _PollsWithoutFCode(MetroTrain):
    """The train of MvbPollsWithoutFCode: a subclass, so the reference's code is not edited."""

    def emit(self, source, kind, **fields):  # noqa: ANN001, ANN201
        if kind == "mvb.msg":
            fields.pop("f_code", None)
        super().emit(source, kind, **fields)


class MvbPollsWithoutFCode(ReferenceMetro):
    """TCN-03 (contract metro-tcn.yaml, mvb.msg: f_code required): the bus analyser's log of a poll leaves its
    F_code out (the checker's overturned mark of tcds.py's mvb.msg emit)."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _PollsWithoutFCode(self._train.cfg)


FAULTY += [
    (LoopReportedByAnotherSource, "VDX-04", "F-ATP-05"),
    (MvbPollsWithoutFCode, "TCN-03", "F-NET-21"),
]


class TokenVisitsCountedFromOne(ReferenceTrain):
    """PRO-04/TST-02: every node's `tokens received` counter starts at 1, not 0 (the checker's overturned mark
    of node.py): the long runs compare counters before and after and cannot see it; the counters against the
    trace since power-up can (H-CPO-01)."""

    def counters(self, node: str) -> dict[str, int]:
        counts = super().counters(node)
        return dict(counts, **{"tokens received": counts["tokens received"] + 1})


FAULTY += [(TokenVisitsCountedFromOne, "PRO-04", "H-CPO-01")]


class SelfTestVerdictInCapitals(ReferenceAtp):
    """VDX-03 (contract vdx.yaml, selftest: `result` is `pass` or `C019`): a passed self-test is logged `PASS`
    (make mutate seed 10's survivor of vdx.py:180). The words a field takes are the contract's: check_event
    holds every field whose values the contract lists to them."""

    def _emit(self, source, kind, **fields):  # noqa: ANN001, ANN202
        if kind == "selftest" and fields.get("result") == "pass":
            fields["result"] = "PASS"
        super()._emit(source, kind, **fields)


FAULTY += [(SelfTestVerdictInCapitals, "VDX-03", "F-ATP-05")]


class _VdxPostponesFromACancelledRelease(VdxInterface):
    """The VDX of SelfTestPostponedFromACancelledRelease."""

    def _selftest_due(self) -> None:
        if self.testing:
            return
        since = self.kernel.now - (self.released_at or 0)
        postpone = (self.cfg.postpone_us or POSTPONE)[self.firmware]
        if since < postpone:
            self._emit("VDX", "selftest.postpone", by_ms=(postpone - since) / 1000, since_release_ms=since / 1000)
            self._test_timer = self.kernel.call_later(postpone - since, self._selftest)
        elif self.fs_on:
            self._selftest()


class SelfTestPostponedFromACancelledRelease(ReferenceAtp):
    """VDX-06: a self-test due while the brake is applied is postponed from the release before that brake and
    runs when the brake is released again, a few ms after that release: the coil is charged and the new
    firmware raises C019 (make mutate seed 10's survivor of vdx.py:147, `or` made `and`)."""
    VDX_INTERFACE = _VdxPostponesFromACancelledRelease


FAULTY += [(SelfTestPostponedFromACancelledRelease, "VDX-06", "F-ATP-06")]


# -- events no step is handed, held to the contract at a scenario's end (ContractDriver.check_trace) ----------
class _PressureUnstatedAtPowerUp(Vehicle):
    """The vehicle of PowerUpStatementWithoutPressure."""
    BULK_READABLE = True         # no state of its own (sut/reference/bulk.py)

    def announce(self) -> None:
        emit = self.train.emit
        self.train.emit = lambda source, kind, **fields: emit(source, kind, **dict(fields, pressure=None))
        try:
            super().announce()
        finally:
            del self.train.emit


class PowerUpStatementWithoutPressure(_OwnParts):
    """CMD-02/ILK-01 (contract crh2.yaml, out.change: `pressure` a number): the optional statement of every
    output at power-up carries no pressure (make mutate seed 10's survivor of vehicle.py:196). No step selects
    those statements; a scenario's end holds every listed kind's first events to its entry."""
    VEHICLE = _PressureUnstatedAtPowerUp


FAULTY += [(PowerUpStatementWithoutPressure, "ILK-01", "F-ILK-01")]


class _FailureRecordedAtPowerUp(MetroTrain):
    """The train of TrainNetworkFailureRecordedAtPowerUp: a subclass, so the reference's code is not edited."""

    def __init__(self, cfg) -> None:  # noqa: ANN001
        super().__init__(cfg)
        self.modes = {1: "starting", 2: "starting"}


class TrainNetworkFailureRecordedAtPowerUp(ReferenceMetro):
    """TCN-09: the mode a unit takes before its first commands have come (train network failure) is recorded
    as a failure at power-up (make mutate seed 11's survivors of tcds.py:138)."""

    def __init__(self) -> None:
        super().__init__()
        self._train = _FailureRecordedAtPowerUp(self._train.cfg)


FAULTY += [(TrainNetworkFailureRecordedAtPowerUp, "TCN-09", "F-NET-25")]
