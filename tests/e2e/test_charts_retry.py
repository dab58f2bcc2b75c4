"""The results' charts are asked again when /charts is refused (503 with Retry-After from
a busy worker, or a failed request), after the wait the answer names, a few times at
most; a refused answer is not kept as the answer for that query.

The waits between asks are the page's own timers, run on Playwright's clock: it is paused
before the page loads, and moved on by hand, so a test sees the next ask come exactly
when its Retry-After has passed (and not a millisecond sooner) without waiting for it."""

from typing import Any

AXIS = "load=100&lead=10&speed=50&length=500"
#: the page's clock time of each /charts ask (``window.chartAsks``), as the page sends it
CHART_ASKS = """(() => {
  const send = window.fetch;
  window.chartAsks = [];
  window.fetch = function (url) {
    if (String(url).includes("/charts?")) { window.chartAsks.push(performance.now()); }
    return send.apply(this, arguments);
  };
})()"""


def refuse_first(page: Any, refusals: int, retry_after_s: int) -> list[str]:
    """Answer the first ``refusals`` /charts requests 503 with ``retry_after_s``; pass the
    rest to the server. Returns the monotonic time of every /charts request."""
    asked: list[str] = []

    def handle(route: Any) -> None:
        asked.append(route.request.url)
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


def paused_on_clock(page: Any, url: str) -> None:
    """``url`` loaded with the page's timers on Playwright's clock, paused from the start:
    no timer of the page fires until the clock is moved on (its first /charts ask is sent
    as the page loads, on no timer)."""
    page.clock.install(time=0)
    page.clock.pause_at(1)
    page.add_init_script(CHART_ASKS)
    page.goto(url)


def asks(page: Any) -> int:
    return int(page.evaluate("() => window.chartAsks.length"))


def refused(page: Any, tries: int) -> None:
    """Wait until the page has taken ``tries`` refusals (it counts them on the slot, as it
    sets the timer of its next ask)."""
    page.wait_for_selector(f'#charts-slot[data-tries="{tries}"]', state="attached")


def next_ask_after(page: Any, wait_ms: int) -> None:
    """The page's next /charts ask comes when ``wait_ms`` have passed on its clock, not
    sooner."""
    before = asks(page)
    page.clock.run_for(wait_ms - 1)
    assert asks(page) == before, f"asked again before {wait_ms} ms"
    page.clock.run_for(1)
    page.wait_for_function(f"() => window.chartAsks.length === {before + 1}")


def test_refused_charts_are_asked_again_after_retry_after(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    asked = refuse_first(page, refusals=2, retry_after_s=1)
    paused_on_clock(page, f"{live_server}/?{AXIS}")
    # each new ask waits the answer's Retry-After (1 s), not less
    for tries in (1, 2):
        refused(page, tries)
        next_ask_after(page, 1_000)
    page.clock.resume()
    page.wait_for_selector("#chart-torque .main-svg", timeout=15_000)
    assert len(asked) == 3
    assert asks(page) == 3
    assert page.query_selector("#charts-slot") is None
    assert [e for e in console_errors if "503" not in e] == []


def test_charts_always_refused_are_asked_a_few_times_and_the_link_stays(
    page: Any, live_server: str
) -> None:
    asked = refuse_first(page, refusals=100, retry_after_s=1)
    paused_on_clock(page, f"{live_server}/?{AXIS}")
    for tries in range(1, 5):
        refused(page, tries)
        next_ask_after(page, 1_000)
    refused(page, 5)
    # past the last ask, twice its Retry-After passes without another
    page.clock.run_for(2_000)
    assert asks(page) == 5  # CHARTS_TRIES in static/js/app.js
    assert len(asked) == 5
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
