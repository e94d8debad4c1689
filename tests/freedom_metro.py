"""Freedom variants of the metro reference (issue 30, item 4); the rules they follow are beside
tests/variants.py FREEDOM_CLASSES."""
from __future__ import annotations

from tests.wording import reword


from sut.reference.metro.backend import ReferenceMetro

MS = 1000

FREEDOM: list[type] = []


# -- optional-feature: a standstill holding brake ---------------------------------------------------------
class StandstillHoldingBrake(ReferenceMetro):
    """Freedom (optional feature): a TCDS that holds 30 % service brake on every BECU while the train stands in
    normal mode and the active cab's train command asks no traction (key in, controller at 0 % or the direction
    switch at neutral), and takes it off on every BECU at the instant that command asks traction (a train-wide
    function of the active cab). No requirement asks for it or forbids it; the suite must accept it
    (docs/decisions.md, "Standstill holding brake")."""
    FREEDOM_CLASS = "optional-feature"
    EXERCISED_BY = "F-CTL-15"
    BEHAVIOUR = {"standstill_holding_brake": 3000}          # 0.01 %


FREEDOM += [StandstillHoldingBrake]


# -- io-map: another I/O channel map, scaling and port layout ------------------------------------------------
class OtherIoMapMetro(ReferenceMetro):
    """Freedom (I/O map): the cab desk wired otherwise inside TCN-07's 28 DI / 3 AI: the traction demand on AI2,
    the brake demand on AI1, both in 0.1 % (1000 counts for 100 %), the direction switch on DI05 (forward) and
    DI06 (reverse); and the I/O module port in a 256-bit slave frame (F_code 4, TCN-05 allows 16..256 bits)
    instead of 128 bits. Declared in tests/declarations/other-io-map-metro.yaml."""
    FREEDOM_CLASS = "io-map"
    DECLARATION = "tests/declarations/other-io-map-metro.yaml"
    BEHAVIOUR = {"ai_traction": 2, "ai_brake": 1, "ai_full_scale": 1000, "di_forward": 5, "di_reverse": 6,
                 "io_port_f_code": 4}


FREEDOM += [OtherIoMapMetro]


# -- record-wording: its own words for the events, in the documented record shape -------------------------------
# Another vendor's English: each message identifier of the form (sut/contract/form.yaml, metro-tcn texts) as its
# display and records word it, <name> where it shows the name. The record line keeps the documented shape
# `<t_ms> <origin>: <text>` (sut/contract/metro-tcn.yaml, records).
OWN_MODES = {"normal": "NORMAL", "no cab": "NO ACTIVE CAB", "train network failure": "TRAIN NETWORK FAILURE",
             "emergency operation": "EMERGENCY MODE"}
OWN_TEXTS = {"<device>: no status data": "<device> status timeout",
             "<device>: answering again": "<device> status OK",
             "<node>: no answer on WTB": "WTB node <node> lost",
             "<node>: answering on WTB again": "WTB node <node> back",
             "WTB master (<node> silent)": "WTB mastership taken over from <node>",
             "inputs from <module>": "I/O source switched to <module>",
             "no MVB I/O module alive": "NO LIVE I/O MODULE, CAB INPUTS LOST",
             "<bus> line <line>: fault": "<bus> channel <line> failed",
             "<bus> line <line>: restored": "<bus> channel <line> recovered",
             "train network failure: braking to a stop": "TRAIN NETWORK FAILURE - BRAKE TO STOP"}


def _reworded(text: str) -> str:
    return reword(text, OWN_TEXTS)


class OwnWordingMetro(ReferenceMetro):
    """Freedom (record wording): the CCU memories record, and the displays show, the events in the vendor's own
    English (`1523.000 car6.CCU: car4.VVVF status timeout`), declared by message identifier in
    tests/declarations/own-wording-metro.yaml."""
    FREEDOM_CLASS = "record-wording"
    DECLARATION = "tests/declarations/own-wording-metro.yaml"

    def monitor(self, cab: int) -> dict:
        shown = super().monitor(cab)
        return {**shown, "mode": OWN_MODES.get(shown["mode"], shown["mode"]),
                "faults": [_reworded(f) for f in shown["faults"]]}

    def records(self, unit: str) -> list[str]:
        return [_reworded(r) for r in super().records(unit)]


FREEDOM += [OwnWordingMetro]


# -- actuator-latency: drives and brake units that apply a command a few ms after it arrives -----------------
class LateActuatorMetro(ReferenceMetro):
    """Freedom (actuator latency): every VVVF and BECU applies a new traction or brake 5 ms after its unit's
    train command asks for it (and drops a change asked back meanwhile), well inside the features' bounds
    (100 ms delivery, 50 ms in emergency operation), which the steps measure at the device (its pd.change and
    reading)."""
    FREEDOM_CLASS = "actuator-latency"
    EXERCISED_BY = "F-CTL-15"
    TIMING = {"actuator_latency_us": 5 * MS}


FREEDOM += [LateActuatorMetro]


# -- task-tick: bus masters on a 1 ms task tick with jitter ------------------------------------------------
class TaskTickMetro(ReferenceMetro):
    """Freedom (task tick): the MVB and WTB masters run on a 1 ms task tick whose every other start is 0.3 ms
    late, declared as timing_resolution_us 1000 (tests/declarations/task-tick-metro.yaml): master frames come
    up to 1.3 ms apart on the MVB and WTB cycles 24.7-25.3 ms apart, each within a tick of TCN-03's figure."""
    FREEDOM_CLASS = "task-tick"
    DECLARATION = "tests/declarations/task-tick-metro.yaml"
    TIMING = {"task_jitter_us": 300}


FREEDOM += [TaskTickMetro]


# -- declared-parameters: its own counts of silent polls --------------------------------------------------------
class OwnSilentPollsMetro(ReferenceMetro):
    """Freedom (declared parameters): a node silent on the WTB and a device silent to its status polls are
    reported after 5 polls, not 3 (the articles give no count), declared as wtb_silent_polls and
    status_silent_polls 5 (tests/declarations/own-silent-polls-metro.yaml)."""
    FREEDOM_CLASS = "declared-parameters"
    DECLARATION = "tests/declarations/own-silent-polls-metro.yaml"
    TIMING = {"status_silence_polls": 5}


FREEDOM += [OwnSilentPollsMetro]


# -- simultaneous-ordering: what changes at one instant, in another order ------------------------------------
class SinksLastFirstMetro(ReferenceMetro):
    """Freedom (simultaneous ordering): a unit refreshes its VVVFs and BECUs in the reverse order, so what
    changes at one instant (a brake released and traction taken up together, TCN-09) is logged last device
    first; the steps judge the train after all events of one instant."""
    FREEDOM_CLASS = "simultaneous-ordering"
    EXERCISED_BY = "F-CTL-15"
    BEHAVIOUR = {"sinks_last_first": True}


FREEDOM += [SinksLastFirstMetro]
