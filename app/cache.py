"""A bounded, per-process cache of whole GET responses for the selection routes.

A selection is a pure function of its query string and the catalog, which is read once
at start-up and never changes while the process runs; so the response to a repeated
query (a share link opened again, a script polling the same axis) can be sent as it was
computed. Nothing is shared between processes: each worker fills its own cache, and a
restart with an edited catalog starts empty. ``X-Cache: hit|miss`` says which happened.
"""

from collections import OrderedDict
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

#: Request headers that change the response of a cached path.
VARY = (b"hx-request", b"hx-history-restore-request")


class ResponseCache:
    """LRU of complete 200 responses to GET on ``paths``, keyed by path, query, headers.

    Bounded by the total size of the bodies kept (``max_bytes``; 0 turns it off).
    """

    def __init__(self, app: ASGIApp, paths: frozenset[str], max_bytes: int) -> None:
        self.app = app
        self.paths = paths
        self.max_bytes = max_bytes
        self.size = 0
        self.entries: OrderedDict[tuple[Any, ...], tuple[Message, bytes]] = OrderedDict()

    def _key(self, scope: Scope) -> tuple[Any, ...]:
        headers = dict(scope.get("headers", []))
        gzip = b"gzip" in headers.get(b"accept-encoding", b"")
        return (
            scope["path"],
            scope.get("query_string", b""),
            gzip,
            *(headers.get(name) for name in VARY),
        )

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if (
            scope["type"] != "http"
            or scope["method"] != "GET"
            or scope["path"] not in self.paths
            or self.max_bytes <= 0
        ):
            await self.app(scope, receive, send)
            return
        key = self._key(scope)
        cached = self.entries.get(key)
        if cached is not None:
            self.entries.move_to_end(key)
            start, body = cached
            await send({**start, "headers": [*start["headers"], (b"x-cache", b"hit")]})
            await send({"type": "http.response.body", "body": body})
            return
        start_message: Message = {}
        chunks: list[bytes] = []

        async def capture(message: Message) -> None:
            nonlocal start_message
            if message["type"] == "http.response.start":
                start_message = message
                message = {**message, "headers": [*message["headers"], (b"x-cache", b"miss")]}
            elif message["type"] == "http.response.body":
                chunks.append(message.get("body", b""))
                if not message.get("more_body", False) and start_message.get("status") == 200:
                    self._store(key, start_message, b"".join(chunks))
            await send(message)

        await self.app(scope, receive, capture)

    def _store(self, key: tuple[Any, ...], start: Message, body: bytes) -> None:
        if len(body) > self.max_bytes // 8 or key in self.entries:
            return
        self.entries[key] = (
            {"type": start["type"], "status": start["status"], "headers": list(start["headers"])},
            body,
        )
        self.size += len(body)
        while self.size > self.max_bytes:
            _, (_, evicted) = self.entries.popitem(last=False)
            self.size -= len(evicted)
