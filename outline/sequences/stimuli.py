"""What a random sequence may do to a SUT of a profile: the driver methods its contract lists, with arguments
drawn from the names the SUT itself gives (ring nodes, boards, supplies, vehicle inputs) and the contract's
value words and units (domains.py for ranges the contract leaves out)."""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from hypothesis import strategies as st

from sut.contract import load as load_contract
from sut.driver import TrainDriver

from . import domains


@dataclass(frozen=True)
class Action:
    """One driver call, `method(*args)`, and where it has one, the step library's sentence that makes it (a
    sequence of such sentences is a scenario a user can paste into a feature file: sentences.py)."""
    method: str
    args: tuple
    sentence: str = field(default="", compare=False)
    more: tuple = ()          # further (method, args) calls the same sentence makes ("to 60 % traction": two)
    kwargs: tuple = ()        # the first call's keyword arguments, as sorted items (a replayed configure(sets=2))

    @property
    def calls(self) -> tuple[tuple[str, tuple], ...]:
        return ((self.method, self.args), *self.more)

    def apply(self, driver: TrainDriver) -> None:
        getattr(driver, self.method)(*self.args, **dict(self.kwargs))
        for method, args in self.more:
            getattr(driver, method)(*args)

    def __str__(self) -> str:
        first = [*map(repr, self.args), *(f"{k}={v!r}" for k, v in self.kwargs)]
        return "; ".join([f"{self.method}({', '.join(first)})",
                          *(f"{method}({', '.join(map(repr, args))})" for method, args in self.more)])


def _expand(pattern: str, names: list[str]) -> list[str]:
    """The names a contract pattern (`car*.brake force`, `car[16].IO[12].DI??`) stands for: those of `names`
    it matches, else its bracket classes spelled out (a `*` or `?` left then drops the pattern)."""
    rx = re.compile(pattern.replace(".", r"\.").replace("*", ".*").replace("?", "."))
    found = [n for n in names if rx.fullmatch(n)]
    if found or "[" not in pattern:
        return found or ([pattern] if not set("*?[") & set(pattern) else [])
    out = [""]
    for part in re.split(r"(\[[^\]]+\])", pattern):
        options = list(part[1:-1]) if part.startswith("[") else [part]
        out = [o + p for o in out for p in options]
    return [n for n in out if not set("*?") & set(n)]


def _values(spec: dict[str, Any]) -> st.SearchStrategy | None:
    if spec.get("values"):
        return st.sampled_from(list(spec["values"]))
    kind, unit = spec.get("type"), spec.get("unit")
    if kind == "boolean":
        return st.booleans()
    if kind == "number" and unit in domains.NUMBER_RANGES:
        lo, hi = domains.NUMBER_RANGES[unit]
        return st.floats(lo, hi, allow_nan=False).map(lambda x: round(x, 1))
    if kind == "integer":
        if unit == "Hz":
            return st.one_of(st.sampled_from(domains.CARRIERS), st.integers(*domains.INTEGER_RANGES["Hz"]))
        if unit and "raw count" in unit:
            return st.integers(*domains.RAW_COUNT)
        if unit in domains.INTEGER_RANGES:
            return st.integers(*domains.INTEGER_RANGES[unit])
    return None


def _names(driver: TrainDriver, method: str, *args: Any) -> list[str]:
    """What the SUT names when asked `method(*args)` (its ring nodes, a node's boards), [] if it does not answer."""
    try:
        return list(getattr(driver, method)(*args))
    except Exception:                    # a SUT that does not answer it: no such stimuli
        return []


