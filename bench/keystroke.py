"""Keystroke to results in Chromium (issue 24): the time from one keystroke in a field of
the selector's form to the results region holding the answer to the new value.

Debian's Chromium (``/usr/bin/chromium``) is driven through Playwright against a server
started as ``bench.web.server`` starts it. Each keystroke replaces the last character of a
field (load, speed, length, stroke, acceleration, moving mass and the motor's torque), so
every value is new to the server's response cache and each answer is computed. In the
page, performance.now() marks the ``input`` event, htmx sending the request (after the
form's trigger delay), the response arriving, a MutationObserver seeing the results
region change, htmx settling (the charts are drawn there) and the next frame after it.
Target: the median from keystroke to updated results under 300 ms.
"""

import statistics
from pathlib import Path
from typing import Any

from bench.report import Report
from bench.web import server

CHROMIUM = "/usr/bin/chromium"
TARGET_MS = 300.0
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
    if (current && current.response === undefined) current.response = performance.now();
  });
  new MutationObserver(() => {
    if (current && current.response !== undefined && current.swapped === undefined) {
      current.swapped = performance.now();
    }
  }).observe(results, {childList: true, subtree: true});
  document.body.addEventListener('htmx:afterSettle', () => {
    const mark = current;
    if (mark && mark.swapped !== undefined && mark.settled === undefined) {
      mark.settled = performance.now();
      requestAnimationFrame(() => setTimeout(() => { mark.painted = performance.now(); }));
    }
  });
}"""
DONE = "() => { const m = window.__bench.marks; return m.length && m[m.length - 1].painted; }"


def type_keys(page: Any) -> list[dict[str, float]]:
    """Every keystroke's marks (ms, performance.now())."""
    page.evaluate(MARKS)
    for field, keys in KEYS.items():
        page.focus(f"#f-{field}")
        page.keyboard.press("End")
        for key in keys:
            page.keyboard.press("Shift+ArrowLeft")
            page.keyboard.press(key)
            page.wait_for_function(DONE, timeout=10_000)
    marks: list[dict[str, float]] = page.evaluate("() => window.__bench.marks")
    return marks


def percentile(values: list[float], share: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(share * (len(ordered) - 1)))]


def show(report: Report, marks: list[dict[str, float]]) -> None:
    def spans(start: str, end: str) -> list[float]:
        return [m[end] - m[start] for m in marks]

    total = spans("key", "swapped")
    report.info("keystrokes measured", f"{len(total)} over {len(KEYS)} fields")
    report.line(
        "keystroke to results, median",
        f"{statistics.median(total):.0f} ms",
        f"< {TARGET_MS:.0f} ms",
        statistics.median(total) < TARGET_MS,
    )
    report.line("keystroke to results, p90", f"{percentile(total, 0.9):.0f} ms", "(shown)", None)
    report.info("  where it goes (medians)", "")
    for name, start, end in (
        ("trigger delay (keystroke to request)", "key", "sent"),
        ("server and network (request to response)", "sent", "response"),
        ("swap (response to results updated)", "response", "swapped"),
        ("settle and charts (updated to settled)", "swapped", "settled"),
        ("to the next frame after settling", "settled", "painted"),
    ):
        report.info(f"    {name}", f"{statistics.median(spans(start, end)):.1f} ms")
    report.info(
        "keystroke to charts drawn and painted, median",
        f"{statistics.median(spans('key', 'painted')):.0f} ms",
    )


def run(report: Report) -> None:
    report.section("Keystroke to results in Chromium (the form, htmx swap, charts)")
    if not Path(CHROMIUM).exists():
        report.line("keystroke to results, median", "no Chromium", f"< {TARGET_MS:.0f} ms", None)
        return
    from playwright.sync_api import sync_playwright

    with server("app.main:create_app", factory=True) as (port, _pid), sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.goto(f"http://127.0.0.1:{port}{START}")
        page.wait_for_selector("#chart-torque .main-svg")  # Plotly loaded and drawn
        show(report, type_keys(page))
        browser.close()
