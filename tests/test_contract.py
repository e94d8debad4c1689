"""The implementer's contract (sut/contract/): the guard in front of every scenario's driver tells a gap of the
suite (it asks for something the catalogue does not list) from a breach of the SUT (it answers outside the
catalogue), never a KeyError; the catalogue files are complete enough to implement a SUT from.

That the steps and the catalogue agree both ways is checked on the whole conformance run by `make test`
(`--contract-record`, then `python -m sut.contract check`); the guard stops any step reading outside it in
every run."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from outline.tree.requirements import load_requirements
from sut.contract import ContractBreach, ContractFileError, ContractGap, load
from sut.contract.catalogue import HERE, parse
from sut.contract.guard import ContractDriver
from sut.contract.record import problems
from sut.trace import Trace, TraceEvent

ROOT = Path(__file__).resolve().parents[1]
PROFILES = sorted(p.stem for p in HERE.glob("*.yaml") if p.stem != "form")


class Rig:
    """A driver as the guard sees one: a trace, outputs and a monitor (duck-typed; the guard wraps any)."""

    def __init__(self, events: list[TraceEvent], outputs: dict[str, str] | None = None):
        self.trace = Trace(events)
        self._outputs = outputs or {}
        self.now_us = 0

    def output(self, name: str) -> str:
        return self._outputs[name]

    def monitor(self, cab: int) -> dict:
        return {"faults": ["C019"]}


def _guarded(events: list[TraceEvent], outputs: dict[str, str] | None = None) -> ContractDriver:
    return ContractDriver(Rig(events, outputs), "vdx", load("vdx"))


def test_a_step_asking_for_an_unlisted_event_kind_is_a_gap_of_the_suite() -> None:
    with pytest.raises(ContractGap, match=r"'bogus.kind' events, which the vdx contract does not list"):
        _guarded([]).trace.first(kind="bogus.kind")


def test_a_step_reading_an_unlisted_field_is_a_gap_of_the_suite() -> None:
    ev = _guarded([TraceEvent(5, "VDX", "loop.change", {"state": "open", "debug": 1})]).trace.first(kind="loop.change")
    assert ev["state"] == "open"
    with pytest.raises(ContractGap, match=r"field 'debug' of a 'loop.change' event"):
        ev["debug"]


def test_a_sut_leaving_out_a_required_field_fails_naming_the_event_and_the_field() -> None:
    # when the event is handed to a step, whether or not the step reads that field (check_event)
    with pytest.raises(ContractBreach, match=r"VDX loop.change at 2.5 ms has no field 'state'; the vdx contract requires it"):
        _guarded([TraceEvent(2500, "VDX", "loop.change", {})]).trace.first(kind="loop.change")
    assert not isinstance(ContractBreach("x"), KeyError) and isinstance(ContractBreach("x"), AssertionError)


def test_a_sut_reporting_an_event_from_a_source_its_entry_does_not_name_fails() -> None:
    with pytest.raises(ContractBreach, match=r"vdx loop.change at 2.5 ms: the vdx contract names its source 'VDX'"):
        _guarded([TraceEvent(2500, "vdx", "loop.change", {"state": "open"})]).trace.select(kind="loop.change")


def test_a_step_selecting_by_an_unlisted_field_is_a_gap() -> None:
    with pytest.raises(ContractGap, match=r"by the field 'colour'"):
        _guarded([]).trace.select(kind="loop.change", colour="red")


def test_a_sut_answering_an_undeclared_value_word_fails() -> None:
    guarded = _guarded([], {"EB loop": "ajar"})
    with pytest.raises(ContractBreach, match=r"answered 'ajar' for the output 'EB loop'; its contract allows"):
        guarded.output("EB loop")


def test_a_step_passing_an_unlisted_name_or_calling_an_unlisted_method_is_a_gap() -> None:
    guarded = _guarded([], {"EB loop": "open"})
    with pytest.raises(ContractGap, match=r"'EB3R' to output\(\)"):
        guarded.output("EB3R")
    with pytest.raises(ContractGap, match=r"called cut_line\(\) on a vdx SUT"):
        guarded.cut_line
    with pytest.raises(ContractGap, match=r"called monitor\(\) on a vdx SUT"):
        guarded.monitor(1)                            # the VDX rig has no DMI: the 200C ATP's has
    atp = ContractDriver(Rig([]), "atp", load("atp"))
    with pytest.raises(ContractGap, match=r"'status' of the SUT's monitor\(\) answer"):
        atp.monitor(1)["status"]


def test_an_unreadable_contract_file_names_the_file_and_entry(tmp_path: Path) -> None:
    bad = tmp_path / "x.yaml"
    bad.write_text("profile: x\nevents:\n  a.b:\n    fields:\n      f: {type: colour}\n", encoding="utf-8")
    with pytest.raises(ContractFileError, match=r"x.yaml: events.a.b.fields.f.type: one of"):
        parse(bad)
    bad.write_text("profile: x\nevents:\n  a.b:\n    changes: {field: g}\n    fields:\n      f: {type: string}\n",
                   encoding="utf-8")
    with pytest.raises(ContractFileError, match=r"x.yaml: events.a.b.changes: a mapping of `field` \(one of the"):
        parse(bad)


def test_a_record_of_a_run_finds_stale_entries() -> None:
    """The check a whole run's record gets in make test: an entry no step reads is reported by its path."""
    found = problems({"vdx": {"methods": {}, "events": {}}}, ["vdx"])
    assert "sut/contract/vdx.yaml: methods.power_on: no step calls it" in found
    assert any(line.startswith("sut/contract/vdx.yaml: events.loop.change: no step reads it") for line in found)


