"""Reading the SUT's trace the way a test engineer reads analyser logs. No pytest, no SUT internals."""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

from sut.driver import TrainDriver
from sut.trace import Trace, TraceEvent

from steps import budgets

QUOTED = re.compile(r'"([^"]+)"')


def quoted_names(text: str) -> list[str]:
    """The quoted names of a sentence's list (`"car6.LCU" and "car2.LCU"`), at least one."""
    names = QUOTED.findall(text)
    assert names, f"no quoted names in {text!r}"
    return names


@dataclass(frozen=True)
class Delivery:
    node: str            # receiving LCU
    seq: int
    system: int
    sent: int            # us, command left the commanding CCU's MDM8
    received: int        # us, at the LCU's MDM8
    hops: int
    direction: str

    @property
    def latency(self) -> int:
        return self.received - self.sent


def command_deliveries(trace: Trace, since: int = 0, until: int | None = None) -> list[Delivery]:
    """Join every `cmd.rx` at an LCU with the `cmd.tx` it came from (same system and sequence number,
    latest transmission before the reception: sequence numbers wrap every 256 commands)."""
    sent: dict[tuple[int, int], list[int]] = {}
    for ev in trace.select(kind="cmd.tx"):
        sent.setdefault((ev["system"], ev["seq"]), []).append(ev.t)
    out = []
    for ev in trace.select(kind="cmd.rx", source="*.LCU.MDM8", since=since, until=until):
        times = [t for t in sent.get((ev["system"], ev["seq"]), []) if t <= ev.t]
        if not times:
            continue
        out.append(Delivery(ev.source.rsplit(".", 1)[0], ev["seq"], ev["system"], times[-1], ev.t, ev["hops"],
                            ev["dir"]))
    return out


def expect_taken(sut: TrainDriver, devices: list[str], t_action: int, window: int, what: str, **want) -> None:
    """Every device took a command with the `want` fields (path, traction, direction, ...) within `window`
    us of the action (a reaction-time budget: steps/budgets.py); the failure says what each laggard took last."""
    assert devices, "no CI or BCU to check"
    until = t_action + window

    def check() -> None:
        for device in devices:
            if sut.trace.first(kind="cmd.in", source=device, since=t_action, until=until, **want) is None:
                last = sut.trace.last(kind="cmd.in", source=device, until=until)
                seen = f"last took {dict(last.fields)} at {ms(last.t)}" if last else "took no command at all"
                raise AssertionError(f"{device} did not receive {what} within {ms(window)} of the action; it {seen}")

    budgets.within(sut, t_action, window, check)


def expect_brake_step(sut: TrainDriver, since: int, step: int, why: str = "") -> None:
    """From `since` on, every BCU took commands, and none but brake step `step`; `why` opens the failure (who
    asked for that step)."""
    for device in [d for d in command_devices(sut) if d.endswith(".BCU")]:
        takes = sut.trace.select(kind="cmd.in", source=device, since=since)
        assert takes, f"{device} received nothing"
        odd = [ev for ev in takes if ev["brake"] != step]
        assert not odd, f"{why}{device} received other brake steps: {describe(odd)}"


def expect_period(times: Iterable[int], lo: float, hi: float, what: str, at_least: int = 3) -> None:
    """`what` happened at least `at_least` times and every gap between two lies in lo..hi ms."""
    times = list(times)
    assert len(times) >= at_least, f"{what}: only {len(times)} times"
    gaps = intervals(times)
    assert us(lo) <= min(gaps) and max(gaps) <= us(hi), (
        f"{what}: every {ms(min(gaps))}..{ms(max(gaps))}, outside {lo:g}..{hi:g} ms")


def intervals(times: Iterable[int]) -> list[int]:
    times = list(times)
    return [b - a for a, b in zip(times, times[1:])]


def cars(sut: TrainDriver) -> list[int]:
    return sorted(int(n[3:].split(".")[0]) for n in sut.ring_nodes() if n.endswith(".LCU"))


def lcus(sut: TrainDriver) -> list[str]:
    return [n for n in sut.ring_nodes() if n.endswith(".LCU")]


def command_devices(sut: TrainDriver, car: int | None = None) -> list[str]:
    chosen = cars(sut) if car is None else [car]
    return [d for c in chosen for d in sut.devices(c) if d.endswith((".CI", ".BCU"))]


def record(size: int) -> bytes:
    """The test record a node is asked to send as block data: recognisable, not all zero."""
    return bytes((i * 7 + 3) & 0xFF for i in range(size))


def us(ms_value: float) -> int:
    """Milliseconds from a sentence as the SUT's integer microseconds."""
    return round(ms_value * 1000)


def same_value(shown: object, want: str) -> bool:
    """A displayed value against a sentence's text: numbers compare as numbers ("4" == 4.0)."""
    try:
        return float(shown) == float(want)
    except (TypeError, ValueError):
        return shown == want


def ms(us: int) -> str:
    return f"{us / 1000:.3f} ms"


def describe(events: list[TraceEvent], limit: int = 6) -> str:
    shown = "; ".join(f"{e.t_ms:.3f} ms {e.source} {e.kind} {dict(e.fields)}" for e in events[:limit])
    more = f" ... ({len(events)} in all)" if len(events) > limit else ""
    return shown + more


def record_event(declaration, event: str) -> str:
    """The word a SUT's fault records (`F|<t ms>|<node>|<board>|<event>`) use for `event`: a board's `failed` and
    `recovered` as it declares them (sut/contract/form.yaml crh2 texts, view records), other events (a supply's
    `restarted after ...`) as they are."""
    return declaration.text(event) if event in ("failed", "recovered") else event
