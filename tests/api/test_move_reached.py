"""Issue 29, item 7: the speed the axis really reaches. A stroke too short to reach the
typed speed is a triangle, and every speed check judges the triangle's peak."""

import math

import pytest
from fastapi.testclient import TestClient

from app.core import motion
from app.core.model import Application
from tests.api.calls import check, evaluate

IN = 0.0254

#: Tr16x4 with a PTFE nut, 500 mm/s typed over a 10 mm stroke at 1000 mm/s^2 (issue 29).
SHORT = {
    "load_n": 10.0,
    "speed_mm_s": 500.0,
    "length_mm": 300.0,
    "stroke_mm": 10.0,
    "accel_mm_s2": 1000.0,
}


def test_nook_triangle_peak() -> None:
    """Nook's manual-lathe kinematics (engineering.md sec. 9): 36 in in 10 s, triangular,
    peaks at 7.2 in/s. Each half lasts 5 s, so a = 7.2 / 5 = 1.44 in/s^2; any typed speed
    above 7.2 in/s is not reached."""
    app = Application(
        load_n=0.0, speed_m_s=20 * IN, length_m=1.0, stroke_m=36 * IN, accel_m_s2=1.44 * IN
    )
    p = motion.move_profile(app)
    assert p is not None and p.kind == "triangle"
    assert motion.reached_speed(app) == pytest.approx(7.2 * IN, rel=1e-9)
    assert p.move_time_s == pytest.approx(10.0, rel=1e-9)


def test_short_stroke_judged_at_the_peak(client: TestClient) -> None:
    """s = 10 mm, a = d = 1000 mm/s^2: v_peak = sqrt(2 s / (1/a + 1/d)) = sqrt(s a) =
    sqrt(10 x 1000) = 100 mm/s, so n = 100 / 4 x 60 = 1,500 rpm, not the typed 500 / 4 x 60
    = 7,500 rpm."""
    c = evaluate(client, "Tr16x4-ptfe", **SHORT)
    assert c["profile"]["kind"] == "triangle"
    assert c["profile"]["peak_speed_mm_s"] == pytest.approx(100.0)
    assert c["rpm"] == pytest.approx(1500.0)
    assert check(c, "critical_speed")["value"] == pytest.approx(1500.0)
    # sliding speed on the flanks: the helix at d2 = 14 mm per turn, 25 turns a second
    helix_mm = math.hypot(4.0, math.pi * 14.0)
    assert check(c, "max_sliding_speed")["value"] == pytest.approx(helix_mm * 25.0, rel=1e-6)


def test_typed_speed_still_judged_when_reached(client: TestClient) -> None:
    """A 400 mm stroke reaches 500 mm/s (the two ramps take 2 x 500^2 / (2 x 1000) =
    250 mm of it): the checks judge 500 / 4 x 60 = 7,500 rpm, as typed."""
    c = evaluate(client, "Tr16x4-ptfe", **{**SHORT, "stroke_mm": 400.0, "length_mm": 600.0})
    assert c["profile"]["kind"] == "trapezoid"
    assert c["rpm"] == pytest.approx(7500.0)


def test_selection_says_the_profile_is_triangular(client: TestClient) -> None:
    """The summary names the speed typed and the speed reached."""
    body = client.post("/api/v1/select", json=SHORT).json()
    message = body["summary"]["message"]
    assert "triangle" in message and "500 mm/s" in message and "100 mm/s" in message
    without = client.post("/api/v1/select", json={**SHORT, "stroke_mm": None}).json()
    assert "triangle" not in without["summary"]["message"]
    # judged at 100 mm/s rather than 500 mm/s, more screws pass
    assert body["counts"]["passed"] > without["counts"]["passed"]
