"""The CRH2 payloads on the ring, above the ARCNET frames of sut/codecs/arcnet.py (re-exported here)."""
from __future__ import annotations

import functools

from dataclasses import dataclass
from typing import Any

from construct import (Byte, Bytes, Const, Construct, ConstructError, Int16ub, Int32sb, Int32ub, Padded, Padding,
                       PrefixedArray, Struct)

from sut.codecs.arcnet import (ALERT_BITS, ARC_TABLE, BITS_PER_BYTE, BROADCAST, EOT, ITT,  # noqa: F401
                               MAX_DATA, PAC_LONG, PAC_SHORT, SOH, FrameError, crc16_arc, crc16_x25,
                               declared_length, decode_pac, encode_itt, encode_pac)


def check_ok(wire: bytes) -> bool:
    """The node's frame check: layout and CRC (what NET-05 discards on)."""
    if not wire:
        return False
    if wire[0] == EOT:
        return len(wire) == 3 and wire[1] == wire[2]
    # The same checks as decode_pac, without building the parsed view: every node runs this on every frame.
    if len(wire) < 8 or wire[0] != SOH or wire[2] != wire[3]:
        return False
    if wire[4] in (1, 2) or wire[4] == 0 and wire[5] < 4:     # 254/255 or 509..512 data bytes (ATA 878.1)
        return False
    return len(wire) == declared_length(wire)[1] and crc16_arc(wire[1:-2]) == int.from_bytes(wire[-2:], "little")


def payload_unchecked(wire: bytes) -> dict[str, Any]:
    """What a receiver without a frame check would read from a packet (faulty variants only): the payload
    where the length byte says it is, CRC ignored. FrameError if even that cannot be read."""
    if len(wire) < 8 or wire[0] != SOH:
        raise FrameError(f"not an ARCNET packet: {len(wire)} bytes")
    offset, _ = declared_length(wire)
    return decode_payload(wire[offset:-2])


# -- CRH2 payloads --------------------------------------------------------------------------------
K_COMMAND, K_STATUS, K_TOKEN_INIT, K_TOKEN_SEND, K_BLOCK = 0x11, 0x22, 0x31, 0x32, 0x41

COMMAND = Struct(                     # PRO-01: 12 bytes
    "kind" / Const(K_COMMAND, Byte),
    "seq" / Byte,
    "cab" / Byte,                     # car number of the commanding cab
    "system" / Byte,                  # CCU system (1 or 2) that put it on the ring
    "direction" / Byte,               # 0 neutral, 1 forward, 2 reverse
    "traction" / Byte,                # notch 0..10
    "brake" / Byte,                   # step 0..7, 8 = emergency
    Padding(1),                       # reserved: master control is decided in the cab (docs/decisions.md)
    "clock_ms" / Int32ub,             # clock correction: ms since power-up
)
assert COMMAND.sizeof() == 12

STATUS_SIZE = 240
POINT = Struct("id" / Int16ub, "value" / Int32sb)   # a display point or an equipment order (display.py)
STATUS = Padded(STATUS_SIZE, Struct(  # PRO-02: 240 bytes
    "kind" / Const(K_STATUS, Byte),
    "node" / Byte,
    "car" / Byte,
    "unit" / Byte,                    # 1 CCU system, 2 LCU
    "health" / Byte,                  # bit per board, set = healthy (see HEALTH_BITS)
    "ports" / Byte,                   # bit0 left link up, bit1 right link up
    "block_request" / Byte,           # blocks waiting to be sent, 0 = no request
    "grant" / Byte,                   # master only: node number granted a block transfer, 0 = none
    "seq" / Int16ub,
    "points" / PrefixedArray(Byte, POINT),   # this node's display points for the cab monitor
    "orders" / PrefixedArray(Byte, POINT),   # commanding CCU only: equipment orders from the monitor
))
assert STATUS.sizeof() == STATUS_SIZE
HEALTH_BITS = ("CPU3", "MDM8", "MDM9", "RXC", "TXC")

TOKEN_CTL = Struct("kind" / Byte, "node" / Byte)

BLOCK_SIZE = 236
BLOCK = Struct(                       # PRO-06: 236-byte blocks
    "kind" / Const(K_BLOCK, Byte),
    "owner" / Byte,
    "record" / Int16ub,               # which record of the owner's data area (docs/decisions.md, "Block data")
    "index" / Int16ub,
    "total" / Int16ub,
    "data" / Bytes(BLOCK_SIZE),
)

LAYOUTS = {K_COMMAND: COMMAND, K_STATUS: STATUS, K_TOKEN_INIT: TOKEN_CTL, K_TOKEN_SEND: TOKEN_CTL,
           K_BLOCK: BLOCK}


