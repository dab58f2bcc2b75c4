"""Issue 34 in real Chromium: /custom with a catalog nut material runs the catalog row's
checks, a screw without nut data names the checks it skipped, and the phone's result bar
shows the top screw's whole id. axe scans these states in test_accessibility, not here a
second time: "/custom bronze-nut", "/custom results" (its checks not run named) and
"/ long-id-accel-in-g" (the long id in the phone's bar, the acceleration in g)."""

from pathlib import Path
from typing import Any

from tests.e2e.shots import shoot
from tests.e2e.test_accessibility import resize

#: Tr12x3 (ISO 2904: d 12 mm, P 3 mm, d3 8.5 mm) in C45 steel, as the form takes it
TR12X3 = {
    "outer_diameter_mm": "12",
    "root_diameter_mm": "8.5",
    "lead_mm": "3",
    "thread_half_angle_deg": "15",
    "friction_dynamic": "0.13",
    "friction_static": "0.16",
}
AXIS = {"load": "500", "speed": "20", "length": "400"}
#: the ISO 304 family alone: the top screw has a long id (Tr16x8(P4)-304-ptfe)
LONG_TOP = "load=200&speed=100&length=500&family=TR-304"


def _check_names(page: Any) -> list[str]:
    return list(page.eval_on_selector_all("li.check", "items => items.map(i => i.dataset.check)"))


def _context(browser: Any, width: int, height: int = 900) -> Any:
    return browser.new_context(viewport={"width": width, "height": height})


def _collect(errors: list[str]) -> Any:
    """A console listener that keeps the page's errors in ``errors``."""

    def listen(message: Any) -> None:
        if message.type == "error":
            errors.append(message.text)

    return listen


def test_a_bronze_nut_gives_the_custom_screw_the_catalogs_checks(
    browser: Any, live_server: str, artifacts: Path
) -> None:
    """Typed on a phone (390 px), then the same page resized to 1280 px (``resize``)."""
    context = _context(browser, 390)
    page = context.new_page()
    errors: list[str] = []
    page.on("console", _collect(errors))
    page.goto(live_server + "/custom")
    page.select_option("#f-material", "c45-steel")
    page.select_option("#f-nut", "bronze")
    for name, value in {**TR12X3, "pitch_mm": "3", **AXIS}.items():
        page.fill(f"#f-{name}", value)
    page.wait_for_function("() => location.search.includes('length=400')")
    page.wait_for_selector("li.check[data-check=bearing_pressure]")
    query = "&".join(f"{k}={v}" for k, v in AXIS.items())
    catalog = context.new_page()
    catalog.goto(f"{live_server}/detail?{query}&id=Tr12x3-bronze")
    for width in (390, 1280):
        resize(page, width)
        assert page.locator("table.nut-limits .kind-handbook").count() >= 1
        assert _check_names(page) == _check_names(catalog)
        assert (
            page.locator(".custom-verdict").inner_text().split(".")[0]
            == catalog.locator(".verdict").inner_text().split(".")[0]
        )
        shoot(page, artifacts / f"custom-bronze-nut-{width}.png", full_page=True)
    assert errors == []
    context.close()


def test_a_screw_without_nut_data_names_the_checks_it_skipped(
    browser: Any, live_server: str, artifacts: Path
) -> None:
    """Loaded at 1280 px, then resized to 390 px (``resize``)."""
    query = "&".join(f"{k}={v}" for k, v in {**TR12X3, **AXIS}.items())
    context = _context(browser, 1280)
    page = context.new_page()
    page.goto(f"{live_server}/custom?{query}")
    for width in (1280, 390):
        resize(page, width)
        verdict = page.locator(".custom-verdict").inner_text()
        assert "every check" not in verdict
        assert "Not checked:" in verdict and "Nut contact pressure (no " in verdict
        assert page.locator(".custom-verdict").is_visible()
        shoot(page, artifacts / f"custom-skipped-checks-{width}.png")
    context.close()


def test_the_phone_bar_shows_the_top_screws_whole_id(
    browser: Any, live_server: str, artifacts: Path
) -> None:
    context = _context(browser, 390, 844)
    page = context.new_page()
    page.goto(f"{live_server}/?{LONG_TOP}")
    page.wait_for_selector("tbody.candidate")
    top = page.locator("tbody.candidate .cid").first.inner_text()
    assert len(top) > 15
    bar = page.locator("#result-bar")
    assert bar.is_visible()
    shown = page.locator("#result-bar .bar-id")
    assert shown.inner_text() == top
    # not cut: the id's box lies inside the phone's width and nothing of it overflows
    box = shown.bounding_box()
    assert box is not None and box["x"] >= 0 and box["x"] + box["width"] <= 390
    assert page.evaluate(
        "() => [...document.querySelectorAll('#result-bar, #result-bar *')]"
        ".every(e => e.scrollWidth <= e.clientWidth + 1 || e.tagName === 'SPAN' "
        "&& getComputedStyle(e).display === 'inline')"
    )
    assert page.evaluate(
        "() => getComputedStyle(document.querySelector('#result-bar .bar-verdict'))"
        ".textOverflow !== 'ellipsis'"
    )
    bar_box = bar.bounding_box()
    assert bar_box is not None and abs(bar_box["y"] + bar_box["height"] - 844) < 1
    shoot(page, artifacts / "result-bar-long-id-390.png")
    context.close()
    wide = browser.new_context(viewport={"width": 1280, "height": 900})
    page = wide.new_page()
    page.goto(f"{live_server}/?{LONG_TOP}")
    page.wait_for_selector("tbody.candidate")
    assert not page.locator("#result-bar").is_visible()
    shoot(page, artifacts / "result-bar-long-id-1280.png")
    wide.close()


def test_the_acceleration_unit_choice_converts_and_its_link_reproduces_the_answer(
    browser: Any, live_server: str, artifacts: Path
) -> None:
    """2000 mm/s² typed, then g chosen: the field shows 0.2039 g (2 / 9.80665), the
    results stay the same, and the share link opens in g with the same answer. Chosen on
    a phone (390 px), then the same page resized to 1280 px (``resize``)."""
    context = _context(browser, 390)
    page = context.new_page()
    page.goto(f"{live_server}/?load=50&speed=200&length=500&stroke=300&accel=2000")
    page.wait_for_selector("tbody.candidate")
    before = page.locator("tbody.candidate .torque-peak").first.inner_text()
    page.select_option("#f-accel_unit", "g")
    page.wait_for_function("() => location.search.includes('accel_unit=g')")
    page.wait_for_function(
        "() => Math.abs(parseFloat(document.querySelector('#f-accel').value) - 0.20394) < 1e-4"
    )
    page.wait_for_selector("tbody.candidate")
    link = page.get_attribute("a.share-link", "href")
    assert link is not None and "accel_unit=g" in link
    other = context.new_page()
    other.goto(live_server + link)
    assert other.input_value("#f-accel_unit") == "g"
    assert other.locator("tbody.candidate .torque-peak").first.inner_text() == before
    for width in (390, 1280):
        resize(page, width)
        assert "g" in page.locator("label[for=f-accel] .unit").inner_text()
        assert page.locator("tbody.candidate .torque-peak").first.inner_text() == before
        shoot(page, artifacts / f"accel-unit-g-{width}.png")
    context.close()
