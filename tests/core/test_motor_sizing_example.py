"""A published servo-motor sizing example for a ball-screw axis, reproduced by the core.

Source: Weihong WISE servo drive (WSDV series) user manual, section 3.5.2.1 "Example of
Motor Selection for Ball Screw System", printed pages 25 to 27, read from stored copies:

- p. 25 (first inputs): https://www.easymanua.ls/weihong/wise-wsdv-6r820psb/manual?p=31
- p. 26 (inputs, running mode, steps 3 to 6):
  https://manualshive.com/ru/manual/weihong/wise-wsdv-11020psb/952565?page=32
- p. 27 (steps 7 to 11): https://www.easymanua.ls/weihong/wise-wsdv-2r820psb/manual?p=33

The three pages come from the stored copies of three drive models' manuals of the same
series; they carry the same section and consecutive printed page numbers.

Inputs, as printed:

- mass of part W_A = 10 kg; ball screw length B_L = 0.5 m; diameter B_D = 0.02 m;
  pitch (travel per revolution) B_P = 0.02 m; ball screw efficiency B_eta = 0.9;
  coupling inertia J_C = 10 x 10^-6 kg m^2; movement distance 0.3 m
- running mode: acceleration time t_a = 0.1 s, constant speed time t_b = 0.8 s,
  deceleration time t_d = 0.1 s, cycle time t_c = 2 s
- used in the steps: density 7.9 x 10^3 kg/m^3 (step 3), friction coefficient mu = 0.1,
  g = 9.8 m/s^2 and external force F = 0 (step 9); the preselected 0.2 kW motor's rotor
  J_M = 0.14 x 10^-4 kg m^2 (step 5)

Published results: screw mass W_B = 1.24 kg (step 3; the core has no screw-mass function,
its rod inertia per length gives the screw's inertia directly, so this one is not
compared); load inertia J_L = J_C + J_B + J_A = 1.73 x 10^-4 kg m^2 (step 4);
V_max = 0.3 / 0.9 = 0.334 m/s (step 7); N = 16.7 r/s = 1002 r/min (step 8); constant
torque T_f = 0.035 N m; acceleration torque (J_L + J_M) 2 pi N / t_a + T_f =
0.196 + 0.035 = 0.231 N m; deceleration torque 0.196 - 0.035 = 0.161 N m (step 9);
effective torque T_rms = sqrt((T_a^2 t_a + T_f^2 t_b + T_d^2 t_d) / t_c) = 0.067 N m
(step 11).

The example gives the move as times, the core takes a top speed and an acceleration: the
test converts with the example's own step 7, v = s / (t_a/2 + t_b + t_d/2), and a = v / t_a.
The coupling inertia is a catalog value in the example and is added as given.
"""

import pytest

from app.core import motion
from app.core.formulas import geometry, profile, torque
from app.core.model import Application

# Inputs, as printed (SI)
W_A = 10.0  # kg, mass of part
B_L = 0.5  # m, ball screw length
B_D = 0.02  # m, ball screw diameter
B_P = 0.02  # m, ball screw pitch: travel per revolution
B_ETA = 0.9  # ball screw efficiency
J_C = 10e-6  # kg m^2, coupling inertia
DISTANCE = 0.3  # m, movement distance
T_A, T_B, T_D, T_C = 0.1, 0.8, 0.1, 2.0  # s: accelerate, constant, decelerate, cycle
RHO = 7.9e3  # kg/m^3, step 3
MU, G, F_EXT = 0.1, 9.8, 0.0  # step 9
J_M = 0.14e-4  # kg m^2, rotor of the preselected 0.2 kW motor, step 5

# Published results, as printed
J_L_PUBLISHED = 1.73e-4  # kg m^2
V_MAX_PUBLISHED = 0.334  # m/s
RPM_PUBLISHED = 1002.0  # r/min
T_F_PUBLISHED = 0.035  # N m
T_INERTIA_PUBLISHED = 0.196  # N m, (J_L + J_M) 2 pi N / t_a
T_A_PUBLISHED = 0.231  # N m
T_D_PUBLISHED = 0.161  # N m
T_RMS_PUBLISHED = 0.067  # N m

