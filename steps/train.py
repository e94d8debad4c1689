"""Composition, power-up and the passing of train time."""
from __future__ import annotations

from pytest_bdd import given, parsers, then, when

from sut.driver import TrainDriver
from steps import analysis, zh


@given(parsers.re(r"一列(?P<cars>\d+)辆编组的CRH2动车组"), converters={"cars": int})
@given(parsers.re(r"an? (?P<cars>\d+)-car CRH2 train set"), converters={"cars": int})
def _(sut: TrainDriver, cars: int) -> None:
    sut.configure(sets=1, cars_per_set=cars)


@given(parsers.parse("两列{cars:d}辆编组的CRH2动车组重联"))
@given(parsers.parse("two {cars:d}-car CRH2 train sets coupled together"))
def _(sut: TrainDriver, cars: int) -> None:
    sut.configure(sets=2, cars_per_set=cars)


@given("列车已上电")
@given("the train is powered up")
def _(sut: TrainDriver) -> None:
    sut.power_on()


@given(parsers.parse("列车已上电{ms:d} ms"), target_fixture="t_action")
@given(parsers.parse("the train has been powered up for {ms:d} ms"), target_fixture="t_action")
def _(sut: TrainDriver, ms: int) -> int:
    sut.power_on()
    sut.advance_ms(ms)
    return sut.now_us


@when(parsers.parse("经过{ms:d} ms"))
@when(parsers.parse("{ms:d} ms pass"))
def _(sut: TrainDriver, ms: int) -> None:
    sut.advance_ms(ms)


@when(parsers.parse("经过{s:d} s"))
@when(parsers.parse("{s:d} s pass"))
def _(sut: TrainDriver, s: int) -> None:
    sut.advance_ms(s * 1000)


# Minutes and hours for latched states: a steady train skips whole periods (sut/reference/bulk.py), so an
# hour costs little more than its first seconds.
@when(parsers.parse("经过{minutes:d} min"))
@when(parsers.parse("{minutes:d} min pass"))
def _(sut: TrainDriver, minutes: int) -> None:
    sut.advance_ms(minutes * 60_000)


@when(parsers.parse("经过{hours:d} h"))
@when(parsers.parse("{hours:d} h pass"))
def _(sut: TrainDriver, hours: int) -> None:
    sut.advance_ms(hours * 3_600_000)


@then(parsers.parse("环网上每辆车都有一个LCU且每辆头车都有一个含系统1和系统2的CCU"))
@then(parsers.parse("every car has an LCU on the ring and every cab car a CCU with systems 1 and 2"))
def _(sut: TrainDriver) -> None:
    nodes = sut.ring_nodes()
    for car in analysis.cars(sut):
        assert f"car{car}.LCU" in nodes, f"car {car} has no LCU on the ring: {nodes}"
    cabs = sorted({int(n[3:].split(".")[0]) for n in nodes if ".CCU." in n})
    assert cabs, f"no CCU on the ring: {nodes}"
    for cab in cabs:
        for system in (1, 2):
            assert f"car{cab}.CCU.sys{system}" in nodes, f"cab car {cab} lacks CCU system {system}: {nodes}"
    first, last = analysis.cars(sut)[0], analysis.cars(sut)[-1]
    assert first in cabs and last in cabs, f"the end cars {first} and {last} must be cab cars; cabs: {cabs}"


@then(parsers.parse('"{unit}"的板卡为{boards}'), converters={"boards": zh.core_list})
@then(parsers.parse('the boards of "{unit}" are {boards}'))
def _(sut: TrainDriver, unit: str, boards: str) -> None:
    want = sorted(b.strip() for b in boards.replace(" and ", ",").split(",") if b.strip())
    got = sorted(sut.boards(unit))
    assert got == want, f"{unit} has boards {got}, expected {want}"


@then(parsers.parse('{car:d}号车装有设备{devices}'), converters={"devices": zh.core_list})
@then(parsers.parse('car {car:d} has the devices {devices}'))
def _(sut: TrainDriver, car: int, devices: str) -> None:
    want = {f"car{car}.{d.strip()}" for d in devices.replace(" and ", ",").split(",") if d.strip()}
    got = set(sut.devices(car))
    assert want <= got, f"car {car} lacks {sorted(want - got)}; it has {sorted(got)}"