@pytest.mark.parametrize("profile", PROFILES)
def test_the_catalogue_says_enough_to_implement_from(profile: str) -> None:
    """Every entry is described: a newcomer writes a SUT from the catalogue (docs/implementing-a-sut.md)."""
    contract = load(profile)
    known = set(load_requirements(ROOT / "docs" / "requirements.md"))
    raw = contract.raw
    assert raw.get("title") and raw.get("about"), f"{profile}: title and about"
    empty = [m for m, note in contract.methods.items() if not note.strip()]
    assert not empty, f"{profile}: methods without a note: {empty}"
    for section, entries in contract.names.items():
        for name, entry in entries.items():
            assert entry.get("note"), f"{profile}: names.{section}.{name}: no note"
    for method, keys in (raw.get("answers") or {}).items():
        for key, note in keys.items():
            assert note, f"{profile}: answers.{method}.{key}: no description"
    for kind, ev in contract.events.items():
        assert ev.source and "#" not in ev.source, f"{profile}: events.{kind}.source"
        assert ev.when and ev.count, f"{profile}: events.{kind}: when and count"
        assert ev.requirements and set(ev.requirements) <= known, f"{profile}: events.{kind}.requirements {ev.requirements}"
        for name, spec in ev.fields.items():
            assert spec.get("type") and spec.get("note"), f"{profile}: events.{kind}.fields.{name}: type and note"


def test_the_step_library_never_reads_a_field_around_the_guard() -> None:
    """`ev.fields[...]` would bypass the guard's check (and give a KeyError for a missing field)."""
    offenders = [f"{path.name}:{n}" for path in sorted((ROOT / "steps").glob("*.py"))
                 for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
                 if re.search(r"\.fields\[", line)]
    assert not offenders, offenders


def test_the_implementers_guide_is_rendered_from_the_catalogue() -> None:
    from sut.contract.render import GUIDE, render
    assert GUIDE.read_text(encoding="utf-8") == render(), \
        "docs/implementing-a-sut.md is stale: python -m sut.contract render"


def test_the_readme_shows_todays_assertion_count_and_every_freedom_variant() -> None:
    from outline.tree.assertions import table
    from tests.variants import FREEDOM, FREEDOM_CLASSES
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert table(ROOT / "features") in readme, "README's assertion table is stale: python -m outline assertions"
    assert readme.count(table(ROOT / "features").splitlines()[0]) == 1, "README holds the assertion table more than once"
    rows = {line.split("|")[1].strip(): line for line in readme.splitlines() if line.startswith("| ")}
    assert set(FREEDOM_CLASSES.values()) <= set(rows), "the README's freedom table lacks a row per freedom class"
    misplaced = [v.__name__ for v in FREEDOM if f"`{v.__name__}`" not in rows[FREEDOM_CLASSES[v.FREEDOM_CLASS]]]
    assert not misplaced, f"freedom variants the README's table does not name in their class's row: {misplaced}"


@pytest.mark.parametrize(("fields", "breach"), [
    ({"path": 1, "traction": 4, "brake": 0, "traction_step": None, "brake_step": None, "direction": "forward"}, None),
    ({"path": 1, "traction": None, "brake": 0, "traction_step": None, "brake_step": None, "direction": "forward"},
     None),                                                      # traction: "integer or null" (paths 2 and 3)
    ({"path": None, "traction": 4, "brake": 0, "traction_step": None, "brake_step": None, "direction": "forward"},
     "path=None; the crh2 contract gives it the type integer"),
    ({"path": 1, "traction": 4.0, "brake": 0, "traction_step": None, "brake_step": None, "direction": "forward"},
     "traction=4.0; the crh2 contract gives it the type integer"),
    ({"path": 1, "traction": True, "brake": 0, "traction_step": None, "brake_step": None, "direction": "forward"},
     "traction=True"),                                             # a flag is no number
])
def test_an_event_handed_to_a_step_holds_each_field_to_its_declared_type(fields: dict, breach: str | None) -> None:
    contract = load("crh2")
    if breach is None:
        contract.check_event("car1.BCU", "cmd.in", fields, 1000)
    else:
        with pytest.raises(ContractBreach, match=re.escape(breach)):
            contract.check_event("car1.BCU", "cmd.in", fields, 1000)


