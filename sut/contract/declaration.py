"""Implementation declarations (ICS + IXIT): what a SUT claims to implement and the parameters the suite
needs to test it, read from a YAML file and checked against the form (`form.yaml`).

    sut: reference                      # a free name, shown in the report
    profiles:
      atp:
        options: [vdx-new-firmware]     # ICS: options of the form it implements
        parameters:                     # IXIT: its values, in the form's units
          timing_resolution_us: 1
          d_sen_m: 3.0
        texts:                          # what its display shows, by message identifier
          CFSK fault: CFSK故障
      metro-tcn:
        texts:                          # an identifier's <name> placeholders: the text keeps each once
          "<device>: no status data": "<device>：无状态数据"

Every mistake is a `DeclarationError` naming the file, the line and the key, raised before any scenario runs.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import re

import yaml

from sut.contract.catalogue import HERE

ROOT = HERE.parents[1]
TYPES = {"integer": (int,), "number": (int, float), "string": (str,), "boolean": (bool,)}
PLACEHOLDER = re.compile(r"<[\w-]+>")       # in a message identifier: a name the features fill in


class DeclarationError(Exception):
    """A declaration that cannot be used: the file, line and key, and what is wrong."""


@lru_cache(maxsize=None)
def form() -> dict[str, dict]:
    """The form, per profile: options {name: note}, parameters {name: spec}, texts {id: spec}."""
    raw = yaml.safe_load((HERE / "form.yaml").read_text(encoding="utf-8"))
    return {name: {part: dict(section.get(part) or {}) for part in ("options", "parameters", "texts")}
            for name, section in raw["profiles"].items()}


@dataclass(frozen=True)
class ProfileDeclaration:
    profile: str
    path: Path
    options: frozenset[str]
    parameters: dict[str, Any]
    texts: dict[str, str]

    def parameter(self, name: str) -> Any:
        if name not in self.parameters:
            raise DeclarationError(f"{self.path}: profiles.{self.profile}.parameters: no {name!r} declared "
                                   f"(the form: sut/contract/form.yaml)")
        return self.parameters[name]

    def text(self, message: str) -> str:
        """What the SUT's display shows for `message` (the identifier the features quote)."""
        return self.texts.get(message, message)

    def claims(self, option: str) -> bool:
        return option in self.options


@dataclass(frozen=True)
class Declaration:
    path: Path
    sut: str
    profiles: dict[str, ProfileDeclaration] = field(default_factory=dict)

    def of(self, profile: str) -> ProfileDeclaration | None:
        return self.profiles.get(profile)


def _lines(text: str) -> dict[tuple[str, ...], int]:
    """The line (1-based) of every key path in a YAML text, from its node tree."""
    found: dict[tuple[str, ...], int] = {}

    def walk(node: Any, path: tuple[str, ...]) -> None:
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                sub = path + (str(key.value),)
                found[sub] = key.start_mark.line + 1
                walk(value, sub)
        elif isinstance(node, yaml.SequenceNode):
            for i, value in enumerate(node.value):
                sub = path + (str(value.value) if isinstance(value, yaml.ScalarNode) else str(i),)
                found[sub] = value.start_mark.line + 1
                walk(value, sub)

    try:
        walk(yaml.compose(text), ())
    except yaml.YAMLError:
        pass
    return found


