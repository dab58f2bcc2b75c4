"""More published worked examples, set up with their own inputs and run through the core.

THK Ball Screw General Catalog, "Examples of Selecting a Ball Screw", Vertical Conveyance
System (the example after the High-speed Transfer Equipment one of
``tests/report/test_thk_example.py``, same catalog section; the figures as transcribed from
those pages in a public repository's reference tests, the PDF itself not at hand). Printed
selection conditions: table m1 = 40 kg, work m2 = 10 kg, stroke 600 mm, top speed 0.3 m/s,
acceleration and deceleration times 0.2 s, guide surface resistance f = 20 N, direct drive,
motor rotor inertia 5e-5 kg m^2; screw BLK1510-5.6 (shaft 15 mm, lead 10 mm, 800 mm long,
shaft inertia 3.9e-4 kg cm^2/mm, efficiency 0.9); g = 9.8 m/s^2. Printed results:
Fa1..Fa6 = 585, 510, 435, 395, 470, 545 N; T1 = 900 N mm (up, uniform), T2 = 830 N mm
(down, uniform); J = 1.58e-4 kg m^2; alpha = 942 rad/s^2; T3 = 200 N mm; Tk1 = 1100,
Tg1 = 700, Tk2 = 630, Tg2 = 1030 N mm; at rest with the work removed Ts = 658 N mm; over
up 0.2/1.8/0.2 s, down 0.2/1.8/0.2 s and a 7.6 s stop, Trms = 743 N mm.

Mott, Machine Elements in Mechanical Design, 4th ed. (Pearson, 2004), Example Problem 17-1,
p. 703: an Acme 1 1/2-4 screw, pitch diameter 1.3429 in, lead 0.250 in:
lead angle 3.39 deg, tan 0.0592.
"""

import math

import numpy as np
import pytest

from app.core import segments
from app.core.formulas import efficiency, geometry, profile, torque
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Move, ScrewSpec
from app.core.quantities import operating_point
from app.core.table import CandidateTable
from app.core.units import to_si
from app.report.thk_example import square_thread
from tests.core.conftest import IN

WITHIN = 0.01

#: THK's vertical example as printed; g as THK takes it.
G_THK = 9.8
TABLE_KG, WORK_KG = 40.0, 10.0
MASS_KG = TABLE_KG + WORK_KG
STROKE_M, SPEED_M_S, RAMP_S, STOP_S = 0.6, 0.3, 0.2, 7.6
GUIDE_N = 20.0
LEAD_M, SHAFT_D_M, LENGTH_M, ETA = 0.010, 0.015, 0.8, 0.9
#: THK's shaft inertia 3.9e-4 kg cm^2 (0.39 g cm^2) per mm, in kg m^2 per m.
SHAFT_INERTIA = to_si(0.39, "g cm²") / to_si(1.0, "mm")
J_MOTOR = 5e-5
ACCEL = SPEED_M_S / RAMP_S


def _screw() -> ScrewSpec:
    """BLK1510-5.6 on its 15 mm shaft, as ``app.report.thk_example`` takes its horizontal
    example's screw (``square_thread``: THK's efficiency 0.9, its shaft inertia)."""
    return square_thread("BLK1510-5.6", SHAFT_D_M, LEAD_M, SHAFT_INERTIA)


def _own_model() -> Application:
    """The example as a user types it: a vertical axis, the 50 kg moving up 600 mm and
    back down, the guide's 20 N against the motion, the 7.6 s stop after the down move.
    The app's own model carries the weight and m a through the thread."""
    up = Move(STROKE_M, SPEED_M_S, ACCEL, ACCEL, 0.0, MASS_KG, GUIDE_N, "opposes")
    down = Move(-STROKE_M, SPEED_M_S, ACCEL, ACCEL, STOP_S, MASS_KG, GUIDE_N, "opposes")
    return Application(
        GUIDE_N, SPEED_M_S, LENGTH_M, moves=(up, down), orientation="vertical",
        motor_inertia_kg_m2=J_MOTOR,
    )  # fmt: skip


