"""The single-fault campaigns (issue 16, outline/campaigns/campaign.py): generated from the SUT's own fault space, and
kept equal to it."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from outline.campaigns import campaign
from outline.campaigns import metro_campaign
from outline.campaigns.campaign import NO_MDM9, OFF_THE_RING, RIDES, TAKES_OVER
from outline.campaigns.fault_model import Fault, Records, TrainShape, fault_record
from outline.campaigns.campaign_text import example_rows, powered, record_bound, regenerated_record_bound
from tests.variants import DOUBLE_ONLY
from tests.test_faulty_variants import ROOT


@pytest.fixture(scope="module")
def eight_cars():
    with powered("reference", "crh2", 1, 8) as sut:
        yield sut


def test_the_checked_in_campaigns_are_the_sut_fault_space(capsys) -> None:
    assert campaign.run(ROOT, "reference", check=True) == 0, capsys.readouterr().err


def test_every_span_board_and_supply_is_a_scenario_and_the_desks_are_listed_as_left_out(eight_cars) -> None:
    text = (ROOT / campaign.CAMPAIGNS[0].path).read_text(encoding="utf-8")
    nodes = eight_cars.ring_nodes()
    # a TXC's board and its supply share a name: a list, not a set; the car and record columns aside
    rows = [tuple(v for k, v in row.items() if k not in ("car", "node", "part")) for row in example_rows(text)]
    spans = {(a, b) for a, b in zip(nodes, nodes[1:] + nodes[:1])}
    boards = {(f"{node}.{board}",) for node in nodes for board in eight_cars.boards(node)}
    supplies = {(s,) for s in eight_cars.supplies() if not s.endswith(".desk")}
    assert set(rows) == spans | boards | supplies
    assert len(rows) == len(spans) + len(boards) + len(supplies) == 80
    assert "  - car1.desk: the desk's digital inputs" in text and "  - car8.desk:" in text


def test_a_campaign_that_misses_a_fault_is_reported_with_its_file(tmp_path: Path, capsys) -> None:
    for one in [*(c.path for c in campaign.CAMPAIGNS), metro_campaign.PATH]:
        (tmp_path / one).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / one, tmp_path / one)
    path = tmp_path / campaign.CAMPAIGNS[0].path
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    path.write_text("".join(line for line in lines if "car5.LCU.MDM9" not in line), encoding="utf-8")
    assert campaign.run(tmp_path, "reference", check=True) == 1
    err = capsys.readouterr().err
    assert f"{campaign.CAMPAIGNS[0].path}:1: the campaign differs from the SUT's fault space" in err
    assert campaign.CAMPAIGNS[1].path not in err and metro_campaign.PATH not in err


@pytest.mark.parametrize("kind, target, group, car", [
    ("span", ("car3.LCU", "car4.LCU"), RIDES, None),                    # NET-03: the other way round
    ("board", ("car1.CCU.sys1.CPU3",), RIDES, None),                    # CMD-01: commands bypass CPU3
    ("board", ("car1.CCU.sys1.MDM8",), TAKES_OVER, None),               # RED-01/02
    ("supply", ("car1.CCU.sys1.TXC",), TAKES_OVER, None),
    ("supply", ("car1.CCU.sys1",), TAKES_OVER, None),                   # its MDM8 goes with it
    ("supply", ("car1.CCU.sys2",), RIDES, None),                        # the standby system
    ("board", ("car8.CCU.sys1.TXC",), RIDES, None),                     # the other cab's CCU
    ("board", ("car5.LCU.MDM8",), OFF_THE_RING, 5),                     # CMD-04: path 3
    ("supply", ("car5.LCU",), OFF_THE_RING, 5),                         # MDM8 and MDM9 on the LCU's supply
    ("supply", ("car5.LCU.RXC",), RIDES, None),                         # the RXC's own supply (CMD-01)
    ("board", ("car5.LCU.MDM9",), NO_MDM9, 5),                          # CMD-03: path 2
    ("board", ("car5.LCU.RXC",), RIDES, None),
])
def test_each_fault_gets_the_designs_answer(eight_cars, kind, target, group, car) -> None:
    assert campaign.expectation(TrainShape.of(eight_cars), Fault(kind, target), campaign.COMMANDING) == (group, car)


def test_the_single_fault_answers_are_the_fault_models(eight_cars) -> None:
    """The campaign's groups, read car by car, are what outline/campaigns/fault_model.py gives for each single fault."""
    shape = TrainShape.of(eight_cars)
    faults, _left_out = campaign.fault_space(eight_cars)
    for fault in faults:
        group, car = campaign.expectation(shape, fault, campaign.COMMANDING)
        off = {OFF_THE_RING: 3, NO_MDM9: 2}.get(group)
        want = {c: (off if c == car else 1) for c in shape.cars}
        assert shape.paths([fault]) == want, fault


