"""Printing in real Chromium: every chart drawn whole at its printed box's size, the
/custom printout without its form, and the filed report as a PDF (read back with pypdf)
holding the inputs, the candidate, the provenance labels and the catalog version."""

import io
import re
import unicodedata
from datetime import UTC, datetime
from pathlib import Path
from typing import Any
from urllib.parse import urlencode

from pypdf import PdfReader

from tests.e2e.shots import shoot

AXIS = "load=100&speed=50&length=500"
#: 22.48 lbf, 2 in/s, 20 in: about 100 N, 50.8 mm/s and 508 mm.
IMPERIAL = "load=22.48&speed=2&length=20&force_unit=lbf&length_unit=in"
#: a 1/2 in screw of 1/8 in lead, in the inches the page is switched to.
SCREW = urlencode(
    {
        "outer_diameter_mm": "1/2",
        "root_diameter_mm": "0.4",
        "lead_mm": "1/8",
        "friction_dynamic": "0.15",
        "friction_static": "0.2",
        "pv_limit_mpa_m_s": "50000",
    }
)
#: records, once the print stylesheet applies and app.js has resized the charts, each
#: chart's box and its drawn figure (the listener runs after app.js's, added earlier).
RECORD_PRINTED_CHARTS = """() => {
  window.printedCharts = [];
  matchMedia("print").addEventListener("change", (event) => {
    if (!event.matches) return;
    document.querySelectorAll(".chart.js-plotly-plot").forEach((chart) => {
      const svg = chart.querySelector("svg.main-svg");
      window.printedCharts.push({
        id: chart.id,
        box: [chart.clientWidth, chart.clientHeight],
        drawn: [Number(svg.getAttribute("width")), Number(svg.getAttribute("height"))],
      });
    });
  });
}"""


def printed(page: Any) -> tuple[bytes, list[dict[str, Any]]]:
    """The page printed to PDF, and each chart's box and drawn size while printing."""
    page.evaluate(RECORD_PRINTED_CHARTS)
    pdf = page.pdf(prefer_css_page_size=True, print_background=True)
    return pdf, page.evaluate("window.printedCharts")


def assert_whole(charts: list[dict[str, Any]], expected: int) -> None:
    """Each chart drawn within its printed box, filling its width (not a fixed size)."""
    assert len(charts) == expected
    for chart in charts:
        (box_w, box_h), (drawn_w, drawn_h) = chart["box"], chart["drawn"]
        assert 0 < drawn_w <= box_w and 0 < drawn_h <= box_h, chart
        assert drawn_w >= box_w - 1, chart


def pdf_text(pdf: bytes) -> str:
    """The PDF's text, its typographic ligatures spelled out (Chromium sets "ff" in a
    catalog hash such as 7ca5ffdf as one glyph, U+FB00)."""
    pages = PdfReader(io.BytesIO(pdf)).pages
    return unicodedata.normalize("NFKC", "\n".join(page.extract_text() for page in pages))


def test_results_print_every_chart_whole(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("#chart-torque .main-svg")
    charts = page.locator(".chart.js-plotly-plot").count()
    screen = page.eval_on_selector("#chart-torque svg.main-svg", "s => s.getAttribute('width')")
    _, during = printed(page)
    assert_whole(during, charts)
    # after printing, the charts are drawn for the screen again
    page.wait_for_function(
        f"() => document.querySelector('#chart-torque svg.main-svg').getAttribute('width')"
        f" === '{screen}'"
    )
    assert console_errors == []


def test_custom_printout_leaves_out_the_form(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/custom?{SCREW}&{IMPERIAL}")
    page.wait_for_selector("#chart-torque .main-svg")
    charts = page.locator(".chart.js-plotly-plot").count()
    pdf, during = printed(page)
    assert_whole(during, charts)
    text = pdf_text(pdf)
    assert "Your screw" not in text and "Your own material" not in text  # the form legends
    assert "Axial load" in text  # the inputs summary prints
    assert "Outer diameter 0.5 in" in re.sub(r"\s+", " ", text)  # the screw, in inches
    page.emulate_media(media="print")
    assert not page.locator("form#custom").is_visible()
    assert page.locator("#chart-torque").is_visible()
    shoot(page, artifacts / "custom-print-imperial-1280.png", full_page=True)
    assert console_errors == []


def test_report_pdf_holds_inputs_candidate_provenance_and_whole_charts(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{IMPERIAL}")
    page.wait_for_selector("tbody.candidate")
    second = page.locator("tbody.candidate").nth(1).get_attribute("data-id")
    page.goto(f"{live_server}/report?{IMPERIAL}&id={second}")
    page.wait_for_selector("#chart-torque .main-svg")
    shoot(page, artifacts / "report-imperial-1280.png", full_page=True)
    charts = page.locator(".chart.js-plotly-plot").count()
    assert charts >= 3
    day_before = datetime.now(UTC).date().isoformat()
    pdf, during = printed(page)
    assert_whole(during, charts)
    text = pdf_text(pdf)
    flat = re.sub(r"\s+", " ", text)
    # the inputs in the units they were given
    for shown in ("Axial load 22.48 lbf", "Screw length 20 in", "Linear speed 2 in/s"):
        assert shown in flat, shown
    assert f"Leadscrew report: {second}" in flat
    assert "Runners-up" in flat
    for label in ("standard", "handbook", "vendor"):
        assert re.search(rf"\b{label}\b", flat), label
    assert "Formula" in flat and "Utilization" in flat
    catalog = page.inner_text(".report-date").split("catalog ")[1].split(" ")[0]
    assert f"catalog {catalog}" in flat
    date = page.get_attribute(".report-date time", "datetime")
    assert date in {day_before, datetime.now(UTC).date().isoformat()} and date in flat
    assert "Print or save as PDF" not in flat and "Back to the results" not in flat
    page.set_viewport_size({"width": 390, "height": 844})
    shoot(page, artifacts / "report-imperial-390.png", full_page=True)
    assert console_errors == []


def test_report_is_linked_from_the_results_and_each_detail(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{AXIS}")
    top = page.locator("tbody.candidate").first.get_attribute("data-id")
    page.click("a.report-link")
    page.wait_for_selector("#report-heading")
    assert page.inner_text("#report-heading .cid") == top
    assert page.locator("button.print-report").is_visible()
    assert console_errors == []
