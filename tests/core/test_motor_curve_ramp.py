"""A ramp runs through every speed from standstill to its top speed: the motor curve
check holds it against the lowest usable torque over that range, so a published curve
that dips at a resonance below the top speed limits the move, by hand."""

import math

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import ScrewSpec
from tests.core.conftest import light_app

#: Changzhou Songyang SY42STH47-1684B, half step at 24 V, as the motor library holds its
#: published pull-out points (rpm, N m): 0.28 N m at 270 rpm, below the 0.29 N m at 360.
SY42STH47 = (
    (0.0, 0.305), (30.0, 0.305), (75.0, 0.3), (105.0, 0.3), (135.0, 0.31), (180.0, 0.3),
    (270.0, 0.28), (360.0, 0.29), (450.0, 0.27), (600.0, 0.25),
)  # fmt: skip


def _load_needing(s: ScrewSpec, need_nm: float) -> float:
    """The load [N] at which ``s`` accelerating at 0.5 m/s^2 on a 0.5 m screw needs
    ``need_nm``: T = F L / (2 pi eta) + J alpha + drag, the Acme thread's
    eta = (cos a - mu tan(lambda)) / (cos a + mu / tan(lambda)), tan(lambda) = L / (pi d_p),
    d_p = (OD + d_r) / 2, alpha = 2 pi a / L, J = inertia per m x 0.5 m."""
    d_p = (s.outer_diameter_m + s.root_diameter_m) / 2
    tan_l = s.lead_m / (math.pi * d_p)
    cos_a, mu = math.cos(s.thread_half_angle_rad), s.friction_dynamic
    eta = (cos_a - mu * tan_l) / (cos_a + mu / tan_l)
    alpha = 2 * math.pi * 0.5 / s.lead_m
    spin = s.inertia_kg_m2_per_m * 0.5 * alpha
    return (need_nm - spin - s.drag_torque_max_nm) * 2 * math.pi * eta / s.lead_m


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
    need = 0.190
    load = _load_needing(s, need)
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


def test_without_a_stroke_the_ramp_is_still_held_to_the_dip(b8000_l10: ScrewSpec) -> None:
    """The axis of the dip test with no stroke to time the move: its segments are the
    same (their torques do not depend on the stroke), so the accelerate segment, 0.190 N m,
    is still held to the 0.28 / 1.5 N m at 270 rpm that it passes through on the way to
    360 rpm, and fails; it was read at the top speed alone (0.1933 N m) and passed."""
    app = light_app(
        load_n=_load_needing(b8000_l10, 0.190), moving_mass_kg=0.0, speed_m_s=0.06,
        accel_m_s2=0.5, length_m=0.5, step_angle_deg=1.8, motor_curve=SY42STH47,
    )  # fmt: skip
    check = next(c for c in evaluate(app, b8000_l10).checks if c.name == "motor_curve")
    assert check.value == pytest.approx(0.190, rel=1e-6)
    assert check.limit == pytest.approx(0.28 / 1.5)
    assert check.message.values["rpm"].value == pytest.approx(270.0)
    assert not check.passed


def test_without_a_stroke_the_decelerate_segment_is_held_to_the_curve(catalog: Catalog) -> None:
    """A 50 kg carriage on R16-10K3-FSCDIN stopped at 10 m/s^2 (accelerated at 0.5): its
    decelerate segment, where m d = 500 N drives the screw and the motor brakes the
    screw's and the rotor's spin, needs far more than the accelerate one. Without a
    stroke the check judges every moving segment at the top speed as it does with one,
    so it gives the same worst segment and torque as the same axis with a 400 mm stroke;
    it judged the accelerating torque alone (0.0727 N m) and passed a 1 N m motor. By
    hand the decelerate segment needs at least the spin, J alpha = (J_screw + 5e-5) x
    2 pi x 10 / 0.01, with J_screw the screw's inertia over its 0.6 m, and the thrust
    that drives the screw through the thread."""
    screw = catalog.by_id["R16-10K3-FSCDIN"]
    axis = {
        "load_n": 5.0, "moving_mass_kg": 50.0, "speed_m_s": 0.2, "length_m": 0.6,
        "accel_m_s2": 0.5, "decel_m_s2": 10.0, "motor_curve": ((0.0, 1.0), (2000.0, 1.0)),
        "motor_inertia_kg_m2": 5e-5,
    }  # fmt: skip
    bare = next(c for c in evaluate(light_app(**axis), screw).checks if c.name == "motor_curve")
    timed = evaluate(light_app(**axis, stroke_m=0.4), screw)
    check = next(c for c in timed.checks if c.name == "motor_curve")
    assert bare.value == pytest.approx(check.value, rel=1e-12)
    spin = (screw.inertia_kg_m2_per_m * 0.6 + 5e-5) * 2 * math.pi * 10.0 / screw.lead_m
    # the 495 N that drives the screw (500 N of m d less the 5 N load) reaches the motor
    # at a ball thread's back-driven efficiency, above 0.9 here (HIWIN: mu 0.003-0.01)
    thread = 495.0 * screw.lead_m * 0.9 / (2 * math.pi)
    assert bare.value > spin + thread > 1.0
    assert not bare.passed
    assert "decelerate out" in str(bare.message)
