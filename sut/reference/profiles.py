"""`reference`: the embedded reference trains, one backend name for every profile they implement.

Like python-can's `Bus(interface=...)`, opening the backend gives the class of the train asked for:
`crh2` (sut/reference/crh2/backend.py), `metro-tcn` (sut/reference/metro/backend.py), or `atp`, `vdx` and
`atp-crh2` (sut/reference/atp/backend.py: the 200C ATP rig, the 300T VDX rig, the ATP fitted to a CRH2 set).
"""
from __future__ import annotations

from sut.driver import TrainDriver
from sut.errors import UnknownName
from sut.reference.crh2.backend import ReferenceTrain
from sut.reference.atp.backend import ReferenceAtp
from sut.reference.metro.backend import ReferenceMetro

TRAINS: dict[str, type[TrainDriver]] = {"crh2": ReferenceTrain, "metro-tcn": ReferenceMetro, "atp": ReferenceAtp,
                                        "vdx": ReferenceAtp, "atp-crh2": ReferenceAtp}


class Reference(TrainDriver):
    """Never a train itself: `open(profile)` returns the reference train of that profile."""

    backend_name = "reference"
    PROFILES = tuple(TRAINS)
    DETERMINISTIC = True           # virtual time, no randomness, nothing outside the model
    DECLARATION = "sut/reference/declaration.yaml"

    @classmethod
    def open(cls, profile: str | None = None) -> TrainDriver:
        profile = profile or cls.PROFILES[0]
        if profile not in TRAINS:
            raise UnknownName("profile of the reference", profile, TRAINS)
        # The train's own open, as a user naming its class gets: the ATP rig notes which of its three
        # profiles it runs (seed 25 found its open never called through the backend name).
        return TRAINS[profile].open(profile)
