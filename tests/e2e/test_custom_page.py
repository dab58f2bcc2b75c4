"""The page of one's own screw and the catalog in real Chromium: typing a screw, its
results and charts, its share link in a fresh page, inline errors (shown under the fields
left, as on the selector), the phone width."""

from typing import Any

SCREW = {
    "outer_diameter_mm": "10",
    "root_diameter_mm": "8",
    "lead_mm": "2",
    "friction_dynamic": "0.15",
    "friction_static": "0.2",
    "pv_limit_mpa_m_s": "3",
}
AXIS = {"load": "100", "speed": "50", "length": "500"}


def check_values(page: Any) -> list[str]:
    return list(page.eval_on_selector_all(".check-value", "cells => cells.map(c => c.textContent)"))


def test_typed_screw_shows_results_charts_and_a_share_link_that_reopens_them(
    page: Any, browser: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(live_server + "/custom")
    for name, value in {**SCREW, **AXIS}.items():
        page.fill(f"#f-{name}", value)
    page.wait_for_function("() => location.search.includes('length=500')")
    page.wait_for_selector("#chart-torque .main-svg")
    assert page.locator("#chart-critical_speed .main-svg").count() >= 1
    assert page.locator("#chart-pv .main-svg").count() >= 1
    assert page.locator(".custom-verdict .governing").count() == 1
    shown = check_values(page)
    link = page.get_attribute("a.share-link", "href")
    assert link.startswith("/custom?") and "root_diameter_mm=8" in link
    fresh = browser.new_context(viewport={"width": 1280, "height": 900})
    other = fresh.new_page()
    other.goto(live_server + link)
    other.wait_for_selector("#chart-torque .main-svg")
    assert check_values(other) == shown
    assert other.input_value("#f-root_diameter_mm") == "8"
    fresh.close()
    assert console_errors == []


def test_root_above_outer_is_an_inline_error_and_keeps_the_text(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    query = "&".join(f"{k}={v}" for k, v in {**SCREW, **AXIS}.items())
    page.goto(f"{live_server}/custom?{query}")
    page.wait_for_selector(".custom-verdict")
    page.fill("#f-root_diameter_mm", "12")
    page.wait_for_function(
        "() => document.getElementById('e-root_diameter_mm').textContent.includes('smaller')"
    )
    page.wait_for_selector("#f-root_diameter_mm[aria-invalid=true]")
    assert page.input_value("#f-root_diameter_mm") == "12"
    assert page.locator("#results.stale").count() == 1
    assert console_errors == []


def test_selector_links_to_the_custom_page(page: Any, live_server: str) -> None:
    page.goto(live_server + "/")
    page.click("a.custom-link")
    page.wait_for_selector("form#custom")
    assert page.url.endswith("/custom")


def test_catalog_fits_a_phone_without_sideways_scrolling(browser: Any, live_server: str) -> None:
    context = browser.new_context(viewport={"width": 390, "height": 844}, is_mobile=True)
    phone = context.new_page()
    for path in ("/catalog", "/custom"):
        phone.goto(live_server + path)
        assert phone.evaluate("() => document.scrollingElement.scrollWidth") <= 390, path
    phone.goto(live_server + "/catalog")
    phone.click("details#ZBX8000 > summary")
    phone.wait_for_selector("details#ZBX8000 table.series-fields")  # loaded when opened
    assert phone.evaluate("() => document.scrollingElement.scrollWidth") <= 390
    context.close()


#: the custom form's error lines showing a message: id -> text
SHOWN = """() => Object.fromEntries([...document.querySelectorAll('#custom span.error')]
  .filter(s => s.textContent.trim()).map(s => [s.id, s.textContent]))"""


def test_errors_show_under_fields_left_not_under_those_not_reached(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    """As on the selector's form: the first keystroke says nothing under the fields not
    yet reached, though the server's answer names them; a required field left empty
    shows its error, and the others stay quiet until they are left too."""
    page.goto(live_server + "/custom")
    with page.expect_response(lambda r: "outer_diameter_mm=1" in r.url):
        page.locator("#f-outer_diameter_mm").press_sequentially("1")
    page.wait_for_function("() => !document.querySelector('#busy.htmx-request')")
    listed = page.eval_on_selector_all(
        "#field-errors [data-error-for]", "items => items.map(i => i.dataset.errorFor)"
    )
    assert {"root_diameter_mm", "lead_mm", "load", "speed", "length"} <= set(listed)
    assert page.evaluate(SHOWN) == {}
    assert page.locator("#custom [aria-invalid]").count() == 0
    page.focus("#f-root_diameter_mm")
    page.keyboard.press("Tab")
    page.wait_for_function(
        "() => document.querySelector('#e-root_diameter_mm').textContent.trim() !== ''"
    )
    assert list(page.evaluate(SHOWN)) == ["e-root_diameter_mm"]
    assert page.get_attribute("#f-root_diameter_mm", "aria-invalid") == "true"
    assert page.locator("#f-lead_mm[aria-invalid]").count() == 0
    assert console_errors == []
