"""A backend served on TCP: one connection = one train, opened by the client's `open` (sut/PROTOCOL.md).

Only the driver interface's methods (`wire.METHODS`) can be called; a connection that sends garbage gets one
error message naming what was wrong and is closed. Each connection has its own train in its own process
(forked; a thread where there is no fork, or for a server inside a test process), so a parallel pytest run
uses every core, and a train that crashes takes no other connection with it.
"""
from __future__ import annotations

import os
import socketserver
import sys
import threading
import traceback
from typing import Any

from sut.contract.declaration import ROOT
from sut.backends import resolve
from sut.driver import TrainDriver
from sut.errors import SutError, UnknownName
from sut.remote import wire

class ProtocolViolation(Exception):
    """A request that is well-formed JSON but not a valid request; answered, then the connection closes."""


class Session:
    """One connection's train and how much of its trace the client has seen."""

    def __init__(self, backend: type[TrainDriver], served: tuple[str, ...]):
        self.backend, self.served = backend, served
        self.driver: TrainDriver | None = None

    def handle(self, request: dict[str, Any]) -> dict[str, Any]:
        op = request.get("op")
        if op not in ("open", "call", "state", "trace", "close"):
            raise ProtocolViolation(f"unknown op {op!r}; known: open, call, state, trace, close")
        if op == "open":
            return self._open(request.get("profile"))
        if op == "close":
            self.close()
            return {"result": None}
        if self.driver is None:
            raise ProtocolViolation(f"op {op!r} before open")
        if op == "call":
            return self._call(request)
        if op == "state":
            # Asked for, never volunteered: reading the time can itself build a train (the reference builds
            # its composition on first use), so the server reads it exactly when a local step would.
            return {"now_us": self.driver.now_us, "total": len(self.driver.trace)}
        return self._trace(request)

    def _open(self, profile: Any) -> dict[str, Any]:
        if self.driver is not None:
            raise ProtocolViolation("open twice on one connection (one connection is one train)")
        if profile is not None and (not isinstance(profile, str) or profile not in self.served):
            raise UnknownName("profile served here", str(profile), self.served)
        self.driver = self.backend.open(profile or self.served[0])
        return {"result": None}

    def _call(self, request: dict[str, Any]) -> dict[str, Any]:
        method, args, kwargs = request.get("method"), request.get("args", []), request.get("kwargs", {})
        if method not in wire.METHODS:
            raise ProtocolViolation(f"method {method!r} is not part of the driver interface")
        if not isinstance(args, list) or not isinstance(kwargs, dict):
            raise ProtocolViolation("args must be an array and kwargs an object")
        result = getattr(self.driver, method)(*wire.decode_value(args), **wire.decode_value(kwargs))
        return {"result": wire.encode_value(result)}

    def _trace(self, request: dict[str, Any]) -> dict[str, Any]:
        since, limit = request.get("since", 0), request.get("limit", wire.TRACE_CHUNK)
        if not all(isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in (since, limit)):
            raise ProtocolViolation("since and limit must be whole numbers >= 0")
        trace = self.driver.trace
        chunk = trace[since:since + min(limit, wire.TRACE_CHUNK)]
        return {"events": [wire.event_to_wire(e.t, e.source, e.kind, e.fields) for e in chunk],
                "total": len(trace)}

    def close(self) -> None:
        if self.driver is not None:
            self.driver.shutdown()


def _error(exc: BaseException) -> dict[str, Any]:
    if isinstance(exc, SutError):
        return {"type": type(exc).__name__, "message": str(exc)}
    if isinstance(exc, (wire.WireError, ProtocolViolation)):
        return {"type": "ProtocolError", "message": str(exc)}
    # A bug in the served backend: say where, keep serving other connections.
    where = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
    at = f" at {where.filename}:{where.lineno}" if where else ""
    return {"type": "RemoteError", "message": f"{type(exc).__name__}: {exc}{at}"}


