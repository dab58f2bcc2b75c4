"""Load shedding: past the in-flight limit a request gets 503 with Retry-After at once.

Deterministic: the requests in progress are held by an app that waits on an event, or
started together in one event loop, never raced against a clock.
"""

import asyncio
import contextlib
import threading
from collections.abc import Awaitable, Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import pytest

from app.api import routes
from app.main import STATED_COSTS, create_app
from app.server.overload import OverloadMiddleware
from app.server.settings import Settings
from app.web import pages
from tests.server.asgi import asgi_get, scope

SELECT = b"load_n=100&speed_mm_s=50&length_mm=500&lead_mm=10"
#: each test builds an app of its own settings, over the one built-in catalog
pytestmark = pytest.mark.usefixtures("catalog_loaded_once")


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


async def asgi_post(app: Any, path: str, query: bytes, body: bytes) -> tuple[int, dict[str, str]]:
    """One POST of a JSON ``body`` into an ASGI app: (status, headers)."""
    sent: list[dict[str, Any]] = []
    request = {**scope(path, query), "method": "POST"}
    request["headers"] = [
        (b"host", b"testserver"),
        (b"content-type", b"application/json"),
        (b"content-length", str(len(body)).encode()),
    ]

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": body, "more_body": False}

    async def send(message: dict[str, Any]) -> None:
        sent.append(message)

    await app(request, receive, send)
    start = sent[0]
    return start["status"], {k.decode(): v.decode() for k, v in start["headers"]}


BODY = b'{"load_n": %d, "speed_mm_s": 50, "length_mm": 500, "limit": 100}'
#: four requests each, every one a full form of a hundred candidates however it is asked
FULL_FORMS = {
    "query": lambda app, i: asgi_get(app, "/api/v1/select", FULL.replace(b"100", b"%d" % i, 1)),
    # percent-encoded: 'detail=full&limit=100' once decoded
    "encoded": lambda app, i: asgi_get(
        app,
        "/api/v1/select",
        b"load_n=%d&speed_mm_s=50&length_mm=500&detail=ful%%6C&limit=1%%300" % i,
    ),
    "limit-in-body": lambda app, i: asgi_post(app, "/api/v1/select", b"detail=full", BODY % i),
    "export-json": lambda app, i: asgi_get(
        app, "/export.json", b"load=%d&speed=50&length=500&limit=100" % i
    ),
    "export-csv": lambda app, i: asgi_get(
        app, "/export.csv", b"load=%d&speed=50&length=500&limit=1%%300" % i
    ),
}
#: the same four as compact selects, or asking a full form of the default 10 candidates
CHEAP = {
    "compact": lambda app, i: asgi_get(app, "/api/v1/select", SELECT + b"&limit=100"),
    "full-10": lambda app, i: asgi_get(app, "/api/v1/select", SELECT + b"&detail=full"),
}


async def _four(ask: Callable[[Any, int], Awaitable[tuple[int, dict[str, str]]]]) -> list[int]:
    app = create_app(Settings(max_requests_in_flight=32, response_cache_bytes=0))
    answers = await asyncio.gather(*(ask(app, 101 + i) for i in range(4)))
    return sorted(status for status, _ in answers)


@pytest.mark.parametrize("ask", FULL_FORMS.values(), ids=FULL_FORMS.keys())
def test_a_full_form_costs_by_its_validated_limit(ask: Any) -> None:
    """Four full forms of a hundred candidates (13 units each, once the input is read)
    against 32 units: two are taken, two shed, however the query spells it or wherever
    the limit is given."""
    assert _run(_four(ask)) == [200, 200, 503, 503]


@pytest.mark.parametrize("ask", CHEAP.values(), ids=CHEAP.keys())
def test_cheap_requests_are_all_taken(ask: Any) -> None:
    """Compact selects (1 unit, whatever their limit) and full forms of 10 (2 units)."""
    assert _run(_four(ask)) == [200, 200, 200, 200]


def test_a_full_form_alone_is_taken_whatever_its_cost() -> None:
    """Past the whole allowance, with nothing else in progress, a request is still served."""

    async def one() -> int:
        app = create_app(Settings(max_requests_in_flight=4, response_cache_bytes=0))
        return (await asgi_get(app, "/api/v1/select", FULL))[0]

    assert _run(one()) == 200


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


#: four results pages of a hundred each (15 units, ``page_units``), however asked
PAGES = {
    "page": lambda app, i: asgi_get(app, "/", b"load=%d&speed=50&length=500&limit=100" % i),
    "encoded": lambda app, i: asgi_get(app, "/", b"load=%d&speed=50&length=500&limit=1%%300" % i),
}


@pytest.mark.parametrize("ask", PAGES.values(), ids=PAGES.keys())
def test_a_results_page_costs_by_its_validated_limit(ask: Any) -> None:
    """Issue 31: distinct results pages of a hundred were counted one unit each and held
    the health check seconds. Four of them (15 units each) against 32: two are taken, the
    third would take 45, so it and the fourth are shed."""
    assert _run(_four(ask)) == [200, 200, 503, 503]


def test_results_pages_of_the_default_limit_are_all_taken() -> None:
    """Pages of 10 results cost 2 units: four of them fit in 32."""
    ask = lambda app, i: asgi_get(app, "/", b"load=%d&speed=50&length=500" % i)  # noqa: E731
    assert _run(_four(ask)) == [200, 200, 200, 200]


