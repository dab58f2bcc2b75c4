"""Further published worked examples run through the core: five of Bhandari's power-screw
examples and THK's ball-screw shaft rules for all four mountings.

Bhandari, Design of Machine Elements, 3rd ed. (Tata McGraw-Hill, 2010), ch. 6 "Power
Screws", the figures as the FOSSEE Scilab textbook companion works them
(github.com/FOSSEE/Scilab-TBC-Uploads, 764/CH6, result6_1.txt, result6_2.txt,
result6_5.txt, result6_6.txt, result6_7.txt). Bhandari takes the mean diameter
d_m = d - 0.5 p, the core diameter d - p for a square thread, and an ISO trapezoidal
thread's friction as mu sec 15 deg.

- Example 6.2: Tr100x12, two starts (lead 24 mm), raising 300 kN, mu 0.15, no collar:
  torque to raise 3378.16 N m, to lower 1030.69 N m, efficiency 33.92 %; the screw
  self-locks (the lowering torque is positive).
- Example 6.5: square thread 80 x 10, single start, 10 kN, mu 0.12 on the thread and on
  a collar of mean radius 30 mm, a 40 mm nut, hand wheel 500 mm across: rim force
  388.91 N, efficiency 16.37 %, bearing pressure on the nut's threads 2.122 N/mm^2.
- Example 6.7: square thread 48 x 8, single start, 500 N at 5 m/min, mu 0.15 on the
  thread and on a collar of mean radius 40 mm: power 0.3473 kW, efficiency 12.00 %.

THK Ball Screw General Catalog, "Permissible Axial Load" (formula 5, P1 = eta_2 d1^4 /
l_a^2 x 10^4 N, 0.5 of Euler's with E = 2.06e5 N/mm^2: eta_2 = 1.3 fixed-free, 5.0
supported-supported, 10.0 fixed-supported, 20.0 fixed-fixed) and "Permissible
Rotational Speed" (formula 7, N1 = lambda_2 d1 / l_b^2 x 10^7 min^-1, 0.8 of the beam's
with gamma = 7.85e-6 kg/mm^3: lambda_2 = 3.4, 9.7, 15.1, 21.9), pp. A15-30 to A15-33
(www.thk.com/jp/en/products/ball_screw/selection/0006/ and 0007/). The same critical
speed factors are reprinted by Engineers Edge ("Critical Speed Ball Screw and Lead Screws
Formulas and Calculator"); MISUMI's allowable axial load example takes m = 10 for
fixed-supported and THK's own high-speed transfer example 20 and 15.1.
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from app.core.evaluate import evaluate
from app.core.formulas import buckling, column_rules, critical_speed, geometry, profile, torque
from app.core.model import Application, ScrewSpec
from app.core.table import CandidateTable
from app.core.units import from_si, to_si

WITHIN = 0.01

#: Carbon steel as the catalog gives it (catalog/common.toml) and THK's own modulus.
STEEL_E, STEEL_RHO, C45_YIELD = 206e9, 7850.0, to_si(310.0, "MPa")
THK_E = to_si(2.06e5, "MPa")


def _thread(
    name: str, major_m: float, pitch_m: float, starts: int, half_angle_deg: float, mu: float
) -> ScrewSpec:
    """Bhandari's screw as a screw of the core's: its core diameter d - p, so that the
    mean (pitch) diameter (d + d_c) / 2 is Bhandari's d - 0.5 p; one friction for running
    and holding, as the book takes it; the nut's flanks H1 = p / 2 on d_m."""
    mean_m = major_m - 0.5 * pitch_m
    return ScrewSpec(
        id=name, series_id="bhandari", series_name="Bhandari, ch. 6", anti_backlash=False,
        coated=False, outer_diameter_m=major_m, root_diameter_m=major_m - pitch_m,
        lead_m=geometry.lead_from_pitch(pitch_m, starts),
        thread_half_angle_rad=math.radians(half_angle_deg), friction_static=mu,
        friction_dynamic=mu, youngs_modulus_pa=STEEL_E, density_kg_m3=STEEL_RHO,
        screw_expansion_per_k=1.2e-5, inertia_kg_m2_per_m=0.0, pitch_m=pitch_m,
        flank_pitch_diameter_m=mean_m, flank_height_m=0.5 * pitch_m,
    )  # fmt: skip


