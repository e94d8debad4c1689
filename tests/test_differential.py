"""The differential checker (outline/sequences, issue 31): two SUTs driven side by side through the driver
interface by the same random stimulus sequences. It must find a difference where a variant behaves otherwise,
print the shortest sequence it shrinks to, find none between a SUT and itself, and answer the same for the
same seed."""
from __future__ import annotations

import pytest

from outline.sequences.differential import main, opener, search
from sut.reference.atp.backend import ReferenceAtp
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.metro.backend import ReferenceMetro
from tests.variants import LongTokenHold, SlowRelay


class SameAtp(ReferenceAtp):
    """The reference under another name: nothing differs."""


class SameTrain(ReferenceTrain):
    pass


class SameMetro(ReferenceMetro):
    pass


@pytest.mark.parametrize(("cls", "profile"), [(SameTrain, "crh2"), (SameMetro, "metro-tcn"), (SameAtp, "atp"),
                                              (SameAtp, "vdx"), (SameAtp, "atp-crh2")])
def test_a_sut_against_itself_shows_no_difference(cls: type, profile: str) -> None:
    assert search(opener("reference", profile), lambda: cls.open(profile), profile, examples=15) is None


def test_a_slow_relay_is_found_by_the_shortest_sequence_that_shows_it() -> None:
    difference = search(opener("reference", "vdx"), lambda: SlowRelay.open("vdx"), "vdx", examples=400,
                        max_actions=12)
    assert difference is not None
    # the loop closes, the FS output goes off (the ATP brakes, or the VDX loses its supply), and a few ms later
    # the reference's EB2R has opened the loop, SlowRelay's not yet
    assert difference.sequence[-1].method == "advance", difference
    assert len(difference.sequence) <= 5, difference


def test_the_same_seed_gives_the_same_answer(capsys: pytest.CaptureFixture) -> None:
    args = ["--profile", "crh2", "--sut", f"tests.variants:{LongTokenHold.__name__}", "--examples", "200",
            "--actions", "10", "--seed", "0"]
    assert main(args) == 1
    first = capsys.readouterr().out
    assert main(args) == 1
    assert capsys.readouterr().out == first
    assert "shortest sequence found" in first and "power_on()" in first


class NarrowAmplitude(ReferenceAtp):
    """Refuses a carrier amplitude of 0 mV, which the reference accepts (the audit's `(0, 10_000)` ->
    `(1, 10_000)`): a refusal on one side only."""

    def set_input(self, name, value):  # noqa: ANN001, ANN201
        if name == "amplitude" and value == 0:
            from sut.errors import OutOfRange
            raise OutOfRange(name, value, "1..10000")
        return super().set_input(name, value)


def test_a_refusal_on_one_side_only_is_the_difference_shown() -> None:
    from outline.sequences.differential import first_difference
    from outline.sequences.stimuli import Action
    difference = first_difference(opener("reference", "atp"), lambda: NarrowAmplitude.open("atp"), "atp",
                                  [Action("set_input", ("amplitude", 0))])
    assert difference is not None
    assert (difference.what, difference.a, difference.b) == ("refused", "no refusal", "OutOfRange")


def test_of_a_free_text_the_contract_fixes_in_part_only_that_part_is_compared() -> None:
    from outline.sequences.observe import Observer
    observer = Observer("metro-tcn", ReferenceMetro.open("metro-tcn"))
    assert observer._listed("frame.discard") == {"error"}
    # metro-tcn.yaml: `error` begins with `line A` or `line B`; what follows is the SUT's own wording
    seen = {text: observer._compared("frame.discard", "error", text) for text in (
        "line A: master frame check sequence failed at raw[2]: received 0xba, computed 0x71",
        "line A: bad FCS", "line B: bad FCS", "no line named")}
    assert list(seen.values()) == ["line A", "line A", "line B", "no line named"]


def test_of_a_number_the_contract_fixes_to_a_resolution_only_whole_steps_of_it_are_compared() -> None:
    from outline.sequences.observe import Observer
    observer = Observer("atp", ReferenceAtp.open("atp"))
    assert "at_m" in observer._listed("carrier.inconsistent")
    # atp.yaml: the position of a carrier inconsistency is read to the centimetre; a finer stamp is the SUT's
    at = [observer._compared("carrier.inconsistent", "at_m", m) for m in (1234.5671, 1234.567, 1234.5749, 1235.0)]
    assert at[0] == at[1] == at[2] != at[3]
    observer._listed("balise")
    assert observer._compared("balise", "at_m", 1234.5671) == 1234.5671     # no resolution given: as it is


