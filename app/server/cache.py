"""A bounded, per-process cache of whole GET responses for the selection routes.

A selection is a pure function of its query string and the catalog, which is read once
at start-up and never changes while the process runs; so the response to a repeated
query (a share link opened again, a script polling the same axis) can be sent as it was
computed. Nothing is shared between processes: each worker fills its own cache, and a
restart with an edited catalog starts empty. Whether a response came from the cache is
counted (``hits``, ``misses``) but never said in it: an ``X-Cache: hit`` would tell anyone
that someone else had run the same inputs.

An entry is keyed by a digest of exactly what its response depends on: the path, the
query, whether the body is gzip-compressed and (on pages) whether it is an HTMX
fragment, each decided by ``app.server.headers`` the same way the response itself decides it.
Header values never enter the key, so a client cannot grow the cache by sending long
ones, nor store one kind of response where another kind is looked up.
"""

import hashlib
import sys
from collections import OrderedDict
from collections.abc import Awaitable, Callable, Iterable, MutableMapping
from dataclasses import dataclass
from typing import Any

from app.server.headers import accepts_gzip, is_htmx_fragment

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

#: Request headers every cached response depends on, and those pages add (fragment or not).
VARY_ALWAYS = ("Accept-Encoding",)
VARY_FRAGMENT = ("HX-Request", "HX-History-Restore-Request")
#: One OrderedDict slot (its link node and hash-table share), which getsizeof cannot see.
SLOT_BYTES = 128


@dataclass(frozen=True, slots=True)
class Entry:
    """A stored response and the bytes of memory it holds, key included."""

    start: Message
    body: bytes
    held_bytes: int


def held_bytes(key: bytes, start: Message, body: bytes) -> int:
    """Memory one entry keeps alive: every object in it, as ``sys.getsizeof`` counts."""
    headers: list[tuple[bytes, bytes]] = start["headers"]
    size = SLOT_BYTES + sys.getsizeof(key) + sys.getsizeof(body)
    size += sys.getsizeof(start) + sys.getsizeof(headers)
    for name, value in headers:
        size += sys.getsizeof((name, value)) + sys.getsizeof(name) + sys.getsizeof(value)
    return size


def merge_vary(headers: list[tuple[bytes, bytes]], names: tuple[str, ...]) -> None:
    """Make the response's Vary list ``names`` beside whatever it already lists."""
    listed: list[str] = []
    for key, value in headers:
        if key == b"vary":
            listed += [v.strip() for v in value.decode("latin-1").split(",") if v.strip()]
    for name in names:
        if name.lower() not in (v.lower() for v in listed):
            listed.append(name)
    headers[:] = [h for h in headers if h[0] != b"vary"]
    headers.append((b"vary", ", ".join(listed).encode("latin-1")))


class PathSet:
    """Paths named exactly, and every path that starts as a name ending in "*" does.

    >>> paths = PathSet({"/", "/catalog", "/catalog/*"})
    >>> "/catalog" in paths, "/catalog/B6000" in paths, "/catalogue" in paths, "/x" in paths
    (True, True, False, False)
    """

    def __init__(self, names: Iterable[str]) -> None:
        self.names = frozenset(names)
        self.prefixes = tuple(name[:-1] for name in self.names if name.endswith("*"))

    def __contains__(self, path: object) -> bool:
        if path in self.names:
            return True
        return isinstance(path, str) and bool(self.prefixes) and path.startswith(self.prefixes)


class ResponseCache:
    """LRU of complete 200 responses to GET on ``paths``.

    Bounded by the bytes its entries hold (``max_bytes``; 0 turns it off) and by their
    number (``max_entries``). Responses on ``fragment_paths`` differ between an HTMX swap
    and a full page; the others do not. Responses on ``query_free_paths`` do not depend on
    the query at all: one entry serves every query, so ``/catalog?x=1``, ``?x=2``... cannot
    make the process compress its largest page again for each. A path set's name that
    ends in "*" stands for every path that starts as it does (``PathSet``).
    """

    def __init__(
        self,
        app: ASGIApp,
        paths: frozenset[str],
        fragment_paths: frozenset[str],
        max_bytes: int,
        max_entries: int,
        query_free_paths: frozenset[str] = frozenset(),
    ) -> None:
        self.app = app
        self.paths = PathSet(paths | query_free_paths)
        self.query_free_paths = PathSet(query_free_paths)
        self.fragment_paths = PathSet(fragment_paths)
        self.max_bytes = max_bytes
        self.max_entries = max_entries
        self.size_bytes = 0
        self.hits = 0
        self.misses = 0
        self.entries: OrderedDict[bytes, Entry] = OrderedDict()

    def _vary(self, path: str) -> tuple[str, ...]:
        return VARY_ALWAYS + (VARY_FRAGMENT if path in self.fragment_paths else ())

    def _key(self, scope: Scope) -> bytes:
        """A fixed-size digest of the path, the query and the header decisions."""
        headers = scope.get("headers", [])
        path: str = scope["path"]
        fragment = path in self.fragment_paths and is_htmx_fragment(headers)
        query = b"" if path in self.query_free_paths else scope.get("query_string", b"")
        inputs = (path, query, accepts_gzip(headers), fragment)
        return hashlib.sha256(repr(inputs).encode()).digest()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if (
            scope["type"] != "http"
            or scope["method"] != "GET"
            or scope["path"] not in self.paths
            or self.max_bytes <= 0
            or self.max_entries <= 0
        ):
            await self.app(scope, receive, send)
            return
        key = self._key(scope)
        cached = self.entries.get(key)
        if cached is not None:
            self.entries.move_to_end(key)
            self.hits += 1
            # a copy: the layers outside may rewrite the message they are sent
            await send({**cached.start, "headers": list(cached.start["headers"])})
            await send({"type": "http.response.body", "body": cached.body})
            return
        self.misses += 1
        vary = self._vary(scope["path"])
        start_message: Message = {}
        chunks: list[bytes] = []

        async def capture(message: Message) -> None:
            nonlocal start_message
            if message["type"] == "http.response.start":
                headers = list(message.get("headers", []))
                merge_vary(headers, vary)
                start_message = {**message, "headers": headers}
                message = {**start_message, "headers": list(headers)}
            elif message["type"] == "http.response.body":
                chunks.append(message.get("body", b""))
                if not message.get("more_body", False) and start_message.get("status") == 200:
                    self._store(key, start_message, b"".join(chunks))
            await send(message)

        await self.app(scope, receive, capture)

    def _store(self, key: bytes, start: Message, body: bytes) -> None:
        if len(body) > self.max_bytes // 8 or key in self.entries:
            return
        kept = {"type": start["type"], "status": start["status"], "headers": start["headers"]}
        entry = Entry(kept, body, held_bytes(key, kept, body))
        self.entries[key] = entry
        self.size_bytes += entry.held_bytes
        while self.size_bytes > self.max_bytes or len(self.entries) > self.max_entries:
            _, evicted = self.entries.popitem(last=False)
            self.size_bytes -= evicted.held_bytes
