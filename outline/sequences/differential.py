"""Two SUTs driven side by side (issue 31): the same random stimulus sequences through the driver interface,
every observable compared after every stimulus (observe.py). A difference is printed as the shortest sequence
hypothesis shrinks it to; none in the budget is the evidence a mutant or variant may be called equivalent.

    python -m outline.sequences.differential --profile crh2 --sut tests.variants:PipeTripTooLow
"""
from __future__ import annotations

import argparse
import sys
import time
from dataclasses import dataclass
from typing import Any, Callable

from hypothesis import HealthCheck, Phase, given, seed as hypothesis_seed, settings
from hypothesis import strategies as st

from sut.backends import resolve
from sut.driver import TrainDriver

from .observe import Observer, comparable
from .stimuli import Action, actions

Factory = Callable[[], TrainDriver]


@dataclass
class Difference:
    sequence: list[Action]
    step: int                      # stimuli applied before the looks differed (0: at power-up)
    what: str                      # the observable
    a: Any
    b: Any

    def calls(self) -> list[str]:
        """The sequence as driver calls, power-up included where it comes (first, unless the sequence has it)."""
        cold = any(a.method == "power_on" for a in self.sequence)
        return ([] if cold else ["power_on()"]) + [str(a) for a in self.sequence]

    def __str__(self) -> str:
        lines = self.calls()
        shown = "\n".join(f"  {'>' if i == self.step else ' '} {line}" for i, line in enumerate(lines))
        return (f"the SUTs differ after {self.step} stimuli, in {self.what}:\n  A: {self.a!r}\n  B: {self.b!r}\n"
                f"shortest sequence found (> marks the last stimulus before the difference):\n{shown}")


def _looks(make: Factory, profile: str, sequence: list[Action], shared: dict[str, Any]):
    """What the SUT shows at power-up and after each stimulus; a sequence that names power_on() has its
    stimuli before it applied to the SUT unpowered, each seen only as done or refused."""
    driver = make()
    cold = next((i for i, a in enumerate(sequence) if a.method == "power_on"), None)
    for action in sequence[:cold] if cold is not None else ():
        try:
            action.apply(driver)
        except Exception as error:      # noqa: BLE001  (a refusal is an observable like any other)
            yield {"refused": type(error).__name__}
            continue
        yield {"before power-up": str(action)}
    driver.power_on()
    # The second SUT is looked at under the first one's names: which names a SUT lists is no behaviour.
    observer = Observer(profile, driver, shared.get("vehicle"))
    shared.setdefault("vehicle", observer.vehicle)
    yield observer.look()
    for action in sequence[cold + 1:] if cold is not None else sequence:
        try:
            action.apply(driver)
        except Exception as error:      # noqa: BLE001  (a refusal is an observable like any other)
            yield {"refused": type(error).__name__}
            continue
        yield observer.look()


def first_difference(make_a: Factory, make_b: Factory, profile: str, sequence: list[Action]) -> Difference | None:
    shared: dict[str, Any] = {}
    for step, (a, b) in enumerate(zip(_looks(make_a, profile, sequence, shared),
                                      _looks(make_b, profile, sequence, shared))):
        a, b = comparable(a, b)
        if a != b:
            # A refusal on one side only is the difference itself, not a missing look to compare field by field.
            what = "refused" if ("refused" in a) != ("refused" in b) else \
                next((k for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k)), "?")
            missing = "no refusal" if what == "refused" else None
            av, bv = a.get(what, missing), b.get(what, missing)
            if what == "events":
                pairs = [(x, y) for x, y in zip(av, bv) if x != y]
                av, bv = pairs[0] if pairs else (av[len(bv):][:1], bv[len(av):][:1])
            return Difference(sequence, step, what, av, bv)
    return None


def opener(sut: str, profile: str) -> Factory:
    cls = resolve(sut)
    return lambda: cls.open(profile)


Sequences = Callable[[str, TrainDriver, int], st.SearchStrategy[list[Action]]]


def search(make_a: Factory, make_b: Factory, profile: str, *, examples: int = 30, max_actions: int = 8,
           seed: int = 0, shrink_s: float | None = None, sequences: Sequences | None = None) -> Difference | None:
    """The shortest difference hypothesis finds in `examples` sequences of up to `max_actions` stimuli, or
    None. Seeded and without a database: the same arguments give the same answer. `shrink_s`: how long the
    shrinking may run (it tries hundreds of sequences, ~1 s each on the metro), after which the shortest one
    found so far is the answer; unbounded, the answer does not depend on the machine's speed. `sequences`:
    another way to draw them from (profile, a powered-up driver, max_actions) than a list of stimuli."""
    probe = make_a()
    probe.power_on()
    drawn = sequences(profile, probe, max_actions) if sequences is not None else \
        st.lists(actions(profile, probe), max_size=max_actions)
    found: list[Difference] = []
    differing: dict[str, Difference] = {}          # by repr of the sequence: hypothesis replays the shortest
    first_found: list[float] = []

    @hypothesis_seed(seed)
    @settings(max_examples=examples, deadline=None, database=None, derandomize=False,
              suppress_health_check=list(HealthCheck), phases=[Phase.generate, Phase.shrink])
    @given(drawn)
    def compare(sequence: list[Action]) -> None:
        key = repr(sequence)
        difference = differing.get(key)
        if difference is None:
            if first_found and shrink_s is not None and time.monotonic() - first_found[0] > shrink_s:
                return          # the shrinking time is spent: only the sequences already seen to differ fail
            difference = first_difference(make_a, make_b, profile, sequence)
        if difference is not None:
            first_found[:] = first_found or [time.monotonic()]
            differing[key] = difference
            found.append(difference)
            raise AssertionError(str(difference))       # one place: hypothesis tells failures apart by it

    try:
        compare()
    except AssertionError:
        return found[-1]                # the last failing example is the shrunk one
    return None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m outline.sequences.differential", description=__doc__.split("\n\n")[0])
    parser.add_argument("--profile", required=True)
    parser.add_argument("--sut", required=True, help="the SUT compared (reference, or package.module:Class)")
    parser.add_argument("--against", default="reference", help="the SUT it is compared with (default: reference)")
    parser.add_argument("--examples", type=int, default=30, help="random sequences tried (default 30)")
    parser.add_argument("--actions", type=int, default=8, help="stimuli per sequence at most (default 8)")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    difference = search(opener(args.against, args.profile), opener(args.sut, args.profile), args.profile,
                        examples=args.examples, max_actions=args.actions, seed=args.seed)
    if difference is None:
        print(f"no difference in {args.examples} sequences of up to {args.actions} stimuli (seed {args.seed})")
        return 0
    print(difference)
    return 1


if __name__ == "__main__":
    sys.exit(main())
