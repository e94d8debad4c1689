"""The implementer's contract of one profile, read from `sut/contract/<profile>.yaml`.

What any SUT of the profile must expose for the suite to test it: the driver methods the steps call, the
names they pass (inputs, outputs, readings, orders, lamps) with their value words, and the trace event kinds
they read with each kind's fields. `docs/implementing-a-sut.md` is rendered from the same files.
"""
from __future__ import annotations

import fnmatch
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml

HERE = Path(__file__).parent
SECTIONS = ("inputs", "outputs", "readings", "orders", "lamps")
FIELD_TYPES = ("integer", "number", "string", "boolean", "list", "mapping", "any")
# What a value of each declared field type may be in Python (a boolean is no number, though Python's bool is
# an int).
TYPES: dict[str, Callable[[Any], bool]] = {
    "integer": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "number": lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
    "string": lambda v: isinstance(v, str),
    "boolean": lambda v: isinstance(v, bool),
    "list": lambda v: isinstance(v, (list, tuple)),
    "mapping": lambda v: isinstance(v, Mapping),
}
# The exact types that hold each field type's values without a closer look: check_event runs on every event
# a step is handed (millions a run), and a value of one of these types needs no isinstance call. A value of
# another type (a subclass, another Mapping) still gets the full test above.
PLAIN_TYPES: dict[str, frozenset[type]] = {
    "integer": frozenset((int,)), "number": frozenset((int, float)), "string": frozenset((str,)),
    "boolean": frozenset((bool,)), "list": frozenset((list, tuple)), "mapping": frozenset((dict,)),
}


def matches(pattern: str, name: str) -> bool:
    """A catalogue entry's name matches: itself, or as a glob where it has one (`car*.CI contactor`)."""
    return name == pattern or any(ch in pattern for ch in "*?[") and fnmatch.fnmatchcase(name, pattern)


class ContractGap(Exception):
    """The suite asked the SUT for something its contract does not list: a bug of the suite, not a verdict."""


class ContractBreach(AssertionError):
    """The SUT answered outside its contract (a value word or an event field): a failure of the SUT."""


class ContractFileError(Exception):
    """A contract file that cannot be read as one, naming the file and the entry."""


_ABSENT = object()          # a field an event does not carry (None is a value a field may hold)

# How many events of each listed kind a passed scenario's end holds to the contract (guard.check_trace).
TRACE_CHECK_PER_KIND = 200


def _conformance_test(checks: tuple, valued: dict[str, tuple]) -> Callable[[Mapping], bool]:
    """The type and value checks of one kind's fields as one function without a loop, made once per kind:
    True when every typed field holds its type (or is absent, or null where nullable) and every listed field
    one of its values. check_event runs on every event a step is handed; it says what is wrong, slowly,
    only when this says False."""
    lines = ["def conforms(fields):", "    get = fields.get"]
    names: dict[str, Any] = {"_ABSENT": _ABSENT}
    for i, (name, plain, is_type, nullable) in enumerate(checks):
        names[f"plain{i}"], names[f"is_type{i}"] = plain, is_type
        only = next(iter(plain)) if len(plain) == 1 else None
        test = f"type(v) is {only.__name__}" if only in _BUILTINS else f"type(v) in plain{i}"
        lines += [f"    v = get({name!r}, _ABSENT)",
                  f"    if not ({test} or v is _ABSENT{' or v is None' if nullable else ''} or is_type{i}(v)):",
                  "        return False"]
    for i, (name, allowed) in enumerate(valued.items()):
        names[f"allowed{i}"] = allowed
        lines += [f"    if {name!r} in fields and fields[{name!r}] not in allowed{i}:", "        return False"]
    lines.append("    return True")
    exec("\n".join(lines), names)      # noqa: S102 (field names are repr'd literals from the contract file)
    return names["conforms"]


# Types the generated test names by their builtin name (one plain type: `type(v) is int`, no set lookup).
_BUILTINS = frozenset((int, float, str, bool, list, tuple, dict))


