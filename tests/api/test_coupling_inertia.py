"""The coupling's inertia turns with the screw: the motor accelerates it, and the inertia
ratio counts it as load (Oriental Motor, Motor Sizing Calculations: the load inertia is
everything the motor drives, the coupling's included; the rotor's is the motor's own).

Tr16x4 (lead 4 mm) at 2 m/s^2 turns at alpha = a 2 pi / lead = 3141.59 rad/s^2: a
3e-6 kg m^2 coupling takes J alpha = 0.0094248 N m more to accelerate, at the start
and on the ramps, and raises the ratio to a 5e-6 kg m^2 rotor by 3e-6 / 5e-6 = 0.6.
"""

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.report.formulas import FORMULAS
from tests.api.calls import check

AXIS = {
    "load_n": 50, "speed_mm_s": 100, "length_mm": 500, "stroke_mm": 300, "accel_mm_s2": 2000,
    "moving_mass_kg": 5, "motor_inertia_kg_m2": 5e-6,
}  # fmt: skip
COUPLING_KG_M2 = 3e-6


def _evaluate(client: TestClient, **extra: Any) -> dict[str, Any]:
    body = {"application": {**AXIS, **extra}, "screw": {"catalog_id": "Tr16x4-bronze"}}
    response = client.post("/api/v1/evaluate", json=body)
    assert response.status_code == 200, response.text
    candidate: dict[str, Any] = response.json()["candidate"]
    return candidate


def test_the_coupling_is_accelerated_with_the_screw_and_counts_as_load(client: TestClient) -> None:
    without = _evaluate(client)
    coupled = _evaluate(client, coupling_inertia_kg_m2=COUPLING_KG_M2)
    alpha = 2.0 * 2.0 * math.pi / 0.004
    extra_nm = COUPLING_KG_M2 * alpha
    assert round(extra_nm, 7) == 0.0094248
    before, after = without["torque"], coupled["torque"]
    assert after["inertia_screw_nm"] - before["inertia_screw_nm"] == pytest.approx(extra_nm)
    assert after["breakaway_nm"] - before["breakaway_nm"] == pytest.approx(extra_nm)
    assert after["inertia_motor_nm"] == pytest.approx(before["inertia_motor_nm"])
    ratio_before = check(without, "inertia_ratio")["value"]
    ratio_after = check(coupled, "inertia_ratio")["value"]
    assert ratio_after - ratio_before == pytest.approx(COUPLING_KG_M2 / 5e-6)


def test_a_negative_coupling_inertia_is_refused_at_its_field(client: TestClient) -> None:
    body = {"application": {**AXIS, "coupling_inertia_kg_m2": -1e-6}}
    body["screw"] = {"catalog_id": "Tr16x4-bronze"}
    response = client.post("/api/v1/evaluate", json=body)
    assert response.status_code == 422
    fields = [d["field"] for d in response.json()["detail"]]
    assert fields == ["application.coupling_inertia_kg_m2"]


def test_the_torque_formulas_name_the_inertias_they_sum() -> None:
    """The formulas table names every inertia the code accelerates: the screw's row the
    coupling's (``segments.screw_side_inertia``), break-away and each segment's torque the
    coupling's and the rotor's too (``drive.breakaway``, ``segments.plus_spin``)."""
    assert "J_coupling" in FORMULAS["torque.inertia_screw_nm"]["formula"]
    for key in ("torque.breakaway_nm", "segments.torque_nm"):
        text = FORMULAS[key]["formula"]
        assert "(J_screw + J_coupling + J_rotor) alpha" in text, key
