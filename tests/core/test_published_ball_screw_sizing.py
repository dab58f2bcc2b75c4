"""Two more makers' worked examples, set up with their own inputs and run through the core.

Rockford Ball Screw, "How To Size A Ball Screw" (update 2018,
rockfordballscrew.com/download/RBS_HowToSizeaBallScrew_Update2018.pdf; the opening steps
as stored at scribd.com/document/620202141, the later steps' figures as transcribed in a
public repository's reference tests, the PDF itself not at hand). Transfer table,
horizontal, dovetail ways f = 0.20, 2500 lb, stroke 38 in, 20 cycles/h, 16 h/day, 250
days/year, 5 years. Printed: step 1, required life 30,400,000 in of travel; step 2,
thrust 2500 x 0.20 = 500 lb. The screw chosen: root 0.84 in, lead 0.250 in, 41.347 in
between bearings, fixed-simple. Step 6: critical speed with end fixity factor 1.47 (its
4.76e6 d / L^2 constant) and factor of safety 0.8, as a travel rate: 687 in/min. Step 9:
column load with end fixity factor 2.00 (its 14.03e6 d^4 / L^2 constant) and 0.8: 6,537
lb. Step 10: drive torque 0.177 x 500 x 0.250 at 90 % efficiency, printed 23 in lb.

Omron, "Technical Guide for Servo Motor Selection" (CSM_Servo Selection_TG_E_3_1), sample
calculation, printed pp. 12-13 (figures as transcribed in the same repository): a ball
screw driven directly, table and work 5 kg, friction 0.1, lead 10 mm, screw 20 mm
across and 3 kg, no reducer (efficiency 1); 300 mm/s over a 360 mm stroke in 1.4 s with
0.2 s ramps and a 0.2 s stop (1.6 s a cycle); motor R88M-U20030, rotor 1.23e-5 kg m^2.
Printed: J_B = 1.5e-4 kg m^2, J_L = 1.63e-4 kg m^2, T_L = 7.8e-3 N m, N = 1800 rpm,
T_A = 0.165 N m, T_1 = 0.173 N m, T_rms = 0.0828 N m.
"""

import math
from typing import Any

import pytest

from app.core.formulas import buckling, column_rules, critical_speed, geometry, life, torque
from app.core.model import Application, Move, ScrewSpec
from app.core.quantities import Quantities, operating_point
from app.core.table import CandidateTable
from app.core.units import from_si, to_si
from app.report import maker_examples as maker
from tests.core.conftest import STEEL_E, STEEL_RHO

WITHIN = 0.01

ROOT_M, LEAD_M, SPAN_M = maker.ROOT_M, maker.LEAD_M, maker.SPAN_M
THRUST_N = to_si(2500 * 0.20, "lbf")
#: Rockford's factor of safety on the critical speed and on the column load.
ROCKFORD_FS = maker.FACTOR
#: Rockford's column constant 14.03e6 [lb in^2 / in^4] is pi^3 E / 64: its steel's E.
ROCKFORD_E_PA = to_si(14.03e6 * 64.0 / math.pi**3, "psi")


def test_rockford_required_life_and_thrust() -> None:
    """Step 1: 38 in a stroke, out and back, 20 cycles an hour, 16 hours a day, 250 days a
    year for 5 years = 30,400,000 in of travel (``life.travel_per_year`` takes a 365-day
    year: the test scales it to Rockford's 250). Step 2: 2500 lb x 0.20 = 500 lb."""
    per_year = life.travel_per_year(to_si(38.0, "in"), 20.0 * 16.0) * 250.0 / life.DAYS_PER_YEAR
    assert from_si(per_year * 5.0, "in") == pytest.approx(30.4e6, rel=WITHIN)
    assert from_si(THRUST_N, "lbf") == pytest.approx(500.0, rel=WITHIN)


def test_rockford_critical_speed_with_the_leadscrew_makers_factor() -> None:
    """Step 6: 1.47 x 4.76e6 x 0.84 / 41.347^2 = 3438 rpm, x 0.8 x 0.250 in = 687 in/min.
    The core's beam for carbon steel (simple-simple 2335 rpm here) times the end fixity
    factor C_s = 1.47 the leadscrew makers print (``rated_critical_speed_rpm`` of a
    leadscrew) gives 3432 rpm and 686.5 in/min."""
    rated = critical_speed.rated_critical_speed_rpm(
        ROOT_M, SPAN_M, STEEL_E, STEEL_RHO, "fixed-simple", False
    )
    allowed = critical_speed.allowed_speed_rpm(float(rated), ROCKFORD_FS)
    assert maker.in_per_min(allowed) == pytest.approx(687.0, rel=WITHIN)


