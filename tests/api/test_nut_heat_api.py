"""The nut's heat through the API, with the arithmetic by hand: the thread's friction at
the thrust it carries in every moving segment (m a on the ramps too) whether the cycle is
typed as the scalar inputs or as moves, and an anti-backlash nut's drag.

Formulas: the thread's friction power F v (1 / eta - 1) (Shigley sec. 8-2), with the
forward efficiency (cos a - mu tan l) / (cos a + mu / tan l), tan l = lead / (pi d_2)
(Shigley eq. 8-4, a = 15 deg); a drag torque's power T_drag 2 pi v / lead; the nut's rise
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


def _conductance(
    root_m: float, outer_m: float, nut_length_m: float, screw_m: float, stroke_m: float
) -> float:
    """The screw a fin each side of the nut, its far end insulated (Incropera Table 3.4,
    case B: sqrt(h P k A) tanh(m L), m = sqrt(4 h / (k d_3))), the nut at the end of a
    stroke centred on the screw, plus the nut's surface h pi (2 d) L."""
    endless = math.sqrt(10.0 * math.pi * root_m * C45_K * math.pi * root_m**2 / 4.0)
    m = math.sqrt(4.0 * 10.0 / (C45_K * root_m))
    near = (screw_m - stroke_m - nut_length_m) / 2.0
    far = screw_m - nut_length_m - near
    fins = endless * (math.tanh(m * near) + math.tanh(m * far))
    return fins + 10.0 * math.pi * 2.0 * outer_m * nut_length_m


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
    """Tr20x4-bronze oiled (d_2 18 mm, d_3 15.5 mm, mu 0.13, a 40 mm nut, rated to 150 C): each
    of the cycle's four ramps takes 0.04 s over 4 mm at |m a| = 250 N, the cycle 0.58 s;
    the thread turns 4 x 250 x 0.004 (1 / eta - 1) / 0.58 = 13.31 W into heat, and the
    nut rises 80.04 K (fins of 155 and 205 mm each side of the nut at the end of the
    stroke). The scalar inputs once reported 0 W and 0 K."""
    candidate = evaluate(client, "Tr20x4-bronze", **axis, lubrication="oiled")
    eta = _efficiency(0.004, 0.018, 0.13)
    power_w = 4 * 250.0 * 0.004 * (1.0 / eta - 1.0) / 0.58
    rise_k = power_w / _conductance(0.0155, 0.020, 0.040, 0.4, 0.05)
    heat = check(candidate, "nut_heat")
    assert candidate["efficiency"] == pytest.approx(eta, rel=1e-12)
    assert heat["value"] == pytest.approx(rise_k, rel=1e-9)
    assert heat["message"].startswith(f"Friction turns {power_w:.2f} W into heat: ")
    assert (round(power_w, 2), round(rise_k, 2)) == (13.31, 80.04)


def test_an_anti_backlash_nuts_drag_heats_the_nut(client: TestClient) -> None:
    """A screw of one's own: Tr10x4(P2) in C45 (d_3 7.5 mm, d_2 = d - P/2 = 9 mm), an
    acetal nut (rated to 100 C) 20 mm long, mu 0.25, preloaded to a drag of 0.03 N m;
    20 N against the motion, 400 mm out and back at 100 mm/s (1 m/s^2 ramps). The cycle
    takes 2 (0.1 + 3.9 + 0.1) = 8.2 s over 0.8 m, a mean 0.09756 m/s: the thread turns
    20 x 0.09756 (1 / eta - 1) = 3.78 W into heat, the drag
    0.03 x 2 pi x 0.09756 / 0.004 = 4.597 W (the drag loss of the cycle's energy over its
    time). The nut rises 160.3 K (fins of 90 and 490 mm each side of it at the end of
    the stroke), above the 80 K of room: rejected."""
    screw = {
        "outer_diameter_mm": 10, "root_diameter_mm": 7.5, "lead_mm": 4, "pitch_mm": 2,
        "thread_half_angle_deg": 15, "friction_dynamic": 0.25, "friction_static": 0.3,
        "material": "c45-steel", "nut_material": "acetal", "drag_torque_nm": 0.03,
    }  # fmt: skip
    axis = {
        "load_n": 20, "speed_mm_s": 100, "length_mm": 600, "stroke_mm": 400,
        "cycles_per_day": 5000, "nut_length_mm": 20,
    }  # fmt: skip
    candidate = evaluate(client, screw, **axis)
    mean_m_s = 0.8 / 8.2
    thread_w = 20.0 * mean_m_s * (1.0 / _efficiency(0.004, 0.009, 0.25) - 1.0)
    drag_w = 0.03 * 2.0 * math.pi * mean_m_s / 0.004
    assert drag_w == pytest.approx(candidate["cycle_drag_loss_j"] / 8.2, rel=1e-9)
    heat = check(candidate, "nut_heat")
    rise_k = (thread_w + drag_w) / _conductance(0.0075, 0.010, 0.020, 0.6, 0.4)
    assert heat["value"] == pytest.approx(rise_k, rel=1e-9)
    assert (round(thread_w, 2), round(drag_w, 3), round(rise_k, 1)) == (3.78, 4.597, 160.3)
    assert heat["limit"] == pytest.approx(80.0) and heat["passed"] is False
    assert heat["message"].startswith(
        f"Friction turns {thread_w:.3g} W into heat and the nut's drag {drag_w:.4g} W more: "
    )
    assert "a nut of less drag" in heat["fix"]
    # the rise is linear in the cycle's mean speed: 80 K of room at 0.09756 x 80 / 160.3
    # m/s, less the 5 % margin
    mean_mm_s = 0.95 * mean_m_s * 80.0 / rise_k * 1e3
    assert f"dwells included) of at most {mean_mm_s:.4g} mm/s" in heat["fix"]
    assert "drag_torque" in heat["sources"]


@pytest.mark.parametrize(
    ("query", "said"),
    [
        # no stroke: the sliding nuts that pass were never judged for heat
        ({"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}, True),
        # a stroke: the heat check ran
        (
            {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10, "stroke_mm": 300},
            False,
        ),
        # only a ball screw passes (20 kN at 1.5 m/s): no sliding nut to heat
        ({"load_n": 20000, "speed_mm_s": 1500, "length_mm": 500}, False),
    ],
)
def test_the_summary_says_when_nut_heat_was_not_checked(
    client: TestClient, query: dict[str, float], said: bool
) -> None:
    message = client.get("/api/v1/select", params=query).json()["summary"]["message"]
    assert ("Nut heat is not checked" in message) is said
    if said:
        assert message.index("candidates pass.") < message.index("Nut heat is not checked")
