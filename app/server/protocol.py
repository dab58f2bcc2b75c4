"""uvicorn's httptools protocol with a request-read deadline and request-head limits.

uvicorn bounds the time an idle connection stays open between requests
(``timeout_keep_alive``), but not the time a client may take to send a request: a
connection that sends nothing, or half a header and then a byte a minute, stays open for
good. Nor does the httptools parser bound a request's head: it gathers a 50 MB header
value in memory as readily as a short one. This protocol adds both bounds:

* the request (head and body) must arrive within ``request_read_timeout_s`` of the
  connection opening or of its first byte, else the connection is closed;
* the request line and headers together may take ``max_header_bytes`` and there may be
  ``max_headers`` of them, else the answer is 431 and the connection is closed, after
  reading at most one socket read past the limit.

* past ``max_connections`` open connections, a request other than the health check is
  answered 503 with Retry-After and the security headers, and its connection closed
  (uvicorn's own limit answers every request a bare 503, the health check included, so
  a thousand idle sockets would make a balancer take the process for dead).

* after a request is shed (503, ``app.server.overload``), nothing more is read from its
  connection for the Retry-After (``overload_retry_after_s``), unless it came through the
  proxy (``X-Forwarded-For``: nginx limits each address itself, and its next request on
  that connection may be another client's). A client that asks again at once, told to
  wait, waits: 64 such clients otherwise kept the event loop refusing 700 requests a
  second, starving the computing they waited for, and the health check queued behind.

* the health check (GET or HEAD of the health path, no query, no body) is answered as
  soon as its head is parsed, with the bytes the app gave the first time it was asked
  (``HealthRecorder``; the answer rests on the version and the catalog, both fixed for
  the life of the process): it never waits for an ASGI task to start and run through the
  middleware behind a flood's work on the event loop (64 clients pulling the 1.4 MB
  catalog page made its p99 1.05 s). Behind a request still in progress on the same
  connection it keeps its turn (pipelining), through the app as before.

* on SIGTERM, a request already sent on a kept-alive connection is answered, and the
  connection then closed cleanly (``shutdown``), where uvicorn's own would close an idle
  connection at once and reset any request waiting unread in its socket.

The limits come from ``app.server.settings`` (``LEADSCREW_*``), so every worker process that
uvicorn starts reads the same ones.
"""

import asyncio
import logging
from collections.abc import Mapping
from typing import Any

from uvicorn.config import Config
from uvicorn.protocols.http.flow_control import service_unavailable
from uvicorn.protocols.http.httptools_impl import (
    STATUS_LINE,
    HttpToolsProtocol,
    RequestResponseCycle,
)
from uvicorn.protocols.utils import get_client_addr, get_path_with_query_string
from uvicorn.server import ServerState

from app.server.overload import (
    NEVER_SHED,
    SHED_KEY,
    ASGIApp,
    Message,
    Receive,
    Scope,
    Send,
    send_busy,
)
from app.server.security import SECURITY_HEADERS
from app.server.settings import get_settings

logger = logging.getLogger("uvicorn.error")
#: what a header line adds to the head besides its name and value: ": " and CRLF
HEADER_LINE_OVERHEAD_BYTES = 4
#: On SIGTERM, how long an idle kept-alive connection stays open for a request already on
#: its way (sent before the signal and not yet read by a busy loop, or crossing it): such a
#: request is answered with ``Connection: close``. Then the connection is half-closed, and
#: what the client still sends is read and dropped for ``SHUTDOWN_LINGER_S`` at most, so
#: the close is a FIN, never a reset.
SHUTDOWN_DRAIN_S = 0.5
SHUTDOWN_LINGER_S = 2.0
#: the ``app_state`` key (shared by every connection of one server) of the health check's
#: answer as the app gave it: (headers, body)
HEALTH_ANSWER = "app.server.health_answer"
#: request headers that announce a body: such a request goes through the app, whose
#: limits decide what to do with it
BODY_HEADERS = frozenset({b"content-length", b"transfer-encoding"})
HealthAnswer = tuple[list[tuple[bytes, bytes]], bytes]