def _compiled(layout: Construct) -> Construct:
    # construct compiles a layout to Python source: the same bytes 3-5x faster (STATUS build 208 -> 48 us;
    # every node builds a status every cycle). Padded does not compile: its inside does. Only for building:
    # a compiled parser meets bad input with struct.error, the declared one with a ConstructError.
    if isinstance(layout, Padded):
        return Padded(layout.length, layout.subcon.compile())
    return layout.compile()


# The declared layouts above are the specification and parse; these build (tests/test_frames.py: they agree).
_BUILDERS = {kind: _compiled(layout) for kind, layout in LAYOUTS.items()}
KIND_NAMES = {K_COMMAND: "command", K_STATUS: "status", K_TOKEN_INIT: "token-init",
              K_TOKEN_SEND: "token-send", K_BLOCK: "block", EOT: "token"}

# Priorities (NET-06): 0 is the token itself, which carries no data.
P_TOKEN, P_COMMAND, P_STATUS, P_BLOCK = 0, 1, 2, 3

# Counters travel in the frames' `fields` as the sender keeps them (unbounded, so a count over 72 h is
# exact and a bulk advance can extrapolate it); the wire carries them modulo the field width.
_WIRE_MASKS = {K_COMMAND: {"seq": 0xFF, "clock_ms": 0xFFFF_FFFF}, K_STATUS: {"seq": 0xFFFF},
               K_BLOCK: {"record": 0xFFFF}}


