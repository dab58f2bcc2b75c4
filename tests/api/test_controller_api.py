"""The stepper controller inputs at the API and in share links: step angle, microsteps,
maximum step rate, with the checks they switch on and field-level 422s."""

from urllib.parse import parse_qsl

import pytest
from fastapi.testclient import TestClient

from app.contract.form import parse_inputs, parse_units
from app.contract.inputs import ApplicationIn
from app.contract.share_link import share_query
from tests.motor_library import MOTORS

#: A printer's Z axis (Tr8x8(P2), 12 mm/s) with a stepper on a 4 kHz controller, 0.5 mm
#: tolerance (the acetal nut's play, up to 0.3 mm, counts in full).
Z_AXIS = {
    "load_n": 20.0,
    "speed_mm_s": 12.0,
    "length_mm": 350.0,
    "lead_mm": 8.0,
    "family": "TR-C45",
    "nut_material": "acetal",
    "step_angle_deg": 1.8,
    "microsteps": 16,
    "max_step_rate_hz": 4000.0,
    "positioning_tolerance_mm": 0.5,
}


def test_controller_inputs_round_trip_through_a_share_link() -> None:
    inputs = ApplicationIn.model_validate(Z_AXIS)
    params = dict(parse_qsl(share_query(inputs)))
    assert params["step_angle"] == "1.8" and params["microsteps"] == "16"
    parsed, errors = parse_inputs(params, parse_units(params))
    assert errors == {} and parsed is not None
    core = parsed.to_core(MOTORS)
    assert (core.step_angle_deg, core.microsteps, core.max_step_rate_hz) == (1.8, 16, 4000.0)


def test_the_step_rate_rejects_and_says_why(client: TestClient) -> None:
    """4800 steps/s needed (90 rpm x 3200 / 60) against 4000: rejected by step_rate."""
    r = client.get("/api/v1/select", params={**Z_AXIS, "detail": "full"})
    assert r.status_code == 200
    body = r.json()
    rejected = {c["id"]: c for c in body["rejected"]}["Tr8x8(P2)-acetal"]
    assert rejected["governing_check"] == "step_rate"
    step = next(c for c in rejected["checks"] if c["name"] == "step_rate")
    assert step["value"] == pytest.approx(4800.0) and not step["passed"]
    r = client.get("/api/v1/select", params={**Z_AXIS, "max_step_rate_hz": 40000.0})
    assert "Tr8x8(P2)-acetal" in {c["id"] for c in r.json()["candidates"]}


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"microsteps": 0}, "microsteps"),
        ({"microsteps": 1.5}, "microsteps"),
        ({"step_angle_deg": -1.8}, "step_angle_deg"),
        ({"max_step_rate_hz": "fast"}, "max_step_rate_hz"),
    ],
)
def test_bad_controller_input_is_a_field_level_422(
    client: TestClient, change: dict[str, object], field: str
) -> None:
    r = client.get("/api/v1/select", params={**Z_AXIS, **change})
    assert r.status_code == 422
    assert field in {d["field"] for d in r.json()["detail"]}


def test_a_step_rate_limit_needs_a_step_angle(client: TestClient) -> None:
    params = {k: v for k, v in Z_AXIS.items() if k != "step_angle_deg"}
    r = client.get("/api/v1/select", params=params)
    assert r.status_code == 422
    assert "max_step_rate_hz" in {d["field"] for d in r.json()["detail"]}
