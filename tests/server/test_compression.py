"""The gzip middleware (app.server.compression) on small, whole, streamed, encoded and
partial responses, with and without a client that takes gzip."""

import asyncio
import gzip
import zlib
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pytest

from app.server.compression import NegotiatedGZipMiddleware

BIG = b"leadscrew " * 200  # 2,000 bytes, over the 500-byte minimum


def _app(body_parts: list[bytes], headers: list[tuple[bytes, bytes]], status: int = 200) -> Any:
    async def app(scope: Any, receive: Any, send: Any) -> None:
        await send({"type": "http.response.start", "status": status, "headers": headers})
        for k, part in enumerate(body_parts):
            more = k < len(body_parts) - 1
            await send({"type": "http.response.body", "body": part, "more_body": more})

    return app


def _run(app: Any, accept: bytes | None) -> tuple[dict[bytes, bytes], bytes]:
    """(response headers, body as sent) through the middleware."""
    sent: list[dict[str, Any]] = []

    async def send(message: dict[str, Any]) -> None:
        sent.append(message)

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": b"", "more_body": False}

    request = [] if accept is None else [(b"accept-encoding", accept)]
    scope = {"type": "http", "method": "GET", "path": "/", "headers": request}
    # a thread of its own: the browser tests leave an event loop running on this one
    with ThreadPoolExecutor(1) as pool:
        call = NegotiatedGZipMiddleware(app, minimum_size=500)(scope, receive, send)
        pool.submit(asyncio.run, call).result()  # type: ignore[arg-type]
    assert sent[0]["type"] == "http.response.start"
    headers = dict(sent[0]["headers"])
    return headers, b"".join(m.get("body", b"") for m in sent[1:])


JSON = [(b"content-type", b"application/json"), (b"content-length", b"2000")]


def test_a_whole_body_is_compressed_with_its_length_and_vary() -> None:
    headers, body = _run(_app([BIG], JSON), b"gzip")
    assert headers[b"content-encoding"] == b"gzip"
    assert headers[b"content-length"] == str(len(body)).encode()
    assert headers[b"vary"] == b"Accept-Encoding"
    assert gzip.decompress(body) == BIG and len(body) < len(BIG)


@pytest.mark.parametrize("accept", [None, b"identity", b"gzip;q=0", b"br"])
def test_a_client_without_gzip_gets_the_body_as_it_is_and_vary(accept: bytes | None) -> None:
    headers, body = _run(_app([BIG], JSON), accept)
    assert body == BIG and b"content-encoding" not in headers
    assert headers[b"content-length"] == b"2000" and headers[b"vary"] == b"Accept-Encoding"


def test_a_small_body_goes_as_it_is_without_vary() -> None:
    headers, body = _run(_app([b"{}"], [(b"content-type", b"application/json")]), b"gzip")
    assert body == b"{}" and b"content-encoding" not in headers and b"vary" not in headers


def test_an_existing_vary_list_is_extended_once() -> None:
    headers, _ = _run(_app([BIG], [*JSON, (b"vary", b"HX-Request")]), b"gzip")
    assert headers[b"vary"] == b"HX-Request, Accept-Encoding"
    headers, _ = _run(_app([BIG], [*JSON, (b"vary", b"accept-encoding")]), b"gzip")
    assert headers[b"vary"] == b"accept-encoding"


def test_a_streamed_body_is_compressed_chunk_by_chunk() -> None:
    parts = [BIG, b"", BIG[:300]]
    headers, body = _run(_app(parts, [(b"content-type", b"text/plain")]), b"gzip")
    assert headers[b"content-encoding"] == b"gzip" and b"content-length" not in headers
    assert zlib.decompress(body, 16 + zlib.MAX_WBITS) == b"".join(parts)


@pytest.mark.parametrize(
    ("headers", "status"),
    [
        ([(b"content-type", b"text/css"), (b"content-encoding", b"gzip")], 200),
        ([(b"content-type", b"application/zip")], 200),
        ([(b"content-type", b"text/event-stream; charset=utf-8")], 200),
        ([(b"content-type", b"text/plain")], 206),
    ],
)
def test_encoded_compressed_or_partial_responses_go_as_they_are(
    headers: list[tuple[bytes, bytes]], status: int
) -> None:
    got, body = _run(_app([BIG], headers, status), b"gzip")
    assert body == BIG and got == dict(headers)
