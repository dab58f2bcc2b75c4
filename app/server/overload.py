"""Load shedding: past an amount of work in progress, answer 503 at once.

One worker computes one response at a time; when more requests arrive than it can finish
promptly, holding them all makes every one of them slow (at 256 connections, seconds
each, and clients time out). Past ``max_in_flight`` units of work in progress (a request
costs one unit, a full form of a hundred candidates as much as thirteen compact selects
and a results page of a hundred as much as fifteen, counted once its input is validated:
``charge``) this answers 503 with Retry-After straight away, so the requests that are
taken stay fast and a balancer or client can go elsewhere or come back.

A request whose query states its cost (a ``limit``, ``detail=full``) is admitted by that
cost before its input is read (``stated_costs``), and charged the rest once validated:
under a flood of results pages of a hundred, refusing each only after validating it took
the event loop 2.5 ms apiece, and the health check queued behind sixty of those.
The health check is never shed: a worker that is busy is not down.
"""

import json
from collections.abc import Awaitable, Callable, Collection, Mapping, MutableMapping
from typing import Any
from urllib.parse import parse_qsl

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


#: Candidates of a full form charged as one compact select (``full_form_units``).
FULL_FORM_CANDIDATES_PER_UNIT = 8
LIMIT_MOST = 100
#: the scope key of the request's ``take`` (``charge``)
WORK_KEY = "app.overload.take"
#: the scope key of the connection's ``shed`` notice, called when its request is shed
#: (``app.server.protocol`` then reads nothing more from it for Retry-After seconds)
SHED_KEY = "app.overload.shed"


class Shed(Exception):
    """Raised by ``charge`` when a request's work would pass the limit: answered 503."""


def full_form_units(limit: int) -> int:
    """Units of work of a full form (``detail=full``, the exports) of ``limit``
    candidates: it builds every number of each, so 1 + limit / 8 (100: 13 units); a page
    or a compact select is 1. Measured, a full form of 100 without a lead costs some 44
    to 50 compact selects: charging that would put it over the whole allowance, so it
    would be taken only with nothing else in progress and a stream of keystrokes could
    hold an export off indefinitely. The charge stays below the allowance on purpose.

    >>> full_form_units(100), full_form_units(10), full_form_units(1)
    (13, 2, 1)
    """
    return 1 + min(max(limit, 1), LIMIT_MOST) // FULL_FORM_CANDIDATES_PER_UNIT


#: Results a page shows for the cost of one compact select: its selection, table rows and
#: rendering (CPU of the whole request in process, distinct queries, against a compact
#: select of the default query: with ``limit`` 10, 50 and 100, about 2.5, 7 and 13 to 15
#: compact selects; the charts and the rejected list are requests of their own).
PAGE_CANDIDATES_PER_UNIT = 7


def page_units(limit: int) -> int:
    """Units of work of a results page (full or fragment) of ``limit`` results: 1 +
    limit / 7 (100: 15 units); an empty form is 1.

    >>> page_units(100), page_units(10), page_units(1)
    (15, 2, 1)
    """
    return 1 + min(max(limit, 1), LIMIT_MOST) // PAGE_CANDIDATES_PER_UNIT


def stated_limit(query: Mapping[str, str]) -> int:
    """The ``limit`` a query states in plain digits, else 1: a lower bound of what its
    validated input asks (a limit left out, or written otherwise, is read by validation
    and charged then).

    >>> stated_limit({"limit": "100"}), stated_limit({}), stated_limit({"limit": "1e2"})
    (100, 1, 1)
    """
    raw = query.get("limit", "")
    return int(raw) if raw.isdigit() and len(raw) <= 3 else 1


def page_stated_units(
    query: Mapping[str, str], required: Collection[str] = (), default_limit: int = 1
) -> int:
    """Units a results page states in its query: ``page_units`` of its limit, or of
    ``default_limit`` when the query leaves the limit out and fills one of the
    ``required`` fields (a page's limit comes from its query alone, so it is the default
    one: charged so once validated, unless the input is invalid and nothing is computed).
    Pages of the default limit are the common flood: refused only once validated, each
    took the event loop 1.3 ms (tests/server/test_overload.py), at the door 0.1 ms.

    >>> page_stated_units({"limit": "100"}), page_stated_units({})
    (15, 1)
    >>> page_stated_units({"load": "100"}, required=("load",), default_limit=10)
    2
    >>> page_stated_units({"load": " "}, required=("load",), default_limit=10)
    1
    """
    if "limit" not in query and any(query.get(name, "").strip() for name in required):
        return page_units(default_limit)
    return page_units(stated_limit(query))


