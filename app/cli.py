"""Console script ``leadscrew-selector``: serve the app with uvicorn."""

import argparse
import json
import os
import signal
import sys
from pathlib import Path
from types import FrameType

import uvicorn

from app.catalog import CatalogError, load_catalog
from app.server.protocol import BoundedHttpToolsProtocol
from app.settings import get_settings


def event_loop(workers: int) -> str:
    """The event loop for ``workers`` processes.

    One process (a pod, the default): asyncio's own loop, which accepts every connection
    waiting when the listening socket turns readable. uvloop's (libuv since
    libuv/libuv#3696; seen here with uvloop 0.23) accepts one per loop iteration, so while
    the worker is busy a new connection waits behind as many iterations as there are
    connections in use: with 32 connections opening at once on the results fragment, p99
    1.2 s against 0.2 s on asyncio's loop at the same throughput (``python3 bench/run.py``).
    Several processes sharing one socket: uvloop, for the same reason the other way round:
    the first process to wake would take every waiting connection on asyncio's loop (two
    workers served 1.0 times one), one at a time they spread (2.1 times).
    """
    return "asyncio" if workers == 1 else "uvloop"


def _stopped(signum: int, frame: FrameType | None) -> None:
    """A requested stop is a clean exit.

    uvicorn shuts down gracefully on SIGTERM or SIGINT, then raises the signal again for
    the handler that was there before it: this one, so that the process exits 0 instead
    of dying by the signal (exit 143) or with a KeyboardInterrupt traceback.
    """
    raise SystemExit(0)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="leadscrew-selector", description=__doc__)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=8000)
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument(
        "--log-level",
        default="info",
        choices=("critical", "error", "warning", "info", "debug"),
        help="info logs each request; warning and above do not",
    )
    parser.add_argument(
        "--catalog-dir",
        action="append",
        type=Path,
        default=[],
        help="extra catalog directory merged into the built-in one (repeatable)",
    )
    args = parser.parse_args(argv)
    try:
        load_catalog(args.catalog_dir)  # fail before forking workers, with the file named
    except CatalogError as exc:
        print(f"catalog error: {exc}", file=sys.stderr)
        return 2
    if args.catalog_dir:
        os.environ["LEADSCREW_CATALOG_DIRS"] = json.dumps(
            [str(p.resolve()) for p in args.catalog_dir]
        )
    for stop in (signal.SIGTERM, signal.SIGINT):
        signal.signal(stop, _stopped)
    settings = get_settings()
    uvicorn.run(
        "app.main:create_app",
        factory=True,
        host=args.host,
        port=args.port,
        workers=args.workers,
        proxy_headers=True,
        loop=event_loop(args.workers),
        log_level=args.log_level,
        # request-read deadline and head limits: app.server.protocol, from the same settings
        http=BoundedHttpToolsProtocol,
        timeout_keep_alive=settings.keep_alive_timeout_s,
        limit_concurrency=settings.max_connections,
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