REL = 0.01

# The example's step 7 turns its times into the top speed; the core takes speed and accel.
V_TOP = DISTANCE / (T_A / 2 + T_B + T_D / 2)
APP = Application(
    load_n=MU * G * W_A + F_EXT,
    speed_m_s=V_TOP,
    length_m=B_L,
    lead_m=B_P,
    accel_m_s2=V_TOP / T_A,
    decel_m_s2=V_TOP / T_D,
    moving_mass_kg=W_A,
    stroke_m=DISTANCE,
    dwell_s=T_C - (T_A + T_B + T_D),
    motor_inertia_kg_m2=J_M,
)


def _load_inertia() -> float:
    """J_L at the motor shaft: the coupling (given) + the screw + the part's mass."""
    j_screw = torque.screw_inertia(torque.solid_rod_inertia_per_length(RHO, B_D), B_L)
    return J_C + j_screw + torque.reflected_mass_inertia(W_A, B_P)


def _constant_torque() -> float:
    return torque.load_torque(APP.load_n, B_P, B_ETA)


def _inertia_torque() -> float:
    """(J_L + J_M) times the screw's angular acceleration."""
    alpha = torque.angular_acceleration(APP.accel_m_s2, B_P)
    return torque.inertia_torque(_load_inertia() + J_M, alpha)


def test_move_profile_is_the_published_running_mode() -> None:
    """Trapezoid of 0.1 s + 0.8 s + 0.1 s over 0.3 m at V_max = 0.334 m/s, 1002 r/min."""
    p = motion.move_profile(APP)
    assert p is not None and p.kind == "trapezoid"
    assert p.peak_speed_m_s == pytest.approx(V_MAX_PUBLISHED, rel=REL)
    assert p.accel_time_s == pytest.approx(T_A, rel=REL)
    assert p.constant_time_s == pytest.approx(T_B, rel=REL)
    assert p.decel_time_s == pytest.approx(T_D, rel=REL)
    assert p.move_time_s + APP.dwell_s == pytest.approx(T_C, rel=REL)
    rpm = geometry.screw_speed_rpm(p.peak_speed_m_s, B_P)
    assert rpm == pytest.approx(RPM_PUBLISHED, rel=REL)


def test_load_inertia() -> None:
    """J_L = J_C + J_B + J_A = 1.73 x 10^-4 kg m^2."""
    assert _load_inertia() == pytest.approx(J_L_PUBLISHED, rel=REL)


def test_constant_torque() -> None:
    """T_f = B_P (mu g W_A + F) / (2 pi B_eta) = 0.035 N m (printed to two figures)."""
    assert _constant_torque() == pytest.approx(T_F_PUBLISHED, rel=REL)


def test_acceleration_torque() -> None:
    """(J_L + J_M) 2 pi N / t_a = 0.196 N m; plus T_f, the acceleration torque 0.231 N m."""
    assert _inertia_torque() == pytest.approx(T_INERTIA_PUBLISHED, rel=REL)
    t_a = torque.total_torque(_inertia_torque(), 0.0, _constant_torque())
    assert t_a == pytest.approx(T_A_PUBLISHED, rel=REL)


def test_deceleration_torque() -> None:
    """Decelerating, the friction helps: 0.196 - 0.035 = 0.161 N m."""
    t_d = torque.total_torque(_inertia_torque(), 0.0, -_constant_torque())
    assert t_d == pytest.approx(T_D_PUBLISHED, rel=REL)


def test_effective_torque() -> None:
    """T_rms over the 2 s cycle, 1 s of it standing still: 0.067 N m."""
    p = motion.move_profile(APP)
    assert p is not None
    t_f = _constant_torque()
    t_a = torque.total_torque(_inertia_torque(), 0.0, t_f)
    t_d = torque.total_torque(_inertia_torque(), 0.0, -t_f)
    durations = [p.accel_time_s, p.constant_time_s, p.decel_time_s, APP.dwell_s]
    assert profile.rms_torque([t_a, t_f, t_d, 0.0], durations) == pytest.approx(
        T_RMS_PUBLISHED, rel=REL
    )
