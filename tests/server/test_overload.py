"""Load shedding: past the in-flight limit a request gets 503 with Retry-After at once.

Deterministic: the requests in progress are held by an app that waits on an event, or
started together in one event loop, never raced against a clock.
"""

import asyncio
import contextlib
import threading
from collections.abc import Awaitable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pytest

from app.api import routes
from app.main import create_app
from app.server.overload import OverloadMiddleware, request_cost
from app.server.settings import Settings
from tests.server.asgi import asgi_get, scope

SELECT = b"load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"


def _run(coroutine: Awaitable[Any]) -> Any:
    """On a thread of its own: Playwright's sync API may hold the main thread's loop."""
    with ThreadPoolExecutor(max_workers=1) as pool:
        return pool.submit(asyncio.run, coroutine).result()  # type: ignore[arg-type]


class HeldApp:
    """Answers 200, but only once ``release`` is set; counts the requests it has."""

    def __init__(self) -> None:
        self.release = asyncio.Event()
        self.holding = 0

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["path"] != "/api/v1/health":
            self.holding += 1
            await self.release.wait()
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": b"ok"})


async def _held_scenario() -> dict[str, Any]:
    held = HeldApp()
    shedder = OverloadMiddleware(
        held, max_in_flight=3, retry_after_s=2, exempt_paths=frozenset({"/api/v1/health"})
    )
    waiting = [asyncio.create_task(asgi_get(shedder, "/slow")) for _ in range(3)]
    while held.holding < 3:
        await asyncio.sleep(0)
    over = await asgi_get(shedder, "/slow")
    health = await asgi_get(shedder, "/api/v1/health")
    in_flight_while_held = shedder.in_flight
    held.release.set()
    served = await asyncio.gather(*waiting)
    after = await asgi_get(shedder, "/slow")
    return {
        "over": over,
        "health": health,
        "served": served,
        "after": after,
        "in_flight_while_held": in_flight_while_held,
        "in_flight_after": shedder.in_flight,
        "shed": shedder.shed,
    }


def test_a_request_past_the_limit_gets_503_with_retry_after_at_once() -> None:
    got = _run(_held_scenario())
    status, headers = got["over"]
    assert status == 503
    assert headers["retry-after"] == "2"
    assert headers["content-type"] == "application/json"
    assert headers["cache-control"] == "no-store"
    assert got["health"][0] == 200  # the health check is never shed
    assert [s for s, _ in got["served"]] == [200, 200, 200]
    assert got["after"][0] == 200  # capacity comes back as requests finish
    assert (got["in_flight_while_held"], got["in_flight_after"], got["shed"]) == (3, 0, 1)


async def _failing_scenario() -> tuple[int, int]:
    async def broken(scope: Any, receive: Any, send: Any) -> None:
        raise RuntimeError("a bug")

    shedder = OverloadMiddleware(broken, max_in_flight=1, retry_after_s=1, exempt_paths=frozenset())
    for _ in range(3):
        with contextlib.suppress(RuntimeError):
            await asgi_get(shedder, "/x")
    return shedder.in_flight, shedder.shed


def test_a_failing_request_gives_its_place_back() -> None:
    assert _run(_failing_scenario()) == (0, 0)


async def _never_waits(scope: Any, receive: Any, send: Any) -> None:
    """A route that computes without awaiting anything: it runs start to end in one go."""
    await send({"type": "http.response.start", "status": 200, "headers": []})
    await send({"type": "http.response.body", "body": b"ok"})


async def _burst_without_awaits() -> list[tuple[int, dict[str, str]]]:
    shedder = OverloadMiddleware(
        _never_waits, max_in_flight=2, retry_after_s=1, exempt_paths=frozenset()
    )
    return await asyncio.gather(*(asgi_get(shedder, "/x") for _ in range(5)))


def test_requests_waiting_in_the_loop_count_even_if_the_route_never_awaits() -> None:
    """Without a yield before the route runs, each of these would finish before the next
    was counted: all five 'in flight' one at a time, the backlog invisible."""
    answers = _run(_burst_without_awaits())
    assert [status for status, _ in answers] == [200, 200, 503, 503, 503]


