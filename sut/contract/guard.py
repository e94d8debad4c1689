"""The driver as the steps see it: every call reaches the SUT, and everything a step asks of it must be in
the profile's contract (sut/contract/<profile>.yaml).

Two kinds of mistake are told apart, because they have different owners:
- the suite asks for something the contract does not list (a method, a name, an event kind or field):
  `ContractGap`, an error of the suite, never a verdict on the SUT;
- the SUT answers outside the contract (a value word it does not list, an event without a required field):
  `ContractBreach`, a failure of the SUT, naming what it did and the contract line it broke.

With a `Recorder` every access is also written down (`--contract-record`): the catalogue test compares it
with the catalogue, both ways.
"""
from __future__ import annotations

import re
from collections import defaultdict
from typing import Any, Callable, Iterator, Mapping

from sut.contract.catalogue import TRACE_CHECK_PER_KIND, Contract, ContractBreach, ContractGap
from sut.driver import TrainDriver
from sut.trace import Trace, TraceEvent, new_event

# Driver methods whose first argument (after a cab number where one is given) is a name from the contract.
_NAMED = {
    "set_input": ("inputs", 0), "ramp_input": ("inputs", 0), "input": ("inputs", 0),
    "output": ("outputs", 0), "reading": ("readings", 0), "monitor_order": ("orders", 1),
    "lamp": ("lamps", 1),
}
# Observations answered with a mapping whose keys the contract lists (`answers:`), nested keys dotted.
_ANSWERS = frozenset({"monitor", "rated_limits", "counters"})


class Recorder:
    """What the steps of a run asked of the SUT, by profile: methods, names with the values seen, event
    kinds with the fields read and the sources asked for, each with the test items that did so."""

    def __init__(self) -> None:
        self.data: dict = defaultdict(lambda: defaultdict(lambda: defaultdict(lambda: defaultdict(set))))
        self.item = "?"
        self.step = "?"

    def note(self, profile: str, section: str, name: str, aspect: str = "items", value: Any = None) -> None:
        entry = self.data[profile][section][name]
        if value is None:
            entry["items"].add(self.item)
            entry["steps"].add(self.step)
        else:
            entry[aspect].add(_plain(value))

    def saw(self, profile: str, ev: TraceEvent) -> None:
        """An event the SUT returned to a step: its source, shaped (`car3.LCU.MDM8` -> `car#.LCU.MDM#`),
        and the type of each of its fields."""
        entry = self.data[profile]["events"][ev.kind]
        entry["sources seen"].add(re.sub(r"\d+", "#", ev.source))
        for name, value in ev.fields.items():
            entry[f"field {name}"].add(_plain(value) if not isinstance(value, str) else "str")

    def as_json(self) -> dict:
        return {p: {s: {n: {a: sorted(v, key=str) for a, v in aspects.items()} for n, aspects in names.items()}
                    for s, names in sections.items()} for p, sections in self.data.items()}


def _plain(value: Any) -> Any:
    """How a recorded value is kept: a word or a flag as itself, anything else by its type."""
    return value if value is None or isinstance(value, (bool, str)) else type(value).__name__


class CheckedFields(dict):
    """An event's fields as a step reads them: a field the contract does not list for the kind is a gap of
    the suite; one the contract requires and the SUT left out is a breach of the SUT (never a KeyError).

    Only a read by name is checked (`ev["state"]`, `ev.get("state")`); a failure message that dumps every
    field (`dict(ev.fields)`, `repr`) is not a reading of the contract. A dict subclass that leaves iteration
    alone gives exactly that: CPython copies such a dict without calling __getitem__."""

    __slots__ = ("_ev", "_guard")

    def __init__(self, fields: Mapping, ev: TraceEvent, guard: "ContractDriver"):
        super().__init__(fields)
        self._ev, self._guard = ev, guard

    def __getitem__(self, key: str) -> Any:
        self._guard._field(self._ev, key)
        try:
            return dict.__getitem__(self, key)
        except KeyError:
            raise ContractBreach(
                f"{self._ev.source} {self._ev.kind} at {self._ev.t / 1000:g} ms has no field {key!r}"
                f"{self._guard._contract.field_note(self._ev.kind, key) if self._guard._contract else ''}") from None

    def get(self, key: str, default: Any = None) -> Any:
        self._guard._field(self._ev, key)
        return dict.get(self, key, default)


