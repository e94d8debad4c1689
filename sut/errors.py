"""Errors a SUT driver raises for bad input: each names the value and what would have been allowed."""
from __future__ import annotations

import difflib
from typing import Any, Iterable


class SutError(Exception):
    """Base of every error the driver interface raises on purpose."""


class UnknownName(SutError):
    def __init__(self, what: str, name: str, known: Iterable[str]):
        known = sorted(known)
        close = difflib.get_close_matches(name, known, n=4, cutoff=0.6)
        hint = f"; did you mean {', '.join(close)}?" if close else ""
        shown = ", ".join(known[:24]) + (f", ... ({len(known)} in all)" if len(known) > 24 else "")
        super().__init__(f"no {what} named {name!r}{hint}; known: {shown}")
        self.what, self.name, self.known = what, name, known


class OutOfRange(SutError):
    def __init__(self, what: str, value: Any, allowed: str):
        super().__init__(f"{what} {value!r} is out of range; allowed: {allowed}")
        self.what, self.value, self.allowed = what, value, allowed


class NotPoweredUp(SutError):
    pass


class NotSupported(SutError):
    """The backend does not model this (python-can style: optional features raise, never fake)."""


class SutUnreachable(SutError):
    """The SUT could not be reached or stopped making sense: refused, closed, silent past the timeout, or
    answering with something that is not the protocol. The scenario's verdict is "SUT not reachable"."""

    def __init__(self, where: str, why: str):
        super().__init__(f"SUT not reachable at {where}: {why}")
        self.where, self.why = where, why


class RemoteError(SutError):
    """The remote SUT raised something that is not one of the driver interface's errors (a bug in it)."""
