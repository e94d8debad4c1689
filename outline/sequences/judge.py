"""Random sequences against the invariants (invariants.py): hypothesis draws sequences of the step library's
sentences (sentences.py), runs them on a fresh SUT, checks an invariant after every stimulus and shrinks a
sequence that breaks it to the shortest it can, printed as a scenario to paste into a feature file. Seeded and
without a database: the same budget and seed give the same verdict."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from hypothesis import HealthCheck, Phase, given, seed as hypothesis_seed, settings
from sut.driver import TrainDriver

from .invariants import SETTLE_US, Done, Invariant, Look
from .sentences import sequences as drawn
from .stimuli import Action

# How each profile's scenario begins (the step library's Given sentences), and what they do (POWER_UP; a
# profile not named there is powered up and nothing more).
OPENING = {"crh2": ["Given an 8-car CRH2 train set", "And the train is powered up"],
           "vdx": ["Given a CTCS3-300T ATP with its VDX emergency-brake interface", "And the train is powered up"],
           "metro-tcn": ["Given a 6-car metro train with its train control and diagnosis system",
                         "And the train is powered up"],
           "atp": ["Given a CTCS-2 200C on-board ATP on the test rig",
                   "And the ATP has completed its start-up self-test"]}


def _metro_powered(driver: TrainDriver) -> None:
    driver.configure(sets=1, cars_per_set=6)
    driver.power_on()


def _atp_started(driver: TrainDriver) -> None:
    """As the step does: powered up, then whole seconds until the DEF self-test is done (ATP-08: 22 s)."""
    driver.configure(sets=1)
    driver.power_on()
    for _ in range(60):
        if driver.trace.first(kind="def.done") is not None:
            return
        driver.advance_ms(1000)
    raise RuntimeError("the ATP did not finish its DEF self-test in 60 s")   # not a verdict on an invariant


POWER_UP: dict[str, Callable[[TrainDriver], None]] = {"metro-tcn": _metro_powered, "atp": _atp_started}


def _power_up(profile: str, driver: TrainDriver) -> None:
    """What the profile's Given sentences do (OPENING)."""
    if profile in POWER_UP:
        POWER_UP[profile](driver)
    else:
        driver.power_on()


# The budget: sequences per invariant and stimuli per sequence (make test; make campaign takes --sequences).
EXAMPLES = 25
MAX_ACTIONS = 12


@dataclass
class Violation:
    invariant: Invariant
    sequence: list[Action]
    step: int                          # stimuli applied when it broke
    what: str

    def gherkin(self) -> str:
        lines = [f"Scenario: {self.invariant.name} (a random sequence, shrunk)"]
        lines += [f"  {line}" for line in OPENING[self.invariant.profile]]
        lines += [f"  {'When' if i == 0 else 'And'} {a.sentence}" for i, a in enumerate(self.sequence[:self.step])]
        lines.append(f"  # Then {self.invariant.name} ({', '.join(self.invariant.requirements)}): "
                     f"it does not: {self.what}")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.gherkin()


Guard = Callable[[TrainDriver], TrainDriver]


def run(make: Callable[[], TrainDriver], invariant: Invariant, sequence: list[Action],
        guard: Guard = lambda driver: driver, declaration: Any = None) -> Violation | None:
    """`sequence` on a fresh SUT from `make`, every call through `guard` (the contract's, in a scenario);
    `declaration`: the SUT's for the profile, whose texts and parameters an invariant may read."""
    raw = make()
    driver = guard(raw)
    # Every sequence ends with the train left alone long enough for the checks that wait for it (SETTLE_US):
    # most random sequences never leave it alone that long on their own.
    sequence = [*sequence, Action("advance_ms", (SETTLE_US // 1000,), f"{SETTLE_US // 1000} ms pass")]
    try:
        _power_up(invariant.profile, driver)
        look = Look(driver, Done(), {}, declaration)
        for step, action in enumerate(sequence, start=1):
            action.apply(driver)
            look.done.note(action, driver.now_us)
            broken = invariant.check(look)
            if broken:
                return Violation(invariant, sequence, step, broken)
        return None
    finally:
        raw.shutdown()


def search(make: Callable[[], TrainDriver], invariant: Invariant, *, examples: int = EXAMPLES,
           max_actions: int = MAX_ACTIONS, seed: int = 0, guard: Guard = lambda driver: driver,
           declaration: Any = None) -> Violation | None:
    """The shortest sequence found that breaks `invariant` in `examples` sequences, or None."""
    probe = make()
    _power_up(invariant.profile, probe)
    sequences = drawn(invariant.profile, guard(probe), max_actions, invariant.focus)
    probe.shutdown()
    found: list[Violation] = []

    @hypothesis_seed(seed)
    @settings(max_examples=examples, deadline=None, database=None, suppress_health_check=list(HealthCheck),
              phases=[Phase.generate, Phase.shrink])
    @given(sequences)
    def holds(sequence: list[Action]) -> None:
        violation = run(make, invariant, sequence, guard, declaration)
        if violation is not None:
            found.append(violation)
            raise AssertionError(violation.what)

    try:
        holds()
    except AssertionError:
        return found[-1]
    return None