class CheckedAnswer(dict):
    """A mapping a driver method answered (the cab monitor, the rated limits, counters), as a step reads it:
    keys the contract lists for that answer, dotted where nested (`display.mode`). As for event fields, only a
    read by name is checked; a message dumping the whole answer is not."""

    __slots__ = ("_method", "_path", "_guard")

    def __init__(self, answer: Mapping, method: str, path: str, guard: "ContractDriver"):
        super().__init__(answer)
        self._method, self._path, self._guard = method, path, guard

    def _key(self, key: Any) -> str:
        dotted = f"{self._path}{key}"
        self._guard._answer_key(self._method, dotted)
        return dotted

    def _wrap(self, dotted: str, value: Any) -> Any:
        if isinstance(value, Mapping) and not isinstance(value, CheckedAnswer):
            return CheckedAnswer(value, self._method, dotted + ".", self._guard)
        return value

    def __getitem__(self, key: Any) -> Any:
        dotted = self._key(key)
        try:
            value = dict.__getitem__(self, key)
        except KeyError:
            raise ContractBreach(
                f"the SUT's {self._method}() answer has no {dotted!r}"
                f"{self._guard._contract.answer_note(self._method, dotted) if self._guard._contract else ''}") from None
        return self._wrap(dotted, value)

    def get(self, key: Any, default: Any = None) -> Any:
        dotted = self._key(key)
        return self._wrap(dotted, dict.get(self, key, default))


class ContractTrace:
    """The SUT's trace as steps query it: by kinds the contract lists, fields it lists for them."""

    def __init__(self, trace: Trace, guard: "ContractDriver"):
        self._trace, self._guard = trace, guard

    def __len__(self) -> int:
        return len(self._trace)

    def _wrap(self, ev: TraceEvent | None) -> TraceEvent | None:
        if ev is None:
            return None
        if self._guard._recorder is not None:
            self._guard._recorder.saw(self._guard._profile, ev)
        if self._guard._contract is not None:
            self._guard._contract.check_event(ev.source, ev.kind, ev.fields, ev.t)
        return new_event(TraceEvent, (ev.t, ev.source, ev.kind, CheckedFields(ev.fields, ev, self._guard)))

    def _asked(self, kind: str | None, source: str | None, where: dict) -> None:
        self._guard._kind(kind, source, where)

    def select(self, kind: str | None = None, source: str | None = None, since: int | None = None,
               until: int | None = None, **where: Any) -> list[TraceEvent]:
        self._asked(kind, source, where)
        return [self._wrap(ev) for ev in self._trace.select(kind, source, since, until, **where)]

    def first(self, **criteria: Any) -> TraceEvent | None:
        self._asked(criteria.get("kind"), criteria.get("source"),
                    {k: v for k, v in criteria.items() if k not in ("kind", "source", "since", "until")})
        return self._wrap(self._trace.first(**criteria))

    def last(self, **criteria: Any) -> TraceEvent | None:
        self._asked(criteria.get("kind"), criteria.get("source"),
                    {k: v for k, v in criteria.items() if k not in ("kind", "source", "since", "until")})
        return self._wrap(self._trace.last(**criteria))