def _thk_convention() -> Application:
    """The example as THK works its torques: the thread carries the uniform-motion loads
    m g + f up and m g - f down (Fa2, Fa5, with THK's g), one way as a weight does; the 50
    kg enters as the inertia m (lead / 2 pi)^2 at the motor."""
    weight = MASS_KG * G_THK
    up = Move(STROKE_M, SPEED_M_S, ACCEL, ACCEL, 0.0, 0.0, weight + GUIDE_N, "fixed")
    down = Move(-STROKE_M, SPEED_M_S, ACCEL, ACCEL, STOP_S, 0.0, weight - GUIDE_N, "fixed")
    reflected = torque.reflected_mass_inertia(MASS_KG, LEAD_M)
    return Application(
        weight + GUIDE_N, SPEED_M_S, LENGTH_M, moves=(up, down), orientation="vertical",
        motor_inertia_kg_m2=J_MOTOR + reflected,
    )  # fmt: skip


def _moving_torques(app: Application) -> list[tuple[float, float]]:
    """Each moving segment's thrust in THK's fixed frame (above 0: the nut pushes up) [N]
    and its motor torque [N m], up accelerate, constant, decelerate, then down."""
    t = CandidateTable.build([_screw()])
    parts = [s for s in segments.segments(app, t, np.zeros(1)) if s.name != "dwell"]
    senses = [1.0] * 3 + [-1.0] * 3
    return [
        (float(s.thrust_n[0]) * v, float(s.torque_nm[0]))
        for s, v in zip(parts, senses, strict=True)
    ]


def test_thk_vertical_axial_loads() -> None:
    """Fa1..Fa6 = m g + f + m a, m g + f, m g + f - m a up; m g - f - m a, m g - f,
    m g - f + m a down (m a = 50 x 1.5 = 75 N): 585, 510, 435, 395, 470, 545 N. The app's
    own model, with g = 9.80665, is 0.33 N above each."""
    thrusts = [f for f, _ in _moving_torques(_own_model())]
    assert thrusts == pytest.approx([585.0, 510.0, 435.0, 395.0, 470.0, 545.0], rel=WITHIN)


def test_thk_vertical_inertia_and_angular_acceleration() -> None:
    """J = 50 (0.01 / 2 pi)^2 + 3.9e-4 kg cm^2/mm x 800 mm = 1.267e-4 + 3.12e-5 =
    1.58e-4 kg m^2; alpha = 2 pi x 0.3 / (0.01 x 0.2) = 942 rad/s^2."""
    shaft = torque.screw_inertia(SHAFT_INERTIA, LENGTH_M)
    assert shaft == pytest.approx(3.12e-5, rel=WITHIN)
    j = shaft + torque.reflected_mass_inertia(MASS_KG, LEAD_M)
    assert j == pytest.approx(1.58e-4, rel=WITHIN)
    assert torque.angular_acceleration(ACCEL, LEAD_M) == pytest.approx(942.0, rel=WITHIN)


def _t3() -> float:
    """THK's T3: (J + Jm) alpha, the shaft, the mass and the rotor spun up [N m]."""
    j = torque.screw_inertia(SHAFT_INERTIA, LENGTH_M) + torque.reflected_mass_inertia(
        MASS_KG, LEAD_M
    )
    return torque.inertia_torque(j + J_MOTOR, torque.angular_acceleration(ACCEL, LEAD_M))


def test_thk_vertical_upward_torques() -> None:
    """Up, THK's way: T1 = 510 x 10 / (2 pi 0.9) = 901.9 N mm (printed 900); T3 =
    2.08e-4 x 942.5 = 196 N mm (printed 200, from its rounded J and alpha); Tk1 = T1 +
    T3 = 1098 (printed 1100), Tg1 = T1 - T3 = 706 (printed 700)."""
    up = [tq for _, tq in _moving_torques(_thk_convention())[:3]]
    assert up == pytest.approx([1.100, 0.900, 0.700], rel=WITHIN)
    assert _t3() == pytest.approx(0.200, rel=0.025)


