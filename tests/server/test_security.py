"""Security headers on every kind of response, no reflected markup, bounded requests.

Payloads go into every page parameter (``app.contract.form`` field and unit names) and every API
field; whatever comes back must not carry them as live markup. Oversized requests get a
4xx before the body is read, in process and from a real uvicorn, and the server answers
its health check afterwards.
"""

import asyncio
import json
import logging
import re
import select
import socket
import subprocess
import sys
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import httpx
import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.contract.fields import BY_PAGE
from app.contract.form import ENTERED_PREFIX, UNIT_CHOICES
from app.contract.schemas import ApplicationIn
from app.contract.screws import CustomScrewIn
from app.main import create_app
from app.server.failures import FailureLog
from app.server.settings import Settings
from deploy.local import free_port, wait_until_healthy
from tests.server.asgi import asgi_get

ROOT = Path(__file__).resolve().parents[2]
PAYLOADS = ["<script>alert(1)</script>", '"><img src=x onerror=alert(1)>', "javascript:alert(1)"]
PAYLOAD_IDS = ["script", "img-onerror", "javascript-url"]
#: live markup: a script element, an element with an event handler, a javascript: link
LIVE = re.compile(
    r"<script>alert|<img src=x onerror|(?:href|src|action|formaction)\s*=\s*[\"']?\s*javascript:",
    re.IGNORECASE,
)
PAGE_BASE = {"load": "100", "speed": "50", "length": "500", "lead": "10"}
PAGE_PARAMS = sorted([*BY_PAGE, *UNIT_CHOICES, *(ENTERED_PREFIX + unit for unit in UNIT_CHOICES)])
API_BASE: dict[str, Any] = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
API_FIELDS = sorted(ApplicationIn.model_fields)
CUSTOM_SCREW: dict[str, Any] = {
    "outer_diameter_mm": 12.7,
    "root_diameter_mm": 10.0,
    "lead_mm": 10.0,
    "friction_dynamic": 0.15,
    "friction_static": 0.08,
}
SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
PAGE = "/?load=100&speed=50&length=500&lead=10"
HX = {"HX-Request": "true"}
TEN_MB = 10 * 1024 * 1024


# --- headers ---------------------------------------------------------------------------


def _csp(value: str) -> dict[str, list[str]]:
    directives = (part.split() for part in value.split(";") if part.strip())
    return {d[0]: d[1:] for d in directives}


def assert_security_headers(response: httpx.Response) -> None:
    csp = _csp(response.headers.get("content-security-policy", ""))
    assert csp.get("script-src") == ["'self'"], csp  # no inline, no eval, no CDN
    assert csp.get("frame-ancestors") == ["'none'"], csp
    assert csp.get("object-src") == ["'none'"], csp
    assert csp.get("default-src") == ["'self'"], csp
    assert response.headers.get("x-content-type-options") == "nosniff"
    assert response.headers.get("referrer-policy") in {
        "same-origin",
        "no-referrer",
        "strict-origin-when-cross-origin",
    }


RESPONSE_KINDS: list[tuple[str, str, str, dict[str, str], int]] = [
    # (id, method, url, headers, expected status)
    ("page", "GET", "/", {}, 200),
    ("page-with-result", "GET", PAGE, {}, 200),
    ("fragment", "GET", PAGE, HX, 200),
    ("catalog-page", "GET", "/catalog", {}, 200),
    ("catalog-series", "GET", "/catalog/ZBX8000", {}, 200),
    ("catalog-series-fragment", "GET", "/catalog/ZBX8000", HX, 200),
    ("catalog-series-404", "GET", "/catalog/NOPE", {}, 404),
    ("api-json", "GET", SELECT, {}, 200),
    ("api-health", "GET", "/api/v1/health", {}, 200),
    ("openapi", "GET", "/openapi.json", {}, 200),
    ("docs", "GET", "/docs", {}, 200),
    ("api-404", "GET", "/api/v1/series/NOPE", {}, 404),
    ("page-404", "GET", "/no-such-page", {}, 404),
    ("static-404", "GET", "/static/no-such-file.js", {}, 404),
    ("api-405", "GET", "/api/v1/machine", {}, 405),
    ("api-422", "GET", "/api/v1/select?load_n=abc", {}, 422),
    ("export-422", "GET", "/export.csv?load=abc&speed=50&length=500", {}, 422),
    ("static-css", "GET", "/static/css/app.css", {}, 200),
    (
        "static-vendor-gzip",
        "GET",
        "/static/vendor/htmx-2.0.11.min.js",
        {"Accept-Encoding": "gzip"},
        200,
    ),
    ("api-gzip", "GET", SELECT, {"Accept-Encoding": "gzip"}, 200),
    ("head-page", "HEAD", "/", {}, 200),
    ("api-405", "DELETE", SELECT, {}, 405),
    ("query-414", "GET", "/?" + "x" * 60_000, {}, 414),
]