def test_an_event_handed_to_a_step_holds_a_field_with_listed_values_to_them() -> None:
    contract = load("vdx")
    contract.check_event("VDX", "selftest", {"result": "C019", "sample_ms": 1.5, "sample_v": 7.0}, 5_000_000)
    with pytest.raises(ContractBreach, match="result='PASS'; the vdx contract allows 'C019', 'pass'"):
        contract.check_event("VDX", "selftest", {"result": "PASS", "sample_ms": 1.5, "sample_v": 1.0}, 5_000_000)


def test_a_scenarios_end_holds_events_no_step_was_handed_to_the_contract() -> None:
    # an optional statement (the selftest at 0 ms) that no step selects is the SUT's statement all the same
    events = [TraceEvent(0, "VDX", "selftest", {"result": "PASS", "sample_ms": 1.5, "sample_v": 1.0}),
              TraceEvent(10, "VDX", "loop.change", {"state": "closed"})]
    guard = _guarded(events)
    assert guard.trace.first(kind="loop.change")["state"] == "closed"
    with pytest.raises(ContractBreach, match="at the scenario's end, in an event no step was handed: VDX selftest at "
                                             "0 ms has result='PASS'"):
        guard.check_trace(Trace(events))


def test_a_scenarios_end_holds_the_first_events_of_each_listed_kind_from_a_named_source() -> None:
    closed = TraceEvent(0, "VDX", "loop.change", {"state": "closed"})
    opened = TraceEvent(0, "VDX", "loop.change", {"state": "open"})
    # an event from a source the entry does not name is outside the contract, as an unlisted kind is
    stray = [TraceEvent(1, "rig", "loop.change", {}), TraceEvent(2, "VDX", "debug.dump", {"x": 1})]
    late = TraceEvent(9, "VDX", "loop.change", {})          # past the first per_kind of its kind: not held
    events = [closed, opened, *stray, late]
    guard = _guarded(events)
    assert guard.check_trace(Trace(events), per_kind=3) == 2
    with pytest.raises(ContractBreach, match="VDX loop.change at 0.009 ms has no field 'state'"):
        guard.check_trace(Trace(events), per_kind=4)


@pytest.mark.parametrize("states, said", [(["open"], "its value before any event"),
                                          (["closed", "open", "open"], "the value its last event gave")])
def test_a_kind_said_once_per_change_may_not_say_the_same_value_twice(states, said) -> None:
    # seed 9026: a VDX whose loop started unset said `open` at power-up, where the loop already was open;
    # every event of such a kind is held, not the first per_kind
    events = [TraceEvent(i, "VDX", "loop.change", {"state": state}) for i, state in enumerate(states)]
    with pytest.raises(ContractBreach, match=f"VDX loop.change at .* says state='open', {said}; the vdx contract "
                                             "counts one event per change"):
        _guarded(events).check_trace(Trace(events), per_kind=1)
    assert _guarded(events[:-1]).check_trace(Trace(events[:-1])) == len(states) - 1


@pytest.mark.parametrize("kind", [None, "", 7])
def test_a_scenarios_end_refuses_an_event_whose_kind_is_no_name(kind) -> None:
    # seed 12: the VDX's supply echo emitted with no kind passed every scenario (an unlisted kind is ignored,
    # but a kind that is no name at all is a malformed trace, not another statement)
    events = [TraceEvent(0, "VDX", "loop.change", {"state": "closed"}), TraceEvent(5, "VDX", kind, {"volts": 77.0})]
    guard = _guarded(events)
    with pytest.raises(ContractBreach, match=re.escape(f"the trace holds an event whose kind is {kind!r}, not a name "
                                                       "(from 'VDX' at t=5 us, fields {'volts': 77.0})")):
        guard.check_trace(Trace(events))
    assert guard.check_trace(Trace(events[:1])) == 1


