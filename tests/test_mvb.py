"""MVB frame codecs of the metro reference (sut/reference/metro/mvb.py): TCN-05, TCN-06, TCN-10."""

from __future__ import annotations

import crc
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sut.codecs.mvb import (F_CODES, SLAVE_SIZES_BITS, DataClass, MasterFrame, MvbFrameError,
                                     SlaveFrame, check_sequence, data_class, decode_master, decode_slave, encode_master,
                                     encode_slave, slave_size_bits)

# Loaded machines make per-example deadlines flaky; these are not timing tests.
relaxed = settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])


# -- an independent reference, written from the definition ---------------------------------------
GENERATOR = "11100101"      # x^7 + x^6 + x^5 + x^2 + 1


def reference_check(bits: str) -> str:
    """M(x)*x^7 mod G(x) by long division, even parity over data and remainder, all 8 bits inverted."""
    reg = list(bits + "0" * 7)
    for i in range(len(bits)):
        if reg[i] == "1":
            for j, g in enumerate(GENERATOR):
                reg[i + j] = "0" if reg[i + j] == g else "1"
    remainder = "".join(reg[-7:])
    parity = str((bits + remainder).count("1") % 2)
    return "".join("1" if b == "0" else "0" for b in remainder + parity)


def reference_body(data: bytes) -> bytes:
    """Frame body with a check sequence after the data, or after every 64 data bits."""
    bits = "".join(f"{b:08b}" for b in data)
    group = min(len(bits), 64)
    out = "".join(bits[i:i + group] + reference_check(bits[i:i + group]) for i in range(0, len(bits), group))
    return int(out, 2).to_bytes(len(out) // 8, "big")


# The crc package cannot run a 7-bit CRC (see mvb.py); as an 8-bit CRC with the generator shifted left
# by one its register holds the 7-bit CRC in its top bits.
CRC7_AS_8 = crc.Calculator(crc.Configuration(width=8, polynomial=0x65 << 1, init_value=0, final_xor_value=0,
                                             reverse_input=False, reverse_output=False), optimized=True)


# -- known answers --------------------------------------------------------------------------------
# Master frames: F_code, address, body. The first is TCN-10's example; the others are frames captured on a
# train's MVB (github.com/yeckel/sigrok_mvb_test, test/mvb/pd_3MHz.output and pd_24MHz.output, as decoded
# without check errors by the public sigrok MVB decoder, github.com/yeckel/sigrok_mvb_decoder).
MASTER_VECTORS = [
    (0, 0x000, "0000ff"),      # TCN-10
    (4, 0x051, "4051e8"),      # pd_3MHz: process data 256, port 81
    (0, 0x067, "0067a7"),      # pd_3MHz: process data 16, port 103
    (9, 0x110, "91107e"),      # pd_3MHz: general event
    (12, 0x005, "c005ff"),     # pd_3MHz: message data, device 5
    (15, 0x9B0, "f9b051"),     # pd_24MHz: device status, device 0x9b0
]
# Slave frames: body in transmission order, from the same captures, each the answer to the master frame named.
SLAVE_VECTORS = [
    "0100f2",                                                       # 16 bits, after 0067a7 (pd_3MHz)
    "000800008f",                                                   # 32 bits, after 109bb1 (pd_24MHz)
    "8a390000000000003d",                                           # 64 bits, after 2132df
    "00e6000000000000290000000000000000ff",                         # 128 bits, after 30fb8a
    "0000ff2000000000e60000000000000000ff00004100000000007200002028376e89385b",  # 256 bits, after 4051e8
]


@pytest.mark.parametrize("f_code, address, body", MASTER_VECTORS)
def test_master_frame_known_answers(f_code, address, body):
    raw = bytes.fromhex(body)
    assert MasterFrame(f_code, address).encode() == raw
    assert decode_master(raw) == MasterFrame(f_code, address)
    assert reference_body(raw[:2]) == raw


@pytest.mark.parametrize("body", SLAVE_VECTORS)
def test_slave_frame_known_answers(body):
    raw = bytes.fromhex(body)
    frame = decode_slave(raw)
    assert frame.encode() == raw
    assert reference_body(frame.data) == raw
    assert len(raw) == {16: 3, 32: 5, 64: 9, 128: 18, 256: 36}[frame.size_bits]


def test_a_captured_poll_and_its_answer():
    poll = decode_master(bytes.fromhex("4051e8"))
    assert (poll.data_class, poll.slave_size_bits) == (DataClass.PROCESS, 256)
    answer = decode_slave(bytes.fromhex(SLAVE_VECTORS[-1]), poll.slave_size_bits)
    assert answer.data.hex() == "0000ff2000000000" "0000000000000000" "0000410000000000" "00002028376e8938"


# -- check sequence against the reference and the crc package -----------------------------------
groups = st.sampled_from([2, 4, 8]).flatmap(lambda n: st.binary(min_size=n, max_size=n))


@settings(relaxed, max_examples=300)
@given(group=groups)
def test_check_sequence_is_the_long_division(group):
    bits = "".join(f"{b:08b}" for b in group)
    assert check_sequence(group) == int(reference_check(bits), 2)


@settings(relaxed, max_examples=300)
@given(group=groups)
def test_check_sequence_agrees_with_the_crc_package(group):
    crc7 = CRC7_AS_8.checksum(group) >> 1
    parity = (int.from_bytes(group, "big").bit_count() + crc7.bit_count()) & 1
    assert check_sequence(group) == ~(crc7 << 1 | parity) & 0xFF


# -- round trips ----------------------------------------------------------------------------------
master_frames = st.builds(MasterFrame, st.sampled_from(sorted(F_CODES)), st.integers(0, 0xFFF))
slave_frames = st.sampled_from(SLAVE_SIZES_BITS).flatmap(
    lambda n: st.binary(min_size=n // 8, max_size=n // 8)).map(SlaveFrame)
frames = st.one_of(master_frames, slave_frames)


@settings(relaxed, max_examples=500)
@given(frame=master_frames)
def test_master_frame_round_trip(frame):
    raw = frame.encode()
    assert raw == reference_body(raw[:2])
    assert decode_master(raw) == frame


@settings(relaxed, max_examples=300)
@given(frame=slave_frames)
def test_slave_frame_round_trip(frame):
    raw = frame.encode()
    assert raw == reference_body(frame.data)
    assert decode_slave(raw) == frame
    assert decode_slave(raw, frame.size_bits) == frame


def test_every_master_frame_round_trips():
    for f_code in F_CODES:
        for address in range(0x1000):
            frame = MasterFrame(f_code, address)
            assert decode_master(frame.encode()) == frame


def _decode(frame, raw, sized=True):
    if isinstance(frame, MasterFrame):
        return decode_master(raw)
    return decode_slave(raw, frame.size_bits if sized else None)


# -- corruption -----------------------------------------------------------------------------------
@settings(relaxed, max_examples=250)
@given(frame=frames, sized=st.booleans())
def test_every_single_bit_error_is_rejected(frame, sized):
    raw = frame.encode()
    for bit in range(len(raw) * 8):     # every bit is data or check bit of some check group
        bad = bytearray(raw)
        bad[bit // 8] ^= 0x80 >> bit % 8
        with pytest.raises(MvbFrameError, match="check sequence"):
            _decode(frame, bytes(bad), sized)


@settings(relaxed, max_examples=250)
@given(frame=frames, extra=st.binary(min_size=1, max_size=40))
def test_truncated_or_extended_frames_are_rejected(frame, extra):
    raw = frame.encode()
    for cut in range(len(raw)):
        with pytest.raises(MvbFrameError):
            _decode(frame, raw[:cut])
    with pytest.raises(MvbFrameError):
        _decode(frame, raw + extra)


def test_a_cut_at_a_group_boundary_needs_the_expected_size():
    # Two whole groups of a 256-bit frame are a valid 128-bit frame; only the size the master frame asked
    # for tells them apart (on the bus the end delimiter marks the cut).
    raw = SlaveFrame(bytes(range(32))).encode()
    assert decode_slave(raw[:18]).data == bytes(range(16))
    with pytest.raises(MvbFrameError, match="256 data bits make 36 bytes"):
        decode_slave(raw[:18], 256)


def test_the_error_says_which_group_failed_and_where():
    raw = bytearray(SlaveFrame(bytes(32)).encode())
    raw[20] ^= 0x01
    with pytest.raises(MvbFrameError, match=r"group 3 of 4 \(data raw\[18:26\]\) failed at raw\[26\]"):
        decode_slave(bytes(raw))
    with pytest.raises(MvbFrameError, match=r"master frame check sequence failed at raw\[2\]"):
        decode_master(b"\x00\x00\x00")


# -- fuzz -----------------------------------------------------------------------------------------
sizes = st.one_of(st.none(), st.sampled_from(SLAVE_SIZES_BITS), st.integers(-1, 300), st.floats(),
                  st.booleans())


def _only_frame_errors(decode, raw):
    try:
        frame = decode(raw)
    except MvbFrameError:
        return
    assert frame.encode() == raw        # anything decoded is exactly a valid frame


@settings(relaxed, max_examples=400)
@given(raw=st.binary(max_size=40), size=sizes)
def test_arbitrary_bytes_raise_only_frame_errors(raw, size):
    _only_frame_errors(decode_master, raw)
    _only_frame_errors(lambda r: decode_slave(r, size), raw)


@settings(relaxed, max_examples=300)
@given(frame=frames, data=st.data())
def test_mutated_frames_raise_only_frame_errors(frame, data):
    raw = bytearray(frame.encode())
    for _ in range(data.draw(st.integers(1, 4))):
        raw[data.draw(st.integers(0, len(raw) - 1))] = data.draw(st.integers(0, 255))
    _only_frame_errors(decode_master, bytes(raw))
    _only_frame_errors(decode_slave, bytes(raw))


@relaxed
@given(raw=st.one_of(st.text(), st.integers(), st.none(), st.lists(st.integers(0, 255))))
def test_non_bytes_raise_frame_errors(raw):
    with pytest.raises(MvbFrameError, match="must be bytes"):
        decode_master(raw)
    with pytest.raises(MvbFrameError, match="must be bytes"):
        decode_slave(raw)


# -- fields and data classes ----------------------------------------------------------------------
@pytest.mark.parametrize("make, message", [
    (lambda: MasterFrame(16, 0), "F_code 16 out of range"),
    (lambda: MasterFrame(-1, 0), "F_code -1 out of range"),
    (lambda: MasterFrame(0, 0x1000), "address 4096 out of range"),
    (lambda: MasterFrame(0, -1), "address -1 out of range"),
    (lambda: SlaveFrame(bytes(3)), "3 bytes .24 bits."),
    (lambda: SlaveFrame(b""), "0 bytes"),
    (lambda: SlaveFrame("ab"), "must be bytes"),
    (lambda: decode_slave(bytes(5), 24), "size 24 bits"),
    (lambda: decode_slave(bytes(4)), "4 bytes is not a valid frame size"),
    (lambda: decode_master(bytes(4)), "master frame of 4 bytes"),
    (lambda: slave_size_bits(10), "F_code 10 is reserved: no slave frame answers it"),
    (lambda: data_class(99), "F_code 99 out of range"),
])
def test_bad_fields_are_named(make, message):
    with pytest.raises(MvbFrameError, match=message):
        make()


@pytest.mark.parametrize("f_code", [5, 6, 7, 10, 11])
def test_a_reserved_f_code_with_a_good_check_sequence_decodes_as_a_reserved_frame(f_code):
    # docs/decisions.md: an analyser names it (as the io4edge MVB sniffer's kReserved types do),
    # a device ignores it: no slave frame answers it.
    head = bytes([f_code << 4, 0x01])
    frame = decode_master(head + bytes([check_sequence(head)]))
    assert frame == MasterFrame(f_code, 1) and frame.reserved and frame.data_class is DataClass.RESERVED
    assert frame.encode() == head + bytes([check_sequence(head)])
    with pytest.raises(MvbFrameError, match=f"F_code {f_code} is reserved: no slave frame answers it"):
        frame.slave_size_bits


def test_a_bit_error_that_makes_a_reserved_f_code_is_a_corrupt_frame():
    raw = bytearray(MasterFrame(15, 1).encode())
    raw[0] ^= 0xA0                                           # F_code 15 -> 5, the check byte as it was
    with pytest.raises(MvbFrameError, match="check sequence failed"):
        decode_master(bytes(raw))


def test_f_codes_name_their_data_class_and_slave_size():
    assert {f: (data_class(f), slave_size_bits(f)) for f in F_CODES} == {
        0: (DataClass.PROCESS, 16), 1: (DataClass.PROCESS, 32), 2: (DataClass.PROCESS, 64),
        3: (DataClass.PROCESS, 128), 4: (DataClass.PROCESS, 256),
        8: (DataClass.SUPERVISORY, 16), 9: (DataClass.SUPERVISORY, 16), 12: (DataClass.MESSAGE, 256),
        13: (DataClass.SUPERVISORY, 16), 14: (DataClass.SUPERVISORY, 16), 15: (DataClass.SUPERVISORY, 16),
    }
    assert MasterFrame(12, 5).data_class is DataClass.MESSAGE


def test_frames_are_immutable():
    frame = MasterFrame(0, 1)
    with pytest.raises(AttributeError):
        frame.address = 2
    assert isinstance(SlaveFrame(bytearray(2)).data, bytes)


# -- the reference's cached encodings and decodings (frames are values) ------------------------------
@settings(relaxed, max_examples=200)
@given(frame=master_frames)
def test_cached_master_encoding_is_the_frames(frame):
    assert encode_master(frame.f_code, frame.address) == frame.encode() == reference_body(frame.encode()[:2])


@settings(relaxed, max_examples=200)
@given(frame=slave_frames)
def test_cached_slave_encoding_is_the_frames(frame):
    assert encode_slave(frame.data) == encode_slave(bytearray(frame.data)) == reference_body(frame.data)


def test_a_bad_frame_is_refused_every_time_not_only_the_first():
    bad = bytearray(MasterFrame(2, 0x123).encode())
    bad[2] ^= 1
    for _ in range(3):
        with pytest.raises(MvbFrameError, match="check sequence failed"):
            decode_master(bytes(bad))
        with pytest.raises(MvbFrameError, match="check sequence"):
            decode_slave(bytes(bad), 16)
    with pytest.raises(MvbFrameError, match="slave frame size"):
        decode_slave(SlaveFrame(b"ab").encode(), [16])              # unhashable: still the codec's own error
    with pytest.raises(MvbFrameError, match="out of range"):
        encode_master(16, 1)


# -- the dual-line bus (sut/reference/metro/bus.py) ---------------------------------------------
def test_a_frame_refused_on_both_whole_lines_counts_once_on_each_line_whichever_path_carries_it():
    """Both lines whole take one decode for both; a frame that decode refuses must leave the lines exactly as
    the line-by-line path leaves them (which a disturbed line B, with nothing left to disturb, takes)."""
    from sut.reference.metro.bus import DualLineBus

    def refuse(raw: bytes):
        raise MvbFrameError("check sequence")

    fast, slow = DualLineBus("unit1.MVB", "AB", switch_after=2), DualLineBus("unit1.MVB", "AB", switch_after=2)
    for _ in range(3):
        got = fast.carry(b"\x01\x02", refuse, lambda *why: pytest.fail(f"switched: {why}"))
        assert (got.data, got.line) == (None, None)
        assert got.errors == ("line A: check sequence", "line B: check sequence")
        slow.lines["B"].disturb = 1                         # forces the line-by-line path ...
        slow.carry(b"\x01\x02", refuse, lambda *why: pytest.fail(f"switched: {why}"))
    assert [fast.lines[ln].bad_run for ln in "AB"] == [slow.lines[ln].bad_run for ln in "AB"] == [3, 3]
    got = fast.carry(b"\x01\x02", lambda raw: raw, lambda *why: None)
    assert (got.data, got.line, got.errors) == (b"\x01\x02", "A", ())
    assert [fast.lines[ln].bad_run for ln in "AB"] == [0, 0]


def _metro_trace_through_faults(sut: str) -> list:
    from sut.backends import open_backend
    driver = open_backend(sut, "metro-tcn")
    try:
        driver.configure(sets=1, cars_per_set=6)
        driver.insert_key(1)
        driver.set_direction(1, "forward")
        driver.power_on()
        driver.advance_ms(300)
        driver.set_traction(1, 40)
        driver.disturb_line("unit1.MVB", "A", 3)
        driver.advance_ms(40)
        # A message's two frames damaged, whole frames, two more: each line's count starts again in between
        for line in "AABB":
            driver.disturb_line("unit1.MVB", line, 2)
            driver.advance_ms(5)
        driver.cut_line("unit2.MVB", "B")
        driver.fail("car2.BECU")
        driver.advance_ms(60)
        driver.restore_line("unit2.MVB", "B")
        driver.disturb_line("unit2.MVB", "B", 1)
        driver.fail("car1.IO1")
        driver.advance_ms(120)
        return [(e.t, e.source, e.kind, e.fields) for e in driver.trace]
    finally:
        driver.shutdown()


@pytest.mark.parametrize("sut", ["reference", "tests.variants:LineSwitchAfterThreeFrames"])
def test_frames_handed_over_as_sent_leave_the_trace_the_bit_path_leaves(monkeypatch, sut):
    """On whole, untapped lines the metro hands each MVB frame over as it was sent, without encoding or decoding
    it (tcds._mvb_message); through line faults, a failed device and a failed I/O module the trace must be the
    one the bit-by-bit path gives (also where receivers switch lines only after three bad frames: the count of
    bad frames on the trusted line must start again with a whole frame either way)."""
    from sut.reference.metro.bus import DualLineBus
    as_sent = _metro_trace_through_faults(sut)
    monkeypatch.setattr(DualLineBus, "whole", property(lambda bus: False))
    bit_by_bit = _metro_trace_through_faults(sut)
    assert len(as_sent) > 1000
    assert as_sent == bit_by_bit