@dataclass(eq=False, slots=True)
class Frame:
    """One frame on the ring: the wire bytes plus the decoded view the sender built them from."""
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)

    kind: int
    src: int
    dst: int
    prio: int
    wire: bytes
    fields: dict[str, Any]
    uid: int = 0                      # one transmission; the ring numbers it when it is first sent
    # The frame check's verdict, once known. A frame the sender encoded passes by construction (encode_pac
    # writes a valid layout and its CRC: tests/test_frames.py), so the receivers do not recompute the CRC
    # of every good frame; a damaged copy (corrupted) starts unknown and is checked.
    _ok: bool | None = None

    # For a bulk advance (bulk.py): the wire image follows from the fields, so only they are extrapolated.
    BULK_DERIVED = ("wire", "_ok")

    def bulk_steady(self) -> bool:
        return self.ok                # a damaged frame in flight is not steady traffic

    def bulk_rebuild(self) -> None:
        if self.kind != EOT:
            self.wire = packet(self.kind, self.src, self.dst, self.fields)
        self._ok = None

    @property
    def ok(self) -> bool:
        if self._ok is None:
            self._ok = check_ok(self.wire)
        return self._ok

    @property
    def data_bytes(self) -> int:
        """Payload length (what PRO-01/02 call the data length), from the packet's length byte."""
        if self.kind == EOT:
            return 0
        offset, total = declared_length(self.wire)
        return total - offset - 2

    @property
    def name(self) -> str:
        return KIND_NAMES.get(self.kind, hex(self.kind))

    def corrupted(self, bit: int = 13) -> "Frame":
        """The same frame with one bit flipped on the way (it keeps its uid: it is the same transmission)."""
        wire = bytearray(self.wire)
        wire[(bit // 8) % len(wire)] ^= 1 << (bit % 8)
        return Frame(self.kind, self.src, self.dst, self.prio, bytes(wire), self.fields, self.uid)


def build_payload(kind: int, fields: dict[str, Any]) -> bytes:
    masks = _WIRE_MASKS.get(kind, {})
    wire = {k: (v & masks[k] if k in masks else v) for k, v in fields.items()}
    return _BUILDERS[kind].build(dict(wire, kind=kind))


def data_frame(kind: int, src: int, dst: int, prio: int, **fields: Any) -> Frame:
    return Frame(kind, src, dst, prio, packet(kind, src, dst, fields), fields, 0, True)


# -- the packets of the steady traffic, put together from templates --------------------------------
# Every node sends a status and the commanding CCU a command every cycle; from one cycle to the next only
# their counters move. So such a packet is built once through the layout with its counters at zero (the
# template, remembered by every other field), and each send writes the counters' bytes into a copy; the
# CRC-16/ARC, linear over GF(2) with a zero start and no final XOR, is the template's CRC xor that of the
# counters' bytes alone (the zeros before them leave the register at zero, those after are one table
# lookup per register byte: _zero_run). Building and checking a status this way is ~10x cheaper;
# tests/test_frames.py holds it equal to encode_pac(build_payload(...)) for random fields.
# Counter fields per kind: (name, offset in the payload, bytes), big-endian as the layouts declare them.
_COUNTERS = {K_COMMAND: (("seq", 1, 1), ("clock_ms", 8, 4)), K_STATUS: (("seq", 8, 2),)}
_COUNTER_NAMES = {kind: frozenset(name for name, _at, _size in counters) for kind, counters in _COUNTERS.items()}
_TEMPLATES: dict[tuple, tuple[bytes, int, int, tuple]] = {}
_TEMPLATES_MAX = 1 << 14


def packet(kind: int, src: int, dst: int, fields: dict[str, Any]) -> bytes:
    """encode_pac(src, dst, build_payload(kind, fields)), from a template where the kind has one."""
    counters = _COUNTERS.get(kind)
    key = _template_key(kind, src, dst, fields, counters) if counters else None
    if key is None:
        return encode_pac(src, dst, build_payload(kind, fields))
    template = _TEMPLATES.get(key)
    if template is None:
        template = _template(kind, src, dst, fields, counters)
        if len(_TEMPLATES) >= _TEMPLATES_MAX:
            _TEMPLATES.clear()
        _TEMPLATES[key] = template
    body, crc, head, places = template
    masks = _WIRE_MASKS[kind]
    out = bytearray(body)
    for name, at, size, trailing in places:
        value = (fields[name] & masks[name]).to_bytes(size, "big")
        out[head + at:head + at + size] = value
        crc ^= _zero_run(crc16_arc(value), trailing)
    return bytes(out) + crc.to_bytes(2, "little")


def _template_key(kind: int, src: int, dst: int, fields: dict[str, Any], counters: tuple) -> tuple | None:
    """Every field but the counters, hashable; None where a value is not plain (the layout judges it)."""
    names = _COUNTER_NAMES[kind]
    key: list = [kind, src, dst]
    found = 0
    for name, value in fields.items():
        if name in names:
            if type(value) is not int:
                return None
            found += 1
        elif type(value) is int:
            key.append((name, value))
        elif type(value) is list and all(type(p) is dict for p in value):
            key.append((name, tuple(tuple(p.items()) for p in value)))
        else:
            return None
    return tuple(key) if found == len(counters) else None


def _template(kind: int, src: int, dst: int, fields: dict[str, Any], counters: tuple) -> tuple:
    zeroed = dict(fields)
    for name, _at, _size in counters:
        zeroed[name] = 0
    wire = encode_pac(src, dst, build_payload(kind, zeroed))
    head, total = declared_length(wire)
    covered = total - 3                       # the CRC covers wire[1:-2]
    places = tuple((name, at, size, covered - (head - 1 + at + size)) for name, at, size in counters)
    return wire[:-2], int.from_bytes(wire[-2:], "little"), head, places


_ZERO_RUNS: dict[int, tuple[list[int], list[int]]] = {}


def _zero_run(reg: int, count: int) -> int:
    """The CRC-16/ARC register after `count` zero bytes, from `reg`: a linear map, so a table per byte."""
    if count == 0:
        return reg
    tables = _ZERO_RUNS.get(count)
    if tables is None:
        low, high = [], []
        for start, table in ((0, low), (8, high)):
            for byte in range(256):
                r = byte << start
                for _ in range(count):
                    r = (r >> 8) ^ ARC_TABLE[r & 0xFF]
                table.append(r)
        tables = _ZERO_RUNS[count] = (low, high)
    low, high = tables
    return low[reg & 0xFF] ^ high[reg >> 8]


def token_frame(src: int, dst: int) -> Frame:
    return Frame(EOT, src, dst, P_TOKEN, encode_itt(dst), {}, 0, True)


def decode_payload(data: bytes) -> dict[str, Any]:
    if not data:
        raise FrameError("empty payload")
    layout = LAYOUTS.get(data[0])
    if layout is None:
        raise FrameError(f"unknown payload kind {data[0]:#04x}")
    try:
        parsed = layout.parse(data)
    except ConstructError as exc:
        raise FrameError(f"{KIND_NAMES[data[0]]} payload: {exc}") from None
    return _plain(parsed)


def _plain(value: Any) -> Any:
    """construct's Containers as plain dicts and lists, without its private `_io` entries."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items() if not k.startswith("_")}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


@functools.lru_cache(maxsize=None)
def tx_time_us(frame_bytes: int, bitrate: int) -> int:
    """Time one frame occupies a link, rounded up to whole microseconds (asked at every hop of every frame, for
    a handful of lengths)."""
    bits = frame_bytes * BITS_PER_BYTE + ALERT_BITS
    return -(-bits * 1_000_000 // bitrate)
