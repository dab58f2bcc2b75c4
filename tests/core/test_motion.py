"""The move profile, the torque of each segment, the RMS torque and the motor checks,
against arithmetic done by hand."""

import math
from dataclasses import replace

import pytest

from app.contract.units import render
from app.core import motion
from app.core.evaluate import evaluate
from app.core.model import STANDARD_GRAVITY_M_S2, Application, ScrewSpec
from tests.core.conftest import light_app


def test_trapezoid_times_and_distances_by_hand() -> None:
    """Stroke 100 mm at 200 mm/s, a = 1 m/s^2, d = 2 m/s^2, dwell 0.5 s: ramps of 0.2 s
    (20 mm) and 0.1 s (10 mm); 70 mm at 200 mm/s take 0.35 s; move 0.65 s, cycle 2.3 s."""
    app = light_app(stroke_m=0.1, speed_m_s=0.2, accel_m_s2=1.0, decel_m_s2=2.0, dwell_s=0.5)
    p = motion.move_profile(app)
    assert p is not None and p.kind == "trapezoid"
    assert (p.accel_time_s, p.decel_time_s) == pytest.approx((0.2, 0.1))
    assert p.constant_time_s == pytest.approx(0.35)
    assert p.move_time_s == pytest.approx(0.65)
    assert p.cycle_time_s == pytest.approx(2.3)
    travelled = 0.5 * 0.2 * (p.accel_time_s + p.decel_time_s) + 0.2 * p.constant_time_s
    assert travelled == pytest.approx(0.1)


def test_triangle_peak_below_the_top_speed() -> None:
    """Stroke 10 mm, a = d = 1 m/s^2: v_p = sqrt(2 x 0.01 / 2) = 0.1 m/s < 0.2 m/s; each
    ramp 0.1 s and 5 mm; no constant segment."""
    app = light_app(stroke_m=0.01, speed_m_s=0.2, accel_m_s2=1.0)
    p = motion.move_profile(app)
    assert p is not None and p.kind == "triangle"
    assert p.peak_speed_m_s == pytest.approx(0.1)
    assert (p.accel_time_s, p.constant_time_s, p.decel_time_s) == pytest.approx((0.1, 0.0, 0.1))


def test_no_stroke_no_profile(b8000_l10: ScrewSpec) -> None:
    assert motion.move_profile(light_app()) is None
    assert evaluate(light_app(), b8000_l10).motion is None


def test_segment_torques_and_rms_by_hand(b8000_l10: ScrewSpec) -> None:
    """Horizontal, 50 N, 5 kg, 10 mm lead, no drag: constant T = F L / (2 pi eta);
    accelerating adds m a through the thread and J alpha of screw and rotor; the RMS is
    sqrt(sum T^2 t / sum t) over both moves and dwells."""
    app = light_app(
        stroke_m=0.1, speed_m_s=0.2, accel_m_s2=1.0, moving_mass_kg=5.0, dwell_s=0.5,
        motor_inertia_kg_m2=2e-5,
    )  # fmt: skip
    ev = evaluate(app, b8000_l10)
    assert ev.motion is not None
    lead, eta = b8000_l10.lead_m, ev.efficiency
    j = b8000_l10.inertia_kg_m2_per_m * app.length_m + 2e-5
    alpha = 2 * math.pi * 1.0 / lead
    run = 50.0 * lead / (2 * math.pi * eta)
    accel = 55.0 * lead / (2 * math.pi * eta) + j * alpha
    seg = {(s.name, s.direction): s for s in ev.motion.segments}
    assert seg["constant", "out"].torque_nm == pytest.approx(run + b8000_l10.drag_torque_max_nm)
    assert seg["accelerate", "out"].torque_nm == pytest.approx(accel + b8000_l10.drag_torque_max_nm)
    assert seg["constant", "out"].rpm == pytest.approx(0.2 * 60 / lead)
    heat = sum(s.torque_nm**2 * s.duration_s for s in ev.motion.segments)
    # a = d = 1 m/s^2: ramps 0.2 s, constant 0.3 s; cycle 2 x (0.7 + 0.5) = 2.4 s
    assert ev.motion.rms_nm == pytest.approx(math.sqrt(heat / 2.4))
    assert ev.motion.peak_nm == pytest.approx(max(abs(s.torque_nm) for s in ev.motion.segments))


def test_descending_load_drives_through_the_back_drive_efficiency(b8000_l10: ScrewSpec) -> None:
    """Vertical, 10 kg, constant speed down: the weight drives, T = -W L eta_b / (2 pi)."""
    app = light_app(load_n=0.0, orientation="vertical", moving_mass_kg=10.0, stroke_m=0.2)
    ev = evaluate(app, b8000_l10)
    assert ev.motion is not None and ev.backdrive_efficiency_running > 0
    down = next(s for s in ev.motion.segments if (s.name, s.direction) == ("constant", "down"))
    weight = 10.0 * STANDARD_GRAVITY_M_S2
    expected = -weight * b8000_l10.lead_m * ev.backdrive_efficiency_running / (2 * math.pi)
    assert down.torque_nm == pytest.approx(expected + b8000_l10.drag_torque_max_nm)