def _names(contract, driver, section: str) -> list[str]:
    """Every name a profile's contract lists under `section`, character classes expanded
    (`car[16].IO[12].DI01`); a name with `*` or `?` stands for names only the train knows, so the driver's
    own list gives them."""
    import itertools
    names = []
    for pattern in contract.names.get(section, {}):
        if "*" in pattern or "?" in pattern:
            continue
        parts = re.split(r"\[([^\]]+)\]", pattern)
        names += ["".join(p) for p in itertools.product(*[[part] if i % 2 == 0 else list(part)
                                                          for i, part in enumerate(parts)])]
    own = driver.vehicle_names().get(section, [])
    return sorted(set(names) | {name for name in own if contract.entry(section, name) is not None})


@pytest.mark.parametrize("profile", ["crh2", "metro-tcn", "atp", "atp-crh2", "vdx"])
def test_every_input_and_output_answers_a_word_its_contract_lists_at_power_up(profile) -> None:
    """An input a step has not set yet still answers in the contract's words (seed 25 started the crh2 doors at
    `CLOSED`, which no step set and none read back; the ATP rig's generator said `ZPW-2000` and an empty code);
    an event input (a reset, a signal) or a level nothing has given yet reads None. Every output does too."""
    from sut.backends import open_backend
    from sut.errors import UnknownName
    contract = load(profile)
    driver = open_backend("reference", profile)
    driver.power_on()
    read = 0
    for section, method in (("inputs", driver.input), ("outputs", driver.output)):
        for name in _names(contract, driver, section):
            try:
                value = method(name)
            except UnknownName:  # input() is the reference's read-back, not a contract method: the metro's
                continue         # wiring-fault channels are set, never read back
            read += 1
            if value is not None:
                contract.check_answer(section, name, value)
    assert read >= 2


@pytest.mark.parametrize("profile", ["crh2", "metro-tcn", "atp"])
def test_the_reference_answers_only_keys_its_contract_lists(profile) -> None:
    """A key the contract does not list is read by no step, so a wrong value under it is seen by nothing (seed
    25's monitor age table, seed 9026's rated `restart ms` and `vibration`): the reference answers none."""
    from sut.backends import open_backend
    from sut.contract.catalogue import matches
    contract = load(profile)
    driver = open_backend("reference", profile)
    driver.power_on()
    driver.advance(2_000_000)
    answers = {"monitor": driver.monitor(1)}
    if "rated_limits" in contract.methods:
        answers["rated_limits"] = driver.rated_limits()
    for method, answer in answers.items():
        listed = contract.answer_keys(method)
        assert listed, method
        assert [key for key in answer if not any(matches(pattern, key) for pattern in listed)] == [], method


_VALUES = st.one_of(st.none(), st.booleans(), st.integers(-3, 3), st.floats(allow_nan=False, width=16),
                    st.sampled_from(["open", "closed", "forward", "A", "-", ""]), st.lists(st.integers(0, 2), max_size=2),
                    st.tuples(st.integers()), st.dictionaries(st.sampled_from("ab"), st.integers(), max_size=1))


@given(data=st.data())
@settings(max_examples=300, deadline=None)
def test_a_kinds_generated_field_test_says_what_its_checks_one_by_one_say(data: st.DataObject) -> None:
    """check_event passes an event on EventKind.conforms (one generated function per kind) and goes through
    the fields one by one, to say what is wrong, only when it fails: the two must agree on every event, or a
    breach goes unsaid. Drawn: a kind of any profile, its required fields and some optional ones, values of
    every type and, for a field with listed values, a listed one or another."""
    contract = load(data.draw(st.sampled_from(PROFILES)))
    kind = contract.events[data.draw(st.sampled_from(sorted(contract.events)))]
    optional = data.draw(st.lists(st.sampled_from(sorted(set(kind.fields) - set(kind.required)) or ["x"]),
                                  unique=True))
    fields = {}
    for name in [*kind.required, *optional]:
        allowed = kind.valued.get(name)
        # a listed value, or one of the same type the list leaves out (a word not in it, a number past it)
        unlisted = [v for v in ("unlisted", 1 + max((a for a in allowed or () if type(a) is int), default=0))
                    if allowed and v not in allowed]
        fields[name] = data.draw(st.sampled_from([*allowed, *unlisted]) if allowed and data.draw(st.booleans())
                                 else _VALUES)
    conforms = kind.conforms
    fast = conforms(fields)
    # The field-by-field path, from a source the entry names.
    kind.conforms, kind.names_source = (lambda fields: False), (lambda source: True)
    try:
        contract.check_event("a source", kind.name, fields, 0)
        one_by_one = True
    except ContractBreach:
        one_by_one = False
    finally:
        kind.conforms = conforms
        del kind.names_source              # the class's own again
    assert fast == one_by_one, fields
