"""Step definitions for the `bad` fixture tree: one sentence is defined twice, one only as a When."""

from pytest_bdd import given, parsers, then, when


@given(parsers.parse("a train of {cars:d} cars"))
def _(cars):
    pass


@when("the driver does something")
def _():
    pass


@then(parsers.parse("the notch is {notch:d}"))
def _(notch):
    pass


@then("the notch is 3")
def _():
    pass
