"""How well each requirement is verified, from the traceability: full, partly, none or out of scope.

- full: at least one item claims it without a `partly` note, and a scenario carries it;
- partly: every item claiming it says which part it covers (registry `partly`), and a scenario carries it;
- none: no scenario carries it (whatever the registry claims);
- out of scope: listed in the registry's `out_of_scope`, with the reason.
With run results, a requirement whose scenarios did not all pass says so next to its level.
"""
from __future__ import annotations

from dataclasses import dataclass

from outline.tracing.trace import Trace

LEVELS = ("full", "partly", "none", "out of scope")


@dataclass(frozen=True)
class Coverage:
    req: str
    text: str
    level: str
    items: tuple[tuple[str, str, str], ...]      # (item ID, item title, partly note or "")
    scenarios: tuple[tuple[str, str, str], ...]  # (item ID, scenario title, last status or "")
    reason: str = ""                             # out of scope: why

    @property
    def statuses(self) -> set[str]:
        return {status for _, _, status in self.scenarios if status}


def coverage(trace: Trace, requirements: dict, out_of_scope: dict[str, str] | None) -> list[Coverage]:
    out: list[Coverage] = []
    for req_id, req in requirements.items():
        by_item = trace.by_requirement.get(req_id, {})
        items = tuple((item_id, trace.by_item.get(item_id, ("", (), {}))[0],
                       trace.by_item.get(item_id, ("", (), {}))[2].get(req_id, ""))
                      for item_id in by_item)
        scenarios = tuple((item_id, title, trace.status.get(title, "")) for item_id, titles in by_item.items()
                          for title in titles)
        if out_of_scope and req_id in out_of_scope and not scenarios:
            level = "out of scope"
        elif not scenarios:
            level = "none"
        elif any(not note for item_id, _, note in items if by_item.get(item_id)):
            level = "full"
        else:
            level = "partly"
        out.append(Coverage(req_id, req.text, level, items, scenarios, (out_of_scope or {}).get(req_id, "")))
    return out


def counts(rows: list[Coverage]) -> dict[str, int]:
    return {level: sum(1 for r in rows if r.level == level) for level in LEVELS}