def actions(profile: str, driver: TrainDriver) -> st.SearchStrategy[Action]:
    """One stimulus a powered-up `driver` of `profile` may be given, or time passing."""
    contract = load_contract(profile)
    has = set(contract.methods).__contains__
    # Drawn by family first (time, inputs, desk, faults, supplies), then within it: thirty inputs must not
    # crowd out time passing, without which nothing happens.
    families: dict[str, list[st.SearchStrategy[Action]]] = {}
    options = families.setdefault("inputs", [])
    vehicle = driver.vehicle_names() if has("set_input") else {}
    for pattern, spec in contract.names.get("inputs", {}).items():
        values = _values(spec)
        for name in _expand(pattern, vehicle.get("inputs", [])) if values is not None else []:
            options.append(values.map(lambda v, n=name: Action("set_input", (n, v))))
    options = families.setdefault("desk", [])
    cabs = domains.CABS.get(profile, ())
    if cabs:
        cab = st.sampled_from(cabs)
        for method, arg in (("set_traction", st.sampled_from(domains.TRACTION_NOTCHES)),
                            ("set_brake", st.sampled_from(domains.BRAKE_STEPS)),
                            ("set_direction", st.sampled_from(domains.DIRECTIONS))):
            if has(method):
                options.append(st.tuples(cab, arg).map(lambda a, m=method: Action(m, a)))
        for method in ("insert_key", "remove_key"):
            if has(method):
                options.append(cab.map(lambda c, m=method: Action(m, (c,))))
    options = families.setdefault("faults", [])
    nodes = _names(driver, "ring_nodes") if has("fail") or has("cut_link") else []
    boards = [f"{n}.{b}" for n in nodes for b in _names(driver, "boards", n)] if has("fail") else []
    # A command board's two CPU groups fail one at a time (FS-01): the contract names them beside the boards.
    boards += [f"{b}.group{g}" for b in boards if b.endswith((".TXC", ".RXC")) for g in (1, 2)]
    for method in ("fail", "repair"):
        if boards and has(method):
            options.append(st.sampled_from(boards).map(lambda b, m=method: Action(m, (b,))))
    spans = list(zip(nodes, nodes[1:] + nodes[:1]))
    for method in ("cut_link", "restore_link"):
        if spans and has(method):
            options.append(st.sampled_from(spans).map(lambda s, m=method: Action(m, s)))
    options = families.setdefault("supplies", [])
    supplies = (_names(driver, "supplies") or list(domains.SUPPLIES.get(profile, ()))
                if has("power_off") or has("set_supply_voltage") else [])
    for method in ("power_off", "restore_power"):
        if supplies and has(method):
            options.append(st.sampled_from(supplies).map(lambda s, m=method: Action(m, (s,))))
    if supplies and has("set_supply_voltage"):
        volts = st.floats(*domains.SUPPLY_VOLTS, allow_nan=False).map(lambda v: round(v, 1))
        options.append(st.tuples(st.sampled_from(supplies), volts).map(lambda a: Action("set_supply_voltage", a)))
    # (one_of flattens nested one_ofs into one uniform choice: a family is picked by sampled_from instead)
    time_passes = st.sampled_from(domains.ADVANCES_US).map(lambda us: Action("advance", (us,)))
    if has("soak"):
        # Now and then a long run (TST-02): a soak is a way of its own through a backend (bulk.run samples and
        # jumps where an advance copies every period), which advances never reach.
        long_run = st.tuples(st.sampled_from(domains.SOAKS_US), st.sampled_from(domains.SOAK_SAMPLES_US)).map(
            lambda a: Action("soak", (a[0],), kwargs=(("sample_every_us", a[1]),)))
        time_passes = st.sampled_from([time_passes] * domains.SOAK_ODDS + [long_run]).flatmap(lambda kind: kind)
    picks = [time_passes] + [st.one_of(family) for family in families.values() if family]
    return st.sampled_from(picks).flatmap(lambda family: family)


def failed_at_power_up(profile: str, driver: TrainDriver) -> st.SearchStrategy[list[Action]]:
    """Boards failed before power-up (one or two, the CPU3 of a node as likely as all its other boards
    together: a node silent from the start), for a SUT that names its ring nodes' boards; [] otherwise. A
    board dead at power-on never had a state to lose, which no fault after power-up reaches."""
    contract = load_contract(profile)
    if "fail" not in contract.methods:
        return st.just([])
    nodes = _names(driver, "ring_nodes")
    boards = [f"{n}.{b}" for n in nodes for b in _names(driver, "boards", n)]
    if not boards:
        return st.just([])
    cpu3 = [b for b in boards if b.endswith(".CPU3")]
    board = st.one_of(st.sampled_from(cpu3), st.sampled_from(boards)) if cpu3 else st.sampled_from(boards)
    return st.lists(board, min_size=1, max_size=2, unique=True).map(lambda bs: [Action("fail", (b,)) for b in bs])
