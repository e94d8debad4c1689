"""Messages of the wire protocol (sut/PROTOCOL.md): one JSON object per line, UTF-8, both ways.

Values are plain JSON; the driver interface's `bytes` travel as `{"$bytes": "<hex>"}` and tuples as arrays.
Every decoding error is a `WireError` naming what was wrong, so a bad peer is reported, never crashed on.
"""
from __future__ import annotations

import json
from typing import Any, BinaryIO

PROTOCOL = "crh2-sut"
VERSIONS = (1,)
MAX_REQUEST = 1 << 20          # a request line (server side); trace chunks keep responses well under:
MAX_RESPONSE = 64 << 20
TRACE_CHUNK = 20_000           # events per `trace` response

# The `call` methods: the driver interface, less the conveniences a client computes from these (advance_ms,
# cut_ring) and the life cycle and observations carried by ops of their own (open, state, trace, close).
METHODS = frozenset({
    "configure", "power_on", "advance", "soak", "counters",
    "insert_key", "remove_key", "set_direction", "set_traction", "set_brake",
    "cut_link", "restore_link", "corrupt_frames", "fail", "repair", "power_off", "restore_power",
    "set_input", "ramp_input", "input", "output", "reading", "monitor_order", "vehicle_names",
    "rated_limits", "set_supply_voltage", "interrupt_supply", "set_temperature", "interfere", "vibrate",
    "withstand_test", "insulation_resistance",
    "cut_line", "restore_line", "disturb_line", "tap_bus", "records", "pass_balise",
    "request_block_transfer", "tap_link",
    "ring_nodes", "boards", "devices", "supplies", "token_holder", "monitor", "watch_monitor", "status_table", "lamp",
    "block_store", "describe",
})


class WireError(ValueError):
    """A line that is not a message of the protocol (bad JSON, not an object, too long, truncated)."""


def encode_value(value: Any) -> Any:
    if isinstance(value, (bytes, bytearray)):
        return {"$bytes": bytes(value).hex()}
    if isinstance(value, (list, tuple)):
        return [encode_value(v) for v in value]
    if isinstance(value, dict):
        out = {}
        for key, v in value.items():
            if not isinstance(key, str):
                raise WireError(f"a mapping key must be a string, not {type(key).__name__} {key!r}")
            out[key] = encode_value(v)
        return out
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    raise WireError(f"{type(value).__name__} {value!r} has no JSON form in the protocol")


def decode_value(value: Any) -> Any:
    if isinstance(value, list):
        return [decode_value(v) for v in value]
    if isinstance(value, dict):
        if set(value) == {"$bytes"}:
            text = value["$bytes"]
            try:
                return bytes.fromhex(text)
            except (TypeError, ValueError):
                raise WireError(f"$bytes is not an even number of hex digits: {str(text)[:40]!r}") from None
        return {key: decode_value(v) for key, v in value.items()}
    return value


def dumps(message: dict[str, Any]) -> bytes:
    """One line: compact JSON, no NaN/Infinity (not JSON), newline-terminated."""
    try:
        text = json.dumps(message, separators=(",", ":"), ensure_ascii=False, allow_nan=False)
    except ValueError as exc:
        raise WireError(f"cannot encode message: {exc}") from None
    return text.encode("utf-8") + b"\n"


def loads(line: bytes) -> dict[str, Any]:
    """The message on one line (with or without its newline)."""
    try:
        message = json.loads(line.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise WireError(f"not UTF-8 at byte {exc.start}: {line[:60]!r}") from None
    except json.JSONDecodeError as exc:
        raise WireError(f"not JSON ({exc.msg} at column {exc.colno}): {line[:60]!r}") from None
    except RecursionError:
        raise WireError("JSON nested too deeply") from None
    except ValueError as exc:           # an integer past Python's str-to-int digit limit (4300 by default)
        raise WireError(f"not JSON the protocol can carry ({exc}): {line[:60]!r}") from None
    if not isinstance(message, dict):
        raise WireError(f"a message is a JSON object, not {type(message).__name__}: {line[:60]!r}")
    return message


def read_message(stream: BinaryIO, limit: int) -> dict[str, Any] | None:
    """The next message, or None at a clean end of stream (the peer closed between messages)."""
    line = stream.readline(limit + 1)
    if not line:
        return None
    if not line.endswith(b"\n"):
        if len(line) > limit:
            raise WireError(f"line longer than {limit} bytes")
        raise WireError(f"truncated message ({len(line)} bytes, no end of line): {line[:60]!r}")
    return loads(line)


def event_to_wire(t: int, source: str, kind: str, fields: Any) -> list[Any]:
    return [t, source, kind, encode_value(dict(fields))]


def event_from_wire(item: Any) -> tuple[int, str, str, dict[str, Any]]:
    if not (isinstance(item, list) and len(item) == 4):
        raise WireError(f"a trace event is [t, source, kind, fields], not {str(item)[:60]}")
    t, source, kind, fields = item
    if isinstance(t, bool) or not isinstance(t, int) or t < 0 or not isinstance(source, str) \
            or not isinstance(kind, str) or not isinstance(fields, dict):
        raise WireError(f"a trace event is [int us >= 0, str, str, object], not {str(item)[:60]}")
    return t, source, kind, decode_value(fields)