def test_rockford_critical_speed_of_a_ball_screw() -> None:
    """The same screw rated as the core rates a ball screw whose family names no maker's
    rule: held to the lowest published one, Rockford's own (C_s 1.47), 687 in/min. Rated
    by HIWIN's rule (a family that declares it, as the built-in HIWIN ones do) it would be
    HIWIN's mounting factor, 0.692 / 0.446 = 1.55 times simple-simple: 3628 rpm, 725.5
    in/min at 0.8, 5.6 % more, which HIWIN allows its own screws and Rockford does not."""
    assert maker.rockford_critical_speed() == pytest.approx(687.0, rel=WITHIN)
    args = (ROOT_M, SPAN_M, STEEL_E, STEEL_RHO, "fixed-simple", True)
    hiwin = critical_speed.rated_critical_speed_rpm(*args, hiwin_rated=True)
    assert float(hiwin) == pytest.approx(3628.0, rel=WITHIN)
    assert maker.rockford_critical_speed(hiwin_rated=True) == pytest.approx(725.5, rel=WITHIN)


def test_rockford_column_load() -> None:
    """Step 9: 2.00 x 14.03e6 x 0.84^4 / 41.347^2 x 0.8 = 6,537 lb. Rockford's constant is
    pi^3 E / 64 with E = 28.96e6 psi (199.7 GPa): with that E the core's Euler load (k = 2
    for fixed-simple, slenderness 139, past Johnson's range) times 0.8 is 6,537 lb. The
    core's carbon steel, 206 GPa, gives a critical load 3.2 % higher (8,431 against 8,172
    lb), but the core allows half of it by default (0.5, 4,215 lb): 36 % below what
    Rockford allows."""
    fcr = buckling.column_critical_load(ROCKFORD_E_PA, ROOT_M, SPAN_M, "fixed-simple", 310e6)
    assert from_si(ROCKFORD_FS * fcr, "lbf") == pytest.approx(6537.0, rel=WITHIN)
    own = buckling.column_critical_load(STEEL_E, ROOT_M, SPAN_M, "fixed-simple", 310e6)
    allowed = buckling.allowed_buckling_load(own, Application(1.0, 0.1, 1.0).buckling_safety_factor)
    assert from_si(allowed, "lbf") < 6537.0


def test_rockford_column_load_of_a_ball_screw() -> None:
    """The same column rated as the core rates a ball screw whose family names no maker's
    rule: at most the lowest published rule, Rockford's own 14.03e6 x 2.00 x 0.84^4 /
    41.347^2 = 8,172 lb, so at Rockford's factor of safety 0.8 it is step 9's 6,537 lb.
    The core's carbon steel alone (206 GPa) gave 8,431 lb, 3.2 % above Rockford's. Rated
    by HIWIN's rule (F 3.25, a family that declares it) the column keeps the core's 8,431
    lb: HIWIN's F_k, Euler with E = 210.1 GPa, is higher still."""
    i = buckling.second_moment_round(ROOT_M)
    own = buckling.column_critical_load(STEEL_E, ROOT_M, SPAN_M, "fixed-simple", 310e6)
    assert maker.rockford_column_lbf() == pytest.approx(6537.0, rel=WITHIN)
    by_hiwin = column_rules.makers_column_modulus(math.inf, True, True)
    assert float(column_rules.rated_column_load(own, i, SPAN_M, "fixed-simple", by_hiwin)) == own
    assert from_si(own, "lbf") == pytest.approx(8431.0, rel=WITHIN)


def test_rockford_drive_torque() -> None:
    """Step 10: T = F l / (2 pi eta) = 500 x 0.250 / (2 pi 0.9) = 22.10 in lb. Rockford
    writes the factor 1 / (2 pi 0.9) as 0.177 and shows 0.177 x 500 x 0.250, which is
    22.1; it prints 23 in lb, 4 % above its own product. The core matches the product."""
    t = torque.load_torque(THRUST_N, LEAD_M, 0.9)
    assert from_si(t, "lb in") == pytest.approx(0.177 * 500 * 0.250, rel=WITHIN)
    assert from_si(t, "lb in") < 23.0


