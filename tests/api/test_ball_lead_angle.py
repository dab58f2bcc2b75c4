"""A ball screw's lead angle is taken on its pitch circle (ball-centre) diameter d0, the
nominal diameter of ISO 3408-1 and of the maker's nut code, not on the mean of the
shaft's outer and core diameters (a sliding thread's rule, which for a ball screw lies
below d0 and so overstates the efficiency).

By hand, HIWIN's thread efficiency eta = tan(l) / tan(l + atan(mu)) (HIWIN GmbH,
Ballscrews & Accessories, BS-08-2-EN-1704-K, sec. 2.1.1) at the rolled family's running
friction mu = 0.01 (atan 0.01 = 0.5729 deg), tan(l) = lead / (pi d0):

    R20-10K3-FSCDIN, d0 = 20 mm: tan l = 10 / (20 pi) = 0.159155, l = 9.0431 deg,
        tan(9.6160 deg) = 0.169425, eta = 0.93939;
        50 N through the thread: 50 x 0.010 / (2 pi x 0.93939) = 0.08471 N m
        (on (19.3 + 16.6) / 2 = 17.95 mm it would be eta 0.94494, 0.08421 N m)
    R40-10K4-FSCDIN, d0 = 40 mm: tan l = 10 / (40 pi) = 0.079577, l = 4.5499 deg,
        tan(5.1228 deg) = 0.089649, eta = 0.88766
        (on (37.8 + 32.8) / 2 = 35.3 mm it would be 0.8994, 1.3 % more)
"""

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import evaluate

AXIS = {"load_n": 50.0, "speed_mm_s": 100.0, "length_mm": 800.0, "accel_mm_s2": 0.0}


@pytest.mark.parametrize(
    ("nut", "d0_mm", "lead_angle_deg", "efficiency"),
    [("R20-10K3-FSCDIN", 20.0, 9.0431, 0.93939), ("R40-10K4-FSCDIN", 40.0, 4.5499, 0.88766)],
)
def test_ball_screw_lead_angle_on_the_pitch_circle(
    client: TestClient, nut: str, d0_mm: float, lead_angle_deg: float, efficiency: float
) -> None:
    screw = evaluate(client, nut, **AXIS)
    assert screw["pitch_diameter_mm"] == pytest.approx(d0_mm)
    assert screw["lead_angle_deg"] == pytest.approx(lead_angle_deg, abs=1e-3)
    assert screw["efficiency"] == pytest.approx(efficiency, rel=1e-4)


def test_load_torque_through_a_ball_thread(client: TestClient) -> None:
    screw = evaluate(client, "R20-10K3-FSCDIN", **AXIS)
    assert screw["torque"]["load_nm"] == pytest.approx(0.08471, rel=1e-3)
