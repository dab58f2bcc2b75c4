"""Load shedding: past an amount of work in progress, answer 503 at once.

One worker computes one response at a time; when more requests arrive than it can finish
promptly, holding them all makes every one of them slow (at 256 connections, seconds
each, and clients time out). Past ``max_in_flight`` units of work in progress (a request
costs what ``request_cost`` says: a full form of a hundred candidates costs as much as
thirteen compact selects) this answers 503 with Retry-After straight away, so the
requests that are taken stay fast and a balancer or client can go elsewhere or come back.
The health check is never shed: a worker that is busy is not down.
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


#: Paths whose answer is a selection's full form, and the path that gives it on request.
FULL_FORM_PATHS = frozenset({"/export.csv", "/export.json"})
SELECT_PATH = "/api/v1/select"
#: Candidates of a full form that cost as much as a compact select (about 4 ms).
FULL_FORM_CANDIDATES_PER_UNIT = 8
LIMIT_DEFAULT, LIMIT_MOST = 10, 100


def request_cost(scope: Scope) -> int:
    """Units of work a request will take: 1 for a page or a compact select; a full form
    (``detail=full``, the exports) builds every number of every returned candidate, so
    1 + limit / 8 (``limit=100``: 13 units, about 50 ms).

    >>> scope = {"path": "/api/v1/select", "query_string": b"load_n=1&detail=full&limit=100"}
    >>> request_cost(scope), request_cost({**scope, "query_string": b"limit=100"})
    (13, 1)
    """
    query: bytes = scope.get("query_string", b"")
    pairs = dict(p.partition(b"=")[::2] for p in query.split(b"&"))
    full = scope["path"] in FULL_FORM_PATHS or (
        scope["path"] == SELECT_PATH and pairs.get(b"detail") == b"full"
    )
    if not full:
        return 1
    text = pairs.get(b"limit", b"")
    limit = int(text) if text.isdigit() and len(text) < 4 else LIMIT_DEFAULT
    return 1 + min(max(limit, 1), LIMIT_MOST) // FULL_FORM_CANDIDATES_PER_UNIT


class OverloadMiddleware:
    """Counts the work of HTTP requests in progress (``cost``: units per request); sheds a
    request that would take it past ``max_in_flight`` with 503. A request costing more
    than the whole allowance is still taken when nothing else is in progress."""

    def __init__(
        self,
        app: ASGIApp,
        max_in_flight: int,
        retry_after_s: int,
        exempt_paths: frozenset[str],
        cost: Callable[[Scope], int] = lambda scope: 1,
    ) -> None:
        self.app = app
        self.max_in_flight = max_in_flight
        self.retry_after_s = retry_after_s
        self.exempt_paths = exempt_paths
        self.cost = cost
        self.in_flight = 0
        self.shed = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or self.max_in_flight <= 0 or scope["path"] in self.exempt_paths:
            await self.app(scope, receive, send)
            return
        cost = self.cost(scope)
        if self.in_flight and self.in_flight + cost > self.max_in_flight:
            self.shed += 1
            await self._busy(send)
            return
        self.in_flight += cost
        try:
            # let every request that already arrived reach the count above before this one
            # computes: a route that never awaits would otherwise finish before the next
            # request is counted, and the queue would build up out of sight
            await anyio.lowlevel.checkpoint()
            await self.app(scope, receive, send)
        finally:
            self.in_flight -= cost

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
