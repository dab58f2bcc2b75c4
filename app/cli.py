"""Console script ``leadscrew-selector``: serve the app with uvicorn."""

import argparse
import json
import os
import re
import signal
import sys
from collections.abc import Callable
from pathlib import Path
from types import FrameType

import uvicorn
from pydantic import ValidationError
from pydantic_settings import SettingsError

from app.catalog import CatalogError, load_catalog
from app.server.protocol import BoundedHttpToolsProtocol
from app.server.settings import Settings, get_settings

#: worker processes at most: one per core is the advice, and each holds the catalog
MAX_WORKERS = 64


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


def whole_number(low: int, high: int) -> Callable[[str], int]:
    """An argparse type: a whole number from ``low`` to ``high``, else a usage error
    (exit 2, one line) rather than a traceback or a server that starts on nonsense.

    >>> whole_number(1, 65535)("8000")
    8000
    """

    def parse(text: str) -> int:
        # digits only: int() would also read "1_0" as 10 and " 8000" as 8000
        if not re.fullmatch(r"-?[0-9]+", text):
            raise argparse.ArgumentTypeError(f"not a whole number: {text!r}")
        value = int(text)
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"must be {low} to {high}, got {value}")
        return value

    return parse


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="leadscrew-selector", description=__doc__)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=whole_number(1, 65535), default=8000)
    parser.add_argument("--workers", type=whole_number(1, MAX_WORKERS), default=1)
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
        help="extra catalog directory merged into the built-in one (repeatable; "
        "default: LEADSCREW_CATALOG_DIRS)",
    )
    return parser


class StartError(Exception):
    """A fault that stops start-up, with the line to print."""


def _checked_settings(catalog_dirs: list[Path]) -> Settings:
    """The settings, and the catalog they name loaded once: every fault stops start-up
    here, before any worker is forked (a worker failing at start-up is started again,
    for ever), as one line naming the setting or the catalog file. ``catalog_dirs`` (the
    command line's) replace the environment's."""
    if catalog_dirs:
        # set before the settings are first read: one worker runs the app factory in this
        # process, and reads the cached settings, not the command line
        os.environ["LEADSCREW_CATALOG_DIRS"] = json.dumps([str(p.resolve()) for p in catalog_dirs])
        get_settings.cache_clear()
    try:
        settings = get_settings()
    except ValidationError as exc:
        raise StartError(f"settings error: {_one_line(exc)}") from exc
    except SettingsError as exc:  # a value that is not JSON where JSON is needed
        raise StartError(f"settings error: {exc}") from exc
    try:
        load_catalog(settings.catalog_dirs)
    except CatalogError as exc:
        raise StartError(f"catalog error: {exc}") from exc
    return settings


def _one_line(exc: ValidationError) -> str:
    """A settings error as the variable and the reason, on one line."""
    return "; ".join(f"LEADSCREW_{str(e['loc'][0]).upper()}: {e['msg']}" for e in exc.errors())


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        settings = _checked_settings(args.catalog_dir)
    except StartError as exc:
        print(exc, file=sys.stderr)
        return 2
    for stop in (signal.SIGTERM, signal.SIGINT):
        signal.signal(stop, _stopped)
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
        # kept-alive connections drain and close cleanly: app.server.protocol
        timeout_graceful_shutdown=settings.graceful_shutdown_timeout_s,
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
