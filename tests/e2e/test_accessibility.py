"""axe-core on every page in Chromium, at 1280 and 390 px (issue 24); /docs, Swagger UI's
own layout, at 1280 only. Each state is reached once, at 1280 px, and scanned there, then
its page is resized to 390 px and scanned again once its charts are redrawn.

Every HTML page the app's router serves is scanned: the routes are read from the app
itself, so a new page is scanned bare as soon as it exists, and a page that needs a query
or an interaction to show its content (results, an open detail, the no-pass advice, an
inline 422 error, a catalog series opened, Swagger UI with an operation of each kind open
and run) has states of its own below. A state another state holds whole (the same page
with less of it opened) is scanned within that one only. axe runs WCAG 2.1 A and AA rules
plus its best practices, and the test asserts no violation of any impact. Nothing is
excluded: /docs is made clean by our own stylesheet and configuration
(static/css/docs.css, static/js/docs.js), not by skipping its rules.

axe-core is vendored under tests/e2e/vendor/ (npm package axe-core, version in the file
name, MPL-2.0 licence beside it) and injected as an init script, which the page's
Content-Security-Policy does not govern.
"""

import html
import re
import urllib.parse
from collections.abc import Callable, Iterator
from functools import cache
from pathlib import Path
from typing import Any

import pytest
from fastapi.routing import APIRoute
from starlette.responses import HTMLResponse

from app.main import create_app

AXE = Path(__file__).resolve().parent / "vendor" / "axe-core-4.14.1.min.js"
RULE_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "best-practice"]
AXIS = "load=50&speed=200&length=500"
#: every optional column of the results table (a move, a motor, its margin)
WIDEST = (
    "load=50&speed=200&length=500&stroke=300&accel=2000&moving_mass_kg=5&max_torque=0.5"
    "&motor_inertia=8e-6&rank_by=motor_margin&limit=20"
)
#: the impossible axis on the seed's screws: the no-pass advice
IMPOSSIBLE = "load=3000&speed=500&length=3000&family=B,ZBX,KHD,VHD"
SCREW = (
    "outer_diameter_mm=10&root_diameter_mm=8&lead_mm=2&friction_dynamic=0.15"
    "&friction_static=0.2&pv_limit_mpa_m_s=3&load=100&speed=50&length=500"
)

#: Tr12x3 in C45 steel with a bronze nut: the catalog's nut checks and its limits' table
BRONZE_NUT = (
    "outer_diameter_mm=12&root_diameter_mm=8.5&lead_mm=3&pitch_mm=3&thread_half_angle_deg=15"
    "&friction_dynamic=0.13&friction_static=0.16&material=c45-steel&nut=bronze"
    "&load=500&speed=20&length=400"
)
#: the ISO 304 family alone, whose top screw has a long id (the phone's result bar shows it
#: whole), with the acceleration given in g
LONG_ID_IN_G = "load=200&speed=100&length=500&family=TR-304&stroke=300&accel=0.2&accel_unit=g"


def _routes(routes: list[Any], prefix: str = "") -> Iterator[tuple[str, Any]]:
    for route in routes:
        included = getattr(route, "original_router", None)
        if included is not None:
            yield from _routes(included.routes, prefix + route.include_context.prefix)
        else:
            yield prefix + getattr(route, "path", ""), route


@cache
def html_pages() -> list[str]:
    """Every GET route of the app that answers with an HTML page (read once: the app is
    built for it, and the scans are listed while collecting)."""
    return sorted(
        path
        for path, route in _routes(create_app().routes)
        if isinstance(route, APIRoute)
        and "GET" in route.methods
        and isinstance(route.response_class, type)
        and issubclass(route.response_class, HTMLResponse)
    )


def first_candidate(page: Any, base: str) -> None:
    """The first candidate's /detail page; its id read off the results fragment, which
    no browser needs to draw for that."""
    fragment = page.request.get(f"{base}/?{AXIS}", headers={"HX-Request": "true"}).text()
    first = re.search(r'<tbody class="candidate" data-id="([^"]+)"', fragment)
    assert first, "no candidate in the results"
    page.goto(f"{base}/detail?{AXIS}&id={urllib.parse.quote(html.unescape(first[1]))}")
    page.wait_for_selector("dl.facts")


def open_detail(page: Any, base: str) -> None:
    page.goto(f"{base}/?{WIDEST}")
    page.locator("tbody.candidate >> nth=0 >> details.detail summary").click()
    page.wait_for_selector("tbody.candidate >> nth=0 >> dl.facts")


