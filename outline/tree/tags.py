"""Tag vocabulary shared by the pytest plugin, the feature binder and `outline check`."""

from __future__ import annotations

# `@kind:value` tags, each turned into one registered marker of the same name.
KINDS = ("item", "req", "profile", "option")
# Bare tags the project defines; each is a registered marker.
PLAIN = ("tentative", "informative", "pending", "on_request")


class TagError(ValueError):
    pass


def classify(tag: str) -> tuple[str | None, str]:
    """`"req:NET-03"` -> `("req", "NET-03")`; `"tentative"` -> `(None, "tentative")`.

    Raises TagError for a `kind:value` tag of unknown kind or without a value, because a typo such as
    `@reqs:NET-03` would otherwise silently drop the requirement from every report.
    """
    tag = tag.lstrip("@")
    kind, sep, value = tag.partition(":")
    if not sep:
        return None, tag
    if kind not in KINDS:
        known = ", ".join(f"@{k}:" for k in KINDS)
        raise TagError(f"unknown tag kind @{tag} (known kinds: {known})")
    if not value:
        raise TagError(f"tag @{tag} has no value")
    return kind, value
