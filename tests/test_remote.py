"""The suite against a SUT in another process (issue 9, sut/PROTOCOL.md): same verdicts and byte-identical traces
as in process; a faulty implementation served remotely is still rejected; bad peers on either side give a
clear error and a "SUT not reachable" verdict, never a pass and never a hang."""
from __future__ import annotations

import re
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from outline.report.allure_meta import CATEGORIES
from sut.backends import open_backend, resolve
from sut.driver import TrainDriver
from sut.errors import NotPoweredUp, OutOfRange, SutUnreachable, UnknownName
from sut.remote import client, server, wire
from tests.helpers import traces, verdicts
from tests.test_faulty_variants import ROOT, run_features

# The routine class (English and zh-CN) and one item of each other profile: the ATP rig item caught a
# client that sent arguments the step never gave.
ITEMS = "R-CTL-01,R-CTL-02,R-CTL-03,R-DIA-01,R-DIA-02,R-DIA-03,R-DSP-01,F-ATP-04,F-NET-21"
FUZZ = settings(max_examples=200, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow])


@contextmanager
def served(*args: str) -> Iterator[str]:
    """`python -m sut serve` in its own process on a free port; yields its tcp:// address."""
    proc = subprocess.Popen([sys.executable, "-m", "sut", "serve", "--port", "0", *args], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()
        match = re.search(r"tcp://\S+", first)
        assert match, f"the server did not start: {first!r} {proc.stderr.read() if proc.poll() is not None else ''}"
        yield match.group(0)
    finally:
        proc.terminate()
        proc.wait(timeout=10)


@pytest.mark.cost(10)
def test_same_verdicts_and_traces_in_process_and_remote(tmp_path: Path) -> None:
    local = run_features(None, f"--item={ITEMS}", "-rA", f"--trace-dir={tmp_path / 'local'}", sut="reference")
    with served() as url:
        remote = run_features(None, f"--item={ITEMS}", "-rA", f"--trace-dir={tmp_path / 'remote'}", sut=url)
    assert local.returncode == 0, local.stdout[-3000:]
    assert remote.returncode == 0, remote.stdout[-3000:] + remote.stderr[-2000:]
    assert verdicts(remote.stdout) == verdicts(local.stdout)
    assert len(verdicts(local.stdout)) >= 50
    expected = traces(tmp_path / "local")
    assert traces(tmp_path / "remote") == expected
    assert sum(len(t) for t in expected.values()) > 1_000_000, "the traces compared are not empty"


def test_a_faulty_implementation_served_remotely_is_rejected() -> None:
    with served("--backend", "tests.variants:SlowTakeover", "--profile", "crh2") as url:
        result = run_features(None, "--item=R-CTL-03", sut=url)
    assert result.returncode == 1 and " failed" in result.stdout.splitlines()[-1], result.stdout[-2000:]


def test_a_served_profile_restricts_what_runs() -> None:
    with served("--profile", "atp") as url:
        assert resolve(url).PROFILES == ("atp",)
        result = run_features(None, "--item=F-ATP-12,R-DSP-01", "-rA", sut=url)
    assert result.returncode == 0, result.stdout[-2000:]
    assert re.search(r"^SKIPPED .*profile crh2: the SUT RemoteTrain declares atp", result.stdout, re.M), \
        result.stdout[-2000:]


def _drive(train: TrainDriver) -> list:
    """The same calls on any backend; returns what they returned."""
    train.configure(sets=1)
    with pytest.raises(NotPoweredUp):
        train.advance(1000)
    train.insert_key(1)
    train.power_on()
    with pytest.raises(UnknownName, match="'car99.LCU'"):
        train.counters("car99.LCU")
    with pytest.raises(OutOfRange, match="traction notch 99 is out of range"):
        train.set_traction(1, 99)
    train.advance_ms(600)
    train.request_block_transfer("car3.LCU", b"\x00\xffrecord")
    train.advance_ms(200)
    return [train.now_us, train.ring_nodes(), train.block_store("car1.CCU.sys1"), train.counters("car3.LCU"),
            train.monitor(1), train.token_holder()]


def test_the_client_carries_the_interface_errors_values_and_trace() -> None:
    with open_backend("reference", "crh2") as local:
        expected = _drive(local)
        expected_trace = local.trace.to_csv()
    with served("--profile", "crh2") as url:
        with open_backend(url, "crh2") as train:
            assert _drive(train) == expected
            assert train.trace.to_csv() == expected_trace
            assert train.describe()["SUT backend"].startswith(url)
    assert expected[0] == 800_000 and expected[2], "the block record did not arrive: nothing compared"


def test_client_and_server_agree_on_the_interface() -> None:
    public = {name for name in dir(TrainDriver) if not name.startswith("_")}
    assert wire.METHODS <= public
    computed = {"advance_ms", "cut_ring", "shutdown", "open", "powered", "now_us", "trace", "check_us",
                "check_direction", "PROFILES", "backend_name", "DETERMINISTIC", "DECLARATION",
                "snapshot", "from_snapshot"}        # in-process copies of a train: never over the wire
    assert public - wire.METHODS == computed, "a driver method the protocol does not carry"
    # every protocol method reaches the server: none left to TrainDriver's NotSupported default
    assert all(getattr(client.RemoteTrain, name) is not getattr(TrainDriver, name, None) for name in wire.METHODS
               if name not in ("power_on", "advance", "soak"))


# -- bad peers: the server side ----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def local_server() -> Iterator[str]:
    srv, thread = server.start("reference", ["crh2"])
    yield srv.url
    srv.shutdown()
    srv.server_close()


def _raw(url: str, *lines: bytes, hello: bool = True, closes: bool = True, timeout: float = 5) -> list:
    """The answers to `lines` and, with `closes`, what follows the last one (None: the server closed)."""
    host, port, _ = client.parse_url(url)
    with socket.create_connection((host, port), timeout=timeout) as sock:
        stream = sock.makefile("rb")
        answers = []
        if hello:
            sock.sendall(wire.dumps({"hello": wire.PROTOCOL, "versions": [1]}))
            answers.append(wire.read_message(stream, wire.MAX_RESPONSE))
        for line in lines:
            sock.sendall(line)
            answers.append(wire.read_message(stream, wire.MAX_RESPONSE))
        if closes:
            answers.append(wire.read_message(stream, wire.MAX_RESPONSE))
        return answers


@pytest.mark.parametrize(("line", "says"), [
    (b"this is not json\n", "not JSON"),
    (b"[1,2]\n", "a message is a JSON object"),
    (b'{"op":"open"}\n', "integer id"),
    (b'{"id":1,"op":"call","method":"advance","args":[1]}\n', "before open"),
    (b'{"id":1,"op":"launch"}\n', "unknown op 'launch'"),
    (b"\xff\xfe\n", "not UTF-8"),
    (b'{"id":' + b"9" * 5000 + b',"op":"open"}\n', "not JSON the protocol can carry"),   # past int's digit limit
])
def test_the_server_answers_garbage_and_closes(local_server: str, line: bytes, says: str) -> None:
    hello, answer, after = _raw(local_server, line)
    assert hello["version"] == 1 and hello["profiles"] == ["crh2"]
    assert answer["error"]["type"] == "ProtocolError" and says in answer["error"]["message"], answer
    assert after is None, "the server kept a garbled connection open"


def test_the_server_refuses_a_method_outside_the_interface(local_server: str) -> None:
    opened = b'{"id":1,"op":"open","profile":"crh2"}\n'
    call = b'{"id":2,"op":"call","method":"_advance","args":[5],"kwargs":{}}\n'
    _, first, answer, after = _raw(local_server, opened, call)
    assert first == {"id": 1, "result": None}
    assert answer["error"]["type"] == "ProtocolError" and "not part of the driver interface" in answer["error"]["message"]
    assert after is None


def test_the_server_reports_a_version_mismatch(local_server: str) -> None:
    answer, after = _raw(local_server, wire.dumps({"hello": wire.PROTOCOL, "versions": [7]}), hello=False)
    assert answer["error"]["type"] == "VersionMismatch" and "[7]" in answer["error"]["message"]
    assert after is None


def test_a_bug_in_the_served_backend_is_a_remote_error(local_server: str) -> None:
    opened = b'{"id":1,"op":"open","profile":"crh2"}\n'
    bad = b'{"id":2,"op":"call","method":"configure","args":[],"kwargs":{"wheels":4}}\n'
    good = b'{"id":3,"op":"call","method":"configure","args":[],"kwargs":{}}\n'
    _, _, answer, fine = _raw(local_server, opened, bad, good, closes=False)
    assert answer["error"]["type"] == "RemoteError" and "wheels" in answer["error"]["message"]
    assert fine == {"id": 3, "result": None}, "one bad call closed the connection"


# -- bad peers: the client side ----------------------------------------------------------------------------
@contextmanager
def fake_server(behaviour) -> Iterator[str]:
    """A TCP peer on loopback that runs `behaviour(connection)` for every client."""
    listener = socket.create_server(("127.0.0.1", 0))
    stop = threading.Event()

    def accept() -> None:
        listener.settimeout(0.2)
        while not stop.is_set():
            try:
                conn, _ = listener.accept()
            except OSError:
                continue
            with conn:
                try:
                    behaviour(conn, conn.makefile("rb"))
                except OSError:
                    pass
    thread = threading.Thread(target=accept, daemon=True)
    thread.start()
    try:
        yield f"tcp://127.0.0.1:{listener.getsockname()[1]}"
    finally:
        stop.set()
        thread.join(5)
        listener.close()


HELLO = wire.dumps({"hello": wire.PROTOCOL, "version": 1, "backend": "fake", "profiles": ["crh2"],
                    "trace_chunk": 10})


def _answer_hello_then(then):
    def behaviour(conn: socket.socket, stream) -> None:
        stream.readline()
        conn.sendall(HELLO)
        then(conn, stream)
    return behaviour


def _open_ok_then(then):
    def after_hello(conn: socket.socket, stream) -> None:
        stream.readline()
        conn.sendall(b'{"id":1,"result":null}\n')
        then(conn, stream)
    return _answer_hello_then(after_hello)


def _silent(conn, stream) -> None:
    stream.readline()
    time.sleep(2)


@pytest.mark.parametrize(("behaviour", "says"), [
    (lambda conn, stream: (stream.readline(), conn.sendall(b"SSH-2.0-OpenSSH_9.2\r\n")), "garbled answer: not JSON"),
    (lambda conn, stream: (stream.readline(), conn.sendall(b'{"hello": "crh2-sut", "vers')),
     "garbled answer: truncated message"),
    (lambda conn, stream: stream.readline(), "closed the connection during hello"),
    (lambda conn, stream: conn.sendall(b'{"hello":"http","version":1,"profiles":[]}\n'), "not a crh2-sut server"),
    (lambda conn, stream: (stream.readline(), conn.sendall(wire.dumps({"error": {"type": "VersionMismatch",
                                                                        "message": "only 2"}}))),
     "refused the connection: VersionMismatch: only 2"),
    (_answer_hello_then(_silent), "no answer to open within 0.5 s"),
    (_open_ok_then(lambda conn, stream: (stream.readline(), conn.sendall(b'{"id":7,"result":null}\n'))),
     "answer to request 7, expected 2"),
    (_open_ok_then(lambda conn, stream: (stream.readline(), conn.sendall(b'{"id":2,"result":{"$bytes":"zz"}}\n'))),
     "garbled result: $bytes"),
    (_open_ok_then(_silent), "no answer to configure() within 0.5 s"),
    (_open_ok_then(lambda conn, stream: (stream.readline(), conn.sendall(b'{"id":2,"result":' + b"7" * 5000 + b"}\n"))),
     "garbled answer: not JSON the protocol can carry"),
])
def test_a_bad_server_is_not_reachable_quickly(behaviour, says: str) -> None:
    with fake_server(behaviour) as url:
        started = time.monotonic()
        with pytest.raises(SutUnreachable) as caught:
            cls = type("Fake", (client.RemoteTrain,), {"URL": url + "?timeout=0.5", "PROFILES": ("crh2",)})
            cls.open("crh2").configure(sets=1)
        assert time.monotonic() - started < 3
    message = str(caught.value)
    assert message.startswith(f"SUT not reachable at {url}") and says in message, message
    assert any(re.match(c["messageRegex"], message) for c in CATEGORIES if c["name"] == "SUT not reachable")


def test_nothing_listening_is_a_usage_error_at_start() -> None:
    with socket.create_server(("127.0.0.1", 0)) as probe:
        port = probe.getsockname()[1]
    result = run_features(None, "--item=R-DSP-01", sut=f"tcp://127.0.0.1:{port}")
    assert result.returncode == 4, result.stdout[-1000:]
    assert f"SUT not reachable at tcp://127.0.0.1:{port}: cannot connect" in result.stderr


def test_a_server_that_stops_answering_fails_the_scenarios_as_not_reachable() -> None:
    """The hello works (so the run starts), then every train hangs: each scenario fails within the timeout."""
    def hang_after_open(conn, stream) -> None:
        stream.readline()
        conn.sendall(b'{"id":1,"result":null}\n')
        stream.readline()
        time.sleep(1.5)             # holds the connection open, silent, well past the client's timeout
    with fake_server(_answer_hello_then(hang_after_open)) as url:
        started = time.monotonic()
        # A quarter second: the server never answers, so any timeout shows it; each scenario waits it out.
        result = run_features(None, "--item=R-DSP-01", "-rA", sut=url + "?timeout=0.25")
        elapsed = time.monotonic() - started
    assert result.returncode == 1, result.stdout[-2000:]
    assert "passed" not in result.stdout.splitlines()[-1]
    # Failed once on a clean clone under load (2026-11-29, 08:50; it passed 3 of 3 here and on the clone before),
    # with the output cut where it would say why: any call meeting the silence counts, and a failure shows the tail.
    assert "SUT not reachable" in result.stdout, result.stdout[-3000:]
    assert re.search(r"no answer to \w+\(\) within 0\.25 s", result.stdout), result.stdout[-3000:]
    assert elapsed < 60


# -- the wire codec on arbitrary input ------------------------------------------------------------------
@FUZZ
@given(st.binary(max_size=300))
def test_any_line_is_a_message_or_a_wire_error(line: bytes) -> None:
    try:
        message = wire.loads(line)
    except wire.WireError:
        return
    assert isinstance(message, dict)


@FUZZ
@given(st.integers(min_value=1, max_value=12_000), st.booleans(),
       st.sampled_from([b'{"id":%d}', b'{"id":1,"result":%d}', b'{"id":1,"events":[[%d,"a","b",{}]]}']))
def test_a_number_of_any_length_is_a_message_or_a_wire_error(digits: int, negative: bool, template: bytes) -> None:
    """JSON has no limit on an integer's digits, Python's int() has (4300): past it is a WireError too."""
    line = template.replace(b"%d", b"-" * negative + b"7" * digits) + b"\n"
    try:
        message = wire.loads(line)
    except wire.WireError:
        assert digits > 4000
        return
    assert isinstance(message, dict)


JSON = st.recursive(st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False)
                    | st.text(max_size=8), lambda inner: st.lists(inner, max_size=4)
                    | st.dictionaries(st.text(max_size=6), inner, max_size=4), max_leaves=12)
