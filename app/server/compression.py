"""Gzip for dynamic responses, decided by the same header reading as the response cache.

The gzip-or-not choice is ``app.server.headers.accepts_gzip``, the function the cache keys on
(Starlette's ``GZipMiddleware`` looks for ``gzip`` anywhere in the first Accept-Encoding
line, ``gzip;q=0`` included). The rules are Starlette's: a body under ``minimum_size``
goes as it is; any larger one gets ``Vary: Accept-Encoding``, and is compressed when the
client takes gzip, unless it is already encoded, a partial (206) response or of a type
that is compressed already. A whole body (the app's pages and JSON) is compressed in one
call, reading and writing the raw header list; a streamed one chunk by chunk.
"""

import zlib
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from app.server.headers import accepts_gzip, first_header

Message = MutableMapping[str, Any]
Scope = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]
#: Types that are compressed already (Starlette's list).
COMPRESSED_TYPES = frozenset(
    {b"text/event-stream", b"application/zip", b"application/gzip", b"application/x-gzip"}
)
GZIP_WBITS = 16 + zlib.MAX_WBITS


def _plain(start: Message) -> bool:
    """Whether a response must go as it is: encoded already, partial, or compressed."""
    headers = start.get("headers", [])
    if start["status"] == 206 or first_header(headers, b"content-encoding") is not None:
        return True
    kind = (first_header(headers, b"content-type") or b"").partition(b";")[0].strip().lower()
    return kind in COMPRESSED_TYPES or kind.startswith(b"application/grpc")


def _vary(headers: list[tuple[bytes, bytes]]) -> None:
    """Add Accept-Encoding to the response's Vary list unless it is there."""
    for k, (name, value) in enumerate(headers):
        if name == b"vary":
            if b"accept-encoding" not in value.lower():
                headers[k] = (name, value + b", Accept-Encoding")
            return
    headers.append((b"vary", b"Accept-Encoding"))


class _Responder:
    """One response on its way out: held at its start until its first body decides."""

    def __init__(self, send: Send, gzip: bool, minimum_size: int, level: int) -> None:
        self.send, self.gzip, self.minimum_size, self.level = send, gzip, minimum_size, level
        self.start: Message | None = None
        self.passing = False  # everything from here on goes as it is
        self.stream: Any = None  # the compressor of a streamed body

    async def __call__(self, message: Message) -> None:
        kind = message["type"]
        if self.passing:
            await self.send(message)
        elif kind == "http.response.start":
            self.start, self.passing = message, _plain(message)
            if self.passing:
                await self.send(message)
        elif kind != "http.response.body":  # early hints, trailers; a file sent by path
            if kind == "http.response.pathsend" and self.start is not None:
                await self.send(self.start)
                self.passing = True
            await self.send(message)
        elif self.stream is not None:  # the rest of a streamed body
            await self.send({**message, "body": self._more(message)})
        else:
            await self._first_body(message)

    def _more(self, message: Message) -> bytes:
        """A later chunk of a streamed body, compressed; the stream ends with the last
        (an empty chunk in between adds nothing: zlib refuses a second flush)."""
        body, more = message.get("body", b""), message.get("more_body", False)
        if not more:
            return bytes(self.stream.compress(body) + self.stream.flush())
        return (
            bytes(self.stream.compress(body) + self.stream.flush(zlib.Z_SYNC_FLUSH))
            if body
            else b""
        )

    async def _first_body(self, message: Message) -> None:
        start = self.start
        assert start is not None, "a body before the response start"
        body, more = message.get("body", b""), message.get("more_body", False)
        headers = list(start.get("headers", []))
        if len(body) >= self.minimum_size or more:
            _vary(headers)
        if not self.gzip or (len(body) < self.minimum_size and not more):
            self.passing = True
            await self.send({**start, "headers": headers})
            await self.send(message)
            return
        headers = [h for h in headers if h[0] != b"content-length"]
        headers.append((b"content-encoding", b"gzip"))
        if more:
            self.stream = zlib.compressobj(self.level, zlib.DEFLATED, GZIP_WBITS)
            body = self.stream.compress(body) + self.stream.flush(zlib.Z_SYNC_FLUSH)
        else:
            body = zlib.compress(body, self.level, GZIP_WBITS)
            if not start.get("trailers", False):
                headers.append((b"content-length", str(len(body)).encode("latin-1")))
        await self.send({**start, "headers": headers})
        await self.send({**message, "body": body})


class NegotiatedGZipMiddleware:
    """Compress bodies of ``minimum_size`` bytes and more at ``compresslevel`` for
    clients that take gzip (``accepts_gzip``)."""

    def __init__(self, app: ASGIApp, minimum_size: int = 500, compresslevel: int = 1) -> None:
        self.app = app
        self.minimum_size = minimum_size
        self.compresslevel = compresslevel

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        gzip = accepts_gzip(scope.get("headers", []))
        responder = _Responder(send, gzip, self.minimum_size, self.compresslevel)
        await self.app(scope, receive, responder)
