"""Step definitions for the `good` fixture tree (a stand-in for steps/*.py)."""

from pytest_bdd import given, parsers, then, when


@given(parsers.parse("a train of {cars:d} cars"), target_fixture="train")
def _(cars):
    return {"cars": cars, "notch": 0, "interval": 10}


@when(parsers.parse("the driver sets traction notch {notch:d}"))
def _(train, notch):
    train["notch"] = notch


@when(parsers.parse("the link between car {a:d} and car {b:d} is cut"))
def _(train, a, b):
    train.setdefault("cuts", []).append((a, b))


@when(parsers.parse("a frame with a bad checksum arrives at car {car:d}"))
def _(train, car):
    raise NotImplementedError


@then(parsers.parse("every car receives traction notch {notch:d}"))
def _(train, notch):
    assert train["notch"] == notch


@then(parsers.parse("the command interval is {ms:d} ms"))
def _(train, ms):
    assert train["interval"] == ms


@then(parsers.parse("car {car:d} discards it"))
def _(train, car):
    raise NotImplementedError
