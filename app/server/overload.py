"""Load shedding: past a number of requests in progress, answer 503 at once.

One worker computes one response at a time; when more requests arrive than it can finish
promptly, holding them all makes every one of them slow (at 256 connections, seconds
each, and clients time out). Past ``max_in_flight`` requests in progress this answers
503 with Retry-After straight away, so the requests that are taken stay fast and a
balancer or client can go elsewhere or come back. The health check is never shed: a
worker that is busy is not down.
"""

import json
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

import anyio.lowlevel

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

#: Answered however busy the process is: a balancer must not take busy for down.
NEVER_SHED = frozenset({"/api/v1/health"})
BUSY = json.dumps(
    {"error": "server busy", "detail": [{"field": "request", "message": "server busy, retry"}]}
).encode()


class OverloadMiddleware:
    """Counts HTTP requests in progress; sheds those past ``max_in_flight`` with 503."""

    def __init__(
        self,
        app: ASGIApp,
        max_in_flight: int,
        retry_after_s: int,
        exempt_paths: frozenset[str],
    ) -> None:
        self.app = app
        self.max_in_flight = max_in_flight
        self.retry_after_s = retry_after_s
        self.exempt_paths = exempt_paths
        self.in_flight = 0
        self.shed = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or self.max_in_flight <= 0 or scope["path"] in self.exempt_paths:
            await self.app(scope, receive, send)
            return
        if self.in_flight >= self.max_in_flight:
            self.shed += 1
            await self._busy(send)
            return
        self.in_flight += 1
        try:
            # let every request that already arrived reach the count above before this one
            # computes: a route that never awaits would otherwise finish before the next
            # request is counted, and the queue would build up out of sight
            await anyio.lowlevel.checkpoint()
            await self.app(scope, receive, send)
        finally:
            self.in_flight -= 1

    async def _busy(self, send: Send) -> None:
        await send_busy(send, self.retry_after_s)


async def send_busy(send: Send, retry_after_s: int, *extra: tuple[bytes, bytes]) -> None:
    """Answer 503 with Retry-After (and ``extra`` headers): come back, or go elsewhere."""
    await send(
        {
            "type": "http.response.start",
            "status": 503,
            "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(BUSY)).encode()),
                (b"retry-after", str(retry_after_s).encode()),
                (b"cache-control", b"no-store"),
                *extra,
            ],
        }
    )
    await send({"type": "http.response.body", "body": BUSY})
