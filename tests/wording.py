"""Texts of a variant in its own words: each message of `table` (identifier -> the variant's words, with the same
<name> placeholders) found in a text is replaced, the names it holds kept. Shared by the freedom variants that
word their displays and records otherwise (tests/variants.py, tests/freedom_metro.py)."""
from __future__ import annotations

import re


def reword(text: str, table: dict[str, str]) -> str:
    for identifier, words in table.items():
        parts = re.split(r"(<\w+>)", identifier)
        rx = "".join(f"(?P<{p[1:-1]}>[A-Za-z0-9_.]+)" if p.startswith("<") else re.escape(p) for p in parts)
        text = re.sub(rx, lambda m, w=words: re.sub(r"<(\w+)>", lambda n: m.group(n.group(1)), w), text)
    return text
