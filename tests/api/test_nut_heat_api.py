"""The nut's heat through the API, with the arithmetic by hand: the thread's friction at
the thrust it carries in every moving segment (m a on the ramps too) whether the cycle is
typed as the scalar inputs or as moves.

Formulas: the thread's friction power F v (1 / eta - 1) (Shigley sec. 8-2), with the
forward efficiency (cos a - mu tan l) / (cos a + mu / tan l), tan l = lead / (pi d_2)
(Shigley eq. 8-4, a = 15 deg); the nut's rise
P / (2 sqrt(h pi d_3 k pi d_3^2 / 4) + h pi (2 d) L), h = 10 W/(m^2 K) (Incropera
sec. 3.6, the screw as an infinite fin both ways, and the nut's surface)."""

import math

import pytest
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

#: C45 steel's conductivity [W/(m K)] (catalog, iso-trapezoidal materials).
C45_K = 50.7


def _efficiency(lead_m: float, pitch_diameter_m: float, mu: float) -> float:
    cos_a, tan_l = math.cos(math.radians(15.0)), lead_m / (math.pi * pitch_diameter_m)
    return (cos_a - mu * tan_l) / (cos_a + mu / tan_l)


def _conductance(root_m: float, outer_m: float, nut_length_m: float) -> float:
    fin = math.sqrt(10.0 * math.pi * root_m * C45_K * math.pi * root_m**2 / 4.0)
    return 2.0 * fin + 10.0 * math.pi * 2.0 * outer_m * nut_length_m


#: A horizontal 50 kg carriage, no load, 50 mm out and back at 200 mm/s, 5 m/s^2 ramps,
#: no dwell: as the scalar inputs, and as the same two moves.
SCALAR = {
    "load_n": 0, "moving_mass_kg": 50, "speed_mm_s": 200, "accel_mm_s2": 5000,
    "stroke_mm": 50, "dwell_s": 0, "length_mm": 400, "cycles_per_day": 10000,
}  # fmt: skip
MOVES = {
    "load_n": 0, "speed_mm_s": 200, "length_mm": 400, "cycles_per_day": 10000,
    "moves": "50:200:5000:5000:0:50:0:auto;-50:200:5000:5000:0:50:0:auto",
}  # fmt: skip


@pytest.mark.parametrize("axis", [SCALAR, MOVES], ids=["scalar-inputs", "moves"])
def test_the_ramps_heat_a_bronze_nut_however_the_cycle_is_typed(
    client: TestClient, axis: dict[str, object]
) -> None:
    """Tr20x4-bronze (d_2 18 mm, d_3 15.5 mm, mu 0.13, a 40 mm nut, rated to 150 C): each
    of the cycle's four ramps takes 0.04 s over 4 mm at |m a| = 250 N, the cycle 0.58 s;
    the thread turns 4 x 250 x 0.004 (1 / eta - 1) / 0.58 = 13.31 W into heat, and the
    nut rises 71.29 K. The scalar inputs once reported 0 W and 0 K."""
    candidate = evaluate(client, "Tr20x4-bronze", **axis)
    eta = _efficiency(0.004, 0.018, 0.13)
    power_w = 4 * 250.0 * 0.004 * (1.0 / eta - 1.0) / 0.58
    rise_k = power_w / _conductance(0.0155, 0.020, 0.040)
    heat = check(candidate, "nut_heat")
    assert candidate["efficiency"] == pytest.approx(eta, rel=1e-12)
    assert heat["value"] == pytest.approx(rise_k, rel=1e-9)
    assert heat["message"].startswith(f"Friction turns {power_w:.2f} W into heat: ")
    assert (round(power_w, 2), round(rise_k, 2)) == (13.31, 71.29)
