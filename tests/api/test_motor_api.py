"""The motor curve at the API and in share links: compact text, pairs, and bad curves."""

from urllib.parse import parse_qsl

import pytest
from fastapi.testclient import TestClient

from app.contract.form import parse_inputs, parse_units
from app.contract.inputs import ApplicationIn
from app.contract.share_link import share_query
from tests.motor_library import MOTORS

BASE = {"load_n": 50.0, "speed_mm_s": 100.0, "length_mm": 500.0, "stroke_mm": 200.0}


def test_curve_round_trips_through_a_share_link() -> None:
    inputs = ApplicationIn.model_validate({**BASE, "motor_curve": [[0, 0.5], [3000, 0.2]]})
    params = dict(parse_qsl(share_query(inputs)))
    assert params["motor_curve"] == "0:0.5,3000:0.2"
    parsed, errors = parse_inputs(params, parse_units(params))
    assert errors == {} and parsed is not None
    assert parsed.to_core(MOTORS).motor_curve == ((0.0, 0.5), (3000.0, 0.2))


def test_page_reads_lines_of_rpm_and_torque() -> None:
    params = {"load": "50", "speed": "100", "length": "500", "motor_curve": "0 0.5\n3000 0.2"}
    parsed, errors = parse_inputs(params, parse_units(params))
    assert errors == {} and parsed is not None
    assert parsed.to_core(MOTORS).motor_curve == ((0.0, 0.5), (3000.0, 0.2))


@pytest.mark.parametrize(
    "query",
    [
        "motor_curve=[[0,0.5],[3000,0.2]]",
        "motor_curve=[0,0.5]&motor_curve=[3000,0.2]",
        "motor_curve=0:0.5&motor_curve=3000:0.2",
        "motor_curve=0,0.5&motor_curve=3000,0.2",
        "motor_curve=0:0.5,1500:0.35&motor_curve=3000:0.2",
    ],
    ids=["json", "json-pairs-repeated", "repeated", "comma-pairs-repeated", "mixed"],
)
def test_a_get_curve_as_json_or_repeated_parameters_is_the_posted_curve(
    client: TestClient, query: str
) -> None:
    base = "&".join(f"{k}={v:g}" for k, v in BASE.items())
    got = client.get(f"/api/v1/select?{base}&{query}")
    assert got.status_code == 200, got.text
    points = [[0, 0.5], [1500, 0.35], [3000, 0.2]] if "1500" in query else [[0, 0.5], [3000, 0.2]]
    posted = client.post("/api/v1/select", json={**BASE, "motor_curve": points}).json()
    assert got.json()["inputs"]["motor_curve"] == points
    assert got.json()["candidates"] == posted["candidates"]


@pytest.mark.parametrize(
    ("curve", "point"),
    [
        ("0:0.5", "2 to 50 points"),
        ("0:0.5,100:-1", "point 2"),
        ("0:0.5,0:0.4", "point 2"),
        (",".join(f"{i}:1" for i in range(51)), "2 to 50 points"),
        ("[[0,0.5],[3000,NaN]]", "point 2 (3000, nan): rpm and torque must be finite"),
        ("[[0,true],[3000,0.2]]", "point 1 is not two numbers"),
        ("[[0,0.5],[3000,0.2]", "is not a JSON list of [rpm, torque] pairs"),
        ("[" * 1000, "is not a JSON list of [rpm, torque] pairs"),
    ],
)
def test_a_bad_curve_is_a_422_naming_the_field_and_point(
    client: TestClient, curve: str, point: str
) -> None:
    r = client.get("/api/v1/select", params={**BASE, "motor_curve": curve})
    assert r.status_code == 422
    detail = r.json()["detail"][0]
    assert detail["field"] == "motor_curve" and point in detail["message"]


def test_profile_and_segments_in_the_response(client: TestClient) -> None:
    r = client.post(
        "/api/v1/select",
        params={"detail": "full"},
        json={**BASE, "motor_curve": [[0, 1.0], [3000, 0.5]]},
    )
    top = r.json()["candidates"][0]
    assert top["profile"]["kind"] == "trapezoid" and len(top["segments"]) == 8
    assert top["torque"]["rms_nm"] > 0 and top["torque"]["peak_nm"] >= top["torque"]["rms_nm"]
