"""`--sut tcp://host:port[?timeout=S]`: a train served by another process (sut/PROTOCOL.md).

`remote_class(url)` says hello once to learn the protocol version and the profiles the server declares, and
returns a `TrainDriver` class carrying them; each `open()` is a new connection and a new train. Every call
waits at most the timeout; a refused, closed, silent or garbled peer raises `SutUnreachable` (the report's
"SUT not reachable" category), and the connection is dropped, so a scenario never passes or hangs on it.
Time and trace are read lazily, as a local step would read them: after a call the client asks for the time
(`state`) only when a step reads it, and fetches the new trace events only when a step reads the trace.
"""
from __future__ import annotations

import socket
import urllib.parse
from typing import Any

from sut import errors
from sut.driver import TrainDriver
from sut.errors import OutOfRange, RemoteError, SutError, SutUnreachable
from sut.remote import wire
from sut.trace import Trace, TraceEvent

DEFAULT_TIMEOUT_S = 60.0       # a 72 h bulk soak of the reference takes ~6 s; a rig may need more (?timeout=)
CONNECT_TIMEOUT_S = 5.0
# The driver interface's own errors are raised as themselves; anything else the server reports is a RemoteError.
_ERRORS = {name: cls for name, cls in vars(errors).items() if isinstance(cls, type) and issubclass(cls, SutError)}


def parse_url(url: str) -> tuple[str, int, float]:
    parts = urllib.parse.urlsplit(url)
    if parts.scheme != "tcp" or not parts.hostname or parts.port is None:
        raise OutOfRange("SUT address", url, "tcp://host:port[?timeout=seconds]")
    query = urllib.parse.parse_qs(parts.query)
    try:
        timeout = float(query.get("timeout", [DEFAULT_TIMEOUT_S])[0])
    except ValueError:
        raise OutOfRange("SUT call timeout", query["timeout"][0], "seconds > 0") from None
    if not timeout > 0:
        raise OutOfRange("SUT call timeout", timeout, "seconds > 0")
    return parts.hostname, parts.port, timeout


