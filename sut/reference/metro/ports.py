"""What the metro TCDS puts in its frames: MVB port layouts and the WTB telegram.

MVB (TCN-05/06/07): process-data ports are read by polling a logical address with F_code 0-4; the slave
frame carries the port. Device status (F_code 15) is supervisory data, 16 bits.
- MVB I/O module port, F_code 3 (128 bits, TCN-07): DI01-DI28 in a 32-bit word, AI1-AI3 as 16-bit values,
  the 16-bit life signal, 32 bits spare.
- train command port, F_code 2 (64 bits): mode, direction, traction and brake in 0.01 %, a sequence number.
- device status word (F_code 15): bit 0 device ready, bit 1 fault.

WTB: HDLC frames with the CRC-16/X-25 frame check sequence; the telegram inside is JSON (the model's
choice: the WTB link layer is IEC 61375-2-1's, the application telegram is vendor-specific).
"""
from __future__ import annotations

import json
import struct
from dataclasses import dataclass

from sut.codecs.arcnet import crc16_x25
from sut.reference.metro.bus import FrameError

IO_PORT_F_CODE = 3
COMMAND_F_CODE = 2
DEVICE_STATUS_F_CODE = 15
COMMAND_ADDRESS = 0x010
IO_ADDRESSES = {"IO1": 0x0A1, "IO2": 0x0A2}

DI_KEY, DI_FORWARD, DI_REVERSE = 1, 2, 3          # DI01..DI03: cab key, direction switch
AI_TRACTION, AI_BRAKE = 1, 2                       # AI1, AI2: master controller, 0.01 % steps

MODES = ("normal", "no cab", "network failure")
DIRECTIONS = ("neutral", "forward", "reverse")

_IO = struct.Struct(">IHHHH4x")
_CMD = struct.Struct(">BBHHH")

READY, FAULT = 0x0001, 0x0002


def _size(data: bytes, layout: struct.Struct, what: str) -> None:
    if len(data) != layout.size:
        raise FrameError(f"{what} of {len(data)} bytes: the port is {layout.size} bytes")


@dataclass(frozen=True)
class IoPort:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    di: int          # DI01 is bit 0
    ai: tuple[int, int, int]
    life: int

    def encode(self) -> bytes:
        return _IO.pack(self.di, *self.ai, self.life)

    @classmethod
    def decode(cls, data: bytes) -> "IoPort":
        """The port in a 128-bit slave frame's data; FrameError if `data` is not 16 bytes."""
        _size(data, _IO, "MVB I/O module port")
        di, a1, a2, a3, life = _IO.unpack(data)
        return cls(di, (a1, a2, a3), life)

    def input(self, n: int) -> bool:
        return bool(self.di >> (n - 1) & 1)


@dataclass(frozen=True)
class Command:
    BULK_READABLE = True  # pragma: no mutate  (a speed declaration: bulk.py)
    mode: str
    direction: str
    traction: int     # 0.01 %
    brake: int        # 0.01 %
    seq: int

    def encode(self) -> bytes:
        return _CMD.pack(MODES.index(self.mode), DIRECTIONS.index(self.direction), self.traction, self.brake,
                         self.seq & 0xFFFF)

    @classmethod
    def decode(cls, data: bytes) -> "Command":
        """The command in a 64-bit slave frame's data; FrameError if it is not 8 bytes or holds no valid command."""
        _size(data, _CMD, "train command port")
        mode, direction, traction, brake, seq = _CMD.unpack(data)
        if mode >= len(MODES) or direction >= len(DIRECTIONS) or traction > 10_000 or brake > 10_000:
            raise FrameError(f"train command port holds no valid command: {data.hex()}")
        return cls(MODES[mode], DIRECTIONS[direction], traction, brake, seq)

    def as_json(self) -> list:
        """The command as a WTB telegram relays it: without its number, which the receiving gateway gives
        itself when it puts the command on its own unit's MVB."""
        return [self.mode, self.direction, self.traction, self.brake]

    @classmethod
    def from_json(cls, value: list) -> "Command":
        return cls(*value, seq=0)


def wtb_encode(telegram: dict) -> bytes:
    body = json.dumps(telegram, separators=(",", ":"), sort_keys=True).encode()
    return body + crc16_x25(body).to_bytes(2, "little")


def wtb_decode(wire: bytes) -> dict:
    """The telegram in a WTB frame; FrameError if the frame check sequence fails or the body is not a UTF-8 JSON
    object."""
    if len(wire) < 3:
        raise FrameError(f"WTB frame of {len(wire)} bytes is shorter than its frame check sequence")
    body, fcs = wire[:-2], int.from_bytes(wire[-2:], "little")
    want = crc16_x25(body)
    if fcs != want:
        raise FrameError(f"WTB frame check sequence failed: received {fcs:#06x}, computed {want:#06x}")
    try:
        telegram = json.loads(body.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise FrameError(f"WTB telegram is not UTF-8: {exc}") from None
    except RecursionError:
        raise FrameError(f"WTB telegram nests too deep ({len(body)} bytes)") from None
    except ValueError as exc:           # JSONDecodeError, an integer over the str-to-int digit limit
        raise FrameError(f"WTB telegram is not JSON: {exc}") from None
    if not isinstance(telegram, dict):
        kind = {list: "array", str: "string", bool: "boolean", type(None): "null"}.get(type(telegram), "number")
        raise FrameError(f"WTB telegram is a JSON {kind}, not an object")
    return telegram