def typed_error(page: Any, base: str) -> None:
    """A field retyped to nonsense: the 422 answer's inline error, results kept dimmed
    (typed once the results and their charts have arrived, as a reader would)."""
    page.goto(f"{base}/?{AXIS}")
    settle(page)
    page.fill("#f-load", "abc")
    page.wait_for_function("() => document.querySelector('#e-load').textContent.trim() !== ''")
    page.wait_for_selector("#results.stale")


def typing(page: Any, base: str) -> None:
    """A new form being filled in: the load typed (its answer names the empty speed and
    length, not shown yet) and the length left empty (its error shown)."""
    page.goto(f"{base}/")
    with page.expect_response(lambda r: "load=5" in r.url):
        page.locator("#f-load").press_sequentially("5")
    page.wait_for_function("() => !document.querySelector('#busy.htmx-request')")
    page.focus("#f-length")
    page.keyboard.press("Tab")
    page.wait_for_function("() => document.querySelector('#e-length').textContent.trim() !== ''")


def custom_error(page: Any, base: str) -> None:
    """The root diameter retyped above the outer: its inline error, results kept dimmed
    (typed once the results and their charts have arrived, as on the selector)."""
    page.goto(f"{base}/custom?{SCREW}")
    settle(page)
    page.fill("#f-root_diameter_mm", "12")
    page.wait_for_function(
        "() => document.querySelector('#e-root_diameter_mm').textContent.trim() !== ''"
    )


def docs_opened(page: Any, base: str) -> None:
    """Swagger UI with one operation of each kind (each HTTP method) open and tried out,
    the health check run, and the schemas open: every kind of block Swagger UI draws,
    each once (opening all of them repeats the same markup at a cost of minutes)."""
    page.goto(f"{base}/docs")
    page.wait_for_selector(".opblock")
    kinds = page.eval_on_selector_all(
        ".opblock",
        "blocks => [...new Set(blocks.map(b => [...b.classList].find("
        "c => c.startsWith('opblock-') && c !== 'opblock-deprecated')))]",
    )
    assert "opblock-get" in kinds and len(kinds) >= 2, kinds
    health = "#operations-api-health_api_v1_health_get"
    for kind in kinds:
        block = page.locator(health if kind == "opblock-get" else f".opblock.{kind}").first
        block.locator(".opblock-summary-control").click()
        block.locator(".try-out__btn").click()
    page.click(f"{health} .execute")
    page.wait_for_selector(f"{health} .live-responses-table")
    if page.locator("section.models.is-open").count() == 0:
        page.click(".models-control")
    page.wait_for_selector("section.models.is-open")


#: a cycle of two moves, out with a part and back empty
MOVES = urllib.parse.urlencode(
    {"moves": "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500:0.2:0.5:10:opposes"}
)


#: a two-axis machine: a Z axis riding on an X axis, each by its selector link
MACHINE = urllib.parse.urlencode(
    {
        "name1": "Z",
        "link1": "/?load=0&moving_mass_kg=0.5&speed=10&length=250&accel=200"
        "&orientation=vertical&stroke=200&lead=8&brake_torque=0.1",
        "frame1": "0.3",
        "name2": "X",
        "link2": "load=0&moving_mass_kg=0.8&speed=100&length=400&accel=1000&stroke=300",
    }
)


def visit(path: str, ready: str = "main") -> Callable[[Any, str], None]:
    def go(page: Any, base: str) -> None:
        page.goto(base + path)
        page.wait_for_selector(ready)

    return go


def series_opened(page: Any, base: str) -> None:
    """The catalog with a series opened: its values loaded into the <details> (from
    /catalog/{series_id}, as a fragment)."""
    page.goto(f"{base}/catalog")
    page.click("details#ZBX8000 > summary")
    page.wait_for_selector("details#ZBX8000 table.series-fields")


def parts_loaded(page: Any, base: str) -> None:
    """The results with the parts loaded after the table: the charts, the rejected list."""
    page.goto(f"{base}/?{AXIS}")
    page.wait_for_selector("section.charts .chart-grid")
    page.click("details.rejected > summary")
    page.wait_for_selector("li.rejected-candidate")


