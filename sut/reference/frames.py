"""Wire formats of the ring (ARCNET, ATA 878.1) and of the CRH2 payloads above it.

Layouts are `construct` structs so that the byte image is the specification. The CRC-16 of an ARCNET
packet (generator x^16+x^15+x^2+1, reflected, zero start: CRC-16/ARC) is computed by `crc16_arc`; the
`crc` package computes the same value but ~40x slower (bench/crc_bench.py), and every frame on the
ring is checked, so the table version is used and tests/test_frames.py holds it equal to the library.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from construct import (Byte, Bytes, Const, ConstructError, Int16ub, Int16ul, Int32sb, Int32ub, Padded,
                       PrefixedArray, Struct, this)

# -- check sequences ------------------------------------------------------------------------------

def _table(poly_reflected: int) -> list[int]:
    table = []
    for byte in range(256):
        reg = byte
        for _ in range(8):
            reg = (reg >> 1) ^ poly_reflected if reg & 1 else reg >> 1
        table.append(reg)
    return table


_ARC = _table(0xA001)     # x^16+x^15+x^2+1 reflected
_X25 = _table(0x8408)     # x^16+x^12+x^5+1 reflected (HDLC FCS)


def crc16_arc(data: bytes) -> int:
    reg = 0
    table = _ARC
    for b in data:
        reg = (reg >> 8) ^ table[(reg ^ b) & 0xFF]
    return reg


def crc16_x25(data: bytes) -> int:
    """HDLC frame check sequence (CRC-16/X-25), used on the self-diagnostic line and MDM9 links."""
    reg = 0xFFFF
    table = _X25
    for b in data:
        reg = (reg >> 8) ^ table[(reg ^ b) & 0xFF]
    return reg ^ 0xFFFF


# -- ARCNET frames --------------------------------------------------------------------------------
SOH, EOT = 0x01, 0x04
BROADCAST = 0x00
MAX_DATA = 508

PAC_SHORT = Struct(
    "soh" / Const(SOH, Byte),
    "sid" / Byte,
    "did" / Byte,
    "did2" / Byte,
    "il" / Byte,                      # 256 - data length (short packet, <= 253 data bytes)
    "data" / Bytes(256 - this.il),
    "crc" / Int16ul,
)
PAC_LONG = Struct(
    "soh" / Const(SOH, Byte),
    "sid" / Byte,
    "did" / Byte,
    "did2" / Byte,
    "zero" / Const(0, Byte),
    "il" / Byte,                      # 512 - data length (long packet, 257..508 data bytes)
    "data" / Bytes(512 - this.il),
    "crc" / Int16ul,
)
ITT = Struct("eot" / Const(EOT, Byte), "did" / Byte, "did2" / Byte)

# ARCNET sends every byte as an 11-bit information symbol unit at 2.5 Mbit/s, plus a 6-bit alert burst.
BITS_PER_BYTE = 11
ALERT_BITS = 6


class FrameError(ValueError):
    """A byte image that is not a valid frame; says what is wrong and where."""


def encode_pac(sid: int, did: int, data: bytes) -> bytes:
    n = len(data)
    if not 1 <= n <= MAX_DATA or 254 <= n <= 256:
        raise FrameError(f"ARCNET packet data length {n} not allowed (1..253 or 257..508 bytes)")
    if n <= 253:
        body = PAC_SHORT.build(dict(sid=sid, did=did, did2=did, il=256 - n, data=data, crc=0))
    else:
        body = PAC_LONG.build(dict(sid=sid, did=did, did2=did, il=512 - n, data=data, crc=0))
    return body[:-2] + crc16_arc(body[1:-2]).to_bytes(2, "little")


def _declared(wire: bytes) -> tuple[int, int]:
    """(offset of the data, whole packet length) as the packet's length byte(s) declare them."""
    if wire[4] == 0:
        return 6, (512 - wire[5]) + 8          # long packet: 0x00 then 512 - n
    return 5, (256 - wire[4]) + 7              # short packet: 256 - n