@dataclass
class EventKind:
    name: str
    source: str
    when: str
    count: str
    fields: dict[str, dict[str, Any]]
    requirements: list[str]
    # A kind said once per change of one field (`changes: {field: state, initially: open}`): no two events of one
    # source in a row hold the same value there, nor the first the value the entry says it has before any.
    changes: str | None = None
    initially: tuple = ()          # (the value,) where the entry gives one
    restated_at_power_up: bool = False   # events at time 0 (power-up) may say again what was said before

    def __post_init__(self) -> None:
        # What check_event holds every event handed to a step against, worked out once per kind.
        self.sources = tuple(p.strip() for p in self.source.split("|") if p.strip())
        self.required = tuple(n for n, spec in self.fields.items() if spec.get("required", True))
        # A field whose entry lists its values may take no other (a word a step compares with is the
        # contract's word, not the reference's spelling of it).
        self.valued = {n: tuple(spec["values"]) for n, spec in self.fields.items() if spec.get("values")}
        # ... and a field of a declared type holds a value of that type (a number may be an integer), or null
        # where its entry says `nullable: true` (a path-1 field of a path-2 command): per typed field (name,
        # plain types, full test, None allowed), one tuple walked per event.
        self.checks = tuple((n, PLAIN_TYPES[spec["type"]], TYPES[spec["type"]], bool(spec.get("nullable")))
                            for n, spec in self.fields.items() if spec.get("type") in TYPES)
        self.required_set = frozenset(self.required)
        self.conforms = _conformance_test(self.checks, self.valued)
        # A run hands steps ~1.8 M events from a few hundred sources: a source's verdict is worked out once.
        self._source_ok: dict[str, bool] = {}

    def holds(self, fields: Mapping) -> bool:
        """Every required field there, every typed and every listed field as the entry says (check_event
        says which is not, slowly, when this is False)."""
        return self.required_set <= fields.keys() and self.conforms(fields)

    def names_source(self, source: str) -> bool:
        ok = self._source_ok.get(source)
        if ok is None:
            ok = self._source_ok[source] = not self.sources or any(matches(p, source) for p in self.sources)
        return ok


@dataclass
class Contract:
    profile: str
    path: Path
    methods: dict[str, str]
    names: dict[str, dict[str, dict[str, Any]]]
    events: dict[str, EventKind]
    raw: dict = field(repr=False, default_factory=dict)

    # -- checks of what the suite asks -----------------------------------------------------------------
    def _where(self) -> str:
        return f" (contract {self.path.relative_to(HERE.parents[1]) if HERE.parents[1] in self.path.parents else self.path})"

    def check_method(self, name: str) -> None:
        if name not in self.methods:
            raise ContractGap(f"a step called {name}() on a {self.profile} SUT, which its contract does not "
                              f"list{self._where()}")

    def entry(self, section: str, name: str) -> dict[str, Any] | None:
        entries = self.names.get(section, {})
        if name in entries:
            return entries[name]
        return next((entry for pattern, entry in entries.items() if matches(pattern, name)), None)

    def check_name(self, section: str, name: str, method: str) -> None:
        if self.entry(section, name) is None:
            raise ContractGap(f"a step passed {name!r} to {method}(), which the {self.profile} contract does not "
                              f"list among its {section}{self._where()}")

    def check_answer(self, section: str, name: str, value: Any) -> None:
        entry = self.entry(section, name) or {}
        words = entry.get("values")
        if words and value not in words:
            raise ContractBreach(f"the SUT answered {value!r} for the {section[:-1]} {name!r}; its contract "
                                 f"allows {', '.join(map(repr, words))}{self._where()}")

    def kinds_matching(self, kind: str) -> list[str]:
        if kind.endswith("*"):
            return [k for k in self.events if k.startswith(kind[:-1])]
        return [kind] if kind in self.events else []

    def check_kind(self, kind: str, where: dict) -> None:
        kinds = self.kinds_matching(kind)
        if not kinds:
            raise ContractGap(f"a step queried the trace for {kind!r} events, which the {self.profile} contract "
                              f"does not list{self._where()}")
        for name in where:
            if not any(name in self.events[k].fields for k in kinds):
                raise ContractGap(f"a step selected {kind!r} events by the field {name!r}, which the "
                                  f"{self.profile} contract does not list for that kind{self._where()}")

    def check_field(self, kind: str, name: str) -> None:
        ev = self.events.get(kind)
        if ev is None:
            raise ContractGap(f"a step read the field {name!r} of a {kind!r} event, a kind the {self.profile} "
                              f"contract does not list{self._where()}")
        if name not in ev.fields:
            raise ContractGap(f"a step read the field {name!r} of a {kind!r} event, which the {self.profile} "
                              f"contract does not list for that kind{self._where()}")

    def check_event(self, source: str, kind: str, fields: Any, t_us: int) -> None:
        """An event the SUT returned to a step: from a source the contract names for its kind, with every field
        it requires, each field of a declared type holding a value of that type and each field whose values the
        contract lists one of them. Whatever a step goes on to read, an event outside its kind's entry is the
        SUT's breach: a step that selects by kind alone would otherwise take a mis-sourced event, and one
        missing a required field would pass wherever no step reads that field."""
        ev = self.events.get(kind)
        if ev is None:
            return                      # a kind no step asked for cannot come back; check_kind owns the gap
        if ev.names_source(source) and ev.holds(fields):
            return
        # Something is outside the entry: the checks again, one by one, to say which.
        if not ev.names_source(source):
            raise ContractBreach(f"{source} {kind} at {t_us / 1000:g} ms: the {self.profile} contract names its "
                                 f"source {ev.source!r}{self._where()}")
        if not ev.required_set <= fields.keys():
            missing = [n for n in ev.required if n not in fields]
            raise ContractBreach(f"{source} {kind} at {t_us / 1000:g} ms has no field {missing[0]!r}; the "
                                 f"{self.profile} contract requires it{self._where()}")
        get = fields.get
        for name, plain, is_type, nullable in ev.checks:
            value = get(name, _ABSENT)
            if type(value) in plain or value is _ABSENT or (value is None and nullable) or is_type(value):
                continue
            raise ContractBreach(f"{source} {kind} at {t_us / 1000:g} ms has {name}={value!r}; the "
                                 f"{self.profile} contract gives it the type {ev.fields[name]['type']}"
                                 f"{self._where()}")
        for name, allowed in ev.valued.items():
            if name in fields and fields[name] not in allowed:
                raise ContractBreach(f"{source} {kind} at {t_us / 1000:g} ms has {name}={fields[name]!r}; the "
                                     f"{self.profile} contract allows {', '.join(map(repr, allowed))}"
                                     f"{self._where()}")

    def answer_keys(self, method: str) -> dict[str, Any]:
        return (self.raw.get("answers") or {}).get(method) or {}

    def check_answer_key(self, method: str, dotted: str) -> None:
        keys = self.answer_keys(method)
        if any(matches(k, dotted) for k in keys):
            return
        raise ContractGap(f"a step read {dotted!r} of the SUT's {method}() answer, which the {self.profile} "
                          f"contract does not list{self._where()}")

    def answer_note(self, method: str, dotted: str) -> str:
        return f"; the {self.profile} contract lists it{self._where()}" if dotted in self.answer_keys(method) else ""

    def field_note(self, kind: str, name: str) -> str:
        ev = self.events.get(kind)
        spec = ev.fields.get(name) if ev else None
        if spec is None:
            return ""
        need = "requires" if spec.get("required", True) else "lists as optional"
        return f"; the {self.profile} contract {need} it{self._where()}"


