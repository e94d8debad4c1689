"""Backends by name, imported lazily (python-can's `BACKENDS` dict).

`open_backend("reference")` gives the embedded simulation. Any `package.module:Class` naming a
`TrainDriver` subclass works too, so another implementation (a rig adapter, a vendor model, a faulty
variant in tests/) is chosen the same way: `pytest --sut package.module:Class`. A `tcp://host:port` address
names a train served by another process (`python -m sut serve`, sut/PROTOCOL.md).
"""
from __future__ import annotations

import importlib
import os

from sut.driver import TrainDriver
from sut.errors import SutError, UnknownName

BACKENDS: dict[str, tuple[str, str]] = {
    "reference": ("sut.reference.profiles", "Reference"),
}

ENV_VAR = "CRH2_SUT"


def resolve(spec: str | None) -> type[TrainDriver]:
    spec = spec or os.environ.get(ENV_VAR) or "reference"
    if spec.startswith("tcp://"):
        from sut.remote.client import remote_class    # the server's hello says which profiles it has

        return remote_class(spec)
    if spec in BACKENDS:
        module_name, class_name = BACKENDS[spec]
    elif ":" in spec:
        module_name, class_name = spec.split(":", 1)
    else:
        raise UnknownName("SUT backend", spec, [*BACKENDS, "<package.module:Class>", "<tcp://host:port>"])
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise SutError(f"SUT backend {spec!r}: cannot import {module_name}: {exc}") from None
    cls = getattr(module, class_name, None)
    if not (isinstance(cls, type) and issubclass(cls, TrainDriver)):
        raise SutError(f"SUT backend {spec!r}: {module_name}.{class_name} is not a TrainDriver subclass")
    return cls


def open_backend(spec: str | None = None, profile: str | None = None) -> TrainDriver:
    return resolve(spec).open(profile)