def test_omron_inertias_speed_and_load_torque() -> None:
    """J_B = 3 x 0.02^2 / 8 = 1.5e-4 kg m^2; J_L = J_B + 5 (0.01 / 2 pi)^2 = 1.627e-4
    (printed 1.63e-4); N = 0.3 / 0.01 x 60 = 1800 rpm; T_L = 0.1 x 5 x 9.8 x 0.01 /
    (2 pi) = 7.80e-3 N m at efficiency 1."""
    assert maker.omron_screw_inertia() == pytest.approx(1.5e-4, rel=WITHIN)
    assert maker.omron_load_inertia() == pytest.approx(1.63e-4, rel=WITHIN)
    assert geometry.screw_speed_rpm(maker.SPEED, maker.OMRON_LEAD_M) == pytest.approx(1800.0)
    assert maker.omron_load_torque() == pytest.approx(7.8e-3, rel=WITHIN)


def test_omron_acceleration_peak_and_rms_torques() -> None:
    """T_A = (J_M + J_L) 2 pi N / (60 t_A) = 1.750e-4 x 942.5 = 0.1649 N m (printed 0.165);
    T_1 = T_A + T_L = 0.1727 (0.173); over 0.2 s at T_1, 1.0 s at T_L, 0.2 s at T_A - T_L
    and the 0.2 s stop, T_rms = 0.0828 N m."""
    assert maker.omron_acceleration_torque() == pytest.approx(0.165, rel=WITHIN)
    assert maker.omron_peak_torque() == pytest.approx(0.173, rel=WITHIN)
    assert maker.omron_rms_torque() == pytest.approx(0.0828, rel=WITHIN)


def test_omron_cycle_through_the_operating_point() -> None:
    """The sample as a user types it: 5 kg out 360 mm and back at 300 mm/s with 0.2 s
    ramps and the 0.2 s stop after each, the guide's mu m g opposing the motion. At
    efficiency 1 the app's own model (m a through the thread) is Omron's (m as inertia),
    so the cycle's peak is T_1 = 0.173 N m and its RMS 0.0828 N m (both halves alike)."""
    motor = _omron_cycle().motor
    assert float(motor.motor_peak_nm[0]) == pytest.approx(0.173, rel=WITHIN)
    assert float(motor.motor_rms_nm[0]) == pytest.approx(0.0828, rel=WITHIN)


def _omron_screw() -> ScrewSpec:
    """Omron's ball screw as a screw of the core's: a square thread without friction
    (efficiency 1), 20 mm across, lead 10 mm, Omron's inertia."""
    return ScrewSpec(
        id="omron-ball-screw", series_id="example", series_name="example",
        anti_backlash=False, coated=False, outer_diameter_m=maker.SCREW_D_M,
        root_diameter_m=maker.SCREW_D_M, lead_m=maker.OMRON_LEAD_M, thread_half_angle_rad=0.0,
        friction_static=0.0, friction_dynamic=0.0, youngs_modulus_pa=maker.STEEL_E,
        density_kg_m3=maker.OMRON_RHO, screw_expansion_per_k=1.2e-5,
        inertia_kg_m2_per_m=torque.solid_rod_inertia_per_length(maker.OMRON_RHO, maker.SCREW_D_M),
    )  # fmt: skip


def _omron_cycle() -> Quantities[Any]:
    """The sample as a user types it: 5 kg out 360 mm and back at 300 mm/s, 0.2 s ramps
    and the 0.2 s stop after each, the guide's mu m g opposing the motion."""
    m = maker
    accel, friction = m.SPEED / m.RAMP_S, m.MU * m.MASS_KG * m.G
    out = Move(m.STROKE_M, m.SPEED, accel, accel, m.STOP_S, m.MASS_KG, friction, "opposes")
    back = Move(-m.STROKE_M, m.SPEED, accel, accel, m.STOP_S, m.MASS_KG, friction, "opposes")
    app = Application(
        friction, m.SPEED, m.SCREW_L_M, moves=(out, back), motor_inertia_kg_m2=m.J_MOTOR
    )
    return operating_point(app, CandidateTable.build([_omron_screw()]))
