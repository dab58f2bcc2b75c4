"""The guides' friction as an input (``guide_friction``): the same answer as its force,
mu m g, typed as a load against the motion; a bad value refused at the field."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import API, evaluate

#: 20 kg moved 400 mm at 100 mm/s, 2000 cycles a day.
AXIS: dict[str, Any] = {
    "speed_mm_s": 100.0,
    "length_mm": 600.0,
    "moving_mass_kg": 20.0,
    "accel_mm_s2": 2000.0,
    "stroke_mm": 400.0,
    "cycles_per_day": 2000.0,
}


@pytest.mark.parametrize(("screw", "lead_mm"), [("Tr16x4-bronze", 4.0), ("R16-10K3-FSCDIN", 10.0)])
def test_guide_friction_answers_as_its_force_typed_as_a_load(
    client: TestClient, screw: str, lead_mm: float
) -> None:
    # mu m g = 0.05 x 20 kg x 9.80665 m/s^2 = 9.80665 N against the motion, both ways: the
    # nut, its torque, life, heat and energy see that force whichever way it is given
    guided = evaluate(client, screw, load_n=5.0, guide_friction=0.05, lead_mm=lead_mm, **AXIS)
    typed = evaluate(client, screw, load_n=5.0 + 9.80665, lead_mm=lead_mm, **AXIS)
    assert guided["axial_load_n"] == pytest.approx(14.80665, rel=1e-12)
    assert guided == typed
    plain = evaluate(client, screw, load_n=5.0, lead_mm=lead_mm, **AXIS)
    assert plain["torque"]["total_nm"] < guided["torque"]["total_nm"]


@pytest.mark.parametrize("value", [-0.1, 1.5])
def test_a_guide_friction_out_of_range_is_refused_at_its_field(
    client: TestClient, value: float
) -> None:
    query = {"load_n": 5.0, "speed_mm_s": 50.0, "length_mm": 500.0, "guide_friction": value}
    response = client.get(f"{API}/select", params=query)
    assert response.status_code == 422
    assert any("guide_friction" in str(e.get("loc", e)) for e in response.json()["detail"])
