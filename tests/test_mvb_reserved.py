"""MVB reserved F_codes (5-7, 10-11; docs/decisions.md): the suite's analyser names a master frame
with one, the metro reference's devices ignore it, and the features reject a master that polls with one."""
from __future__ import annotations

from sut.codecs import mvb
from sut.reference.metro.backend import ReferenceMetro
from tests.variants import StatusPolledWithReservedCode


def _bus_frames(metro: ReferenceMetro, bus: str) -> list[tuple[str, bytes]]:
    metro.tap_bus(bus)
    metro.insert_key(1)
    metro.power_on()
    metro.advance(100_000)
    return [(ev["type"], bytes.fromhex(ev["hex"])) for ev in metro.trace.select(kind="bus.frame", source=bus)]


def test_no_device_answers_a_status_poll_with_a_reserved_f_code() -> None:
    frames = _bus_frames(StatusPolledWithReservedCode(), "unit1.MVB")
    polls = [i for i, (kind, raw) in enumerate(frames) if kind == "master" and mvb.decode_master(raw).reserved]
    assert len(polls) >= 50, f"only {len(polls)} reserved polls in 100 ms"
    answered = [i for i in polls if i + 1 < len(frames) and frames[i + 1][0] == "slave"]
    assert not answered, f"{len(answered)} reserved polls were answered, first {frames[answered[0]][1].hex()}"


def test_the_reference_polls_device_status_with_f_code_15_and_gets_answers() -> None:
    frames = _bus_frames(ReferenceMetro(), "unit1.MVB")
    status = [i for i, (kind, raw) in enumerate(frames) if kind == "master" and mvb.decode_master(raw).f_code == 15]
    assert len(status) >= 50 and all(frames[i + 1][0] == "slave" for i in status if i + 1 < len(frames))
    assert not any(mvb.decode_master(raw).reserved for kind, raw in frames if kind == "master")
