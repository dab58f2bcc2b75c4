"""The results' charts are asked again when /charts is refused (503 with Retry-After from
a busy worker, or a failed request), after the wait the answer names, a few times at
most; a refused answer is not kept as the answer for that query."""

import itertools
import time
from typing import Any

AXIS = "load=100&lead=10&speed=50&length=500"


def refuse_first(page: Any, refusals: int, retry_after_s: int) -> list[float]:
    """Answer the first ``refusals`` /charts requests 503 with ``retry_after_s``; pass the
    rest to the server. Returns the monotonic time of every /charts request."""
    asked: list[float] = []

    def handle(route: Any) -> None:
        asked.append(time.monotonic())
        if len(asked) <= refusals:
            route.fulfill(
                status=503,
                headers={"Retry-After": str(retry_after_s)},
                body='{"error": "server busy"}',
            )
        else:
            route.continue_()

    page.route("**/charts?*", handle)
    return asked


def test_refused_charts_are_asked_again_after_retry_after(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    asked = refuse_first(page, refusals=2, retry_after_s=1)
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("#chart-torque .main-svg", timeout=15_000)
    assert len(asked) == 3
    # each new ask waited the answer's Retry-After (1 s), not less
    assert all(later - earlier >= 0.9 for earlier, later in itertools.pairwise(asked))
    assert page.query_selector("#charts-slot") is None
    assert [e for e in console_errors if "503" not in e] == []


def test_charts_always_refused_are_asked_a_few_times_and_the_link_stays(
    page: Any, live_server: str
) -> None:
    asked = refuse_first(page, refusals=100, retry_after_s=1)
    page.goto(f"{live_server}/?{AXIS}")
    deadline = time.monotonic() + 15
    while len(asked) < 5 and time.monotonic() < deadline:
        page.wait_for_timeout(100)
    # past the last ask, twice its Retry-After passes without another
    page.wait_for_timeout(2_000)
    assert len(asked) == 5  # CHARTS_TRIES in static/js/app.js
    assert page.is_visible("#charts-slot .charts-link a")


def test_a_new_answer_before_the_charts_arrive_sets_no_inline_style(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    """While an answer's charts are on their way their slot holds the old charts' height;
    the next answer's swap must not copy that height onto the new slot as a style
    attribute, which the page's policy (style-src 'self') refuses."""
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("#chart-torque .main-svg", timeout=15_000)
    held: list[Any] = []

    def hold(route: Any) -> None:  # asked, never answered
        held.append(route)

    page.route("**/charts?*", hold)
    page.fill("#f-load", "200")
    page.wait_for_function("() => location.search.includes('load=200')")
    page.wait_for_function(
        "() => parseFloat(getComputedStyle(document.getElementById('charts-slot')).minHeight) > 0"
    )
    page.fill("#f-load", "300")
    page.wait_for_function("() => location.search.includes('load=300')")
    page.wait_for_function("() => !document.querySelector('.htmx-request, .htmx-settling')")
    assert held, "the charts were asked for"
    slot = page.locator("#charts-slot")
    assert float(slot.evaluate("s => parseFloat(getComputedStyle(s).minHeight)")) > 0
    assert console_errors == []
