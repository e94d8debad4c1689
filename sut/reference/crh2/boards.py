"""Boards and the power supplies that feed them (CMD-01, RED-01: separate supplies matter)."""
from __future__ import annotations

from typing import Callable


class PowerSupply:
    """Its output is up while it is switched on (power_off/restore_power) and its input side, run by
    environment.py (voltage, interruptions, temperature, withstand tests), lets it be up."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, name: str):
        self.name = name
        self.switched = True
        self.input_ok = True
        self.on = True            # switched and input_ok, kept rather than computed: read on every frame
        self.boards: list[Board] = []

    def set(self, on: bool) -> None:
        self.switched = on
        self._update()

    def set_input_ok(self, ok: bool) -> None:
        self.input_ok = ok
        self._update()

    def _update(self) -> None:
        was, self.on = self.on, self.switched and self.input_ok
        if self.on != was:
            # every board it feeds is up to date before any of them tells anyone
            for board in self.boards:
                board.alive = not board.failed and self.on
            for board in self.boards:
                board.notify()


class Board:
    """A plug-in board: alive while it is not failed and its supply is on."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    def __init__(self, name: str, supply: PowerSupply):
        self.name = name
        self.supply = supply
        self.failed = False
        self.alive = supply.on    # not failed and supply on, kept rather than computed (ring hot path)
        self.listeners: list[Callable[[], None]] = []
        supply.boards.append(self)

    def set_failed(self, failed: bool) -> None:
        if failed != self.failed:
            self.failed = failed
            self.alive = not failed and self.supply.on
            self.notify()

    def notify(self) -> None:
        for notify in list(self.listeners):
            notify()
