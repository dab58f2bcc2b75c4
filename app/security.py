"""Pure-ASGI middleware: security headers on every response, size limits on requests."""

import json
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

CSP = (
    "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; "
    "connect-src 'self'; font-src 'self'; object-src 'none'; base-uri 'none'; "
    "form-action 'self'; frame-ancestors 'none'"
)
SECURITY_HEADERS = [
    (b"content-security-policy", CSP.encode()),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"same-origin"),
    (b"x-frame-options", b"DENY"),
    (b"cross-origin-opener-policy", b"same-origin"),
]
IMMUTABLE = (b"cache-control", b"public, max-age=31536000, immutable")


class SecurityMiddleware:
    """Adds security headers; refuses oversized bodies and query strings with 4xx."""

    def __init__(
        self, app: ASGIApp, max_body_bytes: int, max_query_chars: int, max_query_params: int
    ) -> None:
        self.app = app
        self.max_body = max_body_bytes
        self.max_query = max_query_chars
        self.max_params = max_query_params

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        query: bytes = scope.get("query_string", b"")
        if len(query) > self.max_query or query.count(b"&") + 1 > self.max_params:
            await self._refuse(send, 414, "query string too long or too many parameters")
            return
        for name, value in scope.get("headers", []):
            if name == b"content-length" and value.isdigit() and int(value) > self.max_body:
                await self._refuse(send, 413, "request body too large")
                return
        versioned = scope["path"].startswith("/static/vendor/")
        received = 0

        async def limited_receive() -> Message:
            nonlocal received
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_body:
                    raise BodyTooLarge
            return message

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                headers = list(message.get("headers", []))
                headers += SECURITY_HEADERS
                if versioned and message.get("status") == 200:
                    headers = [h for h in headers if h[0] != b"cache-control"] + [IMMUTABLE]
                message["headers"] = headers
            await send(message)

        try:
            await self.app(scope, limited_receive, send_with_headers)
        except BodyTooLarge:
            await self._refuse(send, 413, "request body too large")

    async def _refuse(self, send: Send, status: int, reason: str) -> None:
        body = json.dumps(
            {"error": reason, "detail": [{"field": "request", "message": reason}]}
        ).encode()
        await send(
            {
                "type": "http.response.start",
                "status": status,
                "headers": [
                    (b"content-type", b"application/json"),
                    (b"content-length", str(len(body)).encode()),
                    *SECURITY_HEADERS,
                ],
            }
        )
        await send({"type": "http.response.body", "body": body})


class BodyTooLarge(Exception):
    """Raised inside receive when a streamed body passes the limit."""
