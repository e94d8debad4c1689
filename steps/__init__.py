"""The step library: domain sentences -> TrainDriver calls.

Every module listed here is loaded as a pytest plugin by the root conftest, so its step
definitions and fixtures are visible to every feature file.
"""

STEP_MODULES = [
    "steps.fixtures",
    "steps.train",
    "steps.desk",
    "steps.faults",
    "steps.commands",
    "steps.network",
    "steps.vehicle",
    "steps.monitor",
    "steps.extra_control",
    "steps.extra_display",
    "steps.extra_records",
    "steps.environment",
    "steps.longrun",
    "steps.metro",
    "steps.vdx",
    "steps.atp",
    "steps.sequences",
]
