"""The SUT driver over a process boundary: JSON lines on TCP (sut/PROTOCOL.md).

`server.serve()` puts any backend behind a port (`python -m sut serve`); `client.remote_class(url)` is the
backend `--sut tcp://host:port` names. The suite cannot tell the two apart: same verdicts, same traces.
"""
