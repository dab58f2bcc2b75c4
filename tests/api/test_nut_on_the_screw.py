"""The nut length given lies on the screw: refused on the nut length when it is longer
than the screw (it was accepted, and a 10 m nut on a 500 mm screw carried 306 kN), and
a remedy never shortens the screw below it."""

from typing import Any

from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from app.core.input_rules import inputs_hold, least_inputs
from app.core.model import Application

AXIS = {"load_n": 500, "speed_mm_s": 50, "length_mm": 500}


def _errors(client: TestClient, **change: Any) -> dict[str, str]:
    r = client.get("/api/v1/select", params={**AXIS, **change})
    assert r.status_code == 422, r.text
    return {d["field"]: d["message"] for d in r.json()["detail"]}


def test_a_nut_longer_than_the_screw_is_refused_on_the_nut_length(client: TestClient) -> None:
    assert "at most the screw length" in _errors(client, nut_length_mm=10_000)["nut_length_mm"]
    # beside a stroke, the nut is named, not the stroke with a room below 0 mm
    both = _errors(client, nut_length_mm=2000, stroke_mm=1)
    assert set(both) == {"nut_length_mm"}
    # a nut that fits leaves the stroke the screw less the nut
    stroke = _errors(client, nut_length_mm=100, stroke_mm=450)["stroke_mm"]
    assert "less the nut length (500 - 100 mm), 400 mm" in stroke
    fits = client.get("/api/v1/select", params={**AXIS, "nut_length_mm": 500})
    assert fits.status_code == 200


def test_a_change_keeps_the_screw_at_least_as_long_as_the_nut() -> None:
    app = Application(load_n=500.0, speed_m_s=0.05, length_m=0.5, nut_length_m=0.3)
    assert least_inputs(app) == {"length_m": 0.3}
    assert inputs_hold(app)
    assert not inputs_hold(Application(load_n=500.0, speed_m_s=0.05, length_m=0.25,
                                       nut_length_m=0.3))  # fmt: skip


def test_a_length_held_to_the_screws_is_said_in_the_forms_unit(client: TestClient) -> None:
    """On a form in inches a stroke, a nut or a span longer than the 20 in screw is told
    the screw's 20 in (it was told 508 mm, or 508 with no unit); beside a 15 in nut, the
    stroke at most the 5 in left."""
    axis = "/?load=20&speed=1&length=20&length_unit=in"
    for field, value in (("stroke", 30), ("nut_length", 50), ("bearing_to_nut", 30)):
        page = BeautifulSoup(client.get(f"{axis}&{field}={value}").text, "html.parser")
        error = page.select_one(f"#e-{field}")
        assert error is not None and error.text == "Must be at most the screw length, 20 in."
    page = BeautifulSoup(client.get(f"{axis}&nut_length=15&stroke=10").text, "html.parser")
    error = page.select_one("#e-stroke")
    assert error is not None and error.text.startswith(
        "Must be at most the screw length less the nut length, 5 in:"
    )