@pytest.mark.parametrize(
    ("method", "url", "headers", "status"),
    [kind[1:] for kind in RESPONSE_KINDS],
    ids=[kind[0] for kind in RESPONSE_KINDS],
)
def test_security_headers_on_every_response_kind(
    client: TestClient, method: str, url: str, headers: dict[str, str], status: int
) -> None:
    response = client.request(method, url, headers=headers)
    assert response.status_code == status
    assert_security_headers(response)


def test_security_headers_on_a_413(client: TestClient) -> None:
    response = client.post("/api/v1/select", content=b"x" * (10 * 1024 * 1024))
    assert response.status_code == 413
    assert_security_headers(response)


def _failing_client() -> Iterator[TestClient]:
    """The app with one route that raises: what an unexpected bug looks like."""
    app = create_app()

    async def boom() -> None:
        raise RuntimeError("a bug")

    app.add_api_route("/api/v1/boom", boom)
    app.add_api_route("/boom", boom)
    with TestClient(app, raise_server_exceptions=False) as test_client:
        yield test_client


failing_client = pytest.fixture(scope="module")(_failing_client)
#: a new one for each test: its log of causes has seen none yet
new_failing_client = pytest.fixture(_failing_client)


@pytest.mark.parametrize(("path", "kind"), [("/api/v1/boom", "json"), ("/boom", "text/plain")])
def test_an_unexpected_error_is_a_500_with_security_headers(
    failing_client: TestClient, path: str, kind: str
) -> None:
    response = failing_client.get(path)
    assert response.status_code == 500
    assert kind in response.headers["content-type"]
    assert "a bug" not in response.text  # no internals leak
    assert_security_headers(response)
    assert failing_client.get("/api/v1/health").status_code == 200


@pytest.mark.usefixtures("catalog_loaded_once")
def test_a_500_says_it_closes_and_logs_a_line_each_and_the_traceback_once(
    new_failing_client: TestClient, caplog: pytest.LogCaptureFixture
) -> None:
    """Three failures of one cause: three lines (method, path, request id, error), one
    traceback; the client gets the request id and ``Connection: close`` (the server
    drops the connection after a 500, and says so first)."""
    caplog.set_level(logging.ERROR, logger="uvicorn.error")
    answers = [new_failing_client.get("/api/v1/boom", params={"n": n}) for n in range(3)]
    ids = [a.headers["x-request-id"] for a in answers]
    assert len(set(ids)) == 3 and all(re.fullmatch(r"[0-9a-f]{16}", i) for i in ids)
    for answer, request_id in zip(answers, ids, strict=True):
        assert answer.headers["connection"] == "close"
        assert request_id in answer.json()["error"]
    lines = [r for r in caplog.records if "/api/v1/boom" in r.getMessage()]
    assert len(lines) == 3
    for record, request_id in zip(lines, ids, strict=True):
        assert f"GET /api/v1/boom request {request_id}: " in record.getMessage()
    assert all("RuntimeError: a bug" in r.getMessage() for r in lines)
    assert [r.exc_info is not None for r in lines] == [True, False, False]
    assert ids[0] in lines[2].getMessage().split("traceback as request")[1]
    assert all("\n" not in r.getMessage() for r in lines)


def test_a_failing_path_cannot_forge_a_log_line(caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.ERROR, logger="uvicorn.error")
    scope = {"method": "GET", "path": "/x\nINFO forged"}
    FailureLog().record(scope, RuntimeError("two\nlines"))
    (record,) = caplog.records
    assert "\n" not in record.getMessage() and record.exc_info is not None


@pytest.mark.parametrize(
    "path",
    [
        "/static/vendor/htmx-2.0.11.min.js",
        "/static/vendor/swagger-ui-bundle-5.35.0.js",
        "/static/vendor/swagger-ui-5.35.0.css",
        "/static/css/app.css?v=0.1.0",
    ],
)
def test_versioned_assets_are_immutable(client: TestClient, path: str) -> None:
    cache = client.get(path).headers["cache-control"]
    assert "immutable" in cache and "max-age=31536000" in cache