def _thread_torque(screw: ScrewSpec, thrust_n: float) -> float:
    """The core's motor torque to pass ``thrust_n`` through the screw's thread [N m]
    (above 0 driving it, below 0 the load driving it), from its candidate table."""
    t = CandidateTable.build([screw])
    eta, eta_b = float(t.efficiency[0]), float(t.backdrive_efficiency_signed[0])
    return float(profile.thread_torque(thrust_n, screw.lead_m, eta, eta_b))


def test_bhandari_6_2_raising_and_lowering_torques() -> None:
    """Tr100x12, two starts, 300 kN, mu 0.15: tan lambda = 24 / (pi 94) = 0.08127;
    eta = 0.33921 (printed 33.92 %); T_raise = 300e3 x 0.024 / (2 pi 0.33921) = 3378.16
    N m; lowering the load the motor still drives it, F d_m / 2 (mu sec 15 - tan lambda)
    / (1 + mu sec 15 tan lambda) = 1030.69 N m (the core's signed back-drive efficiency,
    -0.8994); the thread self-locks (mu 0.15 >= cos 15 tan lambda = 0.0785)."""
    screw = _thread("Tr100x12-2", 0.100, 0.012, 2, 15.0, 0.15)
    t = CandidateTable.build([screw])
    assert float(t.efficiency[0]) == pytest.approx(0.3392, rel=WITHIN)
    assert _thread_torque(screw, 300e3) == pytest.approx(3378.16, rel=WITHIN)
    assert _thread_torque(screw, -300e3) == pytest.approx(1030.69, rel=WITHIN)
    assert bool(t.self_locking[0])
    assert float(t.backdrive_efficiency[0]) == 0.0


def test_bhandari_6_5_hand_wheel_force_and_nut_pressure() -> None:
    """Square 80 x 10, 10 kN, mu 0.12: the thread's torque 10e3 x 0.010 / (2 pi 0.25995)
    = 61.23 N m (Bhandari's W d_m tan(phi + lambda) / 2, the core's square thread), the
    collar's mu W r_m = 36.0 N m, on a 0.25 m rim arm: 388.91 N; efficiency W l / (2 pi
    T) = 16.37 %. The nut's 40 mm over a 10 mm pitch engages 4 turns of pi 75 x 5 mm^2:
    10 kN over 4712 mm^2 = 2.122 N/mm^2, the core's bearing-pressure check (its demand
    over its capacity at a flat 5 N/mm^2, Bhandari's allowable of example 6.4)."""
    screw = _thread("Sq80x10", 0.080, 0.010, 1, 0.0, 0.12)
    total = _thread_torque(screw, 10e3) + 0.12 * 10e3 * 0.030
    assert total / 0.250 == pytest.approx(388.91, rel=WITHIN)
    assert torque.load_torque(10e3, screw.lead_m, 1.0) / total == pytest.approx(0.1637, rel=WITHIN)
    allowed = to_si(5.0, "MPa")
    nut = replace(screw, nut_length_m=0.040, bearing_pressure_table=((0.0, allowed),))
    check = next(c for c in evaluate(Application(10e3, 0.001, 0.5), nut).checks
                 if c.name == "bearing_pressure")  # fmt: skip
    pressure = check.demand / check.capacity * allowed
    assert from_si(pressure, "MPa") == pytest.approx(2.122, rel=WITHIN)