def full_form_stated_units(query: Mapping[str, str]) -> int:
    """Units an export (every number of each candidate) states in its query."""
    return full_form_units(stated_limit(query))


def select_stated_units(query: Mapping[str, str]) -> int:
    """Units an API select states in its query: a full form by its limit, else 1.

    >>> select_stated_units({"detail": "full", "limit": "100"})
    13
    >>> select_stated_units({"limit": "100"})
    1
    """
    return full_form_stated_units(query) if query.get("detail") == "full" else 1


#: path -> the units of work its query states, read before its input is validated
StatedCosts = Mapping[str, Callable[[Mapping[str, str]], int]]


def charge(scope: Scope, units: int) -> None:
    """Count the request of ``scope`` as ``units`` of work in all, read from its validated
    input (the raw query can hide it: ``detail=ful%6C``, or a limit in the body). It was
    admitted as one; Shed (a 503) if the rest would pass the limit while other work is in
    progress. Nothing without the middleware (limit off, or the health check)."""
    take = scope.get(WORK_KEY)
    if take is not None:
        take(units)


class OverloadMiddleware:
    """Counts the work of HTTP requests in progress: one unit each as it arrives, more
    when its route knows its input asks for more (``charge``); sheds a request that would
    take it past ``max_in_flight`` with 503. A request costing more than the whole
    allowance is still taken when nothing else is in progress."""

    def __init__(
        self,
        app: ASGIApp,
        max_in_flight: int,
        retry_after_s: int,
        exempt_paths: frozenset[str],
        stated_costs: StatedCosts | None = None,
    ) -> None:
        self.app = app
        self.max_in_flight = max_in_flight
        self.retry_after_s = retry_after_s
        self.exempt_paths = exempt_paths
        self.stated_costs = stated_costs or {}
        self.in_flight = 0
        self.shed = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or self.max_in_flight <= 0 or scope["path"] in self.exempt_paths:
            await self.app(scope, receive, send)
            return
        taken = self._stated(scope)
        if self.in_flight + 1 > self.max_in_flight or (
            self.in_flight and self.in_flight + taken > self.max_in_flight
        ):
            self.shed += 1
            await self._busy(scope, send)
            return
        self.in_flight += taken
        started = False

        def take(units: int) -> None:
            nonlocal taken
            more = units - taken
            others = self.in_flight - taken
            if more <= 0:
                return
            if others and self.in_flight + more > self.max_in_flight:
                raise Shed
            self.in_flight += more
            taken += more

        async def watched_send(message: Message) -> None:
            nonlocal started
            started = True
            await send(message)

        scope[WORK_KEY] = take
        try:
            # let every request that already arrived reach the count above before this one
            # computes: a route that never awaits would otherwise finish before the next
            # request is counted, and the queue would build up out of sight
            await anyio.lowlevel.checkpoint()
            await self.app(scope, receive, watched_send)
        except Shed:
            self.shed += 1
            if started:
                raise
            await self._busy(scope, send)
        finally:
            self.in_flight -= taken

    def _stated(self, scope: Scope) -> int:
        """The units of work the request's query states (``stated_costs`` by path), 1 for
        a path without: admitted (or shed) by them before its input is read, so that a
        flood of costly queries is turned away for the price of reading a query string,
        not of validating each one only to refuse it."""
        stated = self.stated_costs.get(scope["path"])
        if stated is None:
            return 1
        query = dict(parse_qsl(scope["query_string"].decode("latin-1"), keep_blank_values=True))
        return max(1, stated(query))

    async def _busy(self, scope: Scope, send: Send) -> None:
        notice = scope.get(SHED_KEY)
        if notice is not None:
            notice()
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