class _Handler(socketserver.StreamRequestHandler):
    server: "SutServer"
    # A client silent this long between requests is gone (a killed pytest): free its train and process.
    timeout = 600

    def handle(self) -> None:
        session = Session(self.server.backend, self.server.served)
        try:
            if not self._hello():
                return
            while True:
                try:
                    request = wire.read_message(self.rfile, wire.MAX_REQUEST)
                except wire.WireError as exc:
                    self._send({"id": None, "error": _error(exc)})
                    return
                if request is None:
                    return
                answer = self._answer(session, request)
                self._send(answer)
                if "error" in answer and answer["error"]["type"] == "ProtocolError" or request.get("op") == "close":
                    return
        except (ConnectionError, OSError):
            return
        finally:
            session.close()

    def _hello(self) -> bool:
        try:
            hello = wire.read_message(self.rfile, wire.MAX_REQUEST)
        except wire.WireError as exc:
            self._send({"error": _error(exc)})
            return False
        if hello is None:
            return False
        versions = hello.get("versions")
        if hello.get("hello") != wire.PROTOCOL or not isinstance(versions, list):
            self._send({"error": {"type": "ProtocolError",
                                  "message": f'the first line must be {{"hello": "{wire.PROTOCOL}", "versions": [...]}}'}})
            return False
        common = [v for v in wire.VERSIONS if v in versions]
        if not common:
            self._send({"error": {"type": "VersionMismatch",
                                  "message": f"client speaks versions {versions}, this server {list(wire.VERSIONS)}"}})
            return False
        hello = {"hello": wire.PROTOCOL, "version": max(common), "backend": self.server.backend_spec,
                 "profiles": list(self.server.served), "trace_chunk": wire.TRACE_CHUNK}
        if self.server.declaration is not None:
            hello["declaration"] = self.server.declaration
        self._send(hello)
        return True

    @staticmethod
    def _answer(session: Session, request: dict[str, Any]) -> dict[str, Any]:
        ident = request.get("id")
        try:
            if isinstance(ident, bool) or not isinstance(ident, int):
                raise ProtocolViolation("every request has an integer id")
            return {"id": ident, **session.handle(request)}
        except Exception as exc:   # noqa: BLE001  every failure becomes an answer; the server stays up
            if not isinstance(exc, (SutError, wire.WireError, ProtocolViolation)):
                traceback.print_exc(file=sys.stderr)
            return {"id": ident if isinstance(ident, int) else None, "error": _error(exc)}

    def _send(self, message: dict[str, Any]) -> None:
        try:
            line = wire.dumps(message)
        except wire.WireError as exc:
            line = wire.dumps({"id": message.get("id"), "error": {"type": "RemoteError", "message": str(exc)}})
        self.wfile.write(line)
        self.wfile.flush()


class SutServer(socketserver.TCPServer):
    allow_reuse_address = True

    def __init__(self, address: tuple[str, int], backend_spec: str, profiles: list[str] | None = None):
        self.backend_spec = backend_spec
        self.backend = resolve(backend_spec)
        # The backend's implementation declaration travels in the hello (PROTOCOL.md), as the text of its file.
        path = getattr(self.backend, "DECLARATION", None)
        self.declaration = (ROOT / path).read_text(encoding="utf-8") if path else None
        declared = tuple(self.backend.PROFILES)
        if profiles:
            unknown = [p for p in profiles if p not in declared]
            if unknown:
                raise UnknownName(f"profile of {backend_spec}", unknown[0], declared)
        self.served = tuple(profiles) if profiles else declared
        super().__init__(address, _Handler)

    @property
    def url(self) -> str:
        host, port = self.server_address[:2]
        return f"tcp://{host}:{port}"


class ForkingSutServer(socketserver.ForkingMixIn, SutServer):
    pass


class ThreadingSutServer(socketserver.ThreadingMixIn, SutServer):
    daemon_threads = True


def make_server(backend_spec: str = "reference", profiles: list[str] | None = None, host: str = "127.0.0.1",
                port: int = 0, *, fork: bool = hasattr(os, "fork")) -> SutServer:
    cls = ForkingSutServer if fork else ThreadingSutServer
    return cls((host, port), backend_spec, profiles)


def start(backend_spec: str = "reference", profiles: list[str] | None = None, host: str = "127.0.0.1",
          port: int = 0) -> tuple[SutServer, threading.Thread]:
    """A server on a background thread (for tests and benchmarks in one process); `server.shutdown()` stops it.
    Connections are threads: forking a process that runs threads is not safe."""
    server = make_server(backend_spec, profiles, host, port, fork=False)
    thread = threading.Thread(target=server.serve_forever, name="sut-server", daemon=True)
    thread.start()
    return server, thread
