"""A vertical ball-screw axis on a library servo, worked by hand (HIWIN BS-08-2-EN-1704-K):
20 kg lifted 300 mm at 250 mm/s and 3 m/s², 1 s dwell at each end, HIWIN R20-10K3-FSC
(ground, preloaded, d0 20 mm, dk 17.32 mm, lead 10 mm, Ca 11,300 N), fixed-simple over
600 mm, Yaskawa SGM7J-01A, a 0.6 N m brake, 5,000 cycles a day for 5 years."""

import math

import pytest
from fastapi.testclient import TestClient

QUERY = {
    "load_n": "0", "moving_mass_kg": "20", "orientation": "vertical", "lead_mm": "10",
    "speed_mm_s": "250", "length_mm": "600", "accel_mm_s2": "3000", "stroke_mm": "300",
    "dwell_s": "1", "cycles_per_day": "5000", "required_life_years": "5",
    "motor": "yaskawa-sgm7j-01a", "brake_torque_nm": "0.6", "catalog_id": "R20-10K3-FSC",
}  # fmt: skip

#: The weight, 20 x 9.80665 = 196.133 N, held at rest through the 10 mm lead: W l / 2 pi
#: = 0.312153 N m. Seed method, forward efficiency at mu 0.01 (tan lambda = 10 / (pi 20)
#: = 0.159155): eta = (1 - 0.01 x 0.159155) / (1 + 0.01 / 0.159155) = 0.939385, 0.293234
#: N m; physics, back-driving at half the static mu 0.003: eta_b = (0.159155 - 0.0015) /
#: (0.159155 x (1 + 0.0015 x 0.159155)) = 0.990341, 0.309139 N m. The larger, 0.309139,
#: times the brake's service factor 1.5: the brake to fit is 0.463709 N m, not 0.309.
HOLD_NM = 196.133 * 0.01 / (2 * math.pi) * 0.990341
BRAKE_TO_FIT_NM = 1.5 * HOLD_NM


def test_the_brake_to_fit_carries_the_service_factor(client: TestClient) -> None:
    """The holding check asks 0.464 N m of the brake; the verdict's watch list, the API's
    brake to fit and the results cell give the same torque, never the 0.309 N m before the
    factor (a 0.318 N m brake, the SGM7J's own, would read as enough and fail the check)."""
    c = client.get("/api/v1/evaluate", params=QUERY).json()["candidate"]
    held = next(k for k in c["checks"] if k["name"] == "holding")
    assert held["value"] == pytest.approx(BRAKE_TO_FIT_NM, rel=1e-4)
    assert c["holding_torque"]["brake_nm"] == pytest.approx(HOLD_NM, rel=1e-4)
    assert c["holding_torque"]["brake_to_fit_nm"] == pytest.approx(BRAKE_TO_FIT_NM, rel=1e-4)
    assert c["hold_margin"] == pytest.approx(0.6 / BRAKE_TO_FIT_NM, rel=1e-4)  # 1.294
    watch = " ".join(c["verdict"]["watch"])
    assert "a brake of at least 0.464 N m holds it power-off" in watch, watch
    page = client.get("/", params={
        "load": "0", "moving_mass_kg": "20", "orientation": "vertical", "lead": "10",
        "speed": "250", "length": "600", "family": "HIWIN-GROUND", "brake_torque": "0.6",
    }).text  # fmt: skip
    assert "brake ≥ 0.464" in page and "brake ≥ 0.309" not in page

