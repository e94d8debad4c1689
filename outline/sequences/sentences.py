"""Stimuli as the step library's own sentences: for the random-sequence invariants (invariants.py), each drawn
stimulus is a `When` sentence of steps/, so a failing sequence prints as a scenario a user pastes into a feature
file (tests/test_invariants.py checks every sentence matches exactly one step definition)."""
from __future__ import annotations

from hypothesis import strategies as st

from sut.driver import TrainDriver

from . import domains
from .stimuli import Action, _names


def _g(value: float) -> str:
    return f"{value:g}"


def time_passes() -> st.SearchStrategy[Action]:
    return st.sampled_from(domains.ADVANCES_US).map(
        lambda us: Action("advance", (us,), f"{us // 1000} ms pass"))


def _crh2(driver: TrainDriver) -> list[st.SearchStrategy[Action]]:
    cab = st.sampled_from(domains.CABS["crh2"])
    nodes = _names(driver, "ring_nodes")
    boards = [f"{n}.{b}" for n in nodes for b in _names(driver, "boards", n)]
    spans = list(zip(nodes, nodes[1:] + nodes[:1]))
    # The supplies the contract names: each node (its CPU side), a CCU system's TXC, an LCU's RXC, a cab's desk.
    supplies = [*nodes, *(f"{n}.{b}" for n in nodes for b in ("TXC", "RXC") if f"{n}.{b}" in boards),
                *(f"car{c}.desk" for c in domains.CABS["crh2"])]
    cars = range(1, domains.CARS["crh2"] + 1)

    def vehicle(name: str, value) -> Action:
        shown = _g(value) if isinstance(value, float) else value
        return Action("set_input", (name, value), f'the vehicle input "{name}" becomes "{shown}"')

    # Values near the bands the requirements give (ILK-02's 580-600 kPa, ILK-05's 5 and 30 km/h) half the time.
    kmh = st.one_of(st.integers(0, 40), st.integers(0, 350)).map(float)
    kpa = st.one_of(st.integers(565, 615), st.integers(450, 900)).map(float)
    desk = [
        cab.map(lambda c: Action("insert_key", (c,), f"the driver inserts the key in cab {c}")),
        cab.map(lambda c: Action("remove_key", (c,), f"the driver removes the key from cab {c}")),
        st.tuples(cab, st.sampled_from(domains.DIRECTIONS)).map(
            lambda a: Action("set_direction", a, f"the driver sets the direction switch of cab {a[0]} to {a[1]}")),
        st.tuples(cab, st.sampled_from(domains.TRACTION_NOTCHES)).map(
            lambda a: Action("set_traction", a, f"the driver moves the traction notch of cab {a[0]} to {a[1]}")),
        st.tuples(cab, st.sampled_from(domains.BRAKE_STEPS)).map(
            lambda a: Action("set_brake", a, f"the driver moves the brake handle of cab {a[0]} to step {a[1]}")),
    ]
    train = [
        kmh.map(lambda v: vehicle("speed", v)),
        kpa.map(lambda v: vehicle("main pipe pressure", v)),
        st.sampled_from(cars[:-1]).map(lambda c: Action(
            "set_input", (f"coupler car{c}~car{c + 1}", "separated"),
            f"the train separates between car {c} and car {c + 1}")),
        st.tuples(st.sampled_from(cars), st.integers(0, 110).map(float)).map(
            lambda a: vehicle(f"car{a[0]}.brake force", a[1])),
        st.sampled_from(["open", "closed"]).map(lambda v: vehicle("doors", v)),
        st.sampled_from(["on", "off"]).map(lambda v: vehicle("door bypass", v)),
        st.sampled_from(["service", "emergency", "none"]).map(lambda v: vehicle("ATP brake", v)),
        st.tuples(st.sampled_from(["unit1", "unit2"]),
                  st.sampled_from(["normal", "primary overcurrent", "secondary earth fault"])).map(
            lambda a: vehicle(f"{a[0]}.transformer", a[1])),
        st.tuples(st.sampled_from(["unit1", "unit2"]), st.sampled_from(["running", "stopped"])).map(
            lambda a: vehicle(f"{a[0]}.oil pump", a[1])),
        st.just(vehicle("main circuit reset", "reset")),
    ]
    network = [
        st.sampled_from(boards).map(lambda b: Action("fail", (b,), f'"{b}" fails')),
        st.sampled_from(boards).map(lambda b: Action("repair", (b,), f'"{b}" is repaired')),
        st.sampled_from(spans).map(lambda s: Action("cut_link", s, f'the ring link between "{s[0]}" and "{s[1]}" is cut')),
        st.sampled_from(spans).map(
            lambda s: Action("restore_link", s, f'the ring link between "{s[0]}" and "{s[1]}" is restored')),
        st.sampled_from(supplies).map(lambda s: Action("power_off", (s,), f'the supply "{s}" is switched off')),
        st.sampled_from(supplies).map(
            lambda s: Action("restore_power", (s,), f'the supply "{s}" is switched on again')),
    ]
    return [*desk, *train, *network]


def _vdx(driver: TrainDriver) -> list[st.SearchStrategy[Action]]:
    return [
        st.just(Action("set_input", ("ATP emergency brake", True), "the ATP applies the emergency brake")),
        st.just(Action("set_input", ("ATP emergency brake", False), "the ATP releases the emergency brake")),
        st.just(Action("set_input", ("ATP isolation switch", True), "the ATP isolation switch is turned on")),
        st.integers(60, 145).map(lambda v: Action("set_supply_voltage", ("VDX", float(v)),
                                                  f"the VDX supply goes to {v} V")),
        st.just(Action("power_off", ("VDX",), 'the supply "VDX" is switched off')),
        st.just(Action("restore_power", ("VDX",), 'the supply "VDX" is switched on again'))]


PROFILES = {"crh2": _crh2, "vdx": _vdx}


def _driving(cab: int) -> list[Action]:
    return [Action("insert_key", (cab,), f"the driver inserts the key in cab {cab}"),
            Action("set_direction", (cab, "forward"), f"the driver sets the direction switch of cab {cab} to forward"),
            Action("set_traction", (cab, 5), f"the driver moves the traction notch of cab {cab} to 5"),
            Action("advance", (2_000_000,), "2000 ms pass")]


# Where a sequence starts (drawn, and shrunk towards the first): at rest, or a cab driving: a sequence from
# rest seldom gets a key, a direction and a notch together before it ends.
OPENINGS = {"crh2": [[], _driving(1), _driving(8)], "vdx": [[]]}


def sequences(profile: str, driver: TrainDriver, max_actions: int) -> st.SearchStrategy[list[Action]]:
    """An opening, then up to `max_actions` random stimuli. Swarm testing (Groce et al., 2012): each sequence
    first draws the few kinds of stimulus it may use, so a kind one in twenty of the draws would give (a
    stopped oil pump) comes again and again in some sequences, undisturbed by the others."""
    kinds = PROFILES[profile](driver)
    swarm = st.lists(st.sampled_from(range(len(kinds))), min_size=1, max_size=3, unique=True)

    def stimuli(chosen: list[int]) -> st.SearchStrategy[list[Action]]:
        picks = [time_passes()] * len(chosen) + [kinds[i] for i in chosen]
        one = st.sampled_from(picks).flatmap(lambda kind: kind)
        return st.lists(one, min_size=min(4, max_actions), max_size=max_actions)

    return st.tuples(st.sampled_from(OPENINGS[profile]), swarm.flatmap(stimuli)).map(
        lambda parts: [*parts[0], *parts[1]])
