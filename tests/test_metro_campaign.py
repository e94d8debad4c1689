"""The metro single-fault campaign (F-NET-34, outline/campaigns/metro_campaign.py): generated from the metro SUT's own
fault space, kept equal to it, and grouped by the design's answers."""
from __future__ import annotations

import pytest

from outline.campaigns import metro_campaign as mc
from outline.campaigns.metro_campaign import (ACTIVE_LOST, ASIDE, DEAD_BRAKE, DEAD_DRIVE, LINE, MODULE_2, MODULE_IDLE,
                                    OTHER_LOST, STANDBY, Fault)
from outline.campaigns.campaign_text import example_rows, powered
from tests.test_faulty_variants import ROOT



@pytest.fixture(scope="module")
def metro():
    with powered("reference", "metro-tcn", 1, 6) as sut:
        yield sut


@pytest.fixture(scope="module")
def text() -> str:
    return (ROOT / mc.PATH).read_text(encoding="utf-8")


def test_the_checked_in_campaign_is_the_generators_output(text: str) -> None:
    assert mc.generate("reference") == (mc.PATH, text), "run `python -m outline campaign`"


def test_every_fault_the_driver_names_is_a_row_or_left_out_with_a_reason(metro, text: str) -> None:
    # The fault space read here without the generator: every unit, board, module and device of cars 1-6, and
    # both lines of every bus the backend names.
    names = {name for car in range(1, 7) for name in metro.devices(car)}
    names |= {f"{unit}.{board}" for unit in names if unit.endswith((".CCU", ".VCU")) for board in metro.boards(unit)}
    lines = {(bus, line) for bus in ("WTB", "unit1.MVB", "unit2.MVB") for line in "AB"}
    rows = example_rows(text)
    run_lines = {(row["bus"], row["line"]) for row in rows if "bus" in row}
    run_names = [value for row in rows if "bus" not in row for value in row.values()]
    listed = [name.strip() for line in text.splitlines() if line.startswith("  - ")
              for name in line[4:].split(": ", 1)[0].split(",")]
    assert run_lines == lines
    assert sorted(run_names + listed) == sorted(names), "each fault exactly once, as a row or left out"
    assert (len(names) + len(lines), len(rows), len(listed)) == (60, 50, 10)


@pytest.mark.parametrize("kind, name, answer", [
    ("line", ("WTB", "A"), LINE),                      # RED-06: the other line, without loss
    ("line", ("unit2.MVB", "B"), LINE),
    ("unit", ("car1.CCU",), ACTIVE_LOST),              # RED-05 adjacent VCU, RED-04 car 2 VCU on the WTB
    ("board", ("car1.CCU.VPS",), ACTIVE_LOST),         # §2.1: without its power supply board the CCU is dead
    ("board", ("car1.CCU.VCPUS",), ACTIVE_LOST),       # nor without its processor
    ("unit", ("car6.CCU",), OTHER_LOST),               # F-CTL-15: car 5's VCU relays the command, car 1 keeps the WTB
    ("board", ("car1.CCU.VMS",), ASIDE),               # §2.1: records only; §3.2: the command goes over the MVB
    ("board", ("car6.CCU.VDIS",), ASIDE),
    ("unit", ("car3.VCU",), STANDBY),                  # RED-04: the WTB stops only with all three of unit 1 down
    ("board", ("car2.VCU.VGWS",), STANDBY),            # a standby's gateway: nothing to hand over
    ("unit", ("car5.VCU",), STANDBY),                  # RED-05: a VCU takes an MVB only from a failed CCU
    ("module", ("car1.IO1",), MODULE_2),               # RED-07: life signal 0 -> module 2
    ("module", ("car1.IO2",), MODULE_IDLE),            # RED-07: module 1 still lives
    ("module", ("car6.IO1",), MODULE_IDLE),            # TCN-08: the cab without the key gives no command
    ("device", ("car6.DU",), ASIDE),                   # TCN-04: a display answers status polls, commands nothing
    ("device", ("car1.VATC",), ASIDE),
    ("device", ("car4.VVVF",), DEAD_DRIVE),            # left out: no network makes a dead drive pull
    ("device", ("car1.BECU",), DEAD_BRAKE),
    ("board", ("car6.CCU.VGWS",), OTHER_LOST),         # cut off from the train: as a dead CCU (docs/decisions.md)
    ("board", ("car1.CCU.VGWS",), ACTIVE_LOST),
])
def test_each_fault_gets_the_designs_answer(kind: str, name: tuple[str, ...], answer) -> None:
    assert mc.expectation(Fault(kind, name)) is answer


def test_the_takeovers_name_the_masters_the_articles_name() -> None:
    # RED-04: car 2's VCU is the first WTB backup; RED-05: the VCU next to the failed CCU takes its MVB.
    assert '"car2.VCU" is the WTB master within 250 ms and stays so' in ACTIVE_LOST.then
    assert '"car2.VCU" is the master of "unit1.MVB" within 100 ms and stays so' in ACTIVE_LOST.then
    assert '"car5.VCU" is the master of "unit2.MVB" within 100 ms and stays so' in OTHER_LOST.then
    assert '"car1.CCU" is the WTB master within 25 ms and stays so' in OTHER_LOST.then     # §3.1: only car 1 CCU


def test_the_bounds_are_the_hand_written_metro_features() -> None:
    """A bound changed in a hand-written item must be changed here too (and the campaign written again)."""
    def item(name: str) -> str:
        return next((ROOT / "features").rglob(f"{name}.feature")).read_text(encoding="utf-8")

    assert f"is the WTB master within {mc.WTB_TAKEOVER} ms and stays so" in item("F-NET-22")
    assert f"is the WTB master within {mc.WTB_CYCLE} ms and stays so" in item("F-NET-22")
    assert f'is the master of "<bus>" within {mc.MVB_TAKEOVER} ms and stays so' in item("F-CTL-15")
    assert f"every VVVF applies 45 % traction within {mc.DELIVERY} ms" in item("F-CTL-15")
    assert f'is the master of "unit<unit>.MVB" within {mc.MVB_PERIOD} ms and stays so' in item("F-NET-21")
    assert f"{mc.WINDOW} ms pass" in item("F-NET-22")


def test_a_fault_the_design_has_no_rule_for_stops_the_generator() -> None:
    """A unit, module or device added to the SUT needs a rule, never a silent group."""
    with pytest.raises(ValueError, match="no rule for device 'car3.HVAC'"):
        mc.expectation(Fault("device", ("car3.HVAC",)))
    with pytest.raises(ValueError, match="no rule for board 'car1.CCU.VXYZ'"):
        mc.expectation(Fault("board", ("car1.CCU.VXYZ",)))