def decode_pac(wire: bytes) -> tuple[int, int, bytes]:
    """(sid, did, data) of a packet; FrameError on a bad layout or check sequence."""
    if len(wire) < 8 or wire[0] != SOH:
        raise FrameError(f"not an ARCNET packet: {len(wire)} bytes starting {wire[:1].hex() or 'nothing'}")
    long = wire[4] == 0
    _, declared = _declared(wire)
    if len(wire) != declared:
        raise FrameError(f"ARCNET packet length byte says {declared} bytes, the frame has {len(wire)}")
    try:
        pac = (PAC_LONG if long else PAC_SHORT).parse(wire)
    except ConstructError as exc:
        raise FrameError(f"ARCNET packet layout: {exc}") from None
    if pac.did != pac.did2:
        raise FrameError(f"ARCNET packet destination bytes disagree: {pac.did:#04x} != {pac.did2:#04x}")
    want = crc16_arc(wire[1:-2])
    if pac.crc != want:
        raise FrameError(f"ARCNET packet CRC {pac.crc:#06x}, computed {want:#06x}")
    return pac.sid, pac.did, pac.data


def check_ok(wire: bytes) -> bool:
    """The node's frame check: layout and CRC (what NET-05 discards on)."""
    if not wire:
        return False
    if wire[0] == EOT:
        return len(wire) == 3 and wire[1] == wire[2]
    # The same checks as decode_pac, without building the parsed view: every node runs this on every frame.
    if len(wire) < 8 or wire[0] != SOH or wire[2] != wire[3]:
        return False
    return len(wire) == _declared(wire)[1] and crc16_arc(wire[1:-2]) == int.from_bytes(wire[-2:], "little")


def payload_unchecked(wire: bytes) -> dict[str, Any]:
    """What a receiver without a frame check would read from a packet (faulty variants only): the payload
    where the length byte says it is, CRC ignored. FrameError if even that cannot be read."""
    if len(wire) < 8 or wire[0] != SOH:
        raise FrameError(f"not an ARCNET packet: {len(wire)} bytes")
    offset, _ = _declared(wire)
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
    "flags" / Byte,                   # bit0 MCR up
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
    "record" / Int16ub,               # which record of the owner's data area (DECISIONS.md, "Block data")
    "index" / Int16ub,
    "total" / Int16ub,
    "data" / Bytes(BLOCK_SIZE),
)

_PAYLOADS = {K_COMMAND: COMMAND, K_STATUS: STATUS, K_TOKEN_INIT: TOKEN_CTL, K_TOKEN_SEND: TOKEN_CTL,
             K_BLOCK: BLOCK}
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

    kind: int
    src: int
    dst: int
    prio: int
    wire: bytes
    fields: dict[str, Any]
    uid: int = 0                      # one transmission; the ring numbers it when it is first sent
    _ok: bool | None = None

    # For a bulk advance (bulk.py): the wire image follows from the fields, so only they are extrapolated.
    BULK_DERIVED = ("wire", "_ok")

    def bulk_steady(self) -> bool:
        return self.ok                # a damaged frame in flight is not steady traffic

    def bulk_rebuild(self) -> None:
        if self.kind != EOT:
            self.wire = encode_pac(self.src, self.dst, build_payload(self.kind, self.fields))
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
        offset, total = _declared(self.wire)
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
    return _PAYLOADS[kind].build(dict(wire, kind=kind))


def data_frame(kind: int, src: int, dst: int, prio: int, **fields: Any) -> Frame:
    return Frame(kind, src, dst, prio, encode_pac(src, dst, build_payload(kind, fields)), fields)


def token_frame(src: int, dst: int) -> Frame:
    return Frame(EOT, src, dst, P_TOKEN, ITT.build(dict(did=dst, did2=dst)), {})


def decode_payload(data: bytes) -> dict[str, Any]:
    if not data:
        raise FrameError("empty payload")
    layout = _PAYLOADS.get(data[0])
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


def tx_time_us(frame_bytes: int, bitrate: int) -> int:
    """Time one frame occupies a link, rounded up to whole microseconds."""
    bits = frame_bytes * BITS_PER_BYTE + ALERT_BITS
    return -(-bits * 1_000_000 // bitrate)