@pytest.mark.parametrize("path", ["/static/css/app.css", "/static/js/app.js", "/static/js/docs.js"])
def test_unversioned_assets_cache_briefly(client: TestClient, path: str) -> None:
    response = client.get(path)
    assert response.status_code == 200
    cache = response.headers["cache-control"]
    max_age = int(re.search(r"max-age=(\d+)", cache)[1])  # type: ignore[index]
    assert "immutable" not in cache and 0 < max_age <= 3600
    again = client.get(path, headers={"If-None-Match": response.headers["etag"]})
    assert again.status_code == 304 and again.headers["cache-control"] == cache


def test_static_files_come_precompressed_and_intact(client: TestClient) -> None:
    path = "/static/vendor/htmx-2.0.11.min.js"
    raw = (ROOT / "static/vendor/htmx-2.0.11.min.js").read_bytes()
    zipped = client.get(path, headers={"Accept-Encoding": "gzip"})
    assert zipped.headers["content-encoding"] == "gzip"
    assert zipped.content == raw  # httpx decompresses
    assert int(zipped.headers["content-length"]) < len(raw) / 2
    plain = client.get(path, headers={"Accept-Encoding": "identity"})
    assert "content-encoding" not in plain.headers and plain.content == raw
    part = client.get(path, headers={"Accept-Encoding": "gzip", "Range": "bytes=0-9"})
    assert part.status_code == 206 and part.content == raw[:10]
    again = client.get(
        path, headers={"Accept-Encoding": "gzip", "If-None-Match": zipped.headers["etag"]}
    )
    assert again.status_code == 304


# --- /docs -----------------------------------------------------------------------------