def load(path: str | Path, text: str | None = None) -> Declaration:
    """A declaration from its file, or from `text` (a remote SUT's, sent in its hello) named `path`."""
    path = Path(path)
    shown = path.relative_to(ROOT) if path.is_absolute() and ROOT in path.parents else path
    if text is None:
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as exc:
            raise DeclarationError(f"{shown}: cannot read the declaration: {exc.strerror}") from None
    try:
        raw = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f":{mark.line + 1}" if mark else ""
        raise DeclarationError(f"{shown}{where}: not YAML: {getattr(exc, 'problem', exc)}") from None
    lines = _lines(text)

    def fail(keys: tuple[str, ...], why: str) -> DeclarationError:
        line = next((lines[keys[:n]] for n in range(len(keys), 0, -1) if keys[:n] in lines), None)
        return DeclarationError(f"{shown}{f':{line}' if line else ''}: {'.'.join(keys) or 'top'}: {why}")

    if not isinstance(raw, dict):
        raise fail((), "a declaration is a mapping with 'sut' and 'profiles'")
    for key in raw:
        if key not in ("sut", "profiles"):
            raise fail((str(key),), "unknown key; a declaration has 'sut' and 'profiles'")
    profiles = raw.get("profiles")
    if not isinstance(profiles, dict) or not profiles:
        raise fail(("profiles",), "declare at least one profile: profiles: {<profile>: {options, parameters, texts}}")
    the_form = form()
    out: dict[str, ProfileDeclaration] = {}
    for profile, section in profiles.items():
        where = ("profiles", str(profile))
        if profile not in the_form:
            raise fail(where, f"no such profile in the form; known: {', '.join(the_form)}")
        section = section or {}
        if not isinstance(section, dict):
            raise fail(where, "a mapping with options, parameters and texts")
        for key in section:
            if key not in ("options", "parameters", "texts"):
                raise fail(where + (str(key),), "unknown key; a profile has options, parameters and texts")
        blank = the_form[profile]
        options = section.get("options") or []
        if not isinstance(options, list):
            raise fail(where + ("options",), "a list of option names")
        for option in options:
            if option not in blank["options"]:
                raise fail(where + ("options", str(option)),
                           f"not an option of {profile}; the form has {', '.join(blank['options']) or 'none'}")
        params = section.get("parameters") or {}
        if not isinstance(params, dict):
            raise fail(where + ("parameters",), "a mapping of parameter: value")
        for name, value in params.items():
            spec = blank["parameters"].get(name)
            keys = where + ("parameters", str(name))
            if spec is None:
                raise fail(keys, f"unknown parameter; the {profile} form has {', '.join(blank['parameters'])}")
            _check_value(fail, keys, spec, value)
        missing = [n for n, spec in blank["parameters"].items() if spec.get("needed", True) and n not in params]
        if missing:
            raise fail(where + ("parameters",), f"missing needed parameter(s) {', '.join(missing)} "
                                                f"(sut/contract/form.yaml says what each is)")
        texts = section.get("texts") or {}
        if not isinstance(texts, dict):
            raise fail(where + ("texts",), "a mapping of message identifier: text")
        for message, shown_text in texts.items():
            if message not in blank["texts"]:
                raise fail(where + ("texts", str(message)),
                           f"no such message identifier; the {profile} form has {', '.join(blank['texts']) or 'none'}")
            if not isinstance(shown_text, str) or not shown_text.strip():
                raise fail(where + ("texts", str(message)), "the text the display shows, a non-empty string")
            wanted = sorted(PLACEHOLDER.findall(str(message)))
            if sorted(PLACEHOLDER.findall(shown_text)) != wanted:
                raise fail(where + ("texts", str(message)),
                           f"the text must hold {', '.join(wanted)} once each, where the display shows those names"
                           if wanted else "the text must hold no <name> placeholder (this identifier has none)")
        out[str(profile)] = ProfileDeclaration(str(profile), path, frozenset(options), dict(params),
                                               {str(k): v for k, v in texts.items()})
    return Declaration(path, str(raw.get("sut") or path.stem), out)


def _check_value(fail, keys: tuple[str, ...], spec: dict, value: Any) -> None:
    kind = spec.get("type", "number")
    ok_types = TYPES.get(kind, (object,))
    if isinstance(value, bool) and kind != "boolean" or not isinstance(value, ok_types):
        raise fail(keys, f"{value!r} is not {'an' if kind[0] in 'ai' else 'a'} {kind}"
                         f"{' in ' + spec['unit'] if spec.get('unit') else ''}")
    lo, hi = (spec.get("range") or [None, None])
    if lo is not None and value < lo or hi is not None and value > hi:
        source = spec.get("requirement", "the form")
        raise fail(keys, f"{value!r} {spec.get('unit', '')} is out of range: {lo}..{hi} ({source})".replace("  ", " "))


@lru_cache(maxsize=None)
def cached(path: str) -> Declaration:
    return load(ROOT / path if not Path(path).is_absolute() else Path(path))


def of_backend(cls: type, override: str | None = None) -> Declaration | None:
    """The declaration of a backend class: `--declaration FILE` where given, else the class's DECLARATION
    (a path relative to the project root; a remote SUT's comes in its hello as DECLARATION_TEXT), else none (the suite then has nothing to select or parameterise
    by, and a scenario that needs a parameter says so)."""
    if override is None and getattr(cls, "DECLARATION_TEXT", None):
        return load(cls.DECLARATION, cls.DECLARATION_TEXT)
    path = override or getattr(cls, "DECLARATION", None)
    return cached(str(path)) if path else None
