"""Pure-ASGI middleware: security headers on every response, size limits on requests,
redirects that stay on the host the client used."""

import json
import re
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from app.server.failures import FailureLog

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
# app.css and app.js change with the app and their URLs carry no version: browsers may
# reuse them for ten minutes, then revalidate (ETag, 304). A ``?v=`` URL is immutable.
SHORT = (b"cache-control", b"public, max-age=600")
CACHED_STATUSES = (200, 304)
#: the scheme and authority of an absolute URL, and the slashes a browser would read as
#: the start of another authority (``//host``, ``/\\host``)
_ABSOLUTE = re.compile(rb"^[a-zA-Z][a-zA-Z0-9+.-]*://[^/?#]*")
_LEADING_SLASHES = re.compile(rb"^[/\\]+")


def path_only(location: bytes) -> bytes:
    """A redirect target without scheme and host: the app only redirects within itself, and
    Starlette builds its slash redirects from the request's Host header, which a client
    chooses. Leading slashes collapse to one so the result cannot name another host.

    >>> path_only(b"http://evil.example/static/"), path_only(b"http://h//evil.example")
    (b'/static/', b'/evil.example')
    >>> path_only(b"/docs?x=1"), path_only(b"https://h")
    (b'/docs?x=1', b'/')
    """
    return _LEADING_SLASHES.sub(b"/", _ABSOLUTE.sub(b"", location)) or b"/"


class SecurityMiddleware:
    """Adds security headers; refuses oversized bodies and query strings with 4xx."""

    def __init__(
        self, app: ASGIApp, max_body_bytes: int, max_query_chars: int, max_query_params: int
    ) -> None:
        self.app = app
        self.max_body = max_body_bytes
        self.max_query = max_query_chars
        self.max_params = max_query_params
        self.failures = FailureLog()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        query: bytes = scope.get("query_string", b"")
        refused = self._refusal(scope, query)
        if refused is not None:
            await self._refuse(send, *refused)
            return
        path: str = scope["path"]
        cache = _cache_header(path, query)
        api = path.startswith("/api/")
        received = 0
        too_large = started = False

        async def limited_receive() -> Message:
            nonlocal received, too_large
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_body:
                    too_large = not started
                    raise BodyTooLarge
            return message

        async def send_with_headers(message: Message) -> None:
            nonlocal started
            if too_large:
                # FastAPI catches errors raised while it reads a body and answers 400 (or
                # the route turns that into a 422); the client should hear 413 instead
                if message["type"] == "http.response.start":
                    started = True
                    await self._refuse(send, 413, "request body too large")
                return
            if message["type"] == "http.response.start":
                started = True
                headers = [
                    (name, path_only(value) if name == b"location" else value)
                    for name, value in message.get("headers", [])
                ]
                headers += SECURITY_HEADERS
                if cache is not None and message.get("status") in CACHED_STATUSES:
                    headers = [h for h in headers if h[0] != b"cache-control"] + [cache]
                message["headers"] = headers
            await send(message)

        try:
            await self.app(scope, limited_receive, send_with_headers)
        except BodyTooLarge:
            if not started:
                await self._refuse(send, 413, "request body too large")
        except Exception as exc:
            # Starlette's own 500 page is sent from outside every middleware, so without
            # this it would go out with no security headers. Ours names the request id of
            # the log's line (app.server.failures) and closes the connection, saying so.
            if started:
                raise  # half a response: the server logs it and drops the connection
            request_id = self.failures.record(scope, exc)
            reason = f"internal server error (request {request_id})"
            closing = [(b"x-request-id", request_id.encode()), (b"connection", b"close")]
            await self._refuse(send, 500, reason, json_body=api, extra=closing)

    def _refusal(self, scope: Scope, query: bytes) -> tuple[int, str] | None:
        """The status and reason to refuse a request with before it is read: a query
        too long or of too many parameters, a body declared too large."""
        if len(query) > self.max_query or query.count(b"&") + 1 > self.max_params:
            return 414, "query string too long or too many parameters"
        for name, value in scope.get("headers", []):
            if name == b"content-length" and value.isdigit() and int(value) > self.max_body:
                return 413, "request body too large"
        return None

    async def _refuse(
        self,
        send: Send,
        status: int,
        reason: str,
        json_body: bool = True,
        extra: list[tuple[bytes, bytes]] | None = None,
    ) -> None:
        if json_body:
            body = json.dumps(
                {"error": reason, "detail": [{"field": "request", "message": reason}]}
            ).encode()
            content_type = b"application/json"
        else:
            body = f"{status} {reason.capitalize()}".encode()
            content_type = b"text/plain; charset=utf-8"
        await send(
            {
                "type": "http.response.start",
                "status": status,
                "headers": [
                    (b"content-type", content_type),
                    (b"content-length", str(len(body)).encode()),
                    *SECURITY_HEADERS,
                    *(extra or []),
                ],
            }
        )
        await send({"type": "http.response.body", "body": body})


class BodyTooLarge(Exception):
    """Raised inside receive when a streamed body passes the limit."""


def _cache_header(path: str, query: bytes) -> tuple[bytes, bytes] | None:
    """The Cache-Control of a static file: for good when its name or query carries its
    version, briefly otherwise; None (the route's own) for everything else."""
    if not path.startswith("/static/"):
        return None
    versioned = path.startswith("/static/vendor/") or query.startswith(b"v=")
    return IMMUTABLE if versioned else SHORT
