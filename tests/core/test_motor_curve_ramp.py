"""A ramp runs through every speed from standstill to its top speed: the motor curve
check holds it against the lowest usable torque over that range, so a published curve
that dips at a resonance below the top speed limits the move, by hand."""

import math

import pytest

from app.core.evaluate import evaluate
from app.core.model import ScrewSpec
from tests.core.conftest import light_app

#: Changzhou Songyang SY42STH47-1684B, half step at 24 V, as the motor library holds its
#: published pull-out points (rpm, N m): 0.28 N m at 270 rpm, below the 0.29 N m at 360.
SY42STH47 = (
    (0.0, 0.305), (30.0, 0.305), (75.0, 0.3), (105.0, 0.3), (135.0, 0.31), (180.0, 0.3),
    (270.0, 0.28), (360.0, 0.29), (450.0, 0.27), (600.0, 0.25),
)  # fmt: skip


def test_an_acceleration_through_a_dip_of_the_curve_is_held_to_the_dip(
    b8000_l10: ScrewSpec,
) -> None:
    """B8000-L10 (10 mm lead), no moving mass, 60 mm/s: 360 rpm at the top. With the
    stepper margin 1.5 the motor gives 0.29 / 1.5 = 0.19333 N m at 360 rpm but only
    0.28 / 1.5 = 0.18667 N m at 270 rpm, which the accelerate segment passes through.

    Hand arithmetic: d_p = (OD + d_r) / 2, tan(lambda) = L / (pi d_p), Acme thread
    eta = (cos a - mu tan(lambda)) / (cos a + mu / tan(lambda)) at mu = 0.15 (uncoated);
    alpha = 2 pi a / L = 2 pi x 0.5 / 0.01 = 314.16 rad/s^2, J = inertia per m x 0.5 m.
    The load F is chosen so that the accelerate segment needs T = F L / (2 pi eta) +
    J alpha = 0.190 N m: within the 0.1933 N m at 360 rpm, over the 0.1867 N m at 270 rpm
    (102 % of it), so the motor stalls on the way up and the check fails there."""
    s = b8000_l10
    d_p = (s.outer_diameter_m + s.root_diameter_m) / 2
    tan_l = s.lead_m / (math.pi * d_p)
    cos_a, mu = math.cos(s.thread_half_angle_rad), s.friction_dynamic
    eta = (cos_a - mu * tan_l) / (cos_a + mu / tan_l)
    alpha = 2 * math.pi * 0.5 / s.lead_m
    spin = s.inertia_kg_m2_per_m * 0.5 * alpha
    need = 0.190
    load = (need - spin - s.drag_torque_max_nm) * 2 * math.pi * eta / s.lead_m
    app = light_app(
        load_n=load, moving_mass_kg=0.0, speed_m_s=0.06, accel_m_s2=0.5, stroke_m=0.3,
        length_m=0.5, step_angle_deg=1.8, motor_curve=SY42STH47,
    )  # fmt: skip
    ev = evaluate(app, s)
    assert ev.motion is not None
    accelerate = next(x for x in ev.motion.segments if x.name == "accelerate")
    assert accelerate.rpm == pytest.approx(360.0)
    assert accelerate.torque_nm == pytest.approx(need, rel=1e-6)
    # held against the dip at 270 rpm, not the 0.1933 N m at its top speed
    assert accelerate.curve_nm == pytest.approx(0.28 / 1.5)
    check = next(c for c in ev.checks if c.name == "motor_curve")
    assert check.limit == pytest.approx(0.28 / 1.5)
    assert check.utilization == pytest.approx(need / (0.28 / 1.5), rel=1e-6)
    assert not check.passed
    assert check.message.values["rpm"].value == pytest.approx(270.0)
    # the constant segment runs at 360 rpm alone: its own point of the curve
    constant = next(x for x in ev.motion.segments if x.name == "constant")
    assert constant.curve_nm == pytest.approx(0.29 / 1.5)


def test_a_curve_that_only_falls_is_read_at_the_top_speed(b8000_l10: ScrewSpec) -> None:
    """On a curve that falls with speed the lowest point of a ramp is its top speed: the
    check reads 0.29 / 1.5 N m at 360 rpm as before (the curve cut at 360 rpm)."""
    falling = ((0.0, 0.4), (360.0, 0.29), (600.0, 0.25))
    app = light_app(
        load_n=50.0, moving_mass_kg=0.0, speed_m_s=0.06, accel_m_s2=0.5, stroke_m=0.3,
        length_m=0.5, step_angle_deg=1.8, motor_curve=falling,
    )  # fmt: skip
    check = next(c for c in evaluate(app, b8000_l10).checks if c.name == "motor_curve")
    assert check.limit == pytest.approx(0.29 / 1.5)
    assert check.message.values["rpm"].value == pytest.approx(360.0)
