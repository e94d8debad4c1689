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
    # advance_ms, as the step "N ms pass" itself: every profile's contract lists it.
    return st.sampled_from(domains.ADVANCES_US).map(
        lambda us: Action("advance_ms", (us // 1000,), f"{us // 1000} ms pass"))


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


def _master_controller(cab: int, pct: int, what: str) -> Action:
    """The step moves the metro's master controller to traction or brake: the other demand goes to 0 first."""
    other, mine = ("set_brake", "set_traction") if what == "traction" else ("set_traction", "set_brake")
    return Action(other, (cab, 0), f"the driver moves the master controller of cab {cab} to {pct} % {what}",
                  more=((mine, (cab, pct)),))


def _metro(driver: TrainDriver) -> dict[str, st.SearchStrategy[Action]]:
    cab = st.sampled_from(domains.CABS["metro-tcn"])
    things = [n for car in range(1, domains.CARS["metro-tcn"] + 1) for n in _names(driver, "devices", car)]
    units = [n for n in things if n.endswith((".CCU", ".VCU"))]
    ccus = [n for u in units if u.endswith(".CCU") for n in (u, *(f"{u}.{b}" for b in _names(driver, "boards", u)))]
    vcus = [n for u in units if u.endswith(".VCU") for n in (u, *(f"{u}.{b}" for b in _names(driver, "boards", u)))]
    others = [n for n in things if n not in units]                   # the I/O modules and the devices
    modules = [n for n in others if n.endswith((".IO1", ".IO2"))]
    # A unit's control units, a few of which fail together: the faults that end a unit's MVB master or the WTB.
    per_unit = [[u for u in units if domains.car_of(u) in cars] for cars in domains.METRO_UNIT_CARS.values()]
    line = st.tuples(st.sampled_from(domains.METRO_BUSES), st.sampled_from("AB"))

    def fails(names: list[str]) -> st.SearchStrategy[Action]:
        return st.sampled_from(names).map(lambda n: Action("fail", (n,), f'"{n}" fails'))

    def repaired(names: list[str]) -> st.SearchStrategy[Action]:
        return st.sampled_from(names).map(lambda n: Action("repair", (n,), f'"{n}" is repaired'))

    def together(names: list[str]) -> Action:
        quoted = ", ".join(f'"{n}"' for n in names)
        return Action("fail", (names[0],), f"{quoted} fail together", more=tuple(("fail", (n,)) for n in names[1:]))

    def wiring(module: str) -> st.SearchStrategy[Action]:
        digital = st.tuples(st.integers(1, 28).map(lambda n: f"DI{n:02d}"), st.integers(0, 1))
        analogue = st.tuples(st.sampled_from(["AI1", "AI2", "AI3"]), st.integers(0, 10_000))
        return st.one_of(digital, analogue).map(lambda a: Action(
            "set_input", (f"{module}.{a[0]}", a[1]),
            f'a wiring fault comes to hold input {a[0]} of "{module}" at {a[1]}'))

    pct = st.integers(0, 100)
    return {
        "key in": cab.map(lambda c: Action("insert_key", (c,), f"the driver inserts the key in cab {c}")),
        "key out": cab.map(lambda c: Action("remove_key", (c,), f"the driver removes the key from cab {c}")),
        "direction": st.tuples(cab, st.sampled_from(domains.DIRECTIONS)).map(
            lambda a: Action("set_direction", a, f"the driver sets the direction switch of cab {a[0]} to {a[1]}")),
        "traction": st.tuples(cab, pct).map(lambda a: _master_controller(a[0], a[1], "traction")),
        "brake": st.tuples(cab, pct).map(lambda a: _master_controller(a[0], a[1], "brake")),
        "emergency switch": st.sampled_from(["on", "off"]).map(lambda v: Action(
            "set_input", ("emergency operation", v == "on"), f"the driver turns the emergency-operation switch {v}")),
        "speed": st.one_of(st.just(0), st.integers(0, 120)).map(lambda v: Action(
            "set_input", ("speed", float(v)), f"the train speed changes to {v} km/h")),
        "CCU fails": fails(ccus), "CCU repaired": repaired(ccus),
        "VCU fails": fails(vcus), "VCU repaired": repaired(vcus),
        "device fails": fails(others), "device repaired": repaired(others),
        "units fail together": st.sampled_from(per_unit).flatmap(
            lambda three: st.lists(st.sampled_from(three), min_size=2, max_size=3, unique=True)).map(together),
        "line cut": line.map(lambda a: Action("cut_line", a, f'line {a[1]} of "{a[0]}" is cut')),
        "line restored": line.map(lambda a: Action("restore_line", a, f'line {a[1]} of "{a[0]}" is restored')),
        "line disturbed": st.tuples(line, st.sampled_from([1, 2, 3, 10, 100])).map(lambda a: Action(
            "disturb_line", (*a[0], a[1]), f'the next {a[1]} frames on line {a[0][1]} of "{a[0][0]}" are disturbed')),
        "both lines disturbed": st.tuples(st.sampled_from(domains.METRO_BUSES), st.sampled_from([1, 2, 3])).map(
            lambda a: Action("disturb_line", (a[0], "A", a[1]),
                             f'the next {a[1]} frames on both lines of "{a[0]}" are disturbed',
                             more=(("disturb_line", (a[0], "B", a[1])),))),
        "wiring fault": st.sampled_from(modules).flatmap(wiring),
    }


def _balise(group: str, sentence: str, *packets: dict) -> Action:
    return Action("pass_balise", (group, list(packets)), sentence)


def _track_balise(eoa: int) -> Action:
    """A balise group describing the line's track circuits (ATP_LINE) and an end of authority."""
    sections = [(float(a), float(b - a), f) for a, b, f in domains.ATP_LINE]
    spec = ", ".join(f"{a}-{b} m {f} Hz" for a, b, f in domains.ATP_LINE)
    return _balise("9-1-1-1", f'the train passes balise group "9-1-1-1" describing track circuits {spec} and an end '
                   f"of authority at {eoa} m", {"type": "CTCS-1", "sections": sections}, {"type": "MA", "end_m": eoa})


def _atp_position(pos: float, kmh: float) -> Action:
    return Action("set_input", ("position", pos), f"the train is set to {_g(pos)} m running at {_g(kmh)} km/h",
                  more=(("set_input", ("speed", kmh)),))


def _generator(carrier: int, code: str) -> Action:
    return Action("set_input", ("carrier", carrier), f"the signal generator switches to {carrier} Hz with code {code}",
                  more=(("set_input", ("low frequency code", code)),))


def _atp(driver: TrainDriver) -> dict[str, st.SearchStrategy[Action]]:
    # Where things happen on the line: near an end of authority (ATP-06's 150 m), anywhere on it; speeds about
    # ATP-07's 45 km/h (40-50) half the time; stops about a stop point (ATP-09's 0.5 m window, by tenths of a metre).
    near_eoa = st.sampled_from(domains.ATP_EOAS).flatmap(lambda eoa: st.integers(eoa - 400, eoa))
    pos = st.one_of(near_eoa, st.integers(0, domains.ATP_LINE[-1][1])).map(float)
    kmh = st.one_of(st.integers(40, 50), st.integers(0, 160)).map(float)
    stop = st.sampled_from(domains.ATP_STOPS).flatmap(lambda at: st.integers(-12, 12).map(lambda d: at + d / 10))
    psd = " with platform screen doors"
    return {
        "position": st.tuples(pos, kmh).map(lambda a: _atp_position(*a)),
        "speed": kmh.map(lambda v: Action("set_input", ("speed", v), f"the train speed changes to {_g(v)} km/h")),
        "stop": stop.map(lambda p: Action("set_input", ("speed", 0.0), f"the train stops at {_g(p)} m",
                                          more=(("set_input", ("position", p)),))),
        "generator": st.tuples(st.sampled_from(domains.CARRIERS), st.sampled_from(domains.ATP_CODES)).map(
            lambda a: _generator(*a)),
        "carrier set at the DMI": st.sampled_from(["up", "down"]).map(lambda w: Action(
            "monitor_order", (1, "carrier set", w), f"the driver selects the {w}-line carrier set at the DMI")),
        "ATP input": st.tuples(st.sampled_from(["sleep", "ATO start", "cab signal mode"]), st.booleans()).map(
            lambda a: Action("set_input", a, f'the ATP input "{a[0]}" is {"set" if a[1] else "cleared"}')),
        "track circuits": st.sampled_from(domains.ATP_EOAS).map(_track_balise),
        "default telegram": st.just(_balise(
            "9-1-1-2", 'the train passes side-line balise group "9-1-1-2" sending the default telegram',
            {"type": "default", "side_line": True})),
        "line information": st.sampled_from(["up", "down"]).map(lambda w: _balise(
            "9-1-1-3", f'the train passes balise group "9-1-1-3" with {w}-line information',
            {"type": "line direction", "direction": w})),
        "packet": st.sampled_from(["ETCS-46", "ETCS-99"]).map(lambda p: _balise(
            "9-1-1-4", f'the train passes balise group "9-1-1-4" with an {p} packet', {"type": p})),
        "stop point": st.tuples(st.sampled_from(domains.ATP_STOPS), st.booleans()).map(lambda a: _balise(
            "9-1-1-5", f'the train passes balise group "9-1-1-5" giving a stop point at {a[0]} m{psd if a[1] else ""}',
            {"type": "stop point", "at_m": float(a[0]), "psd": a[1]})),
        "CFSK fails": st.just(Action("fail", ("CFSK",), '"CFSK" fails')),
        "CFSK repaired": st.just(Action("repair", ("CFSK",), '"CFSK" is repaired')),
    }


PROFILES = {"crh2": _crh2, "vdx": _vdx, "metro-tcn": _metro, "atp": _atp}


def _driving(cab: int) -> list[Action]:
    return [Action("insert_key", (cab,), f"the driver inserts the key in cab {cab}"),
            Action("set_direction", (cab, "forward"), f"the driver sets the direction switch of cab {cab} to forward"),
            Action("set_traction", (cab, 5), f"the driver moves the traction notch of cab {cab} to 5"),
            Action("advance_ms", (2000,), "2000 ms pass")]


def _metro_driving(cab: int) -> list[Action]:
    return [Action("insert_key", (cab,), f"the driver inserts the key in cab {cab}"),
            Action("set_direction", (cab, "forward"), f"the driver sets the direction switch of cab {cab} to forward"),
            _master_controller(cab, 60, "traction"),
            Action("advance_ms", (1000,), "1000 ms pass")]


# The ATP under full supervision at 80 km/h, the carrier of its track circuit on the rails. First its DEF
# self-test runs out (ATP-08: within 22 s of power-up): until then the CFSK compares nothing, and a sequence
# that starts at once never meets a confirmed carrier (the checker found every mark behind one unreached).
ATP_SUPERVISING = [Action("advance_ms", (22000,), "22000 ms pass"),
                   _generator(1700, "L"), _atp_position(500.0, 80.0), _track_balise(domains.ATP_EOAS[-1]),
                   Action("advance_ms", (1000,), "1000 ms pass")]

# Where a sequence starts (drawn, and shrunk towards the first): at rest, or a cab driving: a sequence from
# rest seldom gets a key, a direction and a notch together before it ends. A metro sequence costs a second of
# simulation, so its few start mostly with a cab driving; an ATP without line data meets few of its requirements,
# so its sequences start supervising (and may leave it: a carrier inconsistency, a default telegram, sleep).
OPENINGS = {"crh2": [[], _driving(1), _driving(8)], "vdx": [[]],
            "metro-tcn": [_metro_driving(1), _metro_driving(6), []], "atp": [ATP_SUPERVISING]}


def sequences(profile: str, driver: TrainDriver, max_actions: int,
              focus: tuple[str, ...] = ()) -> st.SearchStrategy[list[Action]]:
    """An opening, then up to `max_actions` random stimuli. Swarm testing (Groce et al., 2012): each sequence
    first draws the few kinds of stimulus it may use, so a kind one in twenty of the draws would give (a
    stopped oil pump) comes again and again in some sequences, undisturbed by the others. `focus` names kinds
    (a profile that labels them) every swarm holds besides: those an invariant is about."""
    kinds = PROFILES[profile](driver)
    labels = list(kinds) if isinstance(kinds, dict) else []
    kinds = list(kinds.values()) if isinstance(kinds, dict) else kinds
    unknown = set(focus) - set(labels)
    if unknown:
        raise LookupError(f"no stimulus kinds {sorted(unknown)} in the {profile} profile: {labels}")
    always = [labels.index(label) for label in focus]
    swarm = st.lists(st.sampled_from(range(len(kinds))), min_size=0 if always else 1, max_size=3, unique=True)
    if always:
        swarm = swarm.map(lambda chosen: [*always, *(i for i in chosen if i not in always)])

    def stimuli(chosen: list[int]) -> st.SearchStrategy[list[Action]]:
        picks = [time_passes()] * len(chosen) + [kinds[i] for i in chosen]
        one = st.sampled_from(picks).flatmap(lambda kind: kind)
        return st.lists(one, min_size=min(4, max_actions), max_size=max_actions)

    return st.tuples(st.sampled_from(OPENINGS[profile]), swarm.flatmap(stimuli)).map(
        lambda parts: [*parts[0], *parts[1]])