def test_a_resolution_on_a_field_that_is_no_number_is_an_error_naming_the_entry(tmp_path) -> None:
    from sut.contract import ContractFileError
    from sut.contract.catalogue import parse
    bad = tmp_path / "x.yaml"
    bad.write_text("profile: x\nevents:\n  a.b:\n    fields:\n      f: {type: string, resolution: 0.1}\n",
                   encoding="utf-8")
    with pytest.raises(ContractFileError, match=r"x.yaml: events.a.b.fields.f.resolution: a number above 0"):
        parse(bad)


class RecordsEverything(ReferenceTrain):
    """A backend that skips nothing in a soak (TrainDriver's own: a rig simply waits), records every event and
    emits no time.skip: conforming (crh2.yaml, time.skip)."""
    BULK_READABLE = True  # pragma: no mutate

    def _soak(self, us: int, sample_every_us: int | None) -> None:
        self._advance(us)


def test_where_a_backend_skips_in_a_soak_is_its_own_choice_and_what_it_leaves_behind_is_compared() -> None:
    from outline.sequences.differential import _looks, first_difference
    from outline.sequences.stimuli import Action
    soak = [Action("insert_key", (1,)), Action("soak", (30_000_000,), kwargs=(("sample_every_us", 10_000_000),))]
    # Looked at raw, the two differ: the reference skipped steady stretches and said so with time.skip.
    raw = [list(_looks(make, "crh2", soak, {}))[-1] for make in (opener("reference", "crh2"), RecordsEverything.open)]
    assert raw[0]["skipped stretches"] and not raw[1]["skipped stretches"]
    assert len(raw[0]["events"]) < len(raw[1]["events"])
    # Compared: the stretches one of them skipped left out on both sides, and nothing else differs.
    assert first_difference(opener("reference", "crh2"), RecordsEverything.open, "crh2", soak) is None
    # What a skip leaves behind still is: a ring link cut in the middle of the soak's steady stretch.
    cut = [*soak, Action("cut_link", ("car3.LCU", "car4.LCU")), Action("soak", (30_000_000,))]
    assert first_difference(opener("reference", "crh2"), RecordsEverything.open, "crh2", cut) is None


def test_an_event_inside_a_stretch_either_side_skipped_is_left_out_and_time_skip_with_it() -> None:
    from outline.sequences.observe import SKIPPED, comparable
    a = {"now us": 9, SKIPPED: [(2, 6)], "events": [(1, "x", "k", {}), (3, "x", "k", {}), (6, "train", "time.skip", {}),
                                                    (7, "x", "k", {})]}
    b = {"now us": 9, SKIPPED: [], "events": [(1, "x", "k", {}), (3, "x", "k", {}), (4, "x", "k", {}),
                                              (7, "x", "k", {})]}
    assert comparable(a, b) == ({"now us": 9, "events": [(1, "x", "k", {}), (7, "x", "k", {})]},
                                {"now us": 9, "events": [(1, "x", "k", {}), (7, "x", "k", {})]})
    # a stretch is (frm, to]: an event at its start was recorded by both and is compared, one at its end not
    b["events"][0] = (2, "x", "k", {})
    assert comparable(a, b)[0] != comparable(a, b)[1]
    b["events"][0], b["events"][2] = (1, "x", "k", {}), (6, "x", "k", {})
    assert comparable(a, b)[0] == comparable(a, b)[1]


@pytest.mark.parametrize("wanted", ["soak", "group2"])
def test_the_checkers_stimuli_hold_long_runs_and_a_command_boards_cpu_groups(wanted: str) -> None:
    # A soak is a backend's own way through (bulk.run), and a CPU group's failure (FS-01) its own fault: the
    # contract lists both, so the checker's stimuli must hold them or no mark behind them is ever reached.
    from hypothesis import find, settings
    from outline.sequences.stimuli import actions
    driver = ReferenceTrain.open("crh2")
    driver.power_on()
    method = "soak" if wanted == "soak" else "fail"
    found = find(actions("crh2", driver), lambda a: a.method == method and wanted in str(a),
                 settings=settings(database=None, max_examples=5000))
    assert found.method == method, found