class HeadTooLarge(Exception):
    """Raised in a parser callback to stop parsing a request head past the limits."""


class OverLimit:
    """The app as a connection past the connection limit meets it: the health check as
    ever, every other request 503 with Retry-After and the security headers (the app's
    own layers are not reached), and the connection closed to free its place."""

    def __init__(self, app: ASGIApp, retry_after_s: int) -> None:
        self.app = app
        self.retry_after_s = retry_after_s

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["path"] in NEVER_SHED:
            await self.app(scope, receive, send)
            return
        await send_busy(send, self.retry_after_s, *SECURITY_HEADERS, (b"connection", b"close"))


def is_plain_health_check(scope: Mapping[str, Any]) -> bool:
    """A GET or HEAD of the health path with no query and no body: always the same answer.

    >>> scope = {"path": "/api/v1/health", "method": "HEAD", "query_string": b"", "headers": []}
    >>> is_plain_health_check(scope), is_plain_health_check({**scope, "query_string": b"x=1"})
    (True, False)
    """
    return (
        scope["path"] in NEVER_SHED
        and scope["method"] in ("GET", "HEAD")
        and not scope["query_string"]
        and not any(name in BODY_HEADERS for name, _ in scope["headers"])
    )


class HealthRecorder:
    """The app, keeping its answer to a plain health check in ``store`` (``HEALTH_ANSWER``)
    when it is a 200 sent whole and not compressed: headers as they leave the outermost
    middleware, and body."""

    def __init__(self, app: ASGIApp, store: dict[str, Any]) -> None:
        self.app = app
        self.store = store

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        start: Message = {}

        async def recording(message: Message) -> None:
            if message["type"] == "http.response.start":
                start.update(message)
            elif start.get("status") == 200 and not message.get("more_body", False):
                headers = list(start.get("headers", []))
                # a compressed answer suits only a client that accepts gzip
                if not any(name == b"content-encoding" for name, _ in headers):
                    self.store.setdefault(HEALTH_ANSWER, (headers, bytes(message.get("body", b""))))
            await send(message)

        await self.app(scope, receive, recording)


