"""A run's record of what the steps asked of the SUT (`pytest features --contract-record FILE`), held against
the catalogue: `python -m sut.contract check FILE...` and `python -m sut.contract update FILE...`.

The guard (guard.py) already stops any step that reads outside the catalogue, in every run. What the record
adds: the catalogue lists nothing the steps no longer read (a stale entry misleads an implementer), and each
entry's `read_by` (the step sentences that read it) is what the run saw.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Iterable

import yaml

from sut.contract.catalogue import HERE, SECTIONS, load, matches, parse

ASPECTS_KEPT = ("items", "steps", "fields", "values", "answers", "sources asked", "sources seen")


def merge(paths: Iterable[Path]) -> dict:
    """One record from a run's files (an xdist run writes FILE.<worker> beside FILE)."""
    total: dict = {}

    def into(a: dict, b: dict) -> None:
        for k, v in b.items():
            if isinstance(v, dict):
                into(a.setdefault(k, {}), v)
            else:
                a[k] = sorted(set(a.get(k, [])) | set(v), key=str)

    for path in paths:
        for found in sorted(Path(path).parent.glob(Path(path).name + "*")):
            into(total, json.loads(found.read_text(encoding="utf-8")))
    return total


def problems(record: dict, profiles: Iterable[str] | None = None) -> list[str]:
    """Where the catalogue and the record disagree: entries no step read, `read_by` lists out of date."""
    out = []
    for profile in profiles or sorted(record):
        contract = load(profile)
        if contract is None:
            out.append(f"{profile}: no contract file sut/contract/{profile}.yaml")
            continue
        seen = record.get(profile, {})
        where = f"sut/contract/{profile}.yaml"
        for method in contract.methods:
            if method not in seen.get("methods", {}):
                out.append(f"{where}: methods.{method}: no step calls it")
        for section in SECTIONS:
            for name, entry in contract.names.get(section, {}).items():
                used = [n for n in seen.get(section, {}) if contract.entry(section, n) is entry]
                if not used:
                    out.append(f"{where}: names.{section}.{name}: no step uses it")
        for kind, ev in contract.events.items():
            got = seen.get("events", {}).get(kind)
            if got is None:
                out.append(f"{where}: events.{kind}: no step reads it")
                continue
            for field in ev.fields:
                if field not in got.get("fields", []):
                    out.append(f"{where}: events.{kind}.fields.{field}: no step reads it")
            listed = sorted((contract.raw["events"][kind] or {}).get("read_by") or [])
            if listed != sorted(got.get("steps", [])):
                out.append(f"{where}: events.{kind}.read_by: out of date (python -m sut.contract update)")
        for method, keys in (contract.raw.get("answers") or {}).items():
            used = {name.split(": ", 1)[1] for name in seen.get("answers", {}) if name.startswith(method + ": ")}
            for key in keys:
                if not any(matches(key, u) for u in used):
                    out.append(f"{where}: answers.{method}.{key}: no step reads it")
    return out


def update(record: dict, profile: str) -> Path:
    """Refresh the `read_by` lists of a profile's contract from a record; everything else is kept. A profile
    with no contract yet gets a skeleton to fill in (types from what the reference returned)."""
    path = HERE / f"{profile}.yaml"
    seen = record.get(profile, {})
    raw: dict[str, Any] = yaml.safe_load(path.read_text(encoding="utf-8")) if path.exists() else {
        "profile": profile, "title": "", "about": "", "methods": {}, "names": {}, "answers": {}, "events": {}}
    for method in sorted(seen.get("methods", {})):
        raw["methods"].setdefault(method, "")
    for section in SECTIONS:
        for name, got in sorted(seen.get(section, {}).items()):
            entries = raw["names"].setdefault(section, {})
            if path.exists() and parse(path).entry(section, name) is not None:
                continue
            entry = entries.setdefault(name, {})
            words = [v for v in got.get("answers", []) + got.get("values", []) if isinstance(v, str)
                     and v not in ("int", "float")]
            if words:
                entry.setdefault("values", words)
    for name in sorted(seen.get("answers", {})):
        method, key = name.split(": ", 1)
        listed = raw["answers"].setdefault(method, {})
        if not any(matches(pattern, key) for pattern in listed):     # `display.car*.lighting` lists car1..car8
            listed[key] = ""
    for kind, got in sorted(seen.get("events", {}).items()):
        if not got.get("steps"):
            continue
        entry = raw["events"].setdefault(kind, {})
        entry.setdefault("source", " | ".join(got.get("sources seen", [])))
        entry.setdefault("when", "")
        entry.setdefault("count", "")
        fields = entry.setdefault("fields", {})
        for field in got.get("fields", []):
            types = got.get(f"field {field}", [])
            kind_of = {"str": "string", "int": "integer", "float": "number", "True": "boolean"}
            shown = sorted({kind_of.get(str(t), "boolean" if t in (True, False) else "any") for t in types
                            if t is not None})
            fields.setdefault(field, {"type": shown[0] if len(shown) == 1 else "any",
                                      **({"required": False} if None in types else {})})
        entry.setdefault("requirements", [])
        entry["read_by"] = sorted(got.get("steps", []))
    path.write_text(yaml.safe_dump(raw, sort_keys=False, allow_unicode=True, width=110), encoding="utf-8")
    return path


def prune(record: dict, profile: str) -> Path:
    """Drop from a profile's contract every entry no step of the recorded run reads (a contract split off
    another profile's keeps only what its own steps need), then refresh the read_by lists."""
    path = HERE / f"{profile}.yaml"
    raw = yaml.safe_load(path.read_text(encoding="utf-8"))
    seen = record.get(profile, {})
    raw["methods"] = {m: n for m, n in (raw.get("methods") or {}).items() if m in seen.get("methods", {})}
    for section in SECTIONS:
        entries = (raw.get("names") or {}).get(section) or {}
        used = seen.get(section, {})
        kept = {name: entry for name, entry in entries.items()
                if any(matches(name, n) for n in used)}
        if kept:
            raw["names"][section] = kept
        else:
            (raw.get("names") or {}).pop(section, None)
    answers = raw.get("answers") or {}
    for method in list(answers):
        used = {n.split(": ", 1)[1] for n in seen.get("answers", {}) if n.startswith(method + ": ")}
        answers[method] = {k: v for k, v in answers[method].items()
                           if any(matches(k, u) for u in used)}
        if not answers[method]:
            del answers[method]
    events = raw.get("events") or {}
    for kind in list(events):
        got = seen.get("events", {}).get(kind)
        if got is None:
            del events[kind]
            continue
        fields = events[kind].get("fields") or {}
        events[kind]["fields"] = {f: spec for f, spec in fields.items() if f in got.get("fields", [])}
    path.write_text(yaml.safe_dump(raw, sort_keys=False, allow_unicode=True, width=110), encoding="utf-8")
    load.cache_clear()
    return update(record, profile)
