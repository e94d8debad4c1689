"""Boards and the power supplies that feed them (CMD-01, RED-01: separate supplies matter)."""
from __future__ import annotations

from typing import Callable


class PowerSupply:
    """Its output is up while it is switched on (power_off/restore_power) and its input side, run by
    environment.py (voltage, interruptions, temperature, withstand tests), lets it be up."""

    def __init__(self, name: str):
        self.name = name
        self.switched = True
        self.input_ok = True
        self.listeners: list[Callable[[], None]] = []

    @property
    def on(self) -> bool:
        return self.switched and self.input_ok

    def set(self, on: bool) -> None:
        self._change(lambda: setattr(self, "switched", on))

    def set_input_ok(self, ok: bool) -> None:
        self._change(lambda: setattr(self, "input_ok", ok))

    def _change(self, apply: Callable[[], None]) -> None:
        was = self.on
        apply()
        if self.on != was:
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
