"""HEAD answered for every GET route, with the GET's headers and no body.

A load balancer's health check, a link checker or ``curl -I`` sends HEAD; FastAPI routes
declared with ``@router.get`` answer it with 405. Rather than list HEAD on each route,
this middleware runs a HEAD as the GET it stands for and drops the body, so the status
and headers (Content-Length and Content-Type included) are exactly the GET's.
"""

from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]


class HeadAsGetMiddleware:
    """Runs HEAD requests as GET and sends only the response's start and an empty body."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] != "HEAD":
            await self.app(scope, receive, send)
            return

        async def without_body(message: Message) -> None:
            if message["type"] == "http.response.body":
                if message.get("more_body", False):
                    return
                message = {"type": "http.response.body", "body": b""}
            await send(message)

        await self.app({**scope, "method": "GET"}, receive, without_body)
