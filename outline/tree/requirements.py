"""The requirement baseline: IDs are the heads of `- XXX-NN text` bullet lines in docs/requirements.md."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

REQ_ID = re.compile(r"^[A-Z]{2,4}-\d{2}$")
_BULLET = re.compile(r"^- ([A-Z]{2,4}-\d{2})\b\s*(.*)$")


@dataclass(frozen=True)
class Requirement:
    id: str
    text: str
    line: int


def load_requirements(path: str | Path) -> dict[str, Requirement]:
    """Requirement ID -> Requirement, in document order (the first bullet wins if an ID repeats)."""
    found: dict[str, Requirement] = {}
    for number, line in enumerate(Path(path).read_text(encoding="utf-8").splitlines(), start=1):
        match = _BULLET.match(line)
        if match and match.group(1) not in found:
            found[match.group(1)] = Requirement(match.group(1), match.group(2), number)
    return found
