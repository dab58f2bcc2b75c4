"""Charts that read, in real Chromium: tick labels on every chart's axes (the wear life's
too), the PV chart's limit curves beside the operating points, no two y tick labels
overlapping at 390 px or in the printed report, and the printed report's pages rendered
to PNG (pdftoppm) and its screens at 1280 and 390 px saved under test-artifacts/ (``shots``)."""

import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

from tests.builtin_catalog import builtin_catalog
from tests.e2e.shots import shoot
from tests.leadscrews import leadscrew_families

#: a duty (the wear-life chart) with a move and a motor curve (motor and move charts).
DUTY = "load=100&speed=50&length=500&stroke=200&cycles_per_day=1000"
IMPERIAL = DUTY.replace("load=100", "load=22.48") + "&force_unit=lbf&length_unit=in"
#: the same duties over the leadscrew families only: ball screws rank beside leadscrews by
#: default and have no PV chart, so the tests of the PV chart name the leadscrews.
LEADSCREWS = "&family=" + ",".join(leadscrew_families(builtin_catalog()))

#: each chart's tick labels (text, box, turned or not) per axis:
#: {chart id: {"x": [...], "y": [...], "y2": [...]}}.
TICKS = r"""() => {
  const out = {};
  document.querySelectorAll(".chart.js-plotly-plot").forEach((chart) => {
    const axes = {};
    for (const kind of ["x", "y", "y2"]) {
      axes[kind] = [...chart.querySelectorAll(`.${kind}tick text`)]
        .filter((t) => t.textContent.trim() && t.getBoundingClientRect().height > 0)
        .map((t) => {
          const r = t.getBoundingClientRect();
          const turned = /rotate\((?!0[,)])/.test(t.getAttribute("transform") || "");
          return { text: t.textContent, box: [r.left, r.top, r.right, r.bottom], turned };
        });
    }
    out[chart.id] = axes;
  });
  return out;
}"""
#: records, once the print stylesheet applies and app.js has redrawn the charts at their
#: printed size (its listener was added first), each chart's tick labels as printed.
RECORD_PRINTED_TICKS = (
    "() => { window.printedTicks = null; matchMedia('print').addEventListener('change',"
    " (event) => { if (event.matches) window.printedTicks = (" + TICKS + ")(); }); }"
)
#: the traces each chart drew: {chart id: [[name, mode], ...]}.
TRACES = """() => Object.fromEntries([...document.querySelectorAll(".chart.js-plotly-plot")]
  .map((chart) => [chart.id, chart.data.map((t) => [t.name, t.mode || t.type])]))"""


def overlaps(labels: list[dict[str, Any]], slack_px: float = 0.5) -> list[tuple[str, str]]:
    """Pairs of tick labels whose boxes intersect (beyond ``slack_px``). Labels Plotly
    turned to fit (the torque chart's candidate ids) are left out: a turned label's
    upright box overlaps its neighbour's while the words stand apart."""
    labels = [label for label in labels if not label["turned"]]
    pairs = []
    for i, a in enumerate(labels):
        for b in labels[i + 1 :]:
            (al, at, ar, ab), (bl, bt, br, bb) = a["box"], b["box"]
            if min(ar, br) - max(al, bl) > slack_px and min(ab, bb) - max(at, bt) > slack_px:
                pairs.append((a["text"], b["text"]))
    return pairs


def drawn(page: Any, url: str) -> None:
    page.goto(url)
    page.wait_for_selector("#chart-life .main-svg")
    page.wait_for_function(
        "() => [...document.querySelectorAll('.chart')].every(c => c.querySelector('.main-svg'))"
    )


def assert_ticks_readable(ticks: dict[str, dict[str, list[dict[str, Any]]]]) -> None:
    """Every chart has labels on both axes, none overlapping another of its axis."""
    for chart, axes in ticks.items():
        assert len(axes["x"]) >= 2 and len(axes["y"]) >= 2, (chart, axes)
        for kind, labels in axes.items():
            assert overlaps(labels) == [], (chart, kind)


def test_every_chart_has_tick_labels_and_the_pv_chart_its_limit(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    drawn(page, f"{live_server}/?{DUTY}{LEADSCREWS}")
    ticks = page.evaluate(TICKS)
    assert {"chart-life", "chart-pv", "chart-critical_speed"} <= set(ticks)
    assert_ticks_readable(ticks)
    life = ticks["chart-life"]
    assert all(t["text"][0].isdigit() for t in life["x"] + life["y"])
    pv = page.evaluate(TRACES)["chart-pv"]
    limits = [name for name, mode in pv if mode == "lines"]
    assert limits and all(n.endswith(("allowed pressure", "PV limit")) for n in limits)
    assert sum(mode == "markers" for _, mode in pv) == len(limits)  # an operating point each
    assert "[MPa]" in page.text_content("#chart-pv .g-ytitle")
    shoot(page, artifacts / "charts-1280.png", full_page=True)
    assert console_errors == []


def test_the_charts_follow_the_unit_choice(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    drawn(page, f"{live_server}/?{IMPERIAL}{LEADSCREWS}")
    assert "[psi]" in page.text_content("#chart-pv .g-ytitle")
    assert "[in/s]" in page.text_content("#chart-pv .g-xtitle")
    assert "[lbf]" in page.text_content("#chart-life .g-xtitle")
    assert "[in]" in page.text_content("#chart-critical_speed .g-xtitle")
    assert console_errors == []


def test_no_tick_labels_overlap_on_a_phone(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.set_viewport_size({"width": 390, "height": 844})
    drawn(page, f"{live_server}/report?{DUTY}")
    ticks = page.evaluate(TICKS)
    assert len(ticks["chart-critical_speed"]["y"]) >= 2
    assert_ticks_readable(ticks)
    shoot(page, artifacts / "report-charts-390.png", full_page=True)
    shoot(page.locator("#chart-critical_speed"), artifacts / "critical-speed-390.png")
    assert console_errors == []


@pytest.mark.parametrize("path", ["/report", "/"], ids=["report", "results"])
def test_no_tick_labels_overlap_when_printed(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str], path: str
) -> None:
    """The tick labels measured as the PDF is made (app.js redraws the charts at their
    printed box's size once the print stylesheet applies), then the PDF's pages rendered
    to PNG to look at: the filed report (two charts a row) and the printed results (three
    a row)."""
    name = "report-charts" if path == "/report" else "results-charts"
    drawn(page, f"{live_server}{path}?{DUTY}")
    shoot(page, artifacts / f"{name}-1280.png", full_page=True)
    page.evaluate(RECORD_PRINTED_TICKS)
    pdf = artifacts / f"{name}.pdf"
    page.pdf(path=str(pdf), prefer_css_page_size=True, print_background=True)
    printed = page.evaluate("window.printedTicks")
    assert printed and len(printed) >= 5
    assert_ticks_readable(printed)
    if shutil.which("pdftoppm") is None:
        pytest.fail("pdftoppm (poppler-utils) is needed to render the PDF's pages")
    for old in artifacts.glob(f"{name}-page-*.png"):
        old.unlink()
    subprocess.run(
        ["pdftoppm", "-r", "100", "-png", str(pdf), str(artifacts / f"{name}-page")],
        check=True,
    )
    assert list(artifacts.glob(f"{name}-page-*.png"))
    assert console_errors == []
