"""What the parts of a CRH2 train may ask of the train that assembled them (train.py implements it).

The parts (ring and nodes, CCUs, LCUs, devices, vehicle, display, environment, self-diagnostic line) are
handed the train as this interface, not as `Train`: they import this module and never train.py, so the
imports run one way (train.py assembles the parts; a part knows only the services listed here, and the
other parts only through them). The services are the few things that are the train's as a whole: its clock,
configuration and trace, and the coordination no single part owns (which CCU commands, block data at the
master, equipment orders, status data that falls back to the self-diagnostic line).
"""
from __future__ import annotations

from typing import Any, Protocol

from sut.reference.crh2.config import TrainConfig
from sut.reference.kernel import Kernel
from sut.trace import TraceEvent


class TrainContext(Protocol):
    cfg: TrainConfig
    kernel: Kernel
    events: list[TraceEvent]
    # The assembled parts, for a part that works across the train (typed loosely: their modules import this).
    ring: Any
    vehicle: Any
    display: Any
    selfdiag: Any
    supplies: dict[str, Any]
    lcus: list[Any]

    def emit(self, source: str, kind: str, /, **fields: Any) -> None: ...

    def emit_free(self, source: str, kind: str, /, **fields: Any) -> None:
        """An event of a free-running emitter (Kernel.metronome), marked as such for bulk advance."""

    def node_by_number(self, number: int) -> Any: ...

    def span_changed(self, span: Any) -> None: ...

    # -- which cab commands (CMD-05, ILK-07) --------------------------------------------------------
    def commanding_ccu(self) -> Any: ...

    def commanding_source_ok(self, fields: dict) -> bool: ...

    # -- PRO-06 block data, kept at the master ------------------------------------------------------
    def block_master(self) -> Any: ...

    def block_grant_for(self, node: Any) -> int: ...

    def block_master_saw_status(self, node: Any, fields: dict, src: int) -> None: ...

    def block_received(self, node: Any, fields: dict, src: int) -> None: ...

    # -- equipment orders from the cab monitor (docs/decisions.md, "Display") ----------------------------
    def orders_for(self, node: Any) -> list[dict[str, int]]: ...

    def orders_received(self, node: Any, fields: dict) -> None: ...

    # -- NET-04: status data and the self-diagnostic line -------------------------------------------
    def selfdiag_status_leak(self, node: Any, frame: Any) -> None: ...

    def selfdiag_status_delivered(self, fields: dict) -> None: ...
