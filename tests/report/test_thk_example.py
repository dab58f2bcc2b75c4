"""THK's whole ball-screw selection example through the app's own core: THK Ball Screw
General Catalog, "Examples of Selecting a Ball Screw", High-speed Transfer Equipment
(Horizontal Use), printed pp. A-744 to A-747 (a distributor's copy:
https://bondy.dk/wp-content/uploads/THK-spindler.pdf; the figures as transcribed from those
pages in a public repository's reference tests).

Printed: Fa1..Fa6 = 550, 17, -516, -550, -17, 516 N; Fm1 = Fm2 = 225 N; L = 4.1e9 rev
(Ca 5.4 kN, f_w 1.5); P1 = 20 x 17.5^4 / 1100^2 x 10^4 = 15,500 N; N1 = 15.1 x 17.5 /
1100^2 x 10^7 = 2180 min^-1; J = 3.39e-3 kg m^2; T1 = 120 N mm; T2 = 4.61 N m;
Tk = 4730 N mm; Tg = -4490 N mm; Trms = 1305 N mm."""

import math

import pytest

from app.report import thk_example as thk

WITHIN = 0.01


def test_the_six_phase_loads_and_travels_match_thk() -> None:
    """m a = 80 x 1 / 0.15 = 533.3 N: Fa1 = 17 + 533.3 = 550.3, Fa3 = 17 - 533.3 =
    -516.3; the ramps travel 1 x 0.15 / 2 = 75 mm, the uniform motion 850 mm."""
    loads = thk.phases()
    published = [550.0, 17.0, -516.0, -550.0, -17.0, 516.0]
    assert [f for f, _ in loads] == pytest.approx(published, rel=WITHIN)
    assert [d for _, d in loads] == pytest.approx([0.075, 0.85, 0.075] * 2)


def test_the_mean_load_one_direction_is_thks_and_the_apps_own_errs_safe() -> None:
    """F_m1 = ((550.3^3 x 75 + 17^3 x 850 + 516.3^3 x 75) / 2000)^(1/3) = 225.2 N
    (printed 225). With every phase on one flank the sum doubles: 225.2 x 2^(1/3) =
    283.7 N, so the app's own life is (225.2 / 283.7)^3 = 1/2 of THK's."""
    one = thk.mean_load_one_direction()
    assert one == pytest.approx(225.0, rel=WITHIN)
    both = thk.mean_load_both_flanks()
    assert both == pytest.approx(one * 2 ** (1 / 3), rel=1e-9)
    assert both > one


def test_life_buckling_and_speed_match_thk() -> None:
    """L = (5400 / (1.5 x 225.2))^3 x 10^6 = 4.09e9 rev (printed 4.1e9); P1 = 0.5 x 4
    pi^2 x 206e9 x (pi 0.0175^4 / 64) / 1.1^2 = 15,472 N (printed 15,500, THK's
    eta_2 = 20 rounds 19.96); N1 = 0.8 x n_c(fixed-supported) = 2182 rpm (printed
    2180)."""
    assert thk.life_revolutions() == pytest.approx(4.1e9, rel=WITHIN)
    assert thk.buckling_load_n() == pytest.approx(15500.0, rel=WITHIN)
    assert thk.critical_speed_rpm() == pytest.approx(2180.0, rel=WITHIN)


def test_the_motor_torques_match_thk() -> None:
    """J = 80 (0.04 / 2 pi)^2 + 1.23e-4 x 1.2 = 3.242e-3 + 1.476e-4 = 3.390e-3;
    alpha = 2 pi x 1500 / 60 / 0.15 = 1047.2 rad/s^2 (printed 1050); T2 = (3.390e-3 +
    1e-3) x 1047.2 = 4.597 N m; T1 = 17 x 0.04 / (2 pi 0.9) = 0.1203 N m; Tk = 4.717,
    Tg = -4.477; Trms = sqrt((4.717^2 x 0.15 + 0.1203^2 x 0.85 + 4.477^2 x 0.15) / 3.75)
    = 1.302 N m."""
    assert thk.load_inertia_kg_m2() == pytest.approx(3.39e-3, rel=WITHIN)
    t1 = thk.segment_torque_nm("constant")
    tk = thk.segment_torque_nm("accelerate")
    tg = thk.segment_torque_nm("decelerate")
    assert t1 == pytest.approx(0.120, rel=WITHIN)
    assert tk - t1 == pytest.approx(4.61, rel=WITHIN)
    assert tk == pytest.approx(4.73, rel=WITHIN)
    assert tg == pytest.approx(-4.49, rel=WITHIN)
    q = thk.cycle()
    assert float(q.motor.motor_peak_nm[0]) == pytest.approx(tk)
    by_hand = math.sqrt((tk**2 * 0.15 + t1**2 * 0.85 + tg**2 * 0.15) / 3.75)
    assert float(q.motor.motor_rms_nm[0]) == pytest.approx(by_hand, rel=1e-9)
    assert by_hand == pytest.approx(1.305, rel=WITHIN)


def test_the_apps_own_model_carries_the_mass_through_the_thread() -> None:
    """Without THK's simplification the 533 N of m a passes through the 0.9 efficiency:
    the app's peak is above THK's by about (1 / 0.9 - 1) of the load's share."""
    own = float(thk.cycle(mass_as_inertia=False).motor.motor_peak_nm[0])
    assert own > thk.segment_torque_nm("accelerate") * 1.05