def test_bhandari_6_7_power_at_the_feed_rate() -> None:
    """Square 48 x 8, 500 N at 5 m/min: 625 rpm; thread 500 x 0.008 / (2 pi 0.27599) =
    2.307 N m and collar 0.15 x 500 x 0.040 = 3.0 N m, 5.307 N m at 625 rpm = 0.3473 kW;
    efficiency 500 x 0.008 / (2 pi 5.307) = 12.00 %."""
    screw = _thread("Sq48x8", 0.048, 0.008, 1, 0.0, 0.15)
    rpm = geometry.screw_speed_rpm(to_si(5000.0 / 60.0, "mm/s"), screw.lead_m)
    assert rpm == pytest.approx(625.0, rel=WITHIN)
    total = _thread_torque(screw, 500.0) + 0.15 * 500.0 * 0.040
    watts = total * rpm * 2.0 * math.pi / 60.0
    assert watts == pytest.approx(347.3, rel=WITHIN)  # printed 0.3473 kW
    assert torque.load_torque(500.0, screw.lead_m, 1.0) / total == pytest.approx(0.1200, rel=WITHIN)


def _collar_nm(mu: float, load_n: float, outer_m: float, inner_m: float) -> float:
    """Bhandari's friction collar under uniform wear, mu W (D_o + D_i) / 4 [N m]: a term
    of his screw jacks the core has no part for (an axis's thrust bearing is a drag)."""
    return mu * load_n * (outer_m + inner_m) / 4.0


def test_bhandari_6_1_an_overhauling_three_start_thread() -> None:
    """Square 50 x 8, three starts (lead 24 mm, d_m 46 mm), 15 kN, mu 0.15 on the thread
    and on a collar of 100 / 65 mm (92.81 N m): to raise 204.644 N m, 409.29 N on a
    500 mm arm; to lower 87.402 N m, the collar's 92.81 less the 5.41 N m the load gives
    back through a thread that overhauls (tan lambda 0.1661 > mu: the core's signed
    back-drive efficiency above 0, the thread's torque below 0). EX6.1, result6_1.txt."""
    screw = _thread("Sq50x8-3", 0.050, 0.008, 3, 0.0, 0.15)
    collar = _collar_nm(0.15, 15e3, 0.100, 0.065)
    raise_nm = _thread_torque(screw, 15e3) + collar
    lower_nm = _thread_torque(screw, -15e3) + collar
    assert raise_nm == pytest.approx(204.644, rel=WITHIN)
    assert raise_nm / 0.500 == pytest.approx(409.288, rel=WITHIN)
    assert lower_nm == pytest.approx(87.4015, rel=WITHIN)
    assert _thread_torque(screw, -15e3) < 0.0
    assert not bool(CandidateTable.build([screw]).self_locking[0])


def test_bhandari_6_6_a_trapezoidal_lead_screws_power() -> None:
    """Tr52 x 8, single start (d_m 48 mm, mu 0.15 as mu sec 15 deg), 2 kN at 30 rpm, and
    a collar of 100 / 60 mm at mu 0.12 (9.6 N m): 0.061838 kW, overall efficiency
    W l / (2 pi T) = 12.937 %. EX6.6, result6_6.txt."""
    screw = _thread("Tr52x8", 0.052, 0.008, 1, 15.0, 0.15)
    total = _thread_torque(screw, 2e3) + _collar_nm(0.12, 2e3, 0.100, 0.060)
    assert total * 30.0 * 2.0 * math.pi / 60.0 == pytest.approx(61.838, rel=WITHIN)
    assert torque.load_torque(2e3, screw.lead_m, 1.0) / total == pytest.approx(0.12937, rel=WITHIN)


#: THK's printed factors, formula 5 (eta_2) and formula 7 (lambda_2), by mounting.
THK_COLUMN = {"fixed-free": 1.3, "simple-simple": 5.0, "fixed-simple": 10.0, "fixed-fixed": 20.0}
THK_SPEED = {"fixed-free": 3.4, "simple-simple": 9.7, "fixed-simple": 15.1, "fixed-fixed": 21.9}
#: A 20 mm root over 1.5 m: slender in every mounting (Euler's range for C45).
ROOT_M, SPAN_M = 0.020, 1.5
ROOT_MM, SPAN_MM = from_si(ROOT_M, "mm"), from_si(SPAN_M, "mm")


