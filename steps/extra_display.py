"""Step sentences added for the extra_display features (see steps/__init__.py)."""
from __future__ import annotations
