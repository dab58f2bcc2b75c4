"""The motor group and its two charts in Chromium: a pasted curve becomes the share link's
compact form, and the torque-speed and move-over-time charts are drawn."""

import json
import urllib.request
from pathlib import Path
from typing import Any

import pytest

from tests.e2e.shots import shoot
from tests.e2e.test_accessibility import resize

pytestmark = pytest.mark.e2e

AXIS = "load=50&speed=50&length=500&lead=10&stroke=200"


def test_motor_curve_and_move_charts(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("table.candidates tbody.candidate")
    page.evaluate("() => document.querySelector('details.advanced').open = true")
    page.click("details.group:has(#f-motor_curve) > summary")
    page.fill("#f-motor_curve", "0 0.4\n600 0.3\n1200 0.1")
    page.locator("#f-motor_curve").dispatch_event("input")
    page.wait_for_url("**motor_curve=0:0.4,600:0.3,1200:0.1**")
    page.wait_for_selector("#chart-motor .main-svg")
    page.wait_for_selector("#chart-move .main-svg")
    legend = page.locator("#chart-motor .legend .traces").all_text_contents()
    assert legend[0] == "Motor curve (as entered)" and len(legend) >= 2
    assert "Time [s]" in page.text_content("#chart-move .g-xtitle")
    shoot(page.locator(".chart-motor"), artifacts / "motor-chart-1280.png")
    shoot(page.locator(".chart-move"), artifacts / "move-chart-1280.png")
    assert console_errors == []


def test_a_library_servo_and_then_any_motor_on_the_page(
    page: Any, live_server: str, artifacts: Path, console_errors: list[str]
) -> None:
    """Typing a library servo (the Pittman 14204S004) draws its peak envelope and fills
    the motor's share column; typing "any" ranks the screw + motor pairs, the share of the
    motor used ascending, and the share link carries it."""
    page.goto(f"{live_server}/?{AXIS}&rank_by=motor_margin")
    page.wait_for_selector("table.candidates tbody.candidate")
    page.evaluate("() => document.querySelector('details.advanced').open = true")
    page.click("details.group:has(#f-motor) > summary")
    page.fill("#f-motor", "pittman-14204s004")
    page.locator("#f-motor").dispatch_event("input")
    page.wait_for_url("**motor=pittman-14204s004**")
    page.wait_for_selector("#chart-motor .main-svg")
    page.wait_for_selector("tbody.candidate .motor-use")
    page.fill("#f-motor", "any")
    page.locator("#f-motor").dispatch_event("input")
    page.wait_for_url("**motor=any**")
    page.wait_for_selector("table.pairs tr.pair")
    used = [
        float(text.strip(" %"))
        for text in page.locator("table.pairs .motor-use").all_text_contents()
    ]
    assert len(used) == 10 and used == sorted(used)
    shoot(page.locator("table.pairs"), artifacts / "motor-pairs-1280.png")
    assert console_errors == []


def test_the_table_gives_each_screws_motor_numbers(
    browser: Any, live_server: str, artifacts: Path
) -> None:
    """With a library motor and a move, each row shows the peak and RMS motor torque and
    the share of the motor used, the same figures as the API's compact select, at either
    width (at 390 px each row is a card of labelled values): loaded at 1280 px, then
    resized to 390 px (``resize``)."""
    # 30 N: the SS2422's usable torque, 0.186 / sqrt 2 / 1.5 = 0.088 N m, drives no screw
    # of the 10 mm lead at 50 N
    query = "load_n=30&speed_mm_s=50&length_mm=500&lead_mm=10&stroke_mm=200&motor=ss2422-5041"
    with urllib.request.urlopen(f"{live_server}/api/v1/select?{query}&limit=5") as response:
        api = json.load(response)["candidates"]
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    page.goto(f"{live_server}/?{AXIS.replace('load=50', 'load=30')}&motor=ss2422-5041&limit=5")
    page.wait_for_selector("tbody.candidate .motor-use")
    for width in (1280, 390):
        resize(page, width)
        rows = page.locator("tbody.candidate")
        assert rows.count() == len(api)
        for i, c in enumerate(api):
            row = rows.nth(i)
            assert row.get_attribute("data-id") == c["id"]
            peak = float(row.locator(".torque-peak").inner_text())
            rms = float(row.locator(".torque-rms").inner_text())
            used = float(row.locator(".motor-use").inner_text().strip(" %"))
            assert peak == pytest.approx(c["torque"]["peak_motor_nm"], rel=5e-3)
            assert rms == pytest.approx(c["torque"]["rms_nm"], rel=5e-3)
            assert used == pytest.approx(100 * c["motor_use"], abs=0.5)
            assert row.locator(".motor-use").is_visible()
            assert row.locator(".torque-rms").is_visible()
        shot = artifacts / f"motor-table-{width}.png"
        shoot(page.locator("table.candidates"), shot)
    context.close()
