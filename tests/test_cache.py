"""The per-process response cache: repeated selection queries are answered as computed."""

from fastapi.testclient import TestClient

from app.cache import ResponseCache
from app.main import create_app
from app.settings import Settings

SELECT = "/api/v1/select?load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
PAGE = "/?load=100&speed=50&length=500&lead=10"


def test_repeated_select_is_a_hit_with_the_same_bytes() -> None:
    client = TestClient(create_app(Settings()))
    first, second = client.get(SELECT), client.get(SELECT)
    assert (first.headers["x-cache"], second.headers["x-cache"]) == ("miss", "hit")
    assert first.content == second.content
    assert second.headers["content-security-policy"].startswith("default-src 'self'")


def test_fragment_and_full_page_are_cached_apart() -> None:
    client = TestClient(create_app(Settings()))
    fragment = client.get(PAGE, headers={"HX-Request": "true"})
    full = client.get(PAGE)
    assert full.headers["x-cache"] == "miss"
    assert "<html" in full.text and "<html" not in fragment.text
    again = client.get(PAGE, headers={"HX-Request": "true"})
    assert again.headers["x-cache"] == "hit" and again.text == fragment.text
    assert again.headers["hx-push-url"] == fragment.headers["hx-push-url"]


def test_other_queries_errors_and_posts_are_not_served_from_cache() -> None:
    client = TestClient(create_app(Settings()))
    client.get(SELECT)
    assert client.get(SELECT.replace("load_n=100", "load_n=101")).headers["x-cache"] == "miss"
    client.get("/api/v1/select?load_n=abc")
    assert client.get("/api/v1/select?load_n=abc").headers["x-cache"] == "miss"
    body = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500}
    assert "x-cache" not in client.post("/api/v1/select", json=body).headers


def test_cache_is_bounded_by_bytes_and_can_be_turned_off() -> None:
    app = create_app(Settings(response_cache_bytes=8 * 20_000))
    client = TestClient(app, headers={"Accept-Encoding": "gzip"})
    for load in range(100, 120):
        client.get(SELECT.replace("load_n=100", f"load_n={load}"))
    cache = app.middleware_stack
    while not isinstance(cache, ResponseCache):
        cache = cache.app
    assert 0 < cache.size <= 8 * 20_000
    assert cache.size == sum(len(body) for _, body in cache.entries.values())
    assert client.get(SELECT).headers["x-cache"] == "miss"  # the oldest was evicted
    off = TestClient(create_app(Settings(response_cache_bytes=0)))
    off.get(SELECT)
    assert "x-cache" not in off.get(SELECT).headers