def test_thk_vertical_peak_torque_by_the_apps_own_model() -> None:
    """The app's own model passes the 75 N of m a through the thread at 0.9 and spins
    only the shaft and rotor as inertia: Tk1 = 585.3 x 10 / (2 pi 0.9) + 8.12e-5 x 942.5
    = 1112 N mm, the cycle's peak, 1.2 % above THK's 1098 (printed 1100): it errs safe by
    m a l (1 / eta - 1) / (2 pi) = 13 N mm."""
    t = CandidateTable.build([_screw()])
    peak = float(operating_point(_own_model(), t).motor.motor_peak_nm[0])
    thrust = MASS_KG * (STANDARD_GRAVITY_M_S2 + ACCEL) + GUIDE_N
    spin = torque.screw_inertia(SHAFT_INERTIA, LENGTH_M) + J_MOTOR
    alpha = torque.angular_acceleration(ACCEL, LEAD_M)
    own = torque.load_torque(thrust, LEAD_M, ETA) + torque.inertia_torque(spin, alpha)
    assert peak == pytest.approx(own, rel=1e-9)
    assert peak == pytest.approx(1.112, rel=WITHIN)
    thk = _moving_torques(_thk_convention())[0][1]
    assert peak > thk
    assert peak - thk == pytest.approx(
        torque.load_torque(MASS_KG * ACCEL, LEAD_M, ETA) * (1.0 - ETA)
        + torque.load_torque(MASS_KG * (STANDARD_GRAVITY_M_S2 - G_THK), LEAD_M, ETA),
        rel=1e-6,
    )


def test_thk_vertical_downward_torques_convert_from_thks_convention() -> None:
    """Down, the load m g - f = 470 N drives the screw. THK sizes on |F| l / (2 pi eta):
    T2 = 470 x 10 / (2 pi 0.9) = 831 N mm (printed 830), Tk2 = T2 - T3 = 635 (printed
    630), Tg2 = T2 + T3 = 1027 (printed 1030). The app passes a load that drives the
    screw through the back-drive efficiency eta' (the motor brakes it: F l eta' / (2 pi),
    negative), so its torques are THK's T2 times eta eta', less or more T3, signed."""
    t2 = torque.load_torque(MASS_KG * G_THK - GUIDE_N, LEAD_M, ETA)
    t3 = _t3()
    assert t2 == pytest.approx(0.830, rel=WITHIN)
    assert t2 - t3 == pytest.approx(0.630, rel=WITHIN)
    assert t2 + t3 == pytest.approx(1.030, rel=WITHIN)
    tan_l = geometry.tan_lead_angle(LEAD_M, SHAFT_D_M)
    mu = efficiency.friction_for_efficiency(tan_l, ETA, 1.0)
    eta_b = efficiency.backdrive_efficiency(tan_l, mu, 1.0)
    braking = t2 * ETA * eta_b
    down = [tq for _, tq in _moving_torques(_thk_convention())[3:]]
    assert down == pytest.approx([-(braking - t3), -braking, -(braking + t3)], rel=1e-9)


def test_thk_vertical_holding_and_rms_torques() -> None:
    """At rest with the work removed THK holds m1 g - f = 372 N as it drives it: Ts =
    372 x 10 / (2 pi 0.9) = 658 N mm; Trms over its seven phases, sqrt((1.1^2 0.2 + 0.9^2
    1.8 + 0.7^2 0.2 + 0.63^2 0.2 + 0.83^2 1.8 + 1.03^2 0.2 + 0.658^2 7.6) / 12) = 743 N mm,
    each torque as the core works it in THK's convention."""
    ts = torque.load_torque(TABLE_KG * G_THK - GUIDE_N, LEAD_M, ETA)
    assert ts == pytest.approx(0.658, rel=WITHIN)
    up = [tq for _, tq in _moving_torques(_thk_convention())[:3]]
    t2, t3 = torque.load_torque(MASS_KG * G_THK - GUIDE_N, LEAD_M, ETA), _t3()
    torques = [*up, t2 - t3, t2, t2 + t3, ts]
    times = [0.2, 1.8, 0.2, 0.2, 1.8, 0.2, 7.6]
    assert profile.rms_torque(torques, times) == pytest.approx(0.743, rel=WITHIN)


def test_mott_acme_lead_angle() -> None:
    """Mott, Example Problem 17-1: lambda = atan(0.250 / (pi 1.3429)) = 3.39 deg,
    tan lambda = 0.0592."""
    lead, d_p = 0.250 * IN, 1.3429 * IN
    assert math.degrees(geometry.lead_angle(lead, d_p)) == pytest.approx(3.39, abs=0.005)
    assert geometry.tan_lead_angle(lead, d_p) == pytest.approx(0.0592, abs=1e-4)
