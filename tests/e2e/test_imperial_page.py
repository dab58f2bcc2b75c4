"""Imperial in real Chromium: an axis typed in lbf, inches (a decimal comma and a
fraction among them) and oz in, with a motor curve and rotor inertia in those units;
the /custom page's screw in inches. Screenshots at 1280 and 390 px."""

from pathlib import Path
from typing import Any

from tests.e2e.shots import shoot

IMPERIAL = "/?force_unit=lbf&length_unit=in&torque_unit=oz_in"


def charts_fit(page: Any) -> None:
    """Wait until every drawn chart has been resized into the (new) viewport's width."""
    page.wait_for_function(
        "() => [...document.querySelectorAll('.chart .main-svg')]"
        ".every(svg => Number(svg.getAttribute('width')) <= window.innerWidth)"
    )


def test_imperial_selector_typed_with_a_comma_and_a_fraction(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(live_server + IMPERIAL)
    assert page.text_content("#w-motor_inertia .unit") == "oz in²"
    assert page.text_content("#w-ambient_c .unit") == "°F"
    page.fill("#f-load", "22,48")
    page.fill("#f-speed", "2")
    page.fill("#f-length", "19 11/16")
    page.wait_for_selector("#results table.candidates tbody.candidate")
    page.wait_for_function("() => location.search.includes('length=19.6875')")
    assert "load=22.48" in page.url
    assert page.inner_text("#e-length") == ""
    # the detail's checks in the chosen units
    page.click("tbody.candidate >> nth=0 >> tr.main td.num >> nth=0")
    page.locator("#detail-1 li.check").first.wait_for()
    limit = page.inner_text("#detail-1 li.check[data-check=buckling] .check-limit")
    assert limit.endswith(" lbf")
    shoot(page, artifacts / "imperial-selector-1280.png", full_page=True)
    page.set_viewport_size({"width": 390, "height": 844})
    charts_fit(page)
    shoot(page, artifacts / "imperial-selector-390.png", full_page=True)
    assert console_errors == []


def test_imperial_fraction_refused_inline(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(live_server + IMPERIAL)
    page.fill("#f-load", "22.48")
    page.fill("#f-speed", "2")
    page.fill("#f-length", "1/0")
    page.press("#f-length", "Tab")  # a new form's field shows its error once it is left
    # the message comes with the swap of the last request (earlier ones said "Required."),
    # aria-invalid with it (app.js)
    page.wait_for_function(
        "() => document.querySelector('#e-length').textContent.includes('denominator')"
        " && document.querySelector('#f-length[aria-invalid]') !== null"
    )
    assert page.inner_text("#e-length") == "A fraction's denominator cannot be 0."
    assert page.get_attribute("#f-length", "aria-invalid") == "true"
    assert console_errors == []


def test_custom_screw_in_inches(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(live_server + "/custom?force_unit=lbf&length_unit=in&torque_unit=oz_in")
    assert page.inner_text("#w-outer_diameter_mm .unit") == "in"
    assert page.inner_text("#w-pv_limit_mpa_m_s .unit") == "psi ft/min"
    typed = {
        "outer_diameter_mm": "1/2",
        "root_diameter_mm": "0,4",
        "lead_mm": "1/8",
        "friction_dynamic": "0.15",
        "friction_static": "0.2",
        "load": "22.48",
        "speed": "2",
        "length": "20",
    }
    for name, value in typed.items():
        page.fill(f"#f-{name}", value)
    page.wait_for_function("() => location.search.includes('length=20')")
    page.wait_for_selector("#chart-torque .main-svg")
    link = page.get_attribute("a.share-link", "href")
    assert "outer_diameter_mm=0.5" in link and "lead_mm=0.125" in link
    # 1/2 in outer diameter, shown back in inches in the detail
    assert "outer 0.5 " in page.inner_text(".facts")
    shoot(page, artifacts / "imperial-custom-1280.png", full_page=True)
    page.set_viewport_size({"width": 390, "height": 844})
    charts_fit(page)
    shoot(page, artifacts / "imperial-custom-390.png", full_page=True)
    assert console_errors == []
