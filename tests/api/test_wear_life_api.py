"""A horizontal axis on a Tr14x3 acetal nut through the API: its wear life band by hand,
from Archard's law h = k p s with the catalog's rate (Neale, Tribology Handbook A5,
unfilled thermoplastics about 1e-6 mm^3/(N m), 3:1 either way) and the allowed wear of a
quarter of the pitch off the thread (Helix Linear; 0.483 H1 on a 15 deg flank)."""

import math

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

#: 200 N running thrust at 10 mm/s (PV 0.048 MPa m/s, inside acetal's 0.07), 200 mm
#: strokes 1000 times a day, a year asked.
DUTY = {
    "load_n": 200.0,
    "speed_mm_s": 10.0,
    "length_mm": 400.0,
    "stroke_mm": 200.0,
    "cycles_per_day": 1000.0,
    "required_life_years": 1.0,
}

# Tr14x3 (ISO 2904): d2 = 14 - 1.5 = 12.5 mm, H1 = P/2 = 1.5 mm; the nut 2 d = 28 mm long
FLANK_AREA_M2 = 28.0 / 3.0 * math.pi * 12.5e-3 * 1.5e-3  # 549.8 mm^2 engaged
ALLOWED_M = 0.483 * 1.5e-3  # 0.7245 mm deep: 0.750 mm = P/4 along the axis
SLIDING_PER_TRAVEL = math.hypot(3.0, math.pi * 12.5) / 3.0  # 13.13 m per m of travel
RATES_M2_N = {"nominal": 1e-15, "high": 3e-15, "low": 3.3e-16}


def _travel_m(load_n: float, rate_m2_n: float) -> float:
    """h = k p s solved for s, divided by the flanks' sliding per metre of travel."""
    return ALLOWED_M / (rate_m2_n * load_n / FLANK_AREA_M2) / SLIDING_PER_TRAVEL


def _evaluate(client: TestClient, **extra: float) -> dict:  # type: ignore[type-arg]
    r = client.post(
        "/api/v1/evaluate",
        json={"application": {**DUTY, **extra}, "screw": {"catalog_id": "Tr14x3-acetal"}},
    )
    assert r.status_code == 200, r.text
    return r.json()["candidate"]  # type: ignore[no-any-return]


def test_the_life_band_of_an_acetal_nut_by_hand(client: TestClient) -> None:
    """p = 200 N / 549.8 mm^2 = 0.3638 MPa; s = 0.7245e-3 / (1e-15 x 0.3638e6) = 1992 km
    slid; / 13.13 = 151.7 km of travel; a cycle is 2 x 0.2 m, 365 000 cycles a year:
    151.7e3 / 0.4 / 365 000 = 1.039 years, which meets the year asked. The band: the
    rate's high end, 3e-6, gives 50.6 km (0.346 years); its low end, 3.3e-7, 459.7 km
    (3.149 years). Hours of operation: each 0.2 m move at 10 mm/s with 0.01 s ramps at
    1 m/s^2 takes 20.01 s, a cycle 40.02 s: 126 400 cycles x 40.02 s = 1405 h to 12 776 h."""
    c = _evaluate(client)
    check = next(k for k in c["checks"] if k["name"] == "wear_life")
    nominal_m = _travel_m(200.0, RATES_M2_N["nominal"])
    assert nominal_m == pytest.approx(151.7e3, rel=1e-3)
    assert check["limit"] == pytest.approx(nominal_m / 0.4 / 365_000.0, rel=1e-6)
    assert check["limit"] == pytest.approx(1.039, rel=1e-3)
    assert check["passed"] and check["utilization"] == pytest.approx(1.0 / 1.039, rel=1e-3)

    life = c["life"]
    assert life["model"] == "wear" and "assumed wear rate" in life["note"]
    ends_m = [_travel_m(200.0, RATES_M2_N["high"]), _travel_m(200.0, RATES_M2_N["low"])]
    assert life["travel_km"] == pytest.approx([m / 1e3 for m in ends_m], rel=1e-6)
    assert life["travel_km"] == pytest.approx([50.57, 459.7], rel=1e-3)
    assert life["years"] == pytest.approx([0.3464, 3.149], rel=1e-3)
    assert life["hours"] == pytest.approx([m / 0.4 * 40.02 / 3600.0 for m in ends_m], rel=1e-6)
    assert life["cycles"] == pytest.approx([m / 0.4 for m in ends_m], rel=1e-6)


def test_twice_the_thrust_halves_the_life_and_fails_the_year(client: TestClient) -> None:
    """Archard's depth is linear in the pressure: at 400 N the nut lasts 0.5196 years,
    short of the year asked, and the whole band halves with it."""
    c = _evaluate(client, load_n=400.0)
    check = next(k for k in c["checks"] if k["name"] == "wear_life")
    assert check["limit"] == pytest.approx(_travel_m(400.0, 1e-15) / 0.4 / 365_000.0)
    assert check["limit"] == pytest.approx(1.039 / 2.0, rel=1e-3)
    assert not check["passed"]
    assert c["life"]["years"] == pytest.approx([0.3464 / 2.0, 3.149 / 2.0], rel=1e-3)


#: The issue's pick-and-place axis: 1.5 kg at 10 m/s^2 to 300 mm/s over 400 mm, no load.
PICK_AND_PLACE = {
    "load_n": 0.0,
    "moving_mass_kg": 1.5,
    "speed_mm_s": 300.0,
    "length_mm": 500.0,
    "accel_mm_s2": 10000.0,
    "stroke_mm": 400.0,
}


def test_a_pick_and_place_nut_wears_by_hours_a_day(client: TestClient) -> None:
    """No load, but m a = 15 N on the four 4.5 mm ramps of a cycle: wear thrust 4 x 15 x
    4.5 / 800 = 0.3375 N. B8000-L10-TFE (0.75 H^2 lead = 1.4637e-8 m^3, k = 1e-15 m^2/N):
    43,370 km of travel. 8 hours a day of the 2.7267 s cycle are 10,562 cycles, 0.8 m each:
    43.37e6 / (0.8 x 10,562 x 365) = 14.06 years, which meets 10 years asked."""
    duty = {"hours_per_day": 8.0, "required_life_years": 10.0}
    c = evaluate(client, "B8000-L10-TFE", **PICK_AND_PLACE, **duty)
    wear = check(c, "wear_life")
    assert wear["limit"] == pytest.approx(43.37e6 / (0.8 * 10562.3 * 365.0), rel=1e-3)
    assert wear["limit"] == pytest.approx(14.06, rel=1e-3) and wear["passed"]
    assert "wear thrust of 0.3375 N" in wear["message"]
    assert c["life"]["years"][0] == pytest.approx(14.06 / 3.0, rel=1e-3)


def test_cycles_and_hours_a_day_together_are_refused(client: TestClient) -> None:
    """Both could disagree: 422 naming the hours in the API, an inline message on the page
    (never a 500)."""
    body = {
        "application": {**PICK_AND_PLACE, "cycles_per_day": 100.0, "hours_per_day": 8.0},
        "screw": {"catalog_id": "B8000-L10-TFE"},
    }
    r = client.post("/api/v1/evaluate", json=body)
    assert r.status_code == 422
    assert [d["field"] for d in r.json()["detail"]] == ["application.hours_per_day"]
    page = client.get(
        "/?load=0&moving_mass_kg=1.5&speed=300&length=500&accel=10000&stroke=400"
        "&cycles_per_day=100&hours_per_day=8"
    )
    assert page.status_code in (200, 422)
    error = BeautifulSoup(page.text, "html.parser").select_one("#e-hours_per_day")
    assert error is not None and "not both" in error.text