def _thk_speed(fixity: str) -> float:
    """THK's permissible speed N1 = lambda_2 d1 / l^2 x 10^7 [rpm] for the shaft (THK's
    constant 10^7 for d1 and l in mm)."""
    return THK_SPEED[fixity] * ROOT_MM / SPAN_MM**2 * 10.0**7


def _thk_column(fixity: str) -> float:
    """THK's permissible axial load P1 = eta_2 d1^4 / l^2 x 10^4 [N] for the shaft (THK's
    constant 10^4 for d1 and l in mm)."""
    return THK_COLUMN[fixity] * ROOT_MM**4 / SPAN_MM**2 * 10.0**4


@pytest.mark.parametrize("fixity", list(THK_SPEED))
def test_thk_factors_are_the_beam_at_thks_factors_of_safety(fixity: str) -> None:
    """THK's factors are the beam's and Euler's with its steel, times 0.8 and 0.5: the
    core's beam and Euler load with E = 2.06e5 N/mm^2 and 7850 kg/m^3 reproduce lambda_2
    (3.44, 9.66, 15.09, 21.89) and eta_2 (1.25, 4.99, 9.98, 19.96) within THK's two and
    three figures; fixed-free THK rounds 3.44 down to 3.4 (1.2 %) but 1.248 up to 1.3
    (4.2 % above its own Euler load)."""
    beam = critical_speed.critical_speed_rpm(ROOT_M, SPAN_M, THK_E, STEEL_RHO, fixity)
    euler = buckling.euler_critical_load(
        THK_E, buckling.second_moment_round(ROOT_M), SPAN_M, fixity
    )
    rounding = 0.015 if fixity == "fixed-free" else WITHIN
    assert critical_speed.allowed_speed_rpm(beam, 0.8) == pytest.approx(
        _thk_speed(fixity), rel=rounding
    )
    column = buckling.allowed_buckling_load(euler, 0.5)
    if fixity == "fixed-free":
        assert column < _thk_column(fixity)
        assert _thk_column(fixity) / column == pytest.approx(1.3 / 1.248, rel=WITHIN / 10)
    else:
        assert column == pytest.approx(_thk_column(fixity), rel=WITHIN)


@pytest.mark.parametrize("hiwin_rated", [False, True], ids=["no-rule", "hiwin-rule"])
@pytest.mark.parametrize("fixity", list(THK_SPEED))
def test_a_ball_screw_is_never_rated_above_thks_shaft_rules(fixity: str, hiwin_rated: bool) -> None:
    """The app's ball screw at its defaults (0.8 of its critical speed, 0.5 of its column)
    is never rated above THK's P1 and N1 for the same shaft: held to the lowest published
    rules (Rockford's and Thomson's C_s 1.47 and E 199.7 GPa, HIWIN's mounting factor
    0.147 fixed-free) it is 0.94-1.00 of THK's speed and 0.93-0.97 of its column; rated by
    HIWIN's rule (its own screws), 0.94-1.00 of both."""
    app = Application(1.0, 0.1, SPAN_M)
    rated = critical_speed.rated_critical_speed_rpm(
        ROOT_M, SPAN_M, STEEL_E, STEEL_RHO, fixity, True, hiwin_rated=hiwin_rated
    )
    speed = critical_speed.allowed_speed_rpm(float(rated), app.critical_speed_safety_factor)
    own = buckling.column_critical_load(STEEL_E, ROOT_M, SPAN_M, fixity, C45_YIELD)
    modulus = column_rules.makers_column_modulus(STEEL_E, True, hiwin_rated)
    column = column_rules.rated_column_load(
        own, buckling.second_moment_round(ROOT_M), SPAN_M, fixity, modulus
    )
    allowed = column_rules.rated_allowed_load(
        column, app.buckling_safety_factor, buckling.root_area(ROOT_M),
        column_rules.makers_allowed_stress(True, hiwin_rated),
    )  # fmt: skip
    assert speed <= _thk_speed(fixity)
    assert float(allowed) <= _thk_column(fixity)
    assert speed / _thk_speed(fixity) > 0.93
    assert float(np.asarray(allowed)) / _thk_column(fixity) > 0.92
