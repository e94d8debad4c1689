"""The one test module of the conformance run: binds every .feature file below this folder.

A new feature file needs no Python: it is found here, its scenarios become tests named after their titles,
and its tags become marks (outline.plugin.pytest_plugin). Malformed files fail collection with file:line.
"""

from pathlib import Path

from pytest_bdd import scenarios

from outline.plugin.binding import feature_paths

_HERE = Path(__file__).parent
_FEATURES = feature_paths(_HERE)

if _FEATURES:  # scenarios() raises when given nothing; an empty tree should just collect no tests (exit 5)
    scenarios(*_FEATURES, features_base_dir=str(_HERE))