class Connection:
    """One TCP connection speaking the protocol: hello at connect, then request/answer with ids."""

    def __init__(self, url: str):
        self.url = url
        host, port, self.timeout = parse_url(url)
        try:
            self.sock = socket.create_connection((host, port), timeout=CONNECT_TIMEOUT_S)
        except OSError as exc:
            raise SutUnreachable(url, f"cannot connect ({exc})") from None
        self.sock.settimeout(self.timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.rfile = self.sock.makefile("rb")
        self.next_id = 0
        self.closed = False
        self.server = self._exchange({"hello": wire.PROTOCOL, "versions": list(wire.VERSIONS)}, "hello")
        if "error" in self.server:
            self.close()
            raise SutUnreachable(url, f"the server refused the connection: {self._error_text(self.server)}")
        if self.server.get("hello") != wire.PROTOCOL or self.server.get("version") not in wire.VERSIONS \
                or not isinstance(self.server.get("profiles"), list):
            self.close()
            raise SutUnreachable(url, f"not a {wire.PROTOCOL} server (hello answered {str(self.server)[:80]})")

    @staticmethod
    def _error_text(message: dict[str, Any]) -> str:
        error = message.get("error")
        if isinstance(error, dict):
            return f"{error.get('type')}: {error.get('message')}"
        return str(error)

    def _exchange(self, message: dict[str, Any], what: str) -> dict[str, Any]:
        if self.closed:
            raise SutUnreachable(self.url, f"{what}: the connection was closed after an earlier failure")
        try:
            self.sock.sendall(wire.dumps(message))
            answer = wire.read_message(self.rfile, wire.MAX_RESPONSE)
        except (socket.timeout, TimeoutError):
            self.close()
            raise SutUnreachable(self.url, f"no answer to {what} within {self.timeout:g} s") from None
        except wire.WireError as exc:
            self.close()
            raise SutUnreachable(self.url, f"{what}: garbled answer: {exc}") from None
        except OSError as exc:
            self.close()
            raise SutUnreachable(self.url, f"{what}: {exc}") from None
        if answer is None:
            self.close()
            raise SutUnreachable(self.url, f"the server closed the connection during {what}")
        return answer

    def request(self, op: str, what: str, **fields: Any) -> dict[str, Any]:
        self.next_id += 1
        answer = self._exchange({"id": self.next_id, "op": op, **fields}, what)
        if answer.get("id") != self.next_id:
            self.close()
            raise SutUnreachable(self.url, f"{what}: answer to request {answer.get('id')!r}, expected {self.next_id}")
        error = answer.get("error")
        if error is not None:
            kind = error.get("type") if isinstance(error, dict) else None
            text = error.get("message") if isinstance(error, dict) else str(error)
            if kind == "ProtocolError":
                self.close()
                raise SutUnreachable(self.url, f"{what}: the server rejected the request: {text}")
            cls = _ERRORS.get(kind, RemoteError)
            exc = cls.__new__(cls)
            Exception.__init__(exc, text if cls is not RemoteError else f"{kind}: {text}")
            raise exc
        return answer

    def close(self) -> None:
        if not self.closed:
            self.closed = True
            for thing in (self.rfile, self.sock):
                try:
                    thing.close()
                except OSError:
                    pass


class RemoteTrain(TrainDriver):
    """A train behind a `python -m sut serve` (or any server of the protocol). Made by `remote_class`."""

    backend_name = "remote"
    URL = ""
    SERVER: dict[str, Any] = {}

    @classmethod
    def open(cls, profile: str | None = None) -> "RemoteTrain":
        if profile is not None and profile not in cls.PROFILES:
            raise errors.UnknownName(f"profile served at {cls.URL}", profile, cls.PROFILES)
        return cls(profile)

    def __init__(self, profile: str | None = None):
        super().__init__()
        self._conn = Connection(self.URL)
        self._events: list[TraceEvent] = []
        self._trace = Trace(self._events)
        self._now_us = 0
        self._total = 0
        self._stale = True          # a call may have moved time or added events since the last `state`
        try:
            self._conn.request("open", "open", profile=profile)
        except BaseException:
            self._conn.close()      # nobody will shut down a driver that was never returned
            raise

    def _state(self) -> None:
        if self._stale:
            answer = self._conn.request("state", "state")
            now, total = answer.get("now_us"), answer.get("total")
            if not all(isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in (now, total)):
                self._conn.close()
                raise SutUnreachable(self.URL, f"state: not whole numbers: {str(answer)[:80]}")
            self._now_us, self._total, self._stale = now, total, False

    def _call(self, method: str, *args: Any, **kwargs: Any) -> Any:
        try:
            message = {"method": method, "args": wire.encode_value(list(args)), "kwargs": wire.encode_value(kwargs)}
        except wire.WireError as exc:
            raise OutOfRange(f"argument of {method}()", args, f"values the protocol carries ({exc})") from None
        self._stale = True
        answer = self._conn.request("call", f"{method}()", **message)
        try:
            return wire.decode_value(answer.get("result"))
        except wire.WireError as exc:
            self._conn.close()
            raise SutUnreachable(self.URL, f"{method}(): garbled result: {exc}") from None

    # -- life cycle and time ------------------------------------------------------------------
    def configure(self, **composition: Any) -> None:
        # Only what the step said: a backend may give an omitted argument a meaning of its own (the ATP
        # rig is fitted to a train only when cars_per_set is given).
        self._call("configure", **composition)

    def _power_on(self) -> None:
        self._call("power_on")

    def _shutdown(self) -> None:
        try:
            if not self._conn.closed:
                self._conn.request("close", "close")
        except SutError:
            pass
        finally:
            self._conn.close()

    @property
    def now_us(self) -> int:
        self._state()
        return self._now_us

    def _advance(self, us: int) -> None:
        self._call("advance", us)

    def _soak(self, us: int, sample_every_us: int | None) -> None:
        self._call("soak", us, sample_every_us=sample_every_us)

    @property
    def trace(self) -> Trace:
        self._state()
        while len(self._events) < self._total:
            answer = self._conn.request("trace", "trace", since=len(self._events), limit=wire.TRACE_CHUNK)
            events = answer.get("events")
            if not isinstance(events, list) or not events:
                self._conn.close()
                raise SutUnreachable(self.URL, f"trace: {self._total} events announced, "
                                               f"{len(self._events)} received")
            try:
                self._events.extend(TraceEvent(*wire.event_from_wire(e)) for e in events)
            except wire.WireError as exc:
                self._conn.close()
                raise SutUnreachable(self.URL, f"trace: {exc}") from None
        return self._trace

    def describe(self) -> dict[str, str]:
        described = self._call("describe")
        return {**(described if isinstance(described, dict) else {}),
                "SUT backend": f"{self.URL} ({self.SERVER.get('backend', '?')}, "
                               f"{wire.PROTOCOL}/{self.SERVER.get('version', '?')})"}


def _forward(name: str):
    def method(self: RemoteTrain, *args: Any, **kwargs: Any) -> Any:
        return self._call(name, *args, **kwargs)
    method.__name__ = method.__qualname__ = name
    method.__doc__ = getattr(TrainDriver, name).__doc__
    return method


# Every other method of the protocol is forwarded as is; these have bodies of their own above.
for _name in wire.METHODS - {"configure", "power_on", "advance", "soak", "describe"}:
    setattr(RemoteTrain, _name, _forward(_name))


def remote_class(url: str) -> type[RemoteTrain]:
    """The backend at `url`: says hello once and returns a class declaring the server's profiles."""
    conn = Connection(url)
    try:
        server = conn.server
    finally:
        try:
            conn.sock.sendall(wire.dumps({"id": 1, "op": "close"}))
        except OSError:
            pass
        conn.close()
    return type("RemoteTrain", (RemoteTrain,), {
        "URL": url, "SERVER": server, "PROFILES": tuple(str(p) for p in server["profiles"]),
        "DECLARATION": f"declaration served by {url}" if isinstance(server.get("declaration"), str) else None,
        "DECLARATION_TEXT": server.get("declaration") if isinstance(server.get("declaration"), str) else None,
        "__module__": __name__})
