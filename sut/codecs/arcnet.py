"""ARCNET frames (ATA 878.1, NET-10) and the HDLC frame check sequence: the layer below the CRH2 payloads.

Shared by the reference, which builds and checks its frames with it, and by the step library, whose ring
analyser decodes the frames on a tapped span with it. Layouts are `construct` structs so that the byte
image is the specification. The CRC-16 of an ARCNET packet (generator x^16+x^15+x^2+1, reflected, zero
start: CRC-16/ARC) is a table computation: the `crc` package computes the same value but ~40x slower
(bench/crc_bench.py), and every frame on the ring is checked; tests/test_frames.py holds it equal to the
library.
"""
from __future__ import annotations

from construct import Byte, Bytes, Const, ConstructError, Int16ul, Struct, this

# -- check sequences ------------------------------------------------------------------------------

def _table(poly_reflected: int) -> list[int]:
    table = []
    for byte in range(256):
        reg = byte
        for _ in range(8):
            reg = (reg >> 1) ^ poly_reflected if reg & 1 else reg >> 1
        table.append(reg)
    return table


ARC_TABLE = _ARC = tuple(_table(0xA001))     # x^16+x^15+x^2+1 reflected (frames.py's zero runs read it too)
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
    """The packet PAC_SHORT or PAC_LONG declare, put together directly: every frame on the ring is encoded
    here, and building through the declared layout costs ~14 us a frame (tests/test_frames.py holds the
    two equal). Node IDs outside 0..255 are refused as the layout would refuse them."""
    n = len(data)
    if not 1 <= n <= MAX_DATA or 254 <= n <= 256:
        raise FrameError(f"ARCNET packet data length {n} not allowed (1..253 or 257..508 bytes)")
    if not (0 <= sid <= 0xFF and 0 <= did <= 0xFF):
        raise FrameError(f"ARCNET node IDs are one byte: source {sid}, destination {did}")
    packet = bytes((SOH, sid, did, did, 256 - n) if n <= 253 else (SOH, sid, did, did, 0, 512 - n)) + data
    return packet + crc16_arc(packet[1:]).to_bytes(2, "little")


def encode_itt(did: int) -> bytes:
    """A token (ITT): EOT and the destination twice."""
    if not 0 <= did <= 0xFF:
        raise FrameError(f"ARCNET node IDs are one byte: destination {did}")
    return bytes((EOT, did, did))


def declared_length(wire: bytes) -> tuple[int, int]:
    """(offset of the data, whole packet length) as the packet's length byte(s) declare them."""
    if wire[4] == 0:
        return 6, (512 - wire[5]) + 8          # long packet: 0x00 then 512 - n
    return 5, (256 - wire[4]) + 7              # short packet: 256 - n


def decode_pac(wire: bytes) -> tuple[int, int, bytes]:
    """(sid, did, data) of a packet; FrameError on a bad layout or check sequence."""
    if len(wire) < 8 or wire[0] != SOH:
        raise FrameError(f"not an ARCNET packet: {len(wire)} bytes starting {wire[:1].hex() or 'nothing'}")
    long = wire[4] == 0
    offset, declared = declared_length(wire)
    n = declared - offset - 2
    if not (257 <= n <= MAX_DATA if long else 1 <= n <= 253):     # 254..256 cannot be sent, > 508 not at all
        raise FrameError(f"ARCNET packet length byte wire[{offset - 1}] = {wire[offset - 1]:#04x} declares {n} data "
                         f"bytes; a {'long packet carries 257..508' if long else 'short packet carries 1..253'}")
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


def decode_itt(wire: bytes) -> int:
    """The destination of a token (ITT); FrameError if `wire` is not one."""
    if len(wire) != 3 or wire[0] != EOT:
        raise FrameError(f"not an ARCNET token: {wire.hex() or 'nothing'} (ITT is 04, destination twice)")
    if wire[1] != wire[2]:
        raise FrameError(f"ARCNET token destination bytes disagree: {wire[1]:#04x} != {wire[2]:#04x}")
    return wire[1]
