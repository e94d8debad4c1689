"""The single-fault campaigns (issue 16, outline/campaign.py): generated from the SUT's own fault space, and
kept equal to it."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from outline import campaign
from outline.campaign import NO_MDM9, OFF_THE_RING, RIDES, TAKES_OVER, Fault
from sut.backends import open_backend
from tests.test_faulty_variants import ROOT


@pytest.fixture(scope="module")
def eight_cars():
    sut = open_backend("reference", "crh2")
    sut.configure(sets=1, cars_per_set=8)
    sut.power_on()
    yield sut
    sut.shutdown()


def test_the_checked_in_campaigns_are_the_sut_fault_space(capsys) -> None:
    assert campaign.run(ROOT, "reference", check=True) == 0, capsys.readouterr().err


def test_every_span_board_and_supply_is_a_scenario_and_the_desks_are_listed_as_left_out(eight_cars) -> None:
    text = (ROOT / campaign.CAMPAIGNS[0].path).read_text(encoding="utf-8")
    nodes = eight_cars.ring_nodes()
    rows = campaign.fault_space_of(text)      # a TXC's board and its supply share a name: a list, not a set
    spans = {(a, b) for a, b in zip(nodes, nodes[1:] + nodes[:1])}
    boards = {(f"{node}.{board}",) for node in nodes for board in eight_cars.boards(node)}
    supplies = {(s,) for s in eight_cars.supplies() if not s.endswith(".desk")}
    bare = {row if len(row) == 2 and "." in row[1] else row[:1] for row in rows}      # the car column aside
    assert bare == spans | boards | supplies
    assert len(rows) == len(spans) + len(boards) + len(supplies) == 80
    assert "  - car1.desk: the desk's digital inputs" in text and "  - car8.desk:" in text


def test_a_campaign_that_misses_a_fault_is_reported_with_its_file(tmp_path: Path, capsys) -> None:
    for one in campaign.CAMPAIGNS:
        (tmp_path / one.path).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / one.path, tmp_path / one.path)
    path = tmp_path / campaign.CAMPAIGNS[0].path
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    path.write_text("".join(line for line in lines if "car5.LCU.MDM9" not in line), encoding="utf-8")
    assert campaign.run(tmp_path, "reference", check=True) == 1
    err = capsys.readouterr().err
    assert f"{campaign.CAMPAIGNS[0].path}:1: the campaign differs from the SUT's fault space" in err
    assert campaign.CAMPAIGNS[1].path not in err


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
    assert campaign.expectation(eight_cars, Fault(kind, target), campaign.COMMANDING) == (group, car)
