"""Settings from the environment (LEADSCREW_*) or the command line."""

from functools import lru_cache
from pathlib import Path

from pydantic_settings import BaseSettings, SettingsConfigDict


class Settings(BaseSettings):
    model_config = SettingsConfigDict(env_prefix="LEADSCREW_")

    catalog_dirs: list[Path] = []
    max_body_bytes: int = 64 * 1024
    #: the selector's form submits every field and each cell of its table of moves: about
    #: 70 parameters and 1.2 KB, and 8 and 100 bytes more a move (tests/web/test_move_table.py);
    #: 50 moves (the most a cycle has) stay within these
    max_query_chars: int = 8192
    max_query_params: int = 512
    #: bytes of whole responses kept per process for repeated selection queries (0: off)
    response_cache_bytes: int = 16 * 1024 * 1024
    #: responses kept at most, however small (0: off)
    response_cache_entries: int = 4096
    #: requests one process works on at once, counted by cost (a page or a compact select
    #: 1, an answer with every number 1 + limit / 8: app.server.overload); more are
    #: answered 503 at once (0: no limit). 32 units of work (about 4 ms each) are all
    #: answered within a fraction of a second; past that, a client does better to retry or
    #: go to another process.
    max_requests_in_flight: int = 32
    #: threads that compute selections and pages, off the event loop (app.server.compute)
    compute_threads: int = 2
    #: how often the interpreter lets another thread run while the compute threads work [s]
    #: (Python's own is 5 ms: app.server.compute)
    thread_switch_interval_s: float = 0.0005
    #: the Retry-After of those 503s [s], and how long nothing more is read from a
    #: connection after its request was shed (not through the proxy: app.server.protocol)
    overload_retry_after_s: int = 1
    # --- the server (app.cli, app.server.protocol) ---
    #: a request's head and body must arrive within this many seconds of the connection
    #: opening or of the request's first byte, else the connection is closed
    request_read_timeout_s: float = 10.0
    #: an idle connection between two requests is closed after this many seconds
    keep_alive_timeout_s: int = 5
    #: on SIGTERM, requests still in progress this many seconds later are cancelled and
    #: the process exits (under Kubernetes' 30 s grace period less the 5 s preStop pause)
    graceful_shutdown_timeout_s: int = 20
    #: request line and headers together, in bytes, and the number of header lines (431)
    max_header_bytes: int = 32 * 1024
    max_headers: int = 100
    #: open connections per process past which a request (not the health check) is
    #: answered 503 with Retry-After and its connection closed (app.server.protocol)
    max_connections: int = 1024


@lru_cache
def get_settings() -> Settings:
    return Settings()
