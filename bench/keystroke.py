"""Keystroke to results in Chromium (issues 24 and 34): the time from one keystroke in a
field of the selector's form to the results table holding the answer to the new value, and
to every chart in view of that answer drawn.

Debian's Chromium (``/usr/bin/chromium``) is driven through Playwright against a server
started as ``bench.web.server`` starts it. Each keystroke replaces the last character of a
field (load, speed, length, stroke, acceleration, moving mass and the motor's torque), so
every value is new to the server's response cache and each answer is computed. Right after
each keystroke the page is scrolled to the charts (at 1280 x 900 they sit below the form
and the table, out of view while a field is typed in), so that the charts an engineer
looks at are in view and their drawing is measured: app.js draws the charts in view as
the answer's figures arrive and the others only once they are scrolled to or no field has
been edited for half a second, so "charts drawn" means the charts in view, and their count
is printed. In the page, performance.now() marks the ``input`` event, htmx sending the
request (after the form's trigger delay), the response arriving, a MutationObserver seeing
the results region change, the next frame after that (the table painted), htmx settling,
the charts' request (/charts, sent by app.js as the answer arrives; its resource timing)
and its answer, and app.js's
``charts:drawn`` (the last chart in view drawn) with the next frame after it.
Targets (issue 34): keystroke to the updated table at most 200 ms median, the trigger delay
included; keystroke to every chart in view drawn at most 400 ms median."""

import statistics
from pathlib import Path
from typing import Any

from bench.report import Report
from bench.web import server

CHROMIUM = "/usr/bin/chromium"
#: keystroke to the results table updated, median (ms)
TABLE_TARGET_MS = 200.0
#: keystroke to every chart of the answer drawn and painted, median (ms)
CHARTS_TARGET_MS = 400.0
#: a move and a motor, so the table has every column and the charts their curves
START = (
    "/?load=50&speed=200&length=500&stroke=300&accel=2000&moving_mass_kg=5&max_torque=0.5"
    "&motor_inertia=8e-6"
)
#: field -> the last characters typed in turn (each differs from the one before it)
KEYS = {
    "load": "1234567",
    "speed": "1234567",
    "length": "1234567",
    "stroke": "1234567",
    "accel": "1234567",
    "moving_mass_kg": "6789432",
    "max_torque": "6789432",
}
MARKS = """() => {
  const bench = window.__bench = {marks: []};
  performance.setResourceTimingBufferSize(2000);
  const results = document.getElementById('results');
  let current = null;
  document.getElementById('selector').addEventListener('input', () => {
    current = {key: performance.now()};
    bench.marks.push(current);
  }, true);
  document.body.addEventListener('htmx:beforeRequest', () => {
    if (current && current.sent === undefined) current.sent = performance.now();
  });
  document.body.addEventListener('htmx:beforeSwap', () => {
    const mark = current;
    if (mark && mark.response === undefined) {
      mark.response = performance.now();
      // registered before app.js's own frame callbacks: the first task after the paint
      requestAnimationFrame(() => setTimeout(() => { mark.shown = performance.now(); }));
    }
  });
  new MutationObserver(() => {
    const mark = current;
    if (mark && mark.response !== undefined && mark.swapped === undefined) {
      mark.swapped = performance.now();
    }
  }).observe(results, {childList: true, subtree: true});
  document.body.addEventListener('htmx:afterSettle', () => {
    if (current && current.response !== undefined && current.settled === undefined) {
      current.settled = performance.now();
    }
  });
  document.addEventListener('charts:drawn', (event) => {
    const mark = current;
    if (mark && mark.swapped !== undefined && mark.drawn === undefined) {
      mark.drawn = performance.now();
      mark.inView = event.detail.drawn;
      requestAnimationFrame(() => setTimeout(() => { mark.painted = performance.now(); }));
    }
  });
}"""
#: each /charts fetch (start, response end), from the page's resource timing
CHARTS_FETCHED = """() => performance.getEntriesByType('resource')
  .filter(e => e.name.includes('/charts?')).map(e => [e.startTime, e.responseEnd])"""
