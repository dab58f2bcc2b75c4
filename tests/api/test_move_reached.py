"""Issue 29, item 7: the speed the axis really reaches. A stroke too short to reach the
typed speed is a triangle, and every speed check judges the triangle's peak."""

import math
from typing import Any

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


def field_errors(response: Any) -> dict[str, str]:
    assert response.status_code == 422, response.text
    return {e["field"]: e["message"] for e in response.json()["detail"]}


@pytest.mark.parametrize(
    ("extra", "room"),
    [({"stroke_mm": 301.0}, "300 mm"), ({"stroke_mm": 280.0, "nut_length_mm": 30.0}, "270 mm")],
    ids=["screw-length", "less-the-nut"],
)
def test_a_stroke_past_the_screw_is_refused(
    client: TestClient, extra: dict[str, float], room: str
) -> None:
    """Screw 300 mm: a 301 mm stroke runs the nut off the screw; with a 30 mm nut typed the
    stroke is at most 300 - 30 = 270 mm. 422 on stroke_mm, in the API and the page."""
    body = {"load_n": 10.0, "speed_mm_s": 100.0, "length_mm": 300.0, **extra}
    errors = field_errors(client.post("/api/v1/select", json=body))
    assert set(errors) == {"stroke_mm"} and room in errors["stroke_mm"]
    page = {"load": "10", "speed": "100", "length": "300", "stroke": str(extra["stroke_mm"])}
    if "nut_length_mm" in extra:
        page["nut_length"] = "30"
    html = client.get("/", params=page).text
    assert 'id="e-stroke"' in html and room in html


def test_each_catalog_nut_must_fit_beside_the_stroke(client: TestClient) -> None:
    """Tr16x4's catalog nut is 2 x 16 = 32 mm: a 270 mm stroke on a 300 mm screw needs
    302 mm and fails the stroke-travel check; 260 mm needs 292 mm and passes."""
    body = {"load_n": 10.0, "speed_mm_s": 50.0, "length_mm": 300.0}
    long = check(evaluate(client, "Tr16x4-ptfe", **body, stroke_mm=270.0), "stroke_travel")
    assert not long["passed"]
    assert (long["value"], long["limit"]) == pytest.approx((302.0, 300.0))
    short = check(evaluate(client, "Tr16x4-ptfe", **body, stroke_mm=260.0), "stroke_travel")
    assert short["passed"] and short["value"] == pytest.approx(292.0)


def test_more_cycles_than_a_day_holds_are_refused(client: TestClient) -> None:
    """200 mm at 100 mm/s, a = 1000 mm/s^2: ramps of 0.1 s (5 mm each), 190 mm at
    100 mm/s in 1.9 s, a move of 2.1 s, a cycle of 4.2 s: at most 86,400 / 4.2 = 20,571
    a day. With a 0.9 s dwell after each move the cycle is 6 s: at most 14,400."""
    body = {"load_n": 10.0, "speed_mm_s": 100.0, "length_mm": 300.0, "stroke_mm": 200.0}
    errors = field_errors(client.post("/api/v1/select", json={**body, "cycles_per_day": 20572}))
    assert set(errors) == {"cycles_per_day"} and "20571.4" in errors["cycles_per_day"]
    fits = client.post("/api/v1/select", json={**body, "cycles_per_day": 20571})
    assert fits.status_code == 200
    dwell = {**body, "dwell_s": 0.9, "cycles_per_day": 14401}
    assert "14400" in field_errors(client.post("/api/v1/select", json=dwell))["cycles_per_day"]
    query = {**body, "cycles_per_day": 20572}
    assert set(field_errors(client.get("/api/v1/select", params=query))) == {"cycles_per_day"}
    page = {"load": "10", "speed": "100", "length": "300", "stroke": "200",
            "cycles_per_day": "20572"}  # fmt: skip
    assert 'id="e-cycles_per_day"' in client.get("/", params=page).text