def _curve_app(torque_at_top_nm: float) -> Application:
    return light_app(
        stroke_m=0.2, speed_m_s=0.1, accel_m_s2=5.0, moving_mass_kg=20.0,
        motor_curve=((0.0, 1.0), (1200.0, torque_at_top_nm)),
    )  # fmt: skip


def test_a_curve_that_passes_and_one_that_fails_at_the_acceleration_only(
    b8000_l10: ScrewSpec,
) -> None:
    """At 600 rpm the accelerate segment needs more than the constant one; a curve between
    the two fails the accelerate segment alone, and the fix names it."""
    base = evaluate(_curve_app(1.0), b8000_l10)
    assert base.motion is not None
    seg = {(s.name, s.direction): s.torque_nm for s in base.motion.segments}
    need_acc, need_run = seg["accelerate", "out"], seg["constant", "out"]
    assert need_acc > need_run
    assert {c.name: c.passed for c in base.checks}["motor_curve"]
    between = (need_acc + need_run) / 2
    # curve linear from 1 N m at 0 to T at 1200 rpm: at 600 rpm it gives (1 + T) / 2
    failing = evaluate(_curve_app(2 * between - 1.0), b8000_l10)
    check = next(c for c in failing.checks if c.name == "motor_curve")
    assert not check.passed and check.limit == pytest.approx(between)
    assert check.message.values["segment"] == "accelerate out"
    assert check.fix is not None and "accel" in check.fix.values
    limits = check.input_limits
    assert limits is not None
    fitted = replace(_curve_app(2 * between - 1.0), accel_m_s2=limits["accel_m_s2"])
    assert {c.name: c.passed for c in evaluate(fitted, b8000_l10).checks}["motor_curve"]
    # the fix's own figure keeps the torque 5 % inside the curve, as its note promises
    fixed = replace(fitted, accel_m_s2=check.fix.values["accel"].value)
    applied = next(c for c in evaluate(fixed, b8000_l10).checks if c.name == "motor_curve")
    assert applied.utilization is not None and applied.utilization <= 1.0 / 1.05 + 1e-9


def test_the_motor_curve_names_the_top_speed_at_which_every_segment_fits(
    b8000_l10: ScrewSpec,
) -> None:
    """A curve falling in a straight line from 1 N m at rest to nothing at 1200 rpm gives
    T(n) = 1 - n / 1200. The segments' torques do not change with the speed, so the move
    fits up to n* = 1200 (1 - SF T_max) rpm, T_max the largest segment torque: the check
    offers that top speed (an acceleration fits no more: the constant segment fails too)
    and the move passes just below it, not just above."""
    app = _curve_app(0.0)
    app = replace(app, motor_curve=((0.0, 1.0), (1200.0, 0.0)), speed_m_s=0.2)
    ev = evaluate(app, b8000_l10)
    assert ev.motion is not None
    need = max(abs(s.torque_nm) for s in ev.motion.segments) * app.torque_safety_factor
    top_rpm = 1200.0 * (1.0 - need)
    expected = top_rpm * b8000_l10.lead_m / 60.0
    check = next(c for c in ev.checks if c.name == "motor_curve")
    assert not check.passed and check.input_limits is not None
    assert check.input_limits["speed_m_s"] == pytest.approx(expected, rel=1e-9)
    assert expected < app.speed_m_s
    # the fix names the speed where the torque is 5 % inside the curve, 1200 (1 - 1.05 SF
    # T_max) rpm: applied, the check passes with that margin
    assert check.fix is not None and "a top speed of at most {speed}" in check.fix.template
    fix_speed = check.fix.values["speed"].value
    assert fix_speed == pytest.approx(1200.0 * (1.0 - 1.05 * need) * b8000_l10.lead_m / 60.0)
    fixed = evaluate(replace(app, speed_m_s=fix_speed), b8000_l10)
    utilization = {c.name: c.utilization for c in fixed.checks}["motor_curve"]
    assert utilization is not None and utilization <= 1.0 / 1.05 + 1e-9
    for share, passes in ((0.999, True), (1.01, False)):
        slower = evaluate(replace(app, speed_m_s=expected * share), b8000_l10)
        assert {c.name: c.passed for c in slower.checks}["motor_curve"] is passes


def test_no_top_speed_is_offered_where_the_curve_is_short_at_rest(b8000_l10: ScrewSpec) -> None:
    """A curve below the segments' torque at every speed: no slower move fits it."""
    app = replace(_curve_app(0.0), motor_curve=((0.0, 0.01), (1200.0, 0.0)))
    check = next(c for c in evaluate(app, b8000_l10).checks if c.name == "motor_curve")
    assert not check.passed
    assert "speed_m_s" not in (check.input_limits or {})
    assert check.fix is not None and "speed" not in render(check.fix)