#: pages that need a query or an interaction to show what they show (path -> states)
STATES: dict[str, dict[str, Callable[[Any, str], None]]] = {
    "/": {
        # the results of AXIS are scanned with their charts drawn and the rejected list
        # open (charts-and-rejected), which holds every element the table alone shows
        "detail-open": open_detail,
        "charts-and-rejected": parts_loaded,
        "no-pass": visit(f"/?{IMPOSSIBLE}", ".no-pass"),
        "long-id-accel-in-g": visit(f"/?{LONG_ID_IN_G}", "tbody.candidate"),
        "error-422-inline": typed_error,
        "typing": typing,
        "moves": visit(f"/?{AXIS}&{MOVES}", "tbody.candidate"),
        "moves-cell-error": visit(f"/?{AXIS}&{MOVES}&m0_speed=fast", "#moves-table"),
    },
    "/detail": {"page": first_candidate},
    "/charts": {"page": visit(f"/charts?{AXIS}", ".chart .main-svg")},
    "/rejected": {"page": visit(f"/rejected?{AXIS}", "li.rejected-candidate")},
    "/custom": {
        "results": visit(f"/custom?{SCREW}", ".custom-verdict"),
        "error": custom_error,
        "bronze-nut": visit(f"/custom?{BRONZE_NUT}", "table.nut-limits"),
    },
    "/docs": {"opened": docs_opened},
    "/catalog": {"series-open": series_opened},
    # a ball screw's, whose id has a space (quoted in its URL)
    "/catalog/{series_id}": {"page": visit("/catalog/HIWIN-GROUND%20R16", "table.series-fields")},
    "/machine": {"results": visit(f"/machine?{MACHINE}", "table.machine")},
    "/versus": {
        "both": visit(f"/versus?{AXIS}", "table.versus"),
        "one-kind-fails": visit("/versus?load=3000&speed=400&length=500", "table.versus"),
    },
}
#: pages whose bare state one of their states holds whole, which is scanned instead: the
#: same page with some of its <details> opened (an operation of each kind, a series)
BARE_WITHIN = {"/docs": "opened", "/catalog": "series-open"}
#: answers that are not a route of their own
ERRORS = {"error-404": visit("/no-such-page", "main")}


def scans() -> list[tuple[str, Callable[[Any, str], None]]]:
    found: list[tuple[str, Callable[[Any, str], None]]] = []
    for path in html_pages():
        if path in STATES:
            found += [(f"{path} {name}", state) for name, state in STATES[path].items()]
        # /detail bare is its 404 page (no candidate named)
        if "{" not in path and path not in BARE_WITHIN:
            found.append((f"{path} bare", visit(path)))
    return found + list(ERRORS.items())


def test_every_page_of_the_router_is_scanned() -> None:
    pages = html_pages()
    assert {"/", "/catalog", "/custom", "/guide", "/validation", "/docs", "/detail"} <= set(pages)
    names = {name for name, _ in scans()}
    scanned = {name.split(" ")[0] for name in names}
    assert set(pages) <= scanned
    # a bare state left out is scanned within a state of the same page
    assert {f"{path} {state}" for path, state in BARE_WITHIN.items()} <= names
    # a page with a path parameter cannot be visited bare: it needs states of its own
    assert all(path in STATES for path in pages if "{" in path)


def summary(violations: list[dict[str, Any]]) -> list[str]:
    return [
        f"{v['id']} ({v['impact']}): {v['help']} at {[n['target'] for n in v['nodes'][:3]]}"
        for v in violations
    ]


#: the widths every page is scanned at: a desktop and a phone
WIDTHS = (1280, 390)
#: pages whose layout is a third party's and does not change with the width: one scan
ONE_WIDTH = {"/docs opened": 1280}


def widths_of(name: str) -> tuple[int, ...]:
    """The widths the state ``name`` is scanned at, in order: the first is the one its
    page is loaded at, the others are reached by resizing that same page."""
    return (ONE_WIDTH[name],) if name in ONE_WIDTH else WIDTHS


def scans_at_widths() -> list[tuple[str, Callable[[Any, str], None], int]]:
    return [(name, state, width) for name, state in scans() for width in widths_of(name)]


def test_every_state_is_scanned_at_both_widths_but_docs() -> None:
    widths: dict[str, set[int]] = {}
    for name, _, width in scans_at_widths():
        widths.setdefault(name, set()).add(width)
    assert set(ONE_WIDTH) <= set(widths)
    assert all(w == set(WIDTHS) for name, w in widths.items() if name not in ONE_WIDTH)