async def _burst(limit: int, requests: int) -> list[tuple[int, dict[str, str]]]:
    app = create_app(Settings(max_requests_in_flight=limit, response_cache_bytes=0))
    calls = [asgi_get(app, "/api/v1/select", SELECT) for _ in range(requests)]
    calls.append(asgi_get(app, "/api/v1/health"))
    return await asyncio.gather(*calls)


def test_a_burst_that_arrives_together_is_counted_before_any_is_computed() -> None:
    """Six selects arriving in one loop turn, limit two: two computed, four shed, though
    the route itself never waits; the health check answers 200 all the same."""
    answers = _run(_burst(limit=2, requests=6))
    *selects, health = answers
    assert sorted(status for status, _ in selects) == [200, 200, 503, 503, 503, 503]
    assert health[0] == 200
    for status, headers in selects:
        if status == 503:
            assert headers["retry-after"] == "1"
            assert "frame-ancestors 'none'" in headers["content-security-policy"]


def test_the_limit_can_be_turned_off() -> None:
    answers = _run(_burst(limit=0, requests=4))
    assert [status for status, _ in answers] == [200] * 5


FULL = SELECT + b"&detail=full&limit=100"


@pytest.mark.parametrize(
    ("path", "query", "cost"),
    [
        ("/api/v1/select", SELECT, 1),
        ("/api/v1/select", SELECT + b"&limit=100", 1),  # the compact form stays cheap
        ("/api/v1/select", SELECT + b"&detail=full", 2),  # 10 candidates
        ("/api/v1/select", FULL, 13),
        ("/api/v1/select", SELECT + b"&detail=full&limit=99999999", 2),  # refused: 422
        ("/api/v1/select", SELECT + b"&detail=full&limit=x", 2),
        ("/export.json", b"load=100&speed=50&length=500&limit=100", 13),
        ("/export.csv", b"load=100&speed=50&length=500", 2),
        ("/", b"load=100&speed=50&length=500&limit=100", 1),
    ],
    ids=[
        "compact",
        "compact-100",
        "full",
        "full-100",
        "full-out-of-bounds",
        "full-bad-limit",
        "export-json-100",
        "export-csv",
        "page",
    ],
)
def test_a_request_costs_by_the_work_it_asks_for(path: str, query: bytes, cost: int) -> None:
    assert request_cost(scope(path, query)) == cost


async def _full_burst() -> list[tuple[int, dict[str, str]]]:
    app = create_app(Settings(max_requests_in_flight=32, response_cache_bytes=0))
    return await asyncio.gather(*(asgi_get(app, "/api/v1/select", FULL) for _ in range(4)))


def test_costly_requests_are_shed_by_their_cost() -> None:
    """Four full forms of a hundred candidates (13 units each) against 32 units: two are
    taken, two shed, where four cheap requests would all have been taken."""
    answers = _run(_full_burst())
    assert sorted(status for status, _ in answers) == [200, 200, 503, 503]


async def _health_beside_full_forms(release: threading.Event) -> list[str]:
    app = create_app(Settings(response_cache_bytes=0))
    finished: list[str] = []

    async def call(name: str, path: str, query: bytes = b"") -> None:
        await asgi_get(app, path, query)
        finished.append(name)

    queries = [FULL.replace(b"load_n=100", b"load_n=%d" % (101 + i)) for i in range(2)]
    started = [asyncio.create_task(call("full", "/api/v1/select", q)) for q in queries]
    for _ in range(10):  # loop turns: the full forms are admitted and computing
        await asyncio.sleep(0)
    await call("health", "/api/v1/health")
    release.set()
    await asyncio.gather(*started)
    return finished


def test_the_health_check_is_answered_while_full_forms_compute(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The full forms compute on threads of their own: the health check, asked once they
    are computing, is answered first. Each full form here waits (5 s at most) until the
    health check has been answered: on threads that wait leaves the loop free; computed
    on the loop, the forms would hold it until they finished, before the health check
    was even read."""
    release = threading.Event()
    full_selection = routes._full_selection

    def held(*args: Any) -> Any:
        release.wait(timeout=5.0)
        return full_selection(*args)

    monkeypatch.setattr(routes, "_full_selection", held)
    assert _run(_health_beside_full_forms(release)) == ["health", "full", "full"]