VALUES = st.recursive(st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False)
                      | st.text(max_size=8) | st.binary(max_size=8),
                      lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner,
                                                                                   max_size=4), max_leaves=12)


@FUZZ
@given(VALUES)
def test_values_survive_the_wire(value) -> None:
    line = wire.dumps({"v": wire.encode_value(value)})
    assert line.count(b"\n") == 1 and line.endswith(b"\n")
    assert wire.decode_value(wire.loads(line)["v"]) == value


@FUZZ
@given(JSON)
def test_any_json_event_is_an_event_or_a_wire_error(item) -> None:
    try:
        t, source, kind, fields = wire.event_from_wire(item)
    except wire.WireError:
        return
    assert isinstance(t, int) and isinstance(fields, dict)


@FUZZ
@given(st.dictionaries(st.sampled_from(["id", "op", "method", "args", "kwargs", "profile", "since", "limit"]),
                       JSON | st.sampled_from(["open", "call", "state", "trace", "close", "ring_nodes", "advance"]),
                       max_size=6))
def test_any_request_gets_an_answer(request: dict) -> None:
    session = server.Session(resolve("reference"), ("crh2",))
    try:
        answer = server._Handler._answer(session, request)
        assert answer.keys() >= {"id"} and ("error" in answer or answer.keys() & {"result", "now_us", "events"})
        if "error" in answer:
            assert answer["error"]["type"] in {"ProtocolError", "RemoteError", "UnknownName", "OutOfRange",
                                               "NotPoweredUp", "NotSupported", "SutError"}
        wire.dumps(answer)
    finally:
        session.close()


