"""Freedom variants of the crh2 reference (issue 30, item 4); the rules they follow are beside
tests/variants.py FREEDOM_CLASSES.

Each changes the reference by its parameter dicts only (TIMING, BEHAVIOUR; the BEHAVIOUR switches they use are
general hooks whose reference values change nothing). Not by subclasses of the model's classes: bulk advance
(sut/reference/bulk.py) reads only classes of sut.*, so a train holding one runs a 72 h soak event by event."""
from __future__ import annotations

from sut.reference.crh2.backend import ReferenceTrain

MS = 1000


class SlowLoopsCrh2(ReferenceTrain):
    """Freedom (actuator latency): slower 20 mA loops between the TXC and its MDM8 (2 ms) and between the
    LCU's MDM8 and its RXC (5 ms), against the reference's 0.5 ms each: a desk command reaches the TXC's
    MDM8 and CI and BCU on paths 2 and 3 later, still inside every bound the features measure where the
    command arrives (cmd.tx at the MDM8, cmd.in at the device). Nothing declares the loops' transfer time;
    F-CTL-01's trace shows the later arrivals."""
    TIMING = {"txc_loop_us": 2 * MS, "rxc_loop_us": 5 * MS}
    FREEDOM_CLASS = "actuator-latency"
    EXERCISED_BY = "F-CTL-01"


class OwnLoopPeriodsCrh2(ReferenceTrain):
    """Freedom (declared parameters): NET-09's "periods per device" of its own, declared: ACS every 80 ms,
    PID every 250 ms, APU every 40 ms, SDD fed every 500 ms, DD reporting every 120 ms, each within 2 %."""
    TIMING = {"current_loop_periods_us": (("ACS", 80 * MS), ("PID", 250 * MS), ("APU", 40 * MS),
                                          ("SDD", 500 * MS), ("DD", 120 * MS))}
    DECLARATION = "tests/declarations/own-loop-periods-crh2.yaml"
    FREEDOM_CLASS = "declared-parameters"


class OutputsLastFirstCrh2(ReferenceTrain):
    """Freedom (simultaneous ordering): the vehicle outputs that change at one instant are logged in the other
    order: at a train separation the rapid brake before the emergency brake (ILK-01's "together"), at a pipe
    trip the valves after the brakes. F-ILK-01's trace shows the other order."""
    BEHAVIOUR = {"outputs_logged_last_first": True}
    FREEDOM_CLASS = "simultaneous-ordering"
    EXERCISED_BY = "F-ILK-01"


class TaskTickCrh2(ReferenceTrain):
    """Freedom (timing resolution): the interlock software runs on a 1 ms task tick, declared
    (timing_resolution_us 1000): it writes the rapid-brake outputs one tick after the emergency-brake loop the
    same input opened (ILK-01's "together" is one instant of the product)."""
    BEHAVIOUR = {"rapid_brake_delay_us": 1 * MS}
    DECLARATION = "tests/declarations/task-tick-crh2.yaml"
    FREEDOM_CLASS = "task-tick"


class OwnRecordWordsCrh2(ReferenceTrain):
    """Freedom (record wording): fault records in the documented shape `F|<t ms>|<node>|<board>|<event>` with
    event words of its own (FAULT, NORMAL), declared (texts `failed`, `recovered`, view records); its
    maintenance view shows them so (`<board> FAULT`, declared for `<board> failed`)."""
    BEHAVIOUR = {"record_words": (("failed", "FAULT"), ("recovered", "NORMAL"))}
    DECLARATION = "tests/declarations/own-record-words-crh2.yaml"
    FREEDOM_CLASS = "record-wording"


FREEDOM: list[type] = [SlowLoopsCrh2, OwnLoopPeriodsCrh2, OutputsLastFirstCrh2, TaskTickCrh2, OwnRecordWordsCrh2]


class SlowReactionsCrh2(ReferenceTrain):
    """Freedom (declared parameters): a product whose every reaction is slower than the reference's, declared
    (reaction_margin_ms 40): CI and BCU act on a command 15 ms after it arrives, the vehicle's outputs follow
    their inputs 25 ms late, the cab monitor shows a change 10 ms late. No requirement bounds these reactions;
    the features' budgets (docs/decisions.md, "Reaction-time budgets") grow by the declared margin."""
    BEHAVIOUR = {"command_take_delay_us": 15 * MS, "output_delay_us": 25 * MS, "display_delay_us": 10 * MS}
    DECLARATION = "tests/declarations/slow-reactions-crh2.yaml"
    FREEDOM_CLASS = "declared-parameters"


FREEDOM.append(SlowReactionsCrh2)


class MeasurementToleranceCrh2(ReferenceTrain):
    """Freedom (measurement tolerance at range edges): the interlocks and the compressor governor act on a main
    pipe pressure read 2.5 kPa low and a speed read 0.4 km/h high, inside the accuracies it declares (3 kPa,
    0.5 km/h). So the press-seal valve energises at 29.6 km/h, the door-open relay acts below 4.6 km/h, the pipe
    trips below 592.5 kPa and the compressor starts below 782.5 kPa. The features feed each edge the declared
    accuracy clear of it and widen each band by it; held to the reference's 0, F-ILK-05 (the valve at 30 km/h)
    and F-CTL-09 (the compressor at 781 kPa) reject it."""
    BEHAVIOUR = {"pressure_read_kpa": -2.5, "speed_read_kmh": 0.4}
    DECLARATION = "tests/declarations/measurement-tolerance-crh2.yaml"
    FREEDOM_CLASS = "range-edge-tolerance"


FREEDOM.append(MeasurementToleranceCrh2)


class StandstillHoldingBrakeCrh2(ReferenceTrain):
    """Freedom (optional feature): a CCU that holds brake step 3 (step A on paths 2 and 3) on every BCU while
    the train stands and the active cab's command carries no traction notch (the controller at 0, or traction
    not permitted), and takes it off in the command that first carries a notch. No requirement asks for it or
    forbids it; the cab's brake lamp still shows the driver's handle (docs/decisions.md, "Standstill holding
    brake (crh2)")."""
    BEHAVIOUR = {"standstill_holding_brake": 3}
    FREEDOM_CLASS = "optional-feature"
    EXERCISED_BY = "F-CTL-01"


FREEDOM.append(StandstillHoldingBrakeCrh2)
