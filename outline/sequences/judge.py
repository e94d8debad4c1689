"""Random sequences against the invariants (invariants.py): hypothesis draws sequences of the step library's
sentences (sentences.py), runs them on a fresh SUT, checks an invariant after every stimulus and shrinks a
sequence that breaks it to the shortest it can, printed as a scenario to paste into a feature file. Seeded and
without a database: the same budget and seed give the same verdict."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from hypothesis import HealthCheck, Phase, given, seed as hypothesis_seed, settings
from sut.driver import TrainDriver

from .invariants import SETTLE_US, Done, Invariant, Look
from .sentences import sequences as drawn
from .stimuli import Action

# How each profile's scenario begins (the step library's Given sentences).
OPENING = {"crh2": ["Given an 8-car CRH2 train set", "And the train is powered up"],
           "vdx": ["Given a CTCS3-300T ATP with its VDX emergency-brake interface", "And the train is powered up"]}
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
        guard: Guard = lambda driver: driver) -> Violation | None:
    """`sequence` on a fresh SUT from `make`, every call through `guard` (the contract's, in a scenario)."""
    raw = make()
    driver = guard(raw)
    # Every sequence ends with the train left alone long enough for the checks that wait for it (SETTLE_US):
    # most random sequences never leave it alone that long on their own.
    sequence = [*sequence, Action("advance", (SETTLE_US,), f"{SETTLE_US // 1000} ms pass")]
    try:
        driver.power_on()
        look = Look(driver, Done(), {})
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
           max_actions: int = MAX_ACTIONS, seed: int = 0, guard: Guard = lambda driver: driver) -> Violation | None:
    """The shortest sequence found that breaks `invariant` in `examples` sequences, or None."""
    probe = make()
    probe.power_on()
    sequences = drawn(invariant.profile, guard(probe), max_actions)
    probe.shutdown()
    found: list[Violation] = []

    @hypothesis_seed(seed)
    @settings(max_examples=examples, deadline=None, database=None, suppress_health_check=list(HealthCheck),
              phases=[Phase.generate, Phase.shrink])
    @given(sequences)
    def holds(sequence: list[Action]) -> None:
        violation = run(make, invariant, sequence, guard)
        if violation is not None:
            found.append(violation)
            raise AssertionError(violation.what)

    try:
        holds()
    except AssertionError:
        return found[-1]
    return None
