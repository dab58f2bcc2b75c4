"""Where the drive's torque or the motor's RMS torque excludes every screw, the select
summary offers a lower acceleration, a lighter load or a longer dwell, verified by
screening again, and never says that no such change was tried.

Drive torque: 200 N and 30 kg at 3 m/s^2 on a drive of 0.25 N m: every screw needs more
(R10-04T2-RSIT 0.365 N m), but at 1 m/s^2 it needs 0.213 N m. RMS: 40 N and 20 kg at
8 m/s^2 with a 50 ms dwell on a motor rated 0.12 N m continuous, HIWIN rolled screws:
each needs more, but a 4 m/s^2 ramp or a 1 s dwell lets one pass."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import API

TORQUE = {"load_n": 200, "moving_mass_kg": 30, "speed_mm_s": 150, "length_mm": 700,
          "stroke_mm": 500, "accel_mm_s2": 3000, "max_torque_nm": 0.25,
          "motor_inertia_kg_m2": 3e-5}  # fmt: skip
RMS = {"load_n": 40, "moving_mass_kg": 20, "speed_mm_s": 400, "length_mm": 800,
       "stroke_mm": 500, "accel_mm_s2": 8000, "dwell_s": 0.05, "motor_rms_torque_nm": 0.12,
       "motor_inertia_kg_m2": 2e-5, "family": "HIWIN-ROLLED"}  # fmt: skip
CASES = pytest.mark.parametrize(
    ("query", "check"), [(TORQUE, "torque"), (RMS, "motor_rms")], ids=["torque", "rms"]
)


def _select(client: TestClient, query: dict[str, Any]) -> dict[str, Any]:
    response = client.get(f"{API}/select", params=query)
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


@CASES
def test_a_motor_bound_selection_is_offered_a_verified_remedy(
    client: TestClient, query: dict[str, Any], check: str
) -> None:
    body = _select(client, query)
    summary = body["summary"]
    assert body["counts"]["passed"] == 0 and summary["most_excluding_check"] == check
    assert summary["remedies"], summary["message"]
    assert summary["impossible"] is None
    assert "tried lets one pass" not in summary["message"]
    for remedy in summary["remedies"]:
        again = _select(client, {**query, **remedy["inputs"]})
        assert again["counts"]["passed"] == remedy["passing"] >= 1, remedy
        # each remedy keeps the margin it promises
        assert remedy["utilization"] <= 1.0 / 1.05 + 1e-9


def test_the_drive_torque_remedy_lowers_the_acceleration(client: TestClient) -> None:
    remedies = _select(client, TORQUE)["summary"]["remedies"]
    alone = [r["inputs"] for r in remedies if set(r["inputs"]) == {"accel_mm_s2"}]
    assert alone and all(a["accel_mm_s2"] < TORQUE["accel_mm_s2"] for a in alone)


def test_the_rms_remedies_lower_the_acceleration_or_lengthen_the_dwell(
    client: TestClient,
) -> None:
    remedies = _select(client, RMS)["summary"]["remedies"]
    keys = {key for r in remedies for key in r["inputs"]}
    assert {"accel_mm_s2", "dwell_s"} <= keys
    for remedy in remedies:
        inputs = remedy["inputs"]
        assert inputs.get("accel_mm_s2", 0.0) < RMS["accel_mm_s2"]
        assert inputs.get("dwell_s", RMS["dwell_s"] + 1.0) > RMS["dwell_s"]