#: the page has finished what it does on its own: loaded, no htmx request in flight (htmx
#: marks the requesting element or its indicator .htmx-request), no detail or list still
#: loading (aria-busy), the results' charts fetched (their slot replaced) and every chart
#: drawn (those out of view draw once the form has been calm a moment, app.js QUIET_MS),
#: and no CSS transition running (Swagger UI's buttons fade for 0.3 s: on a busy machine
#: axe could read a colour half-way). Waited for by these events, not by a time of silence.
SETTLED = """() => document.readyState === 'complete'
  && !document.querySelector('.htmx-request, [aria-busy=true], #charts-slot')
  && [...document.querySelectorAll('script[type="application/json"][data-chart]')].every(
       s => { const chart = document.getElementById(s.dataset.chart);
              return !chart || chart.querySelector('.main-svg') !== null; })
  && document.getAnimations().every(a => a.playState !== 'running')"""

#: axe over the whole document with RULE_TAGS; every rule's outcome is reported, but only
#: the violations' nodes are all collected (axe keeps one node per passing rule, which
#: spares it a unique selector for each of thousands of passing nodes on a large page)
AXE_RUN = """tags => axe.run(document, {
  runOnly: {type: 'tag', values: tags}, resultTypes: ['violations']})"""


def settle(page: Any) -> None:
    page.wait_for_function(SETTLED)


def axe_result(page: Any) -> dict[str, Any]:
    """axe-core's result on ``page`` once it has settled (axe loaded by AXE's init script)."""
    settle(page)
    result: dict[str, Any] = page.evaluate(AXE_RUN, RULE_TAGS)
    return result


#: the window's height at every width
HEIGHT = 900
#: every chart Plotly has drawn is as wide as its box again: Plotly redraws its charts on
#: the window's resize (``responsive``), a moment after it, at the width of their box
RESIZED = """() => [...document.querySelectorAll('.js-plotly-plot')].every(chart => {
  const svg = chart.querySelector('.main-svg');
  return !svg || Math.abs(parseFloat(svg.getAttribute('width'))
                          - chart.getBoundingClientRect().width) < 1; })"""


def resize(page: Any, width: int, height: int = HEIGHT) -> None:
    """``page`` at ``width``: the layout is CSS media queries, which apply at once, and the
    charts, which Plotly redraws for the new width (RESIZED); nothing else the app draws
    depends on the width it was loaded at (static/js/app.js reads no width)."""
    if page.viewport_size != {"width": width, "height": height}:
        page.set_viewport_size({"width": width, "height": height})
        page.wait_for_function(RESIZED)


@pytest.fixture(scope="module")
def axe_context(browser: Any) -> Iterator[Any]:
    """A browser context with axe-core loaded into each of its pages, kept for every scan of
    this module in this worker (each scan opens a page of its own)."""
    context = browser.new_context(viewport={"width": WIDTHS[0], "height": HEIGHT})
    context.add_init_script(path=str(AXE))
    yield context
    context.close()


@pytest.mark.parametrize(("name", "state"), scans(), ids=[name for name, _ in scans()])
def test_axe_finds_no_violation(
    axe_context: Any,
    live_server: str,
    artifacts: Path,
    name: str,
    state: Callable[[Any, str], None],
) -> None:
    """The state is reached once, at its first width, and scanned at each of its widths in
    turn, the page resized between scans (the violations of every width are reported; a
    screenshot of a width that has some is kept in test-artifacts). At each width the page
    is also no wider than the window: nothing runs off its side (a wide table scrolls in a
    region of its own)."""
    page = axe_context.new_page()
    violations: dict[int, list[str]] = {}
    page_widths: dict[int, int] = {}
    try:
        resize(page, widths_of(name)[0])
        state(page, live_server)
        for width in widths_of(name):
            resize(page, width)
            result = axe_result(page)
            assert result["testEngine"]["version"] == "4.14.1"
            assert len(result["passes"]) > 20  # the rules really ran on a page with content
            violations[width] = summary(result["violations"])
            page_widths[width] = page.evaluate("() => document.documentElement.scrollWidth")
            if violations[width]:
                slug = re.sub(r"[^a-z0-9]+", "-", name).strip("-")
                page.screenshot(path=str(artifacts / f"axe-{slug}-{width}.png"))
    finally:
        page.close()
    assert violations == {width: [] for width in widths_of(name)}
    assert page_widths == {width: width for width in widths_of(name)}
