"""Gzip for dynamic responses, decided by the same header reading as the response cache.

Starlette's ``GZipMiddleware`` looks for ``gzip`` anywhere in the first Accept-Encoding
line (``gzip;q=0`` included); the cache must know in advance which body a request will
get, so here the choice is ``app.headers.accepts_gzip``, the function the cache keys on.
"""

from starlette.middleware.gzip import GZipMiddleware, GZipResponder, IdentityResponder
from starlette.types import Receive, Scope, Send

from app.server.headers import accepts_gzip


class NegotiatedGZipMiddleware(GZipMiddleware):
    """``GZipMiddleware`` whose gzip-or-not decision is ``accepts_gzip``."""

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        if accepts_gzip(scope.get("headers", [])):
            await GZipResponder(
                self.app,
                self.minimum_size,
                compresslevel=self.compresslevel,
                thread_minimum_size=self.thread_minimum_size,
                exclude_content_types=self.exclude_content_types,
            )(scope, receive, send)
        else:
            await IdentityResponder(
                self.app, self.minimum_size, exclude_content_types=self.exclude_content_types
            )(scope, receive, send)
