"""The per-process response cache: repeated selection queries are answered as computed.

Also what a hostile client cannot do to it: grow it with long header values, or store one
kind of response (gzip, full page) where another kind (identity, fragment) is looked up
by sending a header twice.
"""

import gzip

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from app.main import create_app
from app.server.cache import ResponseCache
from app.server.settings import Settings
from app.web import catalog_page

SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
PAGE = "/?load=100&speed=50&length=500&lead=10"
HX = {"HX-Request": "true"}
#: each test builds an app of its own settings, over the one built-in catalog
pytestmark = pytest.mark.usefixtures("catalog_loaded_once")


def _cache(app: FastAPI) -> ResponseCache:
    client = TestClient(app)
    client.get("/api/v1/health")  # builds the middleware stack
    layer = app.middleware_stack
    while not isinstance(layer, ResponseCache):
        layer = layer.app  # type: ignore[union-attr]
    return layer


def _cached(settings: Settings | None = None) -> tuple[TestClient, ResponseCache]:
    """A client and the cache of its app, to count hits and misses."""
    app = create_app(settings or Settings())
    return TestClient(app), _cache(app)


def test_repeated_select_is_a_hit_with_the_same_bytes() -> None:
    client, cache = _cached()
    first, second = client.get(SELECT), client.get(SELECT)
    assert (cache.misses, cache.hits) == (1, 1)
    assert first.content == second.content and first.headers == second.headers
    assert second.headers["content-security-policy"].startswith("default-src 'self'")


def test_a_hit_looks_like_a_miss() -> None:
    """Nothing in a response says whether it came from the cache: whether someone else
    ran these inputs is theirs to know."""
    client, cache = _cached()
    for path in (SELECT, PAGE):
        first, second = client.get(path), client.get(path)
        assert cache.hits and "x-cache" not in second.headers
        assert sorted(first.headers.keys()) == sorted(second.headers.keys())


def test_fragment_and_full_page_are_cached_apart() -> None:
    client, cache = _cached()
    fragment = client.get(PAGE, headers={"HX-Request": "true"})
    full = client.get(PAGE)
    assert (cache.misses, cache.hits) == (2, 0)
    assert "<html" in full.text and "<html" not in fragment.text
    again = client.get(PAGE, headers={"HX-Request": "true"})
    assert cache.hits == 1 and again.text == fragment.text
    assert again.headers["hx-push-url"] == fragment.headers["hx-push-url"]


def test_other_queries_errors_and_posts_are_not_served_from_cache() -> None:
    client, cache = _cached()
    client.get(SELECT)
    client.get(SELECT.replace("load_n=100", "load_n=101"))
    client.get("/api/v1/select?load_n=abc")
    client.get("/api/v1/select?load_n=abc")
    assert (cache.misses, cache.hits) == (4, 0)
    body = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500}
    client.post("/api/v1/select", json=body)
    assert (cache.misses, cache.hits) == (4, 0)


def test_cache_is_bounded_by_bytes_and_can_be_turned_off() -> None:
    # the full form: about 42 kB gzipped (41,575 bytes for load 100, with the ball screws,
    # ordering lines and energy rows), each under the eighth of the budget an entry may
    # take (60 kB), some of twenty fit
    app = create_app(Settings(response_cache_bytes=8 * 60_000))
    client = TestClient(app, headers={"Accept-Encoding": "gzip"})
    full = SELECT + "&detail=full"
    for load in range(100, 120):
        client.get(full.replace("load_n=100", f"load_n={load}"))
    cache = _cache(app)
    assert 0 < cache.size_bytes <= 8 * 60_000
    assert cache.size_bytes == sum(entry.held_bytes for entry in cache.entries.values())
    # the count covers more than the body: key, status and headers too
    assert all(entry.held_bytes > len(entry.body) + 500 for entry in cache.entries.values())
    misses = cache.misses
    client.get(full)
    assert cache.misses == misses + 1  # the oldest was evicted
    off, off_cache = _cached(Settings(response_cache_bytes=0))
    off.get(SELECT)
    off.get(SELECT)
    assert (off_cache.misses, off_cache.hits, off_cache.entries) == (0, 0, {})


def test_cache_is_bounded_by_entry_count() -> None:
    app = create_app(Settings(response_cache_entries=5))
    client = TestClient(app)
    for load in range(100, 112):
        client.get(SELECT.replace("load_n=100", f"load_n={load}"))
    assert len(_cache(app).entries) == 5


def test_megabyte_header_values_do_not_grow_the_cache() -> None:
    """200 requests, each with its own 1 MB HX-History-Restore-Request value: the key is a
    fixed-size digest, so the cache holds one entry of the same size whatever was sent."""
    app = create_app(Settings())
    client = TestClient(app)
    cache = _cache(app)
    for i in range(200):
        value = f"{i:06d}" + "x" * 1_000_000
        response = client.get(SELECT, headers={"HX-History-Restore-Request": value})
        assert response.status_code == 200
    assert len(cache.entries) == 1
    assert cache.size_bytes == next(iter(cache.entries.values())).held_bytes < 200_000
    assert all(len(key) == 32 for key in cache.entries)