class BoundedHttpToolsProtocol(HttpToolsProtocol):
    """``HttpToolsProtocol`` with a deadline to read each request and a bounded head."""

    def __init__(
        self,
        config: Config,
        server_state: ServerState,
        app_state: dict[str, Any],
        _loop: asyncio.AbstractEventLoop | None = None,
    ) -> None:
        super().__init__(config, server_state, app_state, _loop)
        settings = get_settings()
        self.max_connections = settings.max_connections
        self.over_limit = OverLimit(self.app, settings.overload_retry_after_s)
        self.read_timeout_s = settings.request_read_timeout_s
        self.max_header_bytes = settings.max_header_bytes
        self.max_headers = settings.max_headers
        self.read_deadline: asyncio.TimerHandle | None = None
        self.reading_head = True
        # bytes received while the head is incomplete (bounds memory before parsing ends),
        # and the parsed head's exact size and header count
        self.received_head_bytes = 0
        self.head_bytes = 0
        self.head_count = 0
        self.head_too_large = False
        # set by ``shutdown``: no request after the one in progress; the drain's timer;
        # whether the connection is half-closed (what arrives is dropped)
        self.stopping = False
        self.drain_timer: asyncio.TimerHandle | None = None
        self.half_closed = False
        # a request shed (``_was_shed``): reading pauses once its answer is sent, for
        # ``shed_pause_s``
        self.shed_pause_s = float(settings.overload_retry_after_s)
        self.pause_after_response = False
        self.shed_timer: asyncio.TimerHandle | None = None

    # --- the read deadline ----------------------------------------------------------

    def _start_read_deadline(self) -> None:
        if self.read_deadline is None:
            self.read_deadline = self.loop.call_later(self.read_timeout_s, self._read_timed_out)

    def _stop_read_deadline(self) -> None:
        if self.read_deadline is not None:
            self.read_deadline.cancel()
            self.read_deadline = None

    def _read_timed_out(self) -> None:
        """The client took too long to send its request: free the connection."""
        self.read_deadline = None
        if not self.transport.is_closing():
            logger.info("Request not received within %s s, connection closed", self.read_timeout_s)
            self.transport.close()

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        self._start_read_deadline()

    def connection_lost(self, exc: Exception | None) -> None:
        self._stop_read_deadline()
        self._stop_drain()
        self._end_shed_pause()
        super().connection_lost(exc)

    def on_message_begin(self) -> None:
        super().on_message_begin()
        self._start_read_deadline()
        # a request under way during the drain is answered, and then closes the connection
        self._stop_drain()

    # --- graceful shutdown ----------------------------------------------------------

    def shutdown(self) -> None:
        """The server stops (SIGTERM): the request in progress is answered with
        ``Connection: close`` (as uvicorn does); an idle connection is kept for
        ``SHUTDOWN_DRAIN_S`` so that a request already sent is answered the same way, then
        closed cleanly (``_close_idle``)."""
        self.stopping = True
        self._end_shed_pause()  # what was sent meanwhile is answered or closed cleanly
        if self.cycle is not None and not self.cycle.response_complete:
            self.cycle.keep_alive = False
            return
        if self.received_head_bytes:
            return  # a request's head is arriving: answered, or ended by the read deadline
        self._unset_keepalive_if_required()
        self.drain_timer = self.loop.call_later(SHUTDOWN_DRAIN_S, self._close_idle)

    def _stop_drain(self) -> None:
        if self.drain_timer is not None:
            self.drain_timer.cancel()
            self.drain_timer = None

    def _close_idle(self) -> None:
        """Half-close: a FIN tells the client no answer will come; what it still sends is
        read and dropped (``data_received``), so the kernel never answers it with a reset;
        the connection ends when the client closes its side, or after
        ``SHUTDOWN_LINGER_S``."""
        self.drain_timer = None
        if self.transport.is_closing():
            return
        self.half_closed = True
        if self.transport.can_write_eof():
            self.transport.write_eof()
        self.loop.call_later(SHUTDOWN_LINGER_S, self.transport.close)

    # --- a pause after a shed request ------------------------------------------------

    def _was_shed(self) -> None:
        """Called by the overload middleware (``SHED_KEY``) when it sheds this request."""
        proxied = any(name == b"x-forwarded-for" for name, _ in self.scope["headers"])
        self.pause_after_response = not proxied

    def on_response_complete(self) -> None:
        super().on_response_complete()
        if self.pause_after_response and not self.stopping and not self.transport.is_closing():
            self.flow.pause_reading()
            self.shed_timer = self.loop.call_later(self.shed_pause_s, self._end_shed_pause)
        self.pause_after_response = False

    def _end_shed_pause(self) -> None:
        if self.shed_timer is not None:
            self.shed_timer.cancel()
            self.shed_timer = None
            if not self.transport.is_closing():
                self.flow.resume_reading()

    # --- the health check, answered here ---------------------------------------------

    def _start_asgi_task(self, cycle: RequestResponseCycle, app: Any) -> None:
        """Start the app on a request, or answer a plain health check at once from the
        app's recorded answer (``HealthRecorder`` records the first). Not for one taken
        off the pipeline with more behind it: each would answer the next from inside the
        last, as deep as the pipeline is long."""
        if app is not service_unavailable and is_plain_health_check(cycle.scope):
            answer: HealthAnswer | None = self.app_state.get(HEALTH_ANSWER)
            if answer is None:
                if cycle.scope["method"] == "GET":  # a HEAD's answer has no body to keep
                    app = HealthRecorder(app, self.app_state)
            elif not self.flow.write_paused and not self.pipeline:
                self._answer_health(cycle, answer)
                return
        super()._start_asgi_task(cycle, app)

    def _answer_health(self, cycle: RequestResponseCycle, answer: HealthAnswer) -> None:
        """Write the recorded answer as uvicorn's cycle writes the app's: the server's
        default headers (date, server) first, ``connection: close`` when the connection
        is not kept alive, no body to a HEAD; then complete the response as it does."""
        headers, body = answer
        scope = cycle.scope
        cycle.keep_alive = cycle.keep_alive and not self.stopping
        cycle.response_started = cycle.response_complete = True
        cycle.waiting_for_100_continue = False
        if self.access_log:
            self.access_logger.info(
                '%s - "%s %s HTTP/%s" %d',
                get_client_addr(scope),
                scope["method"],
                get_path_with_query_string(scope),
                scope["http_version"],
                200,
            )
        content = [STATUS_LINE[200]]
        for name, value in (*cycle.default_headers, *headers):
            content += [name, b": ", value, b"\r\n"]
        if not cycle.keep_alive:
            content.append(b"connection: close\r\n")
        content.append(b"\r\n")
        if scope["method"] != "HEAD":
            content.append(body)
        self.transport.write(b"".join(content))
        cycle.message_event.set()
        if not cycle.keep_alive:
            self.transport.close()
        cycle.on_response()

    def on_message_complete(self) -> None:
        super().on_message_complete()
        self._stop_read_deadline()
        self.reading_head = True

    # --- the head limits ------------------------------------------------------------

    def data_received(self, data: bytes) -> None:
        if self.half_closed:
            return
        if self.reading_head:
            self.received_head_bytes += len(data)
        super().data_received(data)
        if (
            self.reading_head
            and self.received_head_bytes > self.max_header_bytes
            and not self.transport.is_closing()
        ):
            self.head_too_large = True
            self.send_400_response("Request header fields too large.")

    def _count_head(self, size_bytes: int, lines: int) -> None:
        self.head_bytes += size_bytes
        self.head_count += lines
        if self.head_bytes > self.max_header_bytes or self.head_count > self.max_headers:
            self.head_too_large = True
            raise HeadTooLarge

    def on_url(self, url: bytes) -> None:
        self._count_head(len(url), 0)
        super().on_url(url)

    def on_header(self, name: bytes, value: bytes) -> None:
        self._count_head(len(name) + len(value) + HEADER_LINE_OVERHEAD_BYTES, 1)
        super().on_header(name, value)

    def on_headers_complete(self) -> None:
        self.scope[SHED_KEY] = self._was_shed  # type: ignore[literal-required]
        self.reading_head = False
        self.received_head_bytes = self.head_bytes = self.head_count = 0
        if len(self.connections) <= self.max_connections:
            super().on_headers_complete()
        else:
            app, self.app = self.app, self.over_limit  # uvicorn starts ``self.app`` for it
            try:
                super().on_headers_complete()
            finally:
                self.app = app
        if self.stopping and self.cycle is not None:
            self.cycle.keep_alive = False  # answered with Connection: close

    def send_400_response(self, msg: str) -> None:
        """uvicorn's answer to a request it cannot parse; 431 when the head is too large."""
        if not self.head_too_large:
            super().send_400_response(msg)
            return
        reason = b"Request header fields too large."
        content = [STATUS_LINE[431]]
        for name, value in self.server_state.default_headers:
            content += [name, b": ", value, b"\r\n"]
        content += [
            b"content-type: text/plain; charset=utf-8\r\n",
            b"content-length: " + str(len(reason)).encode() + b"\r\n",
            b"connection: close\r\n\r\n",
            reason,
        ]
        self.transport.write(b"".join(content))
        self.transport.close()
