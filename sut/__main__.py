"""`python -m sut serve`: put a SUT backend behind a TCP port for `pytest --sut tcp://host:port`."""
from __future__ import annotations

import argparse
import signal
import sys

from sut.backends import BACKENDS
from sut.errors import SutError
from sut.remote import wire


def _interrupt(*_: object) -> None:
    raise KeyboardInterrupt


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m sut",
        description="The system under test, outside the test process (protocol: sut/PROTOCOL.md).")
    sub = parser.add_subparsers(dest="command", required=True, metavar="{serve}")
    serve = sub.add_parser(
        "serve", help="serve a backend on TCP (one connection = one train)",
        description="Serve a SUT backend on TCP until interrupted. Each connection opens its own train; "
                    f"the protocol is {wire.PROTOCOL} version(s) {', '.join(map(str, wire.VERSIONS))} "
                    "(sut/PROTOCOL.md). Then run the suite with: pytest features --sut tcp://HOST:PORT",
        epilog="example: python -m sut serve --profile crh2 --port 7411")
    serve.add_argument("--backend", default="reference", metavar="NAME",
                       help=f"backend to serve: {', '.join(BACKENDS)} or package.module:Class (default: %(default)s)")
    serve.add_argument("--profile", action="append", default=[], metavar="NAME",
                       help="serve only this train profile (repeatable; default: every profile the backend declares)")
    serve.add_argument("--host", default="127.0.0.1", help="address to listen on (default: %(default)s, loopback only)")
    serve.add_argument("--port", type=int, default=0, help="port (default: 0 = any free port, printed at start)")
    args = parser.parse_args(argv)

    from sut.remote.server import make_server

    try:
        server = make_server(args.backend, args.profile, args.host, args.port)
    except (SutError, OSError) as exc:
        print(f"python -m sut serve: {exc}", file=sys.stderr)
        return 2
    signal.signal(signal.SIGTERM, _interrupt)
    # The first line is for whoever started us (a test, a script): where to connect.
    print(f"serving {args.backend} ({', '.join(server.served)}) on {server.url}", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
