"""Boards and the power supplies that feed them (CMD-01, RED-01: separate supplies matter)."""
from __future__ import annotations

from typing import Callable


class PowerSupply:
    def __init__(self, name: str):
        self.name = name
        self.on = True
        self.listeners: list[Callable[[], None]] = []

    def set(self, on: bool) -> None:
        if on != self.on:
            self.on = on
            for notify in list(self.listeners):
                notify()


class Board:
    """A plug-in board: alive while it is not failed and its supply is on."""

    def __init__(self, name: str, supply: PowerSupply):
        self.name = name
        self.supply = supply
        self.failed = False
        self.listeners: list[Callable[[], None]] = []
        supply.listeners.append(self._changed)

    @property
    def alive(self) -> bool:
        return not self.failed and self.supply.on

    def set_failed(self, failed: bool) -> None:
        if failed != self.failed:
            self.failed = failed
            self._changed()

    def _changed(self) -> None:
        for notify in list(self.listeners):
            notify()
