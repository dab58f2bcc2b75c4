"""Static files, gzip-compressed once at the highest level and kept in memory.

GZipMiddleware would compress every download of a vendored bundle again (Plotly.js basic:
1.2 MB, about 60 ms of CPU at level 6, on the worker that also serves selections). Here
each compressible file is compressed once per process, in a thread, at level 9, and the
bytes reused; the middleware passes a response that already has a Content-Encoding.
"""

import functools
import gzip
from pathlib import Path

import anyio
from starlette.datastructures import Headers
from starlette.responses import FileResponse, Response
from starlette.staticfiles import StaticFiles
from starlette.types import Scope

from app.server.headers import accepts_gzip

COMPRESSIBLE = ("text/", "application/javascript", "application/json", "image/svg+xml")
MINIMUM_SIZE = 500
DROPPED = {"content-length", "content-type", "accept-ranges", "etag"}


class PrecompressedStaticFiles(StaticFiles):
    """``StaticFiles`` that answers ``Accept-Encoding: gzip`` from an in-memory cache."""

    def __init__(self, *, directory: Path) -> None:
        super().__init__(directory=directory)
        self._gzipped: dict[tuple[str, int, int], bytes] = {}

    async def get_response(self, path: str, scope: Scope) -> Response:
        response = await super().get_response(path, scope)
        request = Headers(scope=scope)
        if (
            not isinstance(response, FileResponse)
            or response.status_code != 200
            or not accepts_gzip(request)
            or "range" in request
            or not (response.media_type or "").startswith(COMPRESSIBLE)
            or response.stat_result is None
            or response.stat_result.st_size < MINIMUM_SIZE
        ):
            return response
        stat = response.stat_result
        key = (str(response.path), stat.st_mtime_ns, stat.st_size)
        body = self._gzipped.get(key)
        if body is None:
            data = await anyio.Path(response.path).read_bytes()
            body = await anyio.to_thread.run_sync(
                functools.partial(gzip.compress, data, compresslevel=9, mtime=0)
            )
            self._gzipped[key] = body
        headers = {k: v for k, v in response.headers.items() if k not in DROPPED}
        headers["content-encoding"] = "gzip"
        headers["vary"] = "Accept-Encoding"
        # a weak tag: the gzip bytes are another representation of the same file
        # (Starlette compares If-None-Match without the W/ prefix, so 304s still work)
        headers["etag"] = "W/" + response.headers["etag"]
        return Response(body, headers=headers, media_type=response.media_type)
