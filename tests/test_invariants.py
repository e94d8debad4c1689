"""The random-sequence judge (outline/sequences, steps/sequences.py; features F-ILK-10, F-ATP-14, F-NET-35,
F-ATP-15): its stimuli are the step library's own sentences, so a sequence it prints is a scenario a user can
paste; it finds a variant that breaks an invariant and shrinks the sequence; the same seed gives the same
sequence."""
from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, seed as hypothesis_seed, settings
from hypothesis import strategies as st

from outline.sequences.invariants import INVARIANTS
from outline.sequences.judge import OPENING, search
from outline.sequences.sentences import OPENINGS, PROFILES, sequences
from outline.plugin.stepdefs import definitions_in_modules, step_problem
from steps import STEP_MODULES
from sut.backends import resolve
from sut.contract import declaration as declarations
from sut.snapshot import SnapshotCache, SnapshotDriver
from tests.variants import CarrierAfterOneComparison, IsolationIgnored, SeparationWithoutRapidBrake

DEFINITIONS = definitions_in_modules(STEP_MODULES)


@pytest.mark.parametrize("profile", sorted(PROFILES))
def test_every_stimulus_is_a_sentence_of_the_step_library(profile: str) -> None:
    driver = resolve("reference").open(profile)
    driver.power_on()
    drawn = sequences(profile, driver, 12)
    said: set[str] = set()

    @settings(max_examples=300, database=None, deadline=None, suppress_health_check=list(HealthCheck))
    @given(drawn)
    def collect(sequence) -> None:
        said.update(a.sentence for a in sequence)

    collect()
    said.update(a.sentence for opening in OPENINGS[profile] for a in opening)
    problems = [p for p in (step_problem("when", text, DEFINITIONS) for text in sorted(said)) if p]
    problems += [p for line in OPENING[profile]
                 if (p := step_problem("given", line.split(" ", 1)[1], DEFINITIONS))]
    assert not problems, problems
    assert len(said) > 20, sorted(said)


def _invariant(requirement: str):
    return next(i for i in INVARIANTS if i.requirements[0] == requirement)


def test_a_variant_breaking_an_invariant_is_found_and_shown_as_a_scenario() -> None:
    violation = search(lambda: IsolationIgnored.open("vdx"), _invariant("VDX-01"), examples=40)
    assert violation is not None
    text = violation.gherkin().splitlines()
    assert text[1:3] == [f"  {line}" for line in OPENING["vdx"]]
    assert any(line.endswith(" the ATP isolation switch is turned on") for line in text), text
    assert text[-1].startswith("  # Then the loop is closed exactly when"), text


def test_the_same_seed_finds_the_same_sequence() -> None:
    runs = [search(lambda: SeparationWithoutRapidBrake.open("crh2"), _invariant("ILK-01"), examples=25, seed=0)
            for _ in range(2)]
    assert runs[0] is not None and runs[0].gherkin() == runs[1].gherkin()
    assert "the train separates between car" in runs[0].gherkin()


def test_an_invariant_reads_the_declared_parameters_and_draws_on_its_focus() -> None:
    """ATP-03: a CFSK that reports after one comparison is found against the period the SUT declares; the
    sequences drawn for the invariant draw on the kinds of stimulus it is about."""
    invariant = _invariant("ATP-03")
    declaration = declarations.of_backend(CarrierAfterOneComparison).of("atp")
    violation = search(lambda: CarrierAfterOneComparison.open("atp"), invariant, examples=20,
                       declaration=declaration)
    assert violation is not None and "fewer than 3 comparisons 50 ms apart" in violation.what, violation
    assert search(lambda: resolve("reference").open("atp"), invariant, examples=20, declaration=declaration) is None
    driver = resolve("reference").open("atp")
    driver.power_on()

    def switching(focus: tuple[str, ...]) -> int:
        """How many of 30 sequences drawn with `focus` switch the signal generator after the opening."""
        found: list[bool] = []

        @hypothesis_seed(0)
        @settings(max_examples=30, database=None, deadline=None, suppress_health_check=list(HealthCheck))
        @given(sequences("atp", driver, 12, focus))
        def drawn(sequence) -> None:
            found.append(any(a.sentence.startswith("the signal generator switches to")
                             for a in sequence[len(OPENINGS["atp"][0]):]))

        drawn()
        return sum(found)

    assert switching(invariant.focus) > 2 * switching(()), (switching(invariant.focus), switching(()))


def test_every_invariant_names_requirements_a_feature_verifies() -> None:
    from pathlib import Path
    text = "".join(p.read_text(encoding="utf-8") for p in Path("features").rglob("*.feature"))
    for invariant in INVARIANTS:
        assert f"after every stimulus of every sequence, {invariant.name}\n" in text, invariant


def test_sequences_behind_the_snapshot_journal_find_what_fresh_trains_find() -> None:
    """The scenarios run each sequence behind the run's snapshot journal (steps/fixtures.open_driver): every
    sequence starts with the same power-up, restored instead of simulated. The same seed must give the same
    verdict and the same shrunk sequence as on fresh trains."""
    cache = SnapshotCache()
    invariant = _invariant("ILK-01")
    fresh = search(lambda: SeparationWithoutRapidBrake.open("crh2"), invariant, examples=25, seed=0)
    journaled = search(lambda: SnapshotDriver(SeparationWithoutRapidBrake, "crh2", cache), invariant,
                       examples=25, seed=0)
    assert fresh is not None and journaled is not None
    assert journaled.gherkin() == fresh.gherkin()
    assert cache.restored > 0, cache.summary()