class ContractDriver:
    """A scenario's driver, in front of whatever the `sut` fixture made (a snapshot journal or the backend)."""

    def __init__(self, driver: Any, profile: str, contract: Contract | None, recorder: Recorder | None = None):
        self._driver, self._profile, self._contract, self._recorder = driver, profile, contract, recorder
        self._fields_read: set[tuple[str, str]] = set()

    # -- what a step asks for ----------------------------------------------------------------------
    def _method(self, name: str) -> None:
        if self._recorder is not None:
            self._recorder.note(self._profile, "methods", name)
        if self._contract is not None:
            self._contract.check_method(name)

    def _name(self, method: str, section: str, name: Any, value: Any = None) -> None:
        if self._recorder is not None:
            self._recorder.note(self._profile, section, str(name))
            if value is not None:
                self._recorder.note(self._profile, section, str(name), "values", value)
        if self._contract is not None:
            self._contract.check_name(section, str(name), method)

    def _kind(self, kind: str | None, source: str | None, where: dict) -> None:
        if kind is None:
            raise ContractGap("a step queried the trace without naming an event kind; the contract lists kinds")
        if self._recorder is not None:
            self._recorder.note(self._profile, "events", kind)
            if source is not None:
                self._recorder.note(self._profile, "events", kind, "sources asked", source)
            for field in where:
                self._recorder.note(self._profile, "events", kind, "fields", field)
        if self._contract is not None:
            self._contract.check_kind(kind, where)

    def _field(self, ev: TraceEvent, key: str) -> None:
        if self._recorder is not None:
            self._recorder.note(self._profile, "events", ev.kind)
            self._recorder.note(self._profile, "events", ev.kind, "fields", key)
        if self._contract is not None and (ev.kind, key) not in self._fields_read:
            self._contract.check_field(ev.kind, key)
            self._fields_read.add((ev.kind, key))     # a listed field stays listed: asked once per guard

    def _answer_key(self, method: str, dotted: str) -> None:
        if self._recorder is not None:
            self._recorder.note(self._profile, "answers", f"{method}: {dotted}")
        if self._contract is not None:
            self._contract.check_answer_key(method, dotted)

    def check_trace(self, trace: Trace, per_kind: int = TRACE_CHECK_PER_KIND) -> int:
        """Events no step was handed, held to their kind's entry all the same (check_event): an optional
        statement at power-up, or a kind read only under other conditions, is still the SUT's statement in
        the contract's terms. Of each listed kind, the first `per_kind` events from a source its entry names
        (from another source an event is outside the contract, as an unlisted kind is). Not every event: a
        run holds ~11 M of listed kinds, holding them all cost 50 s of a 270 s run, and the many are periodic
        frames from a few emit sites. Returns how many were held."""
        if self._contract is None:
            return 0
        # An event without a name for its kind is no statement in the contract's terms at all, nor one a
        # user can select: a malformed trace, said as such (a kind is a string, as every entry's name is).
        nameless = sorted((repr(k) for k in trace.kinds() if not isinstance(k, str) or not k))
        if nameless:
            first = next(ev for ev in trace if repr(ev.kind) == nameless[0])
            raise ContractBreach(f"at the scenario's end: the trace holds an event whose kind is {nameless[0]}, not "
                                 f"a name (from {first.source!r} at t={first.t} us, fields {dict(first.fields)}); "
                                 "every event's kind is a non-empty string")
        held, check = 0, self._contract.check_event
        for kind, events in trace.heads(self._contract.events, per_kind).items():
            entry = self._contract.events[kind]
            names, holds = entry.names_source, entry.holds
            for ev in events:
                if names(ev.source):
                    fields = ev.fields
                    # check_event's own test, with the entry already in hand (a million events a profile); it
                    # says what is wrong
                    if not holds(fields):
                        try:
                            check(ev.source, kind, fields, ev.t)
                        except ContractBreach as breach:    # no step to blame: say where it was found
                            raise ContractBreach("at the scenario's end, in an event no step was handed: "
                                                 f"{breach}") from None
                    held += 1
        self._check_changes(trace)
        return held

    def _check_changes(self, trace: Trace) -> None:
        """A kind said once per change (its entry's `changes`): every event of it, not the first few, as one
        repeated is a statement the count rules out (a loop said open again, an output said twice)."""
        for kind, entry in self._contract.events.items():
            if entry.changes is None:
                continue
            last: dict[str, Any] = {}
            for ev in trace.select(kind=kind):
                if not entry.names_source(ev.source) or entry.changes not in ev.fields:
                    continue
                value = ev.fields[entry.changes]
                before = last[ev.source] if ev.source in last else entry.initially
                if before == (value,) and not (entry.restated_at_power_up and ev.t == 0):
                    said = ("its value before any event" if ev.source not in last
                            else "the value its last event gave")
                    raise ContractBreach(f"at the scenario's end: {ev.source} {kind} at {ev.t / 1000:g} ms says "
                                         f"{entry.changes}={value!r}, {said}; the {self._contract.profile} "
                                         f"contract counts one event per change ({entry.count})")
                last[ev.source] = (value,)

    # -- the driver interface ----------------------------------------------------------------------
    @property
    def trace(self) -> ContractTrace:
        self._method("trace")
        return ContractTrace(self._driver.trace, self)

    @property
    def now_us(self) -> int:
        return self._driver.now_us

    @property
    def powered(self) -> bool:
        return self._driver.powered

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        interface = callable(getattr(TrainDriver, name, None))
        if interface:
            self._method(name)                  # before the SUT is asked: a gap of the suite, whatever it has
        attr = getattr(self._driver, name)
        if not callable(attr):
            return attr
        if not interface:
            self._method(name)
        if name in _ANSWERS:
            return lambda *args, **kwargs: CheckedAnswer(attr(*args, **kwargs), name, "", self)
        named = _NAMED.get(name)
        if named is None:
            return attr
        section, position = named
        return self._named_call(name, attr, section, position)

    def _named_call(self, method: str, attr: Callable, section: str, position: int) -> Callable:
        def call(*args: Any, **kwargs: Any) -> Any:
            value = args[position + 1] if method in ("set_input", "monitor_order") and len(args) > position + 1 \
                else None
            if len(args) > position:
                self._name(method, section, args[position], value)
            result = attr(*args, **kwargs)
            if method in ("output", "lamp", "input") and len(args) > position:
                if self._recorder is not None:
                    self._recorder.note(self._profile, section, str(args[position]), "answers", result)
                if self._contract is not None and method == "output":
                    self._contract.check_answer(section, str(args[position]), result)
            return result
        return call
