"""Texts a SUT shows (on a display, in a record, on a maintenance view) read in its own words: the features name
a message identifier of the form (sut/contract/form.yaml, a profile's `texts`), with names filled in, and the
SUT's declaration says how it words that message (any language). Used by steps/metro.py (the metro displays and
records) and by the CRH2 cab monitor's steps (steps/monitor.py, network.py, extra_display.py, extra_records.py,
extra_control.py): `message` gives what to look for.
"""
from __future__ import annotations

import re

from sut.contract.declaration import PLACEHOLDER, ProfileDeclaration, form

NAME = "[A-Za-z0-9_.]+"         # what a feature fills in for a message's <name>: car4.VVVF, car3.LCU.MDM9, unit1, A


def identifiers(profile: str, view: str | None = None) -> list[str]:
    """The message identifiers of a profile's form; with `view`, those the form shows there (its `view` key:
    the part of the SUT's answer that shows the text, where a profile has several)."""
    texts = form()[profile]["texts"]
    return [i for i, spec in texts.items() if view is None or (spec or {}).get("view") == view]


def regex(template: str, fill) -> str:
    """`template` as a regular expression: its words literally, each <name> placeholder as `fill(name)` gives."""
    out, at = [], 0
    for m in PLACEHOLDER.finditer(template):
        out += [re.escape(template[at:m.start()]), fill(m.group())]
        at = m.end()
    return "".join(out) + re.escape(template[at:])


def _filled(template: str, text: str) -> dict[str, str] | None:
    """The names `text` fills into `template`'s placeholders, or None if it does not fill it in."""
    found = re.fullmatch(regex(template, lambda _: f"({NAME})"), text)
    return None if found is None else dict(zip(PLACEHOLDER.findall(template), found.groups()))


def _leading(identifier: str, text: str) -> dict[str, str] | None:
    """The names `text` fills in if it is a leading part of `identifier` with a name in it, cut before a space
    (`car3.LCU.supply restarted` of `<node>.supply restarted after over-temperature`, a bare `car7.LCU.MDM9` of
    `<board> failed`), else None."""
    for space in re.finditer(" ", identifier):
        part = identifier[:space.start()]
        names = _filled(part, text) if PLACEHOLDER.search(part) else None
        if names is not None:
            return names
    return None


def message(declaration: ProfileDeclaration, text: str, view: str | None = None) -> tuple[re.Pattern, str]:
    """How to find the feature's `text` in what the SUT shows, in its own words: the message identifier the text
    fills in (`car4.VVVF: no status data` fills `<device>: no status data`) worded as the SUT declares it, with
    the feature's names. A text may also be
    - an identifier itself (`no status data from <node>`): any names;
    - a leading part of identifiers, with a name (`car3.LCU.supply restarted`, a bare `car7.LCU.MDM9`): any of
      the messages it begins, with its names;
    - the words of an identifier only (`no status data`): any names.
    `view` takes only the identifiers the form shows there (`faults`, `maintenance`). Answers the pattern (search
    a text for it, or match a whole text) and how to say it in a failure message."""
    known = identifiers(declaration.profile, view)
    if text in known:
        candidates = [(text, {})]
    else:
        full, leading, partial = [], [], []
        for identifier in known:
            names = _filled(identifier, text)
            if names is not None:
                full.append((identifier, names))
                continue
            names = _leading(identifier, text)
            if names is not None:
                leading.append((identifier, names))
            elif any(text in words for words in PLACEHOLDER.split(identifier)):
                partial.append((identifier, {}))
        # A leading part names a family of messages on purpose; a whole text or bare words name one.
        candidates, several = (full, False) if full else (leading, True) if leading else (partial, False)
        if not candidates or len(candidates) > 1 and not several:
            where = f"{declaration.profile}{f' ({view})' if view else ''}"
            raise ValueError(f"the text {text!r} names {'several' if candidates else 'no'} message identifier(s) of "
                             f"the {where} form (sut/contract/form.yaml): {[c for c, _ in candidates] or known}")
    shown, patterns = [], []
    for identifier, names in candidates:
        declared = declaration.text(identifier)
        patterns.append(regex(declared, lambda p: re.escape(names[p]) if p in names else ".+?"))
        shown.append(PLACEHOLDER.sub(lambda m: names.get(m.group(), m.group()), declared))
    pattern = re.compile(patterns[0] if len(patterns) == 1 else "(?:" + "|".join(patterns) + ")")
    said = repr(text) if shown == [text] else f"{text!r} (declared as {' or '.join(map(repr, shown))})"
    return pattern, said