# -- the fault model (outline/campaigns/fault_model.py) on double faults, against the articles read by hand -------------
def _paths(shape: TrainShape, *faults: Fault) -> str:
    return "".join("-" if p is None else str(p) for _car, p in sorted(shape.paths(faults).items()))


def _span(a: str, b: str) -> Fault:
    return Fault("span", (a, b))


def _board(name: str) -> Fault:
    return Fault("board", (name,))


def test_the_fault_model_answers_double_faults_as_the_articles_do(eight_cars) -> None:
    shape = TrainShape.of(eight_cars)
    # NET-03 and CMD-04: two cuts split the ring; the segment without the commanding CCU falls back to path 3.
    assert _paths(shape, _span("car3.LCU", "car4.LCU"), _span("car6.LCU", "car7.LCU")) == "11133311"
    # RED-02: system 1 cut off from system 2 on both sides: each commands the segment it is in, on path 1.
    assert _paths(shape, _span("car1.CCU.sys1", "car1.CCU.sys2"), _span("car5.LCU", "car6.LCU")) == "11111111"
    # Both modems of the cab: nothing enters the ring, system 1's TXC still drives the self-diagnostic line.
    assert _paths(shape, _board("car1.CCU.sys1.MDM8"), _board("car1.CCU.sys2.MDM8")) == "33333333"
    # docs/decisions.md: a standby deaf to the ring does not take over, so with system 1's TXC dead nothing commands.
    assert _paths(shape, _board("car1.CCU.sys1.TXC"), _board("car1.CCU.sys2.MDM8")) == "--------"
    # CMD-03 and CMD-01: a car without its MDM9 and its RXC has no path left; the others ride on.
    assert _paths(shape, _board("car5.LCU.MDM9"), Fault("supply", ("car5.LCU.RXC",))) == "1111-111"
    # A dead MDM8 and a cut: car 3's LCU is off the ring, and car 2, between the cut and car 3, hears nobody.
    assert _paths(shape, _board("car3.LCU.MDM8"), _span("car1.LCU", "car2.LCU")) == "13311111"


def test_the_double_fault_campaign_is_bound_only_when_asked_for() -> None:
    import subprocess
    import sys

    def collected(*args: str) -> str:
        run = subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:xdist",
                              "-p", "no:cacheprovider", "--collect-only", *args],
                             cwd=ROOT, capture_output=True, text=True, timeout=300)
        return run.stdout.strip().splitlines()[-1]

    assert "test_fnet32" not in collected()
    assert collected("--item", "F-NET-32").startswith("3160/")


# -- faulty variants that only a double fault exposes (tests/variants.py DOUBLE_ONLY) -------------------------
@pytest.mark.cost(8)
@pytest.mark.parametrize("variant", DOUBLE_ONLY, ids=lambda v: v.__name__)
def test_a_double_fault_only_variant_passes_the_single_fault_campaign_and_fails_the_double(variant) -> None:
    """Both on the 8-car set: every single fault (F-NET-30) passes, some pair of them (F-NET-32) rejects."""
    import subprocess
    import sys

    def run(items: str, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "pytest", "features", "-q", "-p", "no:xdist", "-p",
                               "no:cacheprovider", f"--item={items}", f"--sut=tests.variants:{variant.__name__}",
                               *args], cwd=ROOT, capture_output=True, text=True, timeout=600)

    single = run("F-NET-30")
    assert single.returncode == 0, f"a single fault exposed it:\n{single.stdout[-2000:]}"
    double = run("F-NET-32", "-x")          # the first rejecting pair is enough
    assert double.returncode == 1 and "FAILED features/test_outline.py::test_fnet32" in double.stdout, \
        double.stdout[-2000:]