#: the charts brought into view, as the engineer scrolls down to them after typing
TO_CHARTS = "() => document.querySelector('#results section.charts').scrollIntoView()"
DONE = """() => {
  const m = window.__bench.marks;
  return m.length && m[m.length - 1].painted && m[m.length - 1].shown;
}"""


def type_keys(page: Any) -> list[dict[str, float]]:
    """Every keystroke's marks (ms, performance.now())."""
    page.evaluate(MARKS)
    for field, keys in KEYS.items():
        page.focus(f"#f-{field}")
        page.keyboard.press("End")
        for key in keys:
            page.keyboard.press("Shift+ArrowLeft")
            page.keyboard.press(key)
            page.evaluate(TO_CHARTS)
            page.wait_for_function(DONE, timeout=10_000)
    marks: list[dict[str, float]] = page.evaluate("() => window.__bench.marks")
    asked = page.evaluate(CHARTS_FETCHED)
    for mark in marks:  # the first /charts fetch after each answer arrived
        fetch = next((f for f in asked if f[0] >= mark["response"]), None)
        if fetch is not None:
            mark["chartsAsked"], mark["chartsAnswer"] = fetch
    return marks


def percentile(values: list[float], share: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(share * (len(ordered) - 1)))]


def verdict(report: Report, name: str, values: list[float], target_ms: float) -> None:
    median = statistics.median(values)
    report.line(
        f"{name}, median", f"{median:.0f} ms", f"<= {target_ms:.0f} ms", median <= target_ms
    )
    report.line(f"{name}, p90", f"{percentile(values, 0.9):.0f} ms", "(shown)", None)


def show(report: Report, marks: list[dict[str, float]]) -> None:
    def spans(start: str, end: str) -> list[float]:
        return [m[end] - m[start] for m in marks if start in m and end in m]

    report.info("keystrokes measured", f"{len(marks)} over {len(KEYS)} fields")
    verdict(report, "keystroke to results table", spans("key", "swapped"), TABLE_TARGET_MS)
    verdict(
        report, "keystroke to the charts in view drawn", spans("key", "painted"), CHARTS_TARGET_MS
    )
    in_view = [m["inView"] for m in marks]
    report.info(
        "  charts in view (scrolled to them after the keystroke)",
        f"median {statistics.median(in_view):g}, fewest {min(in_view):g}"
        " (the others draw when scrolled to or after 0.5 s without an edit)",
    )
    report.info("  where it goes (medians)", "")
    for name, start, end in (
        ("trigger delay (keystroke to request)", "key", "sent"),
        ("server and network (request to response)", "sent", "response"),
        ("swap (response to results updated)", "response", "swapped"),
        ("table painted (updated to the frame after)", "swapped", "shown"),
        ("settle (response to settled)", "response", "settled"),
        ("charts asked (response to /charts sent)", "response", "chartsAsked"),
        ("charts' server and network (/charts sent to answered)", "chartsAsked", "chartsAnswer"),
        ("charts in view drawn (answered to the last drawn)", "chartsAnswer", "drawn"),
        ("charts in view drawn (settled to the last drawn)", "settled", "drawn"),
        ("to the next frame after the charts", "drawn", "painted"),
    ):
        report.info(f"    {name}", f"{statistics.median(spans(start, end)):.1f} ms")


def run(report: Report) -> None:
    report.section("Keystroke to results in Chromium (the form, htmx swap, charts)")
    if not Path(CHROMIUM).exists():
        report.line(
            "keystroke to results table", "no Chromium", f"<= {TABLE_TARGET_MS:.0f} ms", None
        )
        return
    from playwright.sync_api import sync_playwright

    with server("app.main:create_app", factory=True) as (port, _pid), sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.goto(f"http://127.0.0.1:{port}{START}")
        page.wait_for_selector("#chart-torque .main-svg")  # Plotly loaded and drawn
        show(report, type_keys(page))
        browser.close()
