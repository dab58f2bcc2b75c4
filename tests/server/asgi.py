"""One GET straight into an ASGI app, without a client (httpx refuses URLs over 64 KB,
and the overload middleware is best reached at the protocol's level)."""

from collections.abc import Awaitable, Callable
from typing import Any

Message = dict[str, Any]


def scope(path: str, query: bytes = b"") -> dict[str, Any]:
    return {
        "type": "http",
        "asgi": {"version": "3.0"},
        "http_version": "1.1",
        "method": "GET",
        "scheme": "http",
        "path": path,
        "raw_path": path.encode(),
        "query_string": query,
        "root_path": "",
        "headers": [(b"host", b"testserver")],
        "client": ("127.0.0.1", 1),
        "server": ("testserver", 80),
        "state": {},
    }


async def asgi_get(
    app: Callable[..., Awaitable[None]], path: str, query: bytes = b""
) -> tuple[int, dict[str, str]]:
    """One GET into an ASGI app: (status, headers)."""
    sent: list[Message] = []

    async def receive() -> Message:
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message: Message) -> None:
        sent.append(message)

    await app(scope(path, query), receive, send)
    return sent[0]["status"], {k.decode(): v.decode() for k, v in sent[0]["headers"]}
