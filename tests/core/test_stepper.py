"""The stepper pull-out model (app.core.formulas.stepper) and the library's curves."""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.catalog.motors import MAX_STEPPER_RPM
from app.contract.inputs import _curve_points
from app.core.formulas import stepper
from tests.motor_library import MOTORS


def test_farnell_corner_speed() -> None:
    """Farnell, Stepper motor calculator: max speed = V / (2 L I spr) rev/s. 24 V, 2 mH,
    1.5 A, 200 steps a turn: 24 / (2 x 0.002 x 1.5 x 200) = 20 rev/s = 1200 rpm."""
    assert stepper.corner_speed_rpm(24.0, 1.5, 0.0, 0.002, 1.8) == pytest.approx(1200.0)


def test_the_winding_resistance_takes_its_share_of_the_supply() -> None:
    """Jones: the current rises at (V - i R) / L. 24 V, 2 A through 1.4 ohm leaves 21.2 V:
    the corner falls in that ratio, from 600 to 530 rpm (3 mH, 200 steps)."""
    bare = stepper.corner_speed_rpm(24.0, 2.0, 0.0, 0.003, 1.8)
    loaded = stepper.corner_speed_rpm(24.0, 2.0, 1.4, 0.003, 1.8)
    assert bare == pytest.approx(600.0)
    assert loaded == pytest.approx(600.0 * 21.2 / 24.0)


def test_a_finer_step_halves_the_corner() -> None:
    """A 0.9 deg motor makes 400 steps a turn: each turn takes twice the reversals."""
    full = stepper.corner_speed_rpm(24.0, 1.0, 1.0, 0.002, 1.8)
    half = stepper.corner_speed_rpm(24.0, 1.0, 1.0, 0.002, 0.9)
    assert half == pytest.approx(full / 2)


@given(rpm=st.floats(1.0, 6000.0), corner=st.floats(10.0, 3000.0))
def test_above_the_corner_the_power_is_constant(rpm: float, corner: float) -> None:
    """Above the corner T n = T_h n_c (constant power); below it, the holding torque."""
    torque = stepper.pull_out_torque(rpm, 0.5, corner)
    if rpm <= corner:
        assert torque == 0.5
    else:
        assert torque * rpm == pytest.approx(0.5 * corner)


@pytest.mark.parametrize("motor_id", sorted(m.id for m in MOTORS.values() if m.kind == "stepper"))
def test_every_library_curve_is_a_valid_motor_curve(motor_id: str) -> None:
    """Each library motor draws a curve the motor_curve input accepts: from its holding
    torque at standstill to the model's last speed, rpm ascending, torque falling."""
    motor = MOTORS[motor_id]
    curve = motor.curve()
    assert _curve_points(list(curve)) == list(curve)
    assert curve[0] == (0.0, motor.value("holding_torque_nm"))
    assert curve[-1][0] == MAX_STEPPER_RPM
    torques = [t for _, t in curve]
    assert torques == sorted(torques, reverse=True)


def test_the_17hs19_curve_at_24_v() -> None:
    """17HS19-2004S1 (0.59 N m, 2 A, 1.4 ohm, 3 mH) on 24 V: corner 530 rpm; at
    1060 rpm half the holding torque, 0.295 N m."""
    motor = MOTORS["17hs19-2004s1"]
    assert motor.corner_rpm() == pytest.approx(530.0)
    assert stepper.pull_out_torque(1060.0, 0.59, motor.corner_rpm()) == pytest.approx(0.295)


@pytest.mark.parametrize("motor_id", sorted(m.id for m in MOTORS.values() if m.kind == "servo"))
def test_every_library_servo_draws_a_valid_peak_envelope(motor_id: str) -> None:
    """A servo's curve is its peak envelope: the peak torque at standstill, the torque at
    its top speed last, accepted by the motor_curve input, never rising."""
    motor = MOTORS[motor_id]
    curve = motor.curve()
    assert _curve_points(list(curve)) == list(curve)
    assert curve[0] == (0.0, motor.value("peak_torque_nm"))
    assert curve[-1] == (motor.value("max_rpm"), motor.value("top_speed_torque_nm"))
    torques = [t for _, t in curve]
    assert torques == sorted(torques, reverse=True)