def test_megabyte_headers_on_many_queries_stay_within_both_bounds() -> None:
    app = create_app(Settings(response_cache_bytes=2 * 1024 * 1024, response_cache_entries=50))
    client = TestClient(app)
    cache = _cache(app)
    for load in range(100, 180):
        query = PAGE.replace("load=100", f"load={load}")
        client.get(query, headers={"HX-History-Restore-Request": "y" * 1_000_000})
        assert cache.size_bytes <= 2 * 1024 * 1024 and len(cache.entries) <= 50
    assert len(cache.entries) == 50


def _raw_get(client: TestClient, url: str, headers: list[tuple[str, str]]) -> bytes:
    """The body as sent (not decompressed), for a request that repeats header lines."""
    with client.stream("GET", url, headers=headers) as response:
        assert response.status_code == 200
        return b"".join(response.iter_raw())


def test_duplicated_accept_encoding_cannot_poison_plain_clients() -> None:
    client = TestClient(create_app(Settings()))
    _raw_get(client, SELECT, [("Accept-Encoding", "gzip"), ("Accept-Encoding", "identity")])
    plain = client.get(SELECT, headers={"Accept-Encoding": "identity"})
    assert "content-encoding" not in plain.headers
    assert plain.content.startswith(b"{")
    zipped = _raw_get(client, SELECT, [("Accept-Encoding", "gzip")])
    assert gzip.decompress(zipped) == plain.content


def test_duplicated_hx_request_cannot_poison_htmx_clients() -> None:
    client, cache = _cached()
    first = client.get(PAGE, headers=[("HX-Request", "zzz"), ("HX-Request", "true")])
    assert "<html" in first.text  # read by its first line, as the page route reads it
    fragment = client.get(PAGE, headers={"HX-Request": "true"})
    assert "<html" not in fragment.text and "hx-push-url" in fragment.headers
    again = client.get(PAGE, headers=[("HX-Request", "true"), ("HX-Request", "zzz")])
    assert cache.hits == 1 and again.text == fragment.text


def test_gzip_at_q0_is_not_gzip_for_the_cache_nor_the_response() -> None:
    client, cache = _cached()
    client.get(SELECT, headers={"Accept-Encoding": "gzip"})
    refused = client.get(SELECT, headers={"Accept-Encoding": "gzip;q=0, identity"})
    assert "content-encoding" not in refused.headers
    assert (cache.misses, cache.hits) == (2, 0)


def _vary(value: str) -> set[str]:
    return {v.strip().lower() for v in value.split(",")}


def test_vary_names_what_cached_responses_depend_on() -> None:
    client = TestClient(create_app(Settings()))
    page_vary = {"accept-encoding", "hx-request", "hx-history-restore-request"}
    for headers in ({}, {"Accept-Encoding": "gzip"}, {"HX-Request": "true"}):
        for _ in range(2):  # the miss, then the hit
            assert _vary(client.get(PAGE, headers=headers).headers["vary"]) == page_vary
    for _ in range(2):
        assert _vary(client.get(SELECT).headers["vary"]) == {"accept-encoding"}


def test_pages_that_ignore_the_query_are_one_entry_for_any_query() -> None:
    """Issue 31: /catalog?r=1, ?r=2... each rendered and compressed a 1.3 MB page. The
    catalog, the guide and the validation page do not depend on the query: the first
    answer serves every query after it, bytes unchanged."""
    client, cache = _cached()
    for path in ("/catalog", "/guide", "/validation"):
        first = client.get(f"{path}?r=1")
        others = [client.get(f"{path}?r={i}") for i in range(2, 5)]
        assert first.status_code == 200
        assert {o.content for o in others} == {first.content}
    assert (cache.misses, cache.hits) == (3, 9)
    assert len(cache.entries) == 3


def test_a_series_page_is_one_entry_per_kind_for_any_query() -> None:
    """/catalog/{series_id} depends on its path alone: ?r=1, ?r=2... share one entry, the
    HTMX fragment (the catalog page's <details> opened) another; an unknown id's 404 is
    not kept, and a path beside /catalog/ is not cached at all."""
    client, cache = _cached()
    page = [client.get(f"/catalog/ZBX8000?r={i}") for i in range(3)]
    fragment = [client.get(f"/catalog/ZBX8000?r={i}", headers=HX) for i in range(3)]
    assert {p.content for p in page} == {page[0].content}
    assert {f.content for f in fragment} == {fragment[0].content}
    assert page[0].content != fragment[0].content
    assert b"<html" in page[0].content and b"<html" not in fragment[0].content
    assert (cache.misses, cache.hits, len(cache.entries)) == (2, 4, 2)
    assert all(_vary(r.headers["vary"]) >= {"hx-request", "accept-encoding"} for r in page)
    for _ in range(2):
        assert client.get("/catalog/NOPE").status_code == 404
    client.get("/catalogue")
    assert (cache.misses, len(cache.entries)) == (4, 2)


def test_the_catalog_page_is_rendered_once_at_start_up(monkeypatch: pytest.MonkeyPatch) -> None:
    """Rendered when the app is built, never per request: with the cache off and the
    page's builder broken afterwards, it is still served, the same each time."""
    client, _ = _cached(Settings(response_cache_bytes=0))
    monkeypatch.setattr(catalog_page, "family_sections", _broken)
    first, second = client.get("/catalog"), client.get("/catalog?x=1")
    assert first.status_code == second.status_code == 200
    assert first.content == second.content and "Provenance" in first.text


def _broken(*_: object) -> None:
    raise AssertionError("the catalog page was rendered again")
