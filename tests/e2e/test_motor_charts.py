"""The motor group and its two charts in Chromium: a pasted curve becomes the share link's
compact form, and the torque-speed and move-over-time charts are drawn."""

from pathlib import Path
from typing import Any

import pytest

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
    page.wait_for_url("**motor_curve=0%3A0.4%2C600%3A0.3%2C1200%3A0.1**")
    page.wait_for_selector("#chart-motor .main-svg")
    page.wait_for_selector("#chart-move .main-svg")
    legend = page.locator("#chart-motor .legend .traces").all_text_contents()
    assert legend[0] == "Motor curve" and len(legend) >= 2
    assert "Time [s]" in page.text_content("#chart-move .g-xtitle")
    page.locator(".chart-motor").screenshot(path=str(artifacts / "motor-chart-1280.png"))
    page.locator(".chart-move").screenshot(path=str(artifacts / "move-chart-1280.png"))
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
    page.locator("table.pairs").screenshot(path=str(artifacts / "motor-pairs-1280.png"))
    assert console_errors == []