@pytest.mark.parametrize(("fault", "record"), [
    (Fault("span", ("car2.LCU", "car3.LCU")), None),                     # no board fails
    (Fault("board", ("car3.LCU.MDM9",)), ("car3.LCU", "MDM9")),
    (Fault("board", ("car1.CCU.sys1.TXC",)), ("car1.CCU.sys1", "TXC")),
    (Fault("board", ("car3.LCU.CPU3",)), None),                          # the writer itself is dead
    (Fault("board", ("car3.LCU.MDM8",)), None),                          # nothing leaves the node
    (Fault("supply", ("car3.LCU",)), None),                              # CPU3 and MDM8 go with the unit's supply
    (Fault("supply", ("car3.LCU.RXC",)), ("car3.LCU", "RXC")),           # CMD-01: the RXC's own supply, the RXC alone
])
def test_the_fault_record_a_single_fault_makes_is_read_off_the_decision(fault: Fault, record) -> None:
    assert fault_record(fault) == record


def test_a_record_after_a_takeover_is_looked_for_at_system_2_within_two_token_rounds() -> None:
    text = (ROOT / campaign.CAMPAIGNS[0].path).read_text(encoding="utf-8")
    outline = text.split("Scenario Outline: F-NET-30 Board <board> failed, the commanding system lost: system 2 "
                         "takes over, recorded at car1.CCU.sys2\n", 1)[1].split("Scenario Outline", 1)[0]
    assert record_bound(12) == 2 * 120 + 100 + 10          # 12 nodes of an 8-car set: 120 ms rounds (PRO-02)
    assert (f'"car1.CCU.sys2" holds a fault record of "<node>" saying "<part>" failed at most {record_bound(12)} ms '
            "after it") in outline
    assert "| car1.CCU.sys1.TXC | car1.CCU.sys1 | TXC  |" in outline


# -- fault records under two faults (outline/campaigns/fault_model.py TrainShape.records), read off docs/decisions.md ----------
def test_the_fault_records_of_a_double_fault_are_read_off_the_decisions(eight_cars) -> None:
    shape = TrainShape.of(eight_cars)
    sys1, sys2 = "car1.CCU.sys1", "car1.CCU.sys2"
    # A cut leaves a way round the ring: car 3's record reaches system 1.
    assert shape.records((_board("car3.LCU.MDM9"), _span("car5.LCU", "car6.LCU"))) == \
        Records(sys1, (("car3.LCU", "MDM9"),), None)
    # Its MDM8 dead too: the record never leaves the node.
    assert shape.records((_board("car3.LCU.MDM9"), _board("car3.LCU.MDM8"))) == Records(sys1, (), None)
    # Two nodes' records, each its own grant.
    assert shape.records((_board("car3.LCU.MDM9"), Fault("supply", ("car5.LCU.RXC",)))) == \
        Records(sys1, (("car3.LCU", "MDM9"), ("car5.LCU", "RXC")), None)
    # System 1's TXC lost and system 2 deaf to the ring: nobody takes over, system 1 stays the master and keeps
    # its own record.
    assert shape.records((_board(f"{sys1}.TXC"), _board(f"{sys2}.MDM8"))) == Records(sys1, ((sys1, "TXC"),), None)
    # After a takeover the record is at system 2, heard the long way round past the cut.
    assert shape.records((_board(f"{sys1}.TXC"), _span(sys1, sys2))) == Records(sys2, ((sys1, "TXC"),), None)
    # The master's own CPU3 dead: no one stores records, and the campaign says so instead of asking.
    unchecked = shape.records((_board(f"{sys1}.CPU3"), _board("car3.LCU.MDM9")))
    assert unchecked.held == () and "car1.CCU.sys1, cannot store records" in unchecked.unchecked
    # Two cuts and no board: nothing to record, nothing left unchecked.
    assert shape.records((_span("car3.LCU", "car4.LCU"), _span("car6.LCU", "car7.LCU"))) == Records(None, (), None)


def test_double_fault_records_are_waited_for_through_a_token_regeneration() -> None:
    # 12 nodes: 500 ms without a token, 240 ms to form it, then per node recording two 240 ms rounds of a line
    # and a 10 ms block, and a takeover.
    assert regenerated_record_bound(12, 1) == 500 + 240 + 480 + 10 + 100
    assert regenerated_record_bound(12, 2) == 500 + 240 + 2 * (480 + 10) + 100
    text = (ROOT / campaign.CAMPAIGNS[2].path).read_text(encoding="utf-8")
    outline = text.split("Scenario Outline: F-NET-32 Board <board1> failed and board <board2> failed: each car by "
                         "the path left to it, both faults recorded at the master\n", 1)[1].split("Examples:", 1)[0]
    assert (f'And "<master>" holds a fault record of "<node2>" saying "<part2>" failed at most '
            f"{regenerated_record_bound(12, 2)} ms after it") in outline