def _fail(path: Path, where: str, why: str) -> ContractFileError:
    return ContractFileError(f"{path}: {where}: {why}")


def parse(path: Path) -> Contract:
    try:
        raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    except yaml.YAMLError as exc:
        raise ContractFileError(f"{path}: not YAML: {exc}") from None
    if not isinstance(raw, dict) or "profile" not in raw:
        raise _fail(path, "top", "a mapping with profile, methods, names and events")
    unknown = set(raw) - {"profile", "title", "about", "methods", "names", "events", "answers", "records"}
    if unknown:
        raise _fail(path, "top", f"unknown keys {sorted(unknown)}")
    methods = {str(k): str(v or "") for k, v in (raw.get("methods") or {}).items()}
    names: dict[str, dict[str, dict]] = {}
    for section, entries in (raw.get("names") or {}).items():
        if section not in SECTIONS:
            raise _fail(path, f"names.{section}", f"not one of {', '.join(SECTIONS)}")
        names[section] = {str(k): dict(v or {}) for k, v in (entries or {}).items()}
    events: dict[str, EventKind] = {}
    for kind, spec in (raw.get("events") or {}).items():
        spec = spec or {}
        fields = {}
        for fname, fspec in (spec.get("fields") or {}).items():
            fspec = dict(fspec or {})
            if fspec.get("type", "any") not in FIELD_TYPES:
                raise _fail(path, f"events.{kind}.fields.{fname}.type", f"one of {', '.join(FIELD_TYPES)}")
            if "fixed" in fspec:
                try:
                    re.compile(str(fspec["fixed"]))
                except re.error as exc:
                    raise _fail(path, f"events.{kind}.fields.{fname}.fixed", f"a regular expression ({exc})") from None
            if "resolution" in fspec and not (fspec.get("type") == "number"
                                              and isinstance(fspec["resolution"], (int, float))
                                              and not isinstance(fspec["resolution"], bool) and fspec["resolution"] > 0):
                raise _fail(path, f"events.{kind}.fields.{fname}.resolution",
                            "a number above 0, on a field of type number")
            fields[str(fname)] = fspec
        changes = spec.get("changes", {})
        if "changes" in spec and not (isinstance(changes, dict) and changes.get("field") in fields
                                      and set(changes) <= {"field", "initially", "restated_at_power_up"}):
            raise _fail(path, f"events.{kind}.changes", "a mapping of `field` (one of the kind's fields) and, "
                        "optionally, `initially` (its value before the first event) and `restated_at_power_up` "
                        "(true: at time 0 a source may say its value again)")
        events[str(kind)] = EventKind(str(kind), str(spec.get("source", "")), str(spec.get("when", "")),
                                      str(spec.get("count", "")), fields, list(spec.get("requirements") or []),
                                      changes.get("field"),
                                      (changes["initially"],) if "initially" in changes else (),
                                      bool(changes.get("restated_at_power_up")))
    return Contract(str(raw["profile"]), path, methods, names, events, raw)


@lru_cache(maxsize=None)
def load(profile: str) -> Contract | None:
    """The contract of `profile`, or None where the project has none (a profile of a fixture tree)."""
    path = HERE / f"{profile}.yaml"
    return parse(path) if path.exists() else None