def _watched(train: TrainDriver, *, looks: bool = False) -> tuple[list, str]:
    """A watch of the cab 1 monitor across a board failure and its repair; with `looks`, TrainDriver's
    own look-by-look loop instead of the backend's watch."""
    train.configure(sets=1, cars_per_set=8)
    train.power_on()
    train.advance_ms(1000)
    watch = TrainDriver.watch_monitor.__get__(train) if looks else train.watch_monitor
    seen = watch(1, 20_000, 1000)
    train.fail("car3.LCU.CPU3")
    seen += watch(1, 400_000, 1000)
    train.repair("car3.LCU.CPU3")
    seen += watch(1, 300_000, 7000)
    return [(t, list(faults)) for t, faults in seen], train.trace.to_csv()


def test_a_watch_of_the_monitor_is_what_looking_between_advances_sees_in_process_and_remote() -> None:
    with open_backend("reference", "crh2") as local:
        expected = _watched(local, looks=True)
    with open_backend("reference", "crh2") as local:
        assert _watched(local) == expected
    samples, _ = expected
    assert len(samples) == 21 + 401 + 44 and samples[-1][0] == 1_720_000
    shown = {fault for _, faults in samples for fault in faults}
    assert any("car3" in fault for fault in shown) and samples[0][1] == [], "the watch saw nothing change"
    with served("--profile", "crh2") as url:
        with open_backend(url, "crh2") as train:
            assert _watched(train) == expected


def test_a_watch_checks_its_span_and_step() -> None:
    with open_backend("reference", "crh2") as train:
        train.configure(sets=1, cars_per_set=8)
        train.power_on()
        for span, step in ((-1, 1000), (1000, 0), (1000, 1.5)):
            with pytest.raises(OutOfRange):
                train.watch_monitor(1, span, step)