async def _health_beside_pages(release: threading.Event) -> list[str]:
    app = create_app(Settings(response_cache_bytes=0))
    finished: list[str] = []

    async def call(name: str, path: str, query: bytes = b"") -> None:
        await asgi_get(app, path, query)
        finished.append(name)

    # pages of fifty: 8 units each, both taken
    queries = [b"load=%d&speed=50&length=500&limit=50" % (101 + i) for i in range(2)]
    started = [asyncio.create_task(call("page", "/", q)) for q in queries]
    for _ in range(10):  # loop turns: the pages are admitted and computing
        await asyncio.sleep(0)
    await call("health", "/api/v1/health")
    release.set()
    await asyncio.gather(*started)
    return finished


def test_the_health_check_is_answered_while_results_pages_compute(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Results pages compute and render on the compute threads: each waits (5 s at most)
    until the health check has been answered, which it is, first. On the loop, the pages
    would hold it until they finished."""
    release = threading.Event()
    page_results = pages.page_results

    def held(*args: Any) -> None:
        release.wait(timeout=5.0)
        page_results(*args)

    monkeypatch.setattr(pages, "page_results", held)
    assert _run(_health_beside_pages(release)) == ["health", "page", "page"]


def stating_shedder(app: Any) -> OverloadMiddleware:
    """``app`` behind the middleware as the app sets it (32 units, the health check never
    shed), with the costs its routes state before their input is read."""
    return OverloadMiddleware(
        app,
        max_in_flight=32,
        retry_after_s=1,
        exempt_paths=frozenset({"/api/v1/health"}),
        stated_costs=STATED_COSTS,
    )


async def _stated_scenario() -> dict[str, Any]:
    """Two results pages of a hundred held in progress (15 units each of 32), then a
    third page, a compact select and the health check arrive."""
    held = HeldApp()
    shedder = stating_shedder(held)
    page = b"load=%d&speed=50&length=500&limit=100"
    waiting = [asyncio.create_task(asgi_get(shedder, "/", page % i)) for i in (101, 102)]
    while held.holding < 2:
        await asyncio.sleep(0)
    third = await asgi_get(shedder, "/", page % 103)
    reached_by_third = held.holding
    in_flight = shedder.in_flight
    compact = asyncio.create_task(asgi_get(shedder, "/api/v1/select", SELECT))
    while held.holding < 3:
        await asyncio.sleep(0)
    health = await asgi_get(shedder, "/api/v1/health")
    held.release.set()
    served = await asyncio.gather(*waiting, compact)
    return {
        "third": third[0],
        "reached_by_third": reached_by_third,
        "in_flight": in_flight,
        "health": health[0],
        "served": [status for status, _ in served],
        "in_flight_after": shedder.in_flight,
    }


def test_a_query_stating_its_cost_is_shed_before_its_input_is_read() -> None:
    """Results pages of a hundred state 15 units each (1 + 100 / 7, ``page_units``): with
    two in progress (30 of 32) a third is refused at the door, the route never reached
    (validating it only to refuse it cost the event loop 2.5 ms a request); a compact
    select (1 unit) is still taken, and the health check answered."""
    got = _run(_stated_scenario())
    assert got["third"] == 503
    assert got["reached_by_third"] == 2
    assert got["in_flight"] == 30
    assert got["health"] == 200
    assert got["served"] == [200, 200, 200]
    assert got["in_flight_after"] == 0


@pytest.mark.parametrize(
    ("path", "query", "units"),
    [
        ("/", {"limit": "100"}, 15),
        ("/", {}, 1),  # the empty form: nothing is computed
        # no limit, a required field filled: the default limit (10), 2 units, as validated
        ("/", {"load": "100"}, 2),
        ("/charts", {"load": "100", "speed": "50"}, 2),
        ("/", {"load": "100", "limit": "1e2"}, 1),  # not plain digits: charged once validated
        ("/", {"limit": "1e2"}, 1),  # not plain digits: charged once validated
        ("/api/v1/select", {"limit": "100"}, 1),
        ("/api/v1/select", {"limit": "100", "detail": "full"}, 13),
        ("/export.csv", {"limit": "100"}, 13),
        ("/export.json", {}, 1),
    ],
)
def test_the_stated_cost_is_a_lower_bound_of_the_charged_one(
    path: str, query: dict[str, str], units: int
) -> None:
    """What a query states is what validation would charge for it when it is spelled
    plainly (``page_units`` and ``full_form_units`` of its limit), and less otherwise."""
    assert STATED_COSTS[path](query) == units


async def _default_pages_scenario() -> tuple[int, int, int]:
    """Sixteen results pages of the default limit (no ``limit`` in the query) held in
    progress against 32 units, then a seventeenth arrives."""
    held = HeldApp()
    shedder = stating_shedder(held)
    page = b"load=%d&speed=50&length=500"
    waiting = [asyncio.create_task(asgi_get(shedder, "/", page % (101 + i))) for i in range(16)]
    while held.holding < 16:
        await asyncio.sleep(0)
    last = asyncio.create_task(asgi_get(shedder, "/", page % 117))
    for _ in range(10):  # loop turns: refused, or taken and held with the others
        await asyncio.sleep(0)
    reached = held.holding
    held.release.set()
    await asyncio.gather(*waiting)
    return (await last)[0], reached, shedder.in_flight


def test_pages_of_the_default_limit_are_shed_before_their_input_is_read() -> None:
    """A page of the default limit (10 results, ``page_units`` 2) states its 2 units
    though its query leaves the limit out: sixteen take the 32 units, and the seventeenth
    is refused at the door (the route never reached). Refused only once validated, each
    such refusal cost the event loop the validation of a form (about 1.3 ms against
    0.1 ms at the door, in process), which under 32 clients asking again at once was most
    of what the worker did."""
    assert _run(_default_pages_scenario()) == (503, 16, 0)
