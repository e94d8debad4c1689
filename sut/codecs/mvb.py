"""MVB frames of IEC 61375-3-1 (TCN-05, TCN-06, TCN-10): master frame, slave frame, check sequence.

A frame body is the bytes between the start and the end delimiter, in transmission order (MSB first):
a master frame is F_code (4 bits), address (12 bits) and one check byte; a slave frame is 16/32/64 data
bits and one check byte, or for 128/256 bits a check byte after every 64 data bits. The delimiters are
non-data Manchester symbols, not bytes, and the master and slave start delimiters differ; so the frame type
is not in the body but in the function that decodes it (`decode_master` / `decode_slave`), as a receiver
learns it from the start delimiter before the data.

Check sequence: 7-bit CRC, generator x^7+x^6+x^5+x^2+1, zero start, MSB first over one group (16, 32 or 64
data bits), then an even-parity bit over the group and the 7 CRC bits; all 8 bits are sent inverted.

Sources used (public):
- the sigrok MVB decoder by Libor Tomsik, github.com/yeckel/sigrok_mvb_decoder mvb/pd.py (commit d9bd4b8):
  divisor 11100101, parity over data and remainder, the 8 bits inverted, one check per 64 bits of a long
  slave frame, F_code names 0-4 PD 2/4/8/16/32 bytes, 8 master transfer, 9 general event, 12 MD,
  13 group event, 14 single event, 15 device status, 5-7 and 10-11 reserved;
- its real-bus captures decoded in github.com/yeckel/sigrok_mvb_test test/mvb/pd_*.output: all 1682 check
  groups agree with this module (tests/test_mvb.py holds a sample as known answers); they also show
  F_code 0-4 answered by 16/32/64/128/256-bit slave frames;
- the BME MIT MVB VHDL stack (e_CRC_CALCULATOR: "the 7 bit remainder is extended by an even parity bit,
  the eight bits are transmitted inverted").
DreamSourceLab's C port of that decoder (PXView, "mvb_c") runs an 8-bit register with 0xE5 and XORs the
parity into the inverted CRC; for the captured master frame 40 51 it computes 0x6c, not the 0xe8 on the
bus, so it is not used.
Slave frame sizes for F_code 8-15 (16 bits, 256 for message data) are IEC 61375-3-1's table; none of the
public sources above states them.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from enum import Enum
from typing import NamedTuple


class MvbFrameError(ValueError):
    """A frame, or a field for one, that IEC 61375-3-1 does not allow; the message says what and where."""


class DataClass(Enum):
    PROCESS = "process data"            # cyclic, sent on the master's poll of a logical address
    MESSAGE = "message data"            # numbered packets the destination acknowledges
    SUPERVISORY = "supervisory data"    # device status, master transfer, event arbitration
    RESERVED = "reserved"               # F_code 5-7 and 10-11: no slave answers (docs/decisions.md)


class FCode(NamedTuple):
    name: str
    data_class: DataClass
    slave_size_bits: int


F_CODES: dict[int, FCode] = {
    0: FCode("process data 16", DataClass.PROCESS, 16),
    1: FCode("process data 32", DataClass.PROCESS, 32),
    2: FCode("process data 64", DataClass.PROCESS, 64),
    3: FCode("process data 128", DataClass.PROCESS, 128),
    4: FCode("process data 256", DataClass.PROCESS, 256),
    8: FCode("master transfer", DataClass.SUPERVISORY, 16),
    9: FCode("general event", DataClass.SUPERVISORY, 16),
    12: FCode("message data", DataClass.MESSAGE, 256),
    13: FCode("group event", DataClass.SUPERVISORY, 16),
    14: FCode("single event", DataClass.SUPERVISORY, 16),
    15: FCode("device status", DataClass.SUPERVISORY, 16),
}

SLAVE_SIZES_BITS = (16, 32, 64, 128, 256)
GROUP_BITS = 64
MASTER_FRAME_BYTES = 3
MAX_ADDRESS = 0xFFF


# -- check sequence -------------------------------------------------------------------------------
# The `crc` package (8.0) cannot compute this CRC: its registers shift each input byte by (width - 8),
# which is negative for width 7 (ValueError "negative shift count", plain and table-driven alike). So
# the CRC is computed here, the 7-bit register held left-aligned in a byte so one table lookup per data
# byte suffices; tests/test_mvb.py holds it equal to a bit-by-bit long division and to the `crc`
# package run as an 8-bit CRC with the generator shifted left by one.
_GENERATOR = 0x65       # x^7 + x^6 + x^5 + x^2 + 1 without the x^7 term


def _crc_table() -> tuple[int, ...]:
    table = []
    for byte in range(256):
        reg = byte
        for _ in range(8):
            reg = ((reg << 1) ^ (_GENERATOR << 1) if reg & 0x80 else reg << 1) & 0xFF
        table.append(reg)
    return tuple(table)


_CRC_TABLE = _crc_table()


def check_sequence(group: bytes) -> int:
    """The check byte sent after `group` (2, 4 or 8 data bytes): CRC-7, even parity, inverted."""
    return _check_sequence(group if type(group) is bytes else bytes(group))


# Remembered per group: a bus carries the same few hundred groups every basic period, and computing it was
# the metro reference's hottest function (bench/suite_bench.py --profile-run).
@functools.lru_cache(maxsize=1 << 16)
def _check_sequence(group: bytes) -> int:
    reg = 0
    for byte in group:
        reg = _CRC_TABLE[reg ^ byte]
    crc7 = reg >> 1
    parity = (int.from_bytes(group, "big").bit_count() + crc7.bit_count()) & 1
    return ~(crc7 << 1 | parity) & 0xFF


# -- F_code ---------------------------------------------------------------------------------------
def _in_range(f_code: int) -> int:
    if not isinstance(f_code, int) or not 0 <= f_code <= 15:
        raise MvbFrameError(f"F_code {f_code!r} out of range 0..15 (4 bits)")
    return f_code


def is_reserved(f_code: int) -> bool:
    """F_code 5-7 and 10-11: a master frame an analyser reads and names, and no device answers."""
    return _in_range(f_code) not in F_CODES


def data_class(f_code: int) -> DataClass:
    """The data class a master frame with this F_code asks for (RESERVED for a reserved F_code)."""
    return DataClass.RESERVED if is_reserved(f_code) else F_CODES[f_code].data_class


def slave_size_bits(f_code: int) -> int:
    """Data bits of the slave frame that answers a master frame with this F_code; MvbFrameError for a
    reserved F_code, which no slave frame answers."""
    if type(f_code) is int:                    # asked for every frame on a bus: one lookup where it can be
        bits = _SLAVE_BITS.get(f_code)
        if bits is not None:
            return bits
    if is_reserved(f_code):
        raise MvbFrameError(f"F_code {f_code} is reserved: no slave frame answers it "
                            f"(IEC 61375-3-1 assigns {sorted(F_CODES)})")
    return F_CODES[f_code].slave_size_bits


_SLAVE_BITS = {code: spec.slave_size_bits for code, spec in F_CODES.items()}


# -- frames ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MasterFrame:
    f_code: int
    address: int

    def __post_init__(self) -> None:
        _in_range(self.f_code)             # a reserved F_code is a frame too: analysers name it, devices ignore it
        if not isinstance(self.address, int) or not 0 <= self.address <= MAX_ADDRESS:
            raise MvbFrameError(f"master frame address {self.address!r} out of range 0..{MAX_ADDRESS:#x} "
                                "(12 bits)")

    @property
    def reserved(self) -> bool:
        return self.f_code not in F_CODES          # is_reserved, the range checked when the frame was made

    @property
    def data_class(self) -> DataClass:
        return data_class(self.f_code)

    @property
    def slave_size_bits(self) -> int:
        return slave_size_bits(self.f_code)

    def encode(self) -> bytes:
        return _master_wire(self.f_code, self.address)


@dataclass(frozen=True)
class SlaveFrame:
    data: bytes

    def __post_init__(self) -> None:
        if not isinstance(self.data, (bytes, bytearray, memoryview)):
            raise MvbFrameError(f"slave frame data must be bytes, got {type(self.data).__name__}")
        object.__setattr__(self, "data", bytes(self.data))
        if len(self.data) * 8 not in SLAVE_SIZES_BITS:
            raise MvbFrameError(f"slave frame data of {len(self.data)} bytes ({len(self.data) * 8} bits): "
                                f"a slave frame carries {'/'.join(map(str, SLAVE_SIZES_BITS))} bits")

    @property
    def size_bits(self) -> int:
        return len(self.data) * 8

    def encode(self) -> bytes:
        return _slave_wire(self.data)


# Frames are values: a bus carries the same few hundred of them every basic period, so each wire image and
# each decoding is worked out once (the metro reference spent a third of its time here; bench/suite_bench.py
# --profile-run). A decoding that fails raises every time: lru_cache keeps no exceptions.
@functools.lru_cache(maxsize=1 << 16)
def _master_wire(f_code: int, address: int) -> bytes:
    head = (f_code << 12 | address).to_bytes(2, "big")
    return head + bytes([check_sequence(head)])


@functools.lru_cache(maxsize=1 << 16)
def _slave_wire(data: bytes) -> bytes:
    out = bytearray()
    for group in _groups(data):
        out += group
        out.append(check_sequence(group))
    return bytes(out)


def encode_master(f_code: int, address: int) -> bytes:
    """`MasterFrame(f_code, address).encode()`, the frame checked once per F_code and address."""
    return _master_frame(f_code, address).encode()


def encode_slave(data: bytes) -> bytes:
    """`SlaveFrame(data).encode()`, the frame checked once per data."""
    if type(data) is not bytes:
        return SlaveFrame(data).encode()
    return _slave_frame(data).encode()


@functools.lru_cache(maxsize=1 << 16)
def _master_frame(f_code: int, address: int) -> "MasterFrame":
    return MasterFrame(f_code, address)


def master_frame(f_code: int, address: int) -> "MasterFrame":
    """`MasterFrame(f_code, address)`, checked once per F_code and address (a frame is a value)."""
    return _master_frame(f_code, address)


@functools.lru_cache(maxsize=1 << 16)
def _slave_frame(data: bytes) -> "SlaveFrame":
    return SlaveFrame(data)


def _groups(data: bytes) -> list[bytes]:
    step = GROUP_BITS // 8
    return [data[i:i + step] for i in range(0, len(data), step)]


def _frame_bytes(size_bits: int) -> int:
    groups = -(-size_bits // GROUP_BITS)
    return size_bits // 8 + groups


_SIZE_BY_FRAME_BYTES = {_frame_bytes(bits): bits for bits in SLAVE_SIZES_BITS}     # 3/5/9/18/36 bytes


def slave_frame_bytes(f_code: int) -> int:
    """Bytes on the wire of the slave frame answering this F_code: its data and one check byte per 64 data bits,
    at least one (TCN-05), delimiters left out; MvbFrameError for a reserved F_code."""
    return _frame_bytes(slave_size_bits(f_code))


def _as_bytes(raw: object, what: str) -> bytes:
    if not isinstance(raw, (bytes, bytearray, memoryview)):
        raise MvbFrameError(f"{what} must be bytes, got {type(raw).__name__}")
    return bytes(raw)


def decode_master(raw: bytes) -> MasterFrame:
    """The master frame in `raw` (body after a master start delimiter); MvbFrameError if it is not one."""
    return _decode_master(raw if type(raw) is bytes else _as_bytes(raw, "master frame"))


@functools.lru_cache(maxsize=1 << 16)
def _decode_master(raw: bytes) -> MasterFrame:
    if len(raw) != MASTER_FRAME_BYTES:
        raise MvbFrameError(f"master frame of {len(raw)} bytes: a master frame is {MASTER_FRAME_BYTES} bytes "
                            "(F_code, address, check sequence)")
    want = check_sequence(raw[:2])
    if raw[2] != want:
        raise MvbFrameError(f"master frame check sequence failed at raw[2]: received {raw[2]:#04x}, "
                            f"computed {want:#04x}")
    # The check comes first: a bit error in the F_code must read as a corrupt frame, not a reserved code.
    # A reserved F_code with a good check is a frame (`.reserved`): what to do with it is the reader's call.
    word = int.from_bytes(raw[:2], "big")
    return MasterFrame(word >> 12, word & MAX_ADDRESS)


def decode_slave(raw: bytes, size_bits: int | None = None) -> SlaveFrame:
    """The slave frame in `raw` (body after a slave start delimiter); MvbFrameError if it is not one.

    `size_bits` is what the master frame asked for (`slave_size_bits(f_code)`). Pass it: without it the
    size follows from the length, and a 128/256-bit frame cut after a whole 64-bit group and its check
    byte reads as a valid shorter frame.
    """
    raw = raw if type(raw) is bytes else _as_bytes(raw, "slave frame")
    if size_bits is None or type(size_bits) is int:
        return _decode_slave(raw, size_bits)
    return _decode_slave.__wrapped__(raw, size_bits)        # unhashable: its error, not lru_cache's


@functools.lru_cache(maxsize=1 << 16)
def _decode_slave(raw: bytes, size_bits: int | None) -> SlaveFrame:
    if size_bits is None:
        if len(raw) not in _SIZE_BY_FRAME_BYTES:
            raise MvbFrameError(f"slave frame of {len(raw)} bytes is not a valid frame size (3, 5, 9, 18 or "
                                "36 bytes for 16/32/64/128/256 data bits)")
        size_bits = _SIZE_BY_FRAME_BYTES[len(raw)]
    elif not isinstance(size_bits, int) or size_bits not in SLAVE_SIZES_BITS:
        raise MvbFrameError(f"slave frame size {size_bits!r} bits: a slave frame carries "
                            f"{'/'.join(map(str, SLAVE_SIZES_BITS))} bits")
    elif len(raw) != _frame_bytes(size_bits):
        raise MvbFrameError(f"slave frame of {len(raw)} bytes: {size_bits} data bits make "
                            f"{_frame_bytes(size_bits)} bytes with their check sequences")
    step = min(size_bits, GROUP_BITS) // 8 + 1
    count = len(raw) // step
    data = bytearray()
    for index, start in enumerate(range(0, len(raw), step)):
        group, received = raw[start:start + step - 1], raw[start + step - 1]
        want = check_sequence(group)
        if received != want:
            raise MvbFrameError(f"slave frame check sequence of group {index + 1} of {count} "
                                f"(data raw[{start}:{start + step - 1}]) failed at raw[{start + step - 1}]: "
                                f"received {received:#04x}, computed {want:#04x}")
        data += group
    return SlaveFrame(bytes(data))
