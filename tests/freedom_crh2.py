"""Freedom variants of the crh2 reference (issue 30, item 4); the rules they follow are beside
tests/variants.py FREEDOM_CLASSES."""
from __future__ import annotations

MS = 1000

FREEDOM: list[type] = []