class _Refs(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.urls: list[str] = []
        self.inline_scripts = 0
        self._in_script = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        for name in ("src", "href"):
            if a.get(name):
                self.urls.append(str(a[name]))
        if tag == "script":
            self._in_script = not a.get("src")
        if any(name.startswith("on") for name in a):
            self.inline_scripts += 1

    def handle_data(self, data: str) -> None:
        if self._in_script and data.strip():
            self.inline_scripts += 1

    def handle_endtag(self, tag: str) -> None:
        if tag == "script":
            self._in_script = False


def test_docs_uses_only_our_static_files(client: TestClient) -> None:
    response = client.get("/docs")
    assert response.status_code == 200
    refs = _Refs()
    refs.feed(response.text)
    assert refs.urls, "the docs page references no assets"
    assert refs.inline_scripts == 0
    for url in refs.urls:
        assert url.startswith("/static/"), url
        assert client.get(url).status_code == 200, url
    assert '"/openapi.json"' in response.text
    assert client.get("/openapi.json").status_code == 200


def test_redoc_is_off(client: TestClient) -> None:
    assert client.get("/redoc").status_code == 404


# --- reflected input -------------------------------------------------------------------


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
def test_the_markup_check_catches_a_raw_reflection(payload: str) -> None:
    """The check itself: raw payloads in a page are found, escaped ones are not."""
    from markupsafe import escape

    raw = f'<p>{payload}</p><a href="{payload}">x</a>'
    assert LIVE.search(raw)
    assert not LIVE.search(f'<p>{escape(payload)}</p><a href="/?q={escape(payload)}">x</a>')


def assert_no_live_markup(response: httpx.Response) -> None:
    match = LIVE.search(response.text)
    assert match is None, response.text[max(0, match.start() - 200) : match.end() + 200]
    for name, value in response.headers.items():
        assert "<" not in value and "javascript:" not in value.lower(), (name, value)


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
@pytest.mark.parametrize("param", PAGE_PARAMS)
def test_page_never_reflects_markup(client: TestClient, param: str, payload: str) -> None:
    params = {**PAGE_BASE, param: payload}
    for headers in ({}, HX):
        response = client.get("/", params=params, headers=headers)
        assert response.status_code == 200
        assert response.headers["content-type"].startswith("text/html")
        assert_no_live_markup(response)


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
@pytest.mark.parametrize("param", PAGE_PARAMS)
def test_exports_never_reflect_markup(client: TestClient, param: str, payload: str) -> None:
    params = {**PAGE_BASE, param: payload}
    csv = client.get("/export.csv", params=params)
    assert csv.status_code in (200, 422)
    if csv.status_code == 200:
        assert csv.headers["content-type"].startswith("text/csv")
        assert csv.headers["content-disposition"].startswith("attachment")
    assert_no_live_markup(csv)
    data = client.get("/export.json", params=params)
    assert data.status_code in (200, 422)
    if data.status_code == 200:
        assert data.headers["content-type"] == "application/json"
    assert_no_live_markup(data)


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
def test_page_never_reflects_markup_in_names_or_paths(client: TestClient, payload: str) -> None:
    for response in (
        client.get("/", params={**PAGE_BASE, payload: "1"}),
        client.get("/", params={**PAGE_BASE, payload: "1"}, headers=HX),
        client.get("/no-such-page/" + payload),
    ):
        assert response.status_code in (200, 404)
        assert_no_live_markup(response)


def assert_json(response: httpx.Response, statuses: tuple[int, ...]) -> Any:
    assert response.status_code in statuses, response.text
    assert response.headers["content-type"] == "application/json"
    assert response.headers["x-content-type-options"] == "nosniff"
    return response.json()


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
@pytest.mark.parametrize("field", API_FIELDS)
def test_api_select_answers_json_to_markup(client: TestClient, field: str, payload: str) -> None:
    body = {**API_BASE, field: payload}
    got = assert_json(client.get("/api/v1/select", params=body), (422,))
    # the cycle's text names the move and the part it cannot read (moves.0.distance_mm)
    assert got["detail"][0]["field"].split(".")[0] == field
    assert_json(client.post("/api/v1/select", json=body), (422,))


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
def test_api_answers_json_to_markup_in_names_and_ids(client: TestClient, payload: str) -> None:
    assert_json(client.get("/api/v1/select", params={**API_BASE, payload: 1}), (422,))
    assert_json(client.post("/api/v1/select", json={**API_BASE, payload: 1}), (422,))
    assert_json(client.get("/api/v1/series/" + payload), (404,))
    evaluate = {"application": API_BASE, "screw": {"catalog_id": payload}}
    got = assert_json(client.post("/api/v1/evaluate", json=evaluate), (404,))
    assert got["error"] == "unknown screw"


@pytest.mark.parametrize("payload", PAYLOADS, ids=PAYLOAD_IDS)
@pytest.mark.parametrize(
    "where",
    [f"application.{f}" for f in API_FIELDS]
    + [f"screw.{f}" for f in sorted(CustomScrewIn.model_fields)],
)
def test_api_evaluate_answers_json_to_markup(client: TestClient, where: str, payload: str) -> None:
    part, field = where.split(".")
    body: dict[str, Any] = {"application": dict(API_BASE), "screw": dict(CUSTOM_SCREW)}
    body[part][field] = payload
    assert_json(client.post("/api/v1/evaluate", json=body), (422,))


def test_api_refuses_a_body_that_is_not_json(client: TestClient) -> None:
    response = client.post(
        "/api/v1/select",
        content=b"<script>alert(1)</script>",
        headers={"Content-Type": "text/html"},
    )
    assert_json(response, (422,))


# --- oversized requests, in process ----------------------------------------------------


def _chunks(total: int, size: int = 64 * 1024) -> Iterator[bytes]:
    for _ in range(total // size):
        yield b"x" * size


BODIES: dict[str, Any] = {
    "10MB": lambda: b"{" * TEN_MB,
    "10MB-chunked": lambda: _chunks(TEN_MB),  # no Content-Length: counted as it arrives
    "10MB-chunked-json": lambda: (b" " * 65536 for _ in range(TEN_MB // 65536)),
}


@pytest.mark.parametrize("make_body", BODIES.values(), ids=BODIES.keys())
@pytest.mark.parametrize("path", ["/api/v1/select", "/api/v1/evaluate"])
def test_oversized_bodies_get_413(client: TestClient, path: str, make_body: Any) -> None:
    response = client.post(path, content=make_body(), headers={"Content-Type": "application/json"})
    assert response.status_code == 413
    assert response.json()["error"] == "request body too large"
    assert_security_headers(response)
    assert client.get("/api/v1/health").status_code == 200


QUERIES: dict[str, tuple[str, bytes]] = {
    "100KB-api": ("/api/v1/select", b"load_n=" + b"1" * 100_000),
    "100KB-page": ("/", b"load=" + b"1" * 100_000),
    "100KB-export": ("/export.csv", b"load=" + b"1" * 100_000),
    "5000-params-api": ("/api/v1/select", b"&".join([b"a=1"] * 5000)),
    "5000-params-page": ("/", b"&".join([b"load=1"] * 5000)),
}


@pytest.mark.parametrize(("path", "query"), QUERIES.values(), ids=QUERIES.keys())
def test_oversized_queries_get_414(
    app: FastAPI, client: TestClient, path: str, query: bytes
) -> None:
    # on a thread of its own: Playwright's sync API (browser tests earlier in the same
    # session) keeps an event loop running on the main thread
    with ThreadPoolExecutor(max_workers=1) as pool:
        status, headers = pool.submit(asyncio.run, asgi_get(app, path, query)).result()
    assert status == 414
    assert headers["content-type"] == "application/json"
    assert "frame-ancestors 'none'" in headers["content-security-policy"]
    assert client.get("/api/v1/health").status_code == 200


@pytest.mark.usefixtures("catalog_loaded_once")
def test_many_parameters_are_refused_even_in_a_short_query() -> None:
    app = create_app(Settings(max_query_chars=1_000_000))
    with TestClient(app) as test_client:
        query = "&".join(["a"] * 5000)
        assert test_client.get("/api/v1/select?" + query).status_code == 414
        assert test_client.get(SELECT).status_code == 200


def test_a_large_body_within_the_limit_is_read(client: TestClient) -> None:
    """The limit refuses big bodies, not big-enough ones: 60 KB of JSON whitespace."""
    body = json.dumps(API_BASE) + " " * 60_000
    response = client.post(
        "/api/v1/select", content=body, headers={"Content-Type": "application/json"}
    )
    assert response.status_code == 200


# --- oversized bodies against a real uvicorn -------------------------------------------


#: the tests of the live server run on one xdist worker (``--dist loadgroup``): it starts once
ON_LIVE_SERVER = pytest.mark.xdist_group("security-live-server")


@pytest.fixture(scope="module")
def live_port() -> Iterator[int]:
    port = free_port()
    cmd = [sys.executable, "-m", "uvicorn", "app.main:create_app", "--factory"]
    proc = subprocess.Popen([*cmd, "--port", str(port), "--log-level", "warning"], cwd=ROOT)
    try:
        wait_until_healthy(port, proc, "uvicorn")
        yield port
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def _status(port: int, path: str) -> int | None:
    try:
        return httpx.get(f"http://127.0.0.1:{port}{path}", timeout=5).status_code
    except httpx.HTTPError:
        return None


def _post_raw(port: int, head: str, body_chunks: Iterator[bytes]) -> tuple[bytes, int]:
    """Send a request, stop sending as soon as an answer is readable; (answer, bytes sent)."""
    sent = 0
    with socket.create_connection(("127.0.0.1", port), timeout=10) as sock:
        sock.sendall(head.encode())
        for chunk in body_chunks:
            if select.select([sock], [], [], 0)[0]:
                break
            try:
                sock.sendall(chunk)
            except OSError:  # the server answered and closed while we were sending
                break
            sent += len(chunk)
        answer = b""
        try:
            while b"\r\n\r\n" not in answer:
                data = sock.recv(65536)
                if not data:
                    break
                answer += data
        except ConnectionResetError:
            pass
    return answer, sent


@ON_LIVE_SERVER
def test_real_server_refuses_a_10mb_body_before_reading_it(live_port: int) -> None:
    head = (
        "POST /api/v1/select HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
        f"Content-Length: {TEN_MB}\r\n\r\n"
    )
    answer, sent = _post_raw(live_port, head, _chunks(TEN_MB))
    assert answer.startswith(b"HTTP/1.1 413"), answer[:200]
    assert sent < TEN_MB  # the answer came before the body was sent
    assert _status(live_port, "/api/v1/health") == 200


@ON_LIVE_SERVER
def test_real_server_refuses_a_10mb_chunked_body(live_port: int) -> None:
    head = (
        "POST /api/v1/select HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
        "Transfer-Encoding: chunked\r\n\r\n"
    )
    size = 64 * 1024
    chunk = f"{size:x}\r\n".encode() + b" " * size + b"\r\n"
    answer, sent = _post_raw(live_port, head, (chunk for _ in range(TEN_MB // size)))
    assert answer.startswith(b"HTTP/1.1 413"), answer[:200]
    assert sent < TEN_MB
    assert _status(live_port, "/api/v1/health") == 200


@ON_LIVE_SERVER
def test_real_server_refuses_oversized_queries(live_port: int) -> None:
    """A 100 KB request line stops in uvicorn's parser (400, before the app); 5,000
    parameters in a shorter query reach the app and get its 414."""
    with socket.create_connection(("127.0.0.1", live_port), timeout=10) as sock:
        sock.sendall(
            f"GET /api/v1/select?load_n={'1' * 100_000} HTTP/1.1\r\nHost: x\r\n\r\n".encode()
        )
        assert sock.recv(64).split(b" ")[1] in (b"400", b"414")
    many = "&".join(["a=1"] * 5000)
    response = httpx.get(f"http://127.0.0.1:{live_port}/api/v1/select?{many}", timeout=10)
    assert response.status_code == 414
    assert_security_headers(response)
    assert _status(live_port, "/api/v1/health") == 200
