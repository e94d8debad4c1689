"""Random stimulus sequences as a judge of their own (issue 31: model-based testing). A scenario names an
invariant the requirements state (outline/sequences/invariants.py); hypothesis drives fresh SUTs of the
scenario's profile with sequences of this library's own `When` sentences and checks the invariant after every
stimulus. A sequence that breaks it is shrunk and printed as a scenario to paste into a feature file.

The budget is the feature's (sequences per invariant, seed); `--sequences N` replaces the count for a longer
hunt (make campaign)."""
from __future__ import annotations

import allure
import pytest
from pytest_bdd import given, parsers, then

from outline.sequences.invariants import INVARIANTS, Invariant
from outline.sequences.judge import search
from sut.contract import load as load_contract
from sut.contract.guard import ContractDriver
from sut.driver import TrainDriver
from steps.fixtures import _RECORDER, _declared, _profile_for, open_driver


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.getgroup("outline").addoption(
        "--sequences", type=int, default=None, metavar="N",
        help="random sequences per invariant in the random-sequence scenarios (default: each feature's own)")


@given(parsers.parse("步骤库的随机激励序列，每个不变量{examples:d}条，种子{seed:d}"), target_fixture="sequence_budget")
@given(parsers.parse("random sequences of the step library's stimuli, {examples:d} per invariant from seed {seed:d}"),
       target_fixture="sequence_budget")
def _(request: pytest.FixtureRequest, examples: int, seed: int) -> tuple[int, int]:
    return request.config.getoption("--sequences") or examples, seed


def _invariant(profile: str, name: str) -> Invariant:
    known = [i for i in INVARIANTS if i.profile == profile]
    found = [i for i in known if i.name == name]
    if not found:
        raise LookupError(f"no invariant {name!r} of the {profile} profile (outline/sequences/invariants.py); "
                          f"known: {[i.name for i in known]}")
    return found[0]


@then(parsers.parse("每条序列的每次激励之后，{name}"))   # the invariant's name is its identifier, as written
@then(parsers.parse("after every stimulus of every sequence, {name}"))
def _(sut_class: type[TrainDriver], request: pytest.FixtureRequest, sequence_budget: tuple[int, int],
      name: str) -> None:
    profile = _profile_for(request.node, sut_class) or ""
    invariant = _invariant(profile, name)
    contract, recorder = load_contract(profile), request.config.stash.get(_RECORDER, None)
    examples, seed = sequence_budget
    # The SUT's declaration, where it has one: the texts and parameters an invariant reads (None otherwise).
    _, declaration = _declared(request.node, sut_class, request.config)
    violation = search(lambda: open_driver(sut_class, profile, request.config), invariant, examples=examples, seed=seed,
                       guard=lambda driver: ContractDriver(driver, profile, contract, recorder),
                       declaration=declaration)
    if violation is not None:
        allure.attach(violation.gherkin(), name="the shortest sequence found, as a scenario",
                      attachment_type=allure.attachment_type.TEXT)
    assert violation is None, (f"{invariant} broken by a random sequence ({examples} tried, seed {seed}); "
                               f"shrunk, as a scenario to paste into a feature file:\n{violation}")
