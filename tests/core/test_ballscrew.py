"""Ball screws in the core: their formulas (app.core.formulas.ballscrew) against published
worked examples, their checks (ball_life, ball_static, ball_speed), the leadscrew checks
that do not apply to them, and one ranking of both kinds."""

import math
from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core.evaluate import evaluate
from app.core.formulas import ballscrew
from app.core.model import Application
from app.core.selection import select
from app.core.table import CandidateTable
from tests.core.conftest import light_app

#: Checks of a sliding nut, which a ball nut does not have.
LEADSCREW_ONLY = {
    "pv",
    "bearing_pressure",
    "max_sliding_speed",
    "nut_heat",
    "life",
    "wear_life",
    "design_load",
}


def test_misumi_life_calculation_example() -> None:
    """MISUMI Economy Series e-catalog 2025, Selection of Ball Screws 3, p. 1678, 6-1 Life
    Calculation Example: BSS1520, C = 4400 N, P_m = 250 N, N_m = 2118 rpm, f_w = 1.2 ->
    L_h = 10^6 / (60 x 2118) x (4400 / (250 x 1.2))^3 = 24824 h."""
    hours = ballscrew.rated_life_revolutions(4400.0, 1.2, 250.0) / (60.0 * 2118.0)
    assert hours == pytest.approx(24824.0, rel=0.01)


def test_mitcalc_required_dynamic_load_example() -> None:
    """MITCalc Ball screws, preliminary design (scribd 'Ball Screw Design & Calculations'):
    F_m 1000 N, n_m 2400 rpm, f_w 1.2, L_h 20,000 h -> Ca_req 17073.1 N; its DN check
    32 mm x 2400 rpm = 76,800."""
    ca = ballscrew.required_dynamic_load(1.2, 1000.0, 20_000 * 60 * 2400.0)
    assert ca == pytest.approx(17073.1, rel=1e-4)
    assert ballscrew.dn_value(0.032, 2400.0) == 76_800.0
    # the rated life at exactly that rating is the life asked
    assert ballscrew.rated_life_revolutions(ca, 1.2, 1000.0) == pytest.approx(20_000 * 60 * 2400.0)


def test_the_cubic_mean_load_weighs_each_segment_by_its_travel() -> None:
    """HIWIN BS-08-2-EN-1704-K F 3.9 with n_i t_i as travel: a constant load is its own
    mean; a short heavy segment dominates a long light one more than its share."""
    assert ballscrew.cubic_mean_load([700.0, -700.0], [0.3, 0.3]) == pytest.approx(700.0)
    mixed = ballscrew.cubic_mean_load([1000.0, 100.0], [0.1, 0.9])
    assert mixed == pytest.approx((1000.0**3 * 0.1 + 100.0**3 * 0.9) ** (1 / 3))
    assert mixed > 1000.0 * 0.1 + 100.0 * 0.9
    assert ballscrew.cubic_mean_load([500.0], [0.0]) == 0.0


def test_a_ball_screws_efficiency_is_in_hiwins_range(catalog: Catalog) -> None:
    """The thread-efficiency formula with a 0 flank angle and mu = 0.01 (HIWIN Fig. 2.1's
    highest curve) gives 0.85 to 0.95 forward (HIWIN F 3.15: eta_1 0.85 to 0.95), the lead
    angle on the pitch circle d0, the nominal diameter (ISO 3408-1): R16-05T3, d0 = 16 mm,
    tan(lambda) = 5 / (pi 16) = 0.099472,
    eta = 0.099472 (1 - 0.01 x 0.099472) / (0.099472 + 0.01) = 0.9077."""
    t = CandidateTable.build([catalog.by_id["R16-05T3-FSIDIN"], catalog.by_id["R40-10K4-FSCDIN"]])
    tan_l = 5.0 / (math.pi * 16.0)
    assert t.efficiency[0] == pytest.approx(tan_l * (1 - 0.01 * tan_l) / (tan_l + 0.01))
    assert t.efficiency[0] == pytest.approx(0.9077, abs=1e-4)
    assert all(0.85 <= e <= 0.95 for e in t.efficiency)
    assert not t.self_locking.any() and not t.seed_rule_no_backdrive.any()


def _check(app: Application, screw_id: str, name: str, catalog: Catalog):  # type: ignore[no-untyped-def]
    return next(c for c in evaluate(app, catalog.by_id[screw_id]).checks if c.name == name)


@pytest.mark.parametrize(("load_n", "passes"), [(5000.0, True), (6000.0, False)])
def test_static_safety_on_the_peak_load(catalog: Catalog, load_n: float, passes: bool) -> None:
    """R16-05T3-FSIDIN, C0a = 11,700 N (HIWIN Table 4.4), f_s = 2 (THK Table 21): 5000 N x 2
    = 10,000 N passes, 6000 N x 2 = 12,000 N does not."""
    c = _check(light_app(load_n=load_n), "R16-05T3-FSIDIN", "ball_static", catalog)
    assert c.passed is passes
    assert c.utilization == pytest.approx(2 * load_n / 11_700.0)
    assert "which a rolling ball nut does not have" in c.message.template


@pytest.mark.parametrize(("speed_m_s", "passes"), [(0.3, True), (0.5, False)])
def test_dn_speed_limit(catalog: Catalog, speed_m_s: float, passes: bool) -> None:
    """R16-05T3-FSIDIN, rolled: DN 70,000 (HIWIN sec. 3.7.6) on its nominal (ball-centre)
    diameter 16 mm, as Roton and THK take it, rather than its 15.5 mm outer diameter:
    4375 rpm, not 4516; lead 5 mm: 0.3 m/s is 3600 rpm, 0.5 m/s 6000 rpm."""
    c = _check(light_app(speed_m_s=speed_m_s), "R16-05T3-FSIDIN", "ball_speed", catalog)
    assert c.passed is passes
    assert c.capacity == pytest.approx(70_000.0 / 16.0)
    assert c.demand == pytest.approx(speed_m_s / 0.005 * 60.0)


def test_l10_life_in_years_of_the_duty(catalog: Catalog) -> None:
    """500 N throughout (no moving mass), 200 mm stroke, 1000 cycles a day, R16-05T3 (Ca
    6500 N, lead 5 mm), f_w 1.2: L = (6500 / 600)^3 x 10^6 = 1.2714e9 rev; a day is
    2 x 0.2 / 0.005 x 1000 = 80,000 rev; 1.2714e9 / (80,000 x 365) = 43.54 years."""
    app = light_app(load_n=500.0, stroke_m=0.2, cycles_per_day=1000.0, required_life_years=50.0)
    c = _check(app, "R16-05T3-FSIDIN", "ball_life", catalog)
    assert c.capacity == pytest.approx(43.54, rel=1e-3)
    assert not c.passed
    easy = _check(replace(app, required_life_years=40.0), "R16-05T3-FSIDIN", "ball_life", catalog)
    assert easy.passed


def test_leadscrew_checks_do_not_run_for_a_ball_screw_and_ball_checks_not_for_a_leadscrew(
    catalog: Catalog,
) -> None:
    app = light_app(stroke_m=0.2, cycles_per_day=1000.0, required_life_years=1.0)
    ball = {c.name for c in evaluate(app, catalog.by_id["R16-05T3-FSIDIN"]).checks}
    lead = {c.name for c in evaluate(app, catalog.by_id["ZBX8000-L10"]).checks}
    assert not ball & LEADSCREW_ONLY
    assert {"ball_life", "ball_static", "ball_speed", "critical_speed", "buckling"} <= ball
    assert not {n for n in lead if n.startswith("ball_")}


def test_a_ball_screw_always_back_drives(catalog: Catalog) -> None:
    """A vertical load with no brake: the ball screw cannot hold it (mu 0.003 against a
    lead angle of atan 0.112), and says a brake is needed."""
    app = light_app(orientation="vertical")
    c = _check(app, "R16-05T3-FSIDIN", "back_driving", catalog)
    assert not c.passed
    assert "always back-drives" in c.message.template
    assert "brake" in c.message.template


def test_when_no_leadscrew_passes_the_summary_says_so_first_and_names_ball_screws(
    catalog: Catalog,
) -> None:
    """2 kN at 0.5 m/s over 1 m: the leadscrews' nuts cannot (design load, sliding
    speed), rolled and ground ball screws can."""
    app = Application(
        load_n=2000.0,
        speed_m_s=0.5,
        length_m=1.0,
        stroke_m=0.8,
        cycles_per_day=2000.0,
        required_life_years=5.0,
        moving_mass_kg=50.0,
        accel_m_s2=2.0,
    )
    sel = select(app, catalog.index)
    assert sel.passed > 0
    assert {c.screw.screw_type for c in sel.candidates} == {"ball"}
    first = sel.summary.message.values["p0"].template
    assert first.startswith("No leadscrew passes: ")
    assert sel.candidates[0].screw.id in first
    # naming the leadscrew families: none passes
    lead = tuple(sorted({s.family_id for s in catalog.screws if s.screw_type == "lead"}))
    assert select(replace(app, families=lead), catalog.index).passed == 0


def test_one_passing_ball_screw_is_counted_in_the_singular(catalog: Catalog) -> None:
    """20 kN at 1.5 m/s over 0.5 m: the design load excludes every leadscrew but ten
    (which fail other checks) and one ball screw passes; the summary says so in the
    singular, as does the count."""
    sel = select(Application(load_n=20_000.0, speed_m_s=1.5, length_m=0.5), catalog.index)
    assert sel.passed == 1
    text = render(sel.summary.message)
    assert "1 ball screw does, first R40-40K2-FSC." in text
    assert text.endswith(f"1 of {sel.evaluated} candidates passes.")


def test_when_neither_kind_can_it_names_the_limit_and_another_drive(catalog: Catalog) -> None:
    """3 m/s over a 2 m screw: every screw whirls (critical speed), ball screws too; the
    summary names the limit and a belt, a rack and pinion or a linear motor."""
    app = Application(load_n=200.0, speed_m_s=3.0, length_m=2.0)
    sel = select(app, catalog.index)
    assert sel.passed == 0
    first = sel.summary.message.values["p0"].template
    assert first.startswith("Neither a leadscrew nor a ball screw in the catalog can do this")
    assert "Critical speed" in first
    assert "a belt drive, a rack and pinion or a linear motor" in first


def test_when_only_the_brake_is_missing_it_says_a_ball_screw_with_a_brake(
    catalog: Catalog,
) -> None:
    """50 kg lifted at 0.1 m/s: no leadscrew's nut runs at it, and every ball screw
    passes everything but back-driving; with a 5 N m brake ball screws pass."""
    app = Application(
        load_n=0.0, speed_m_s=0.1, length_m=0.5, moving_mass_kg=50.0, orientation="vertical"
    )
    sel = select(app, catalog.index)
    assert sel.passed == 0
    first = sel.summary.message.values["p0"].template
    balls = sum(1 for s in catalog.screws if s.screw_type == "ball")
    assert f"{balls} of them pass every other check: a ball screw with a brake can" in first
    braked = select(replace(app, brake_torque_nm=5.0), catalog.index)
    assert {c.screw.screw_type for c in braked.candidates} == {"ball"}
    # 2 kN more: the smallest nuts fail their static rating too, and only the others
    # are counted (54 of the 57)
    heavy = select(replace(app, load_n=2000.0), catalog.index)
    text = heavy.summary.message.values["p0"].template
    assert f"{balls} of them" not in text
    assert "of them pass every other check" in text


def test_a_ball_nuts_life_is_its_l10_in_travel_and_years(catalog: Catalog) -> None:
    """R20-10K3-FSCDIN (HIWIN Table 4.4: Ca 10,000 N) under 2,000 N against the motion
    both ways, 600 mm strokes, 1,000 cycles a day: L10 = (10000 / (1.2 x 2000))^3 x 10^6
    = 72.338e6 revolutions x 10 mm = 723.38 km; a cycle is 1.2 m of travel, so
    723,380 / (1.2 x 1000 x 365) = 1.6515 years: the life section and the ball_life
    check give the same."""
    app = Application(
        load_n=2000.0, speed_m_s=0.5, length_m=0.8, stroke_m=0.6, cycles_per_day=1000.0,
        required_life_years=5.0,
    )  # fmt: skip
    c = evaluate(app, catalog.by_id["R20-10K3-FSCDIN"])
    life = c.life
    assert life is not None and life.model == "l10"
    travel = (10_000.0 / (1.2 * 2000.0)) ** 3 * 1e6 * 0.010
    assert life.travel_m == pytest.approx((travel, travel), rel=1e-12)
    assert life.years_min == pytest.approx(travel / (1.2 * 1000.0 * 365.0), rel=1e-12)
    (check,) = [k for k in c.checks if k.name == "ball_life"]
    assert check.limit == pytest.approx(life.years_min, rel=1e-12)  # the life it offers
    assert evaluate(replace(app, stroke_m=None, cycles_per_day=None, required_life_years=None),
                    catalog.by_id["R20-10K3-FSCDIN"]).life is None  # fmt: skip


def test_a_preloaded_nut_carries_its_preload_below_the_disengagement_force() -> None:
    """HIWIN BS-08-2-EN-1704-K sec. 3.7.2 F 3.7: F_lim = 2^(3/2) F_pr; below it
    F_b = (1 + F / F_lim)^(3/2) F_pr (F_pr at no load), at or above it F_b = F. Worked by
    hand: 480 N of preload, 50.9 N external: (1 + 50.9 / 1357.6)^1.5 x 480 = 507.2 N."""
    limit = 2.0**1.5 * 480.0
    assert float(ballscrew.preloaded_operating_load(0.0, 480.0)) == pytest.approx(480.0)
    assert float(ballscrew.preloaded_operating_load(50.9, 480.0)) == pytest.approx(507.2, abs=0.05)
    assert float(ballscrew.preloaded_operating_load(-50.9, 480.0)) == pytest.approx(507.2, abs=0.05)
    # continuous at the disengagement force: (1 + 1)^1.5 F_pr = 2^1.5 F_pr = F_lim
    assert float(ballscrew.preloaded_operating_load(limit * 0.999999, 480.0)) == pytest.approx(
        limit, rel=1e-5
    )
    assert float(ballscrew.preloaded_operating_load(2000.0, 480.0)) == 2000.0
    assert float(ballscrew.preloaded_operating_load(50.9, 0.0)) == 50.9


def test_a_ball_nut_travels_its_stroke_on_the_screw(catalog: Catalog) -> None:
    """R12-05K4-FSCDIN's nut is 33 mm long (HIWIN BS-08-2-EN Table 4.4, L): a 790 mm
    stroke on an 800 mm screw runs it off the thread (823 mm), a 700 mm one fits (733 mm).
    Its nut has no thread pitch to rate turns by, and the check was left out unsaid: the
    nut that cannot fit passed."""
    screw = catalog.by_id["R12-05K4-FSCDIN"]
    assert screw.nut_length_m == pytest.approx(0.033)
    for stroke_m, passes in ((0.79, False), (0.7, True)):
        app = Application(load_n=50.0, speed_m_s=0.1, length_m=0.8, stroke_m=stroke_m)
        stroke = next(c for c in evaluate(app, screw).checks if c.name == "stroke_travel")
        assert stroke.value == pytest.approx(stroke_m + 0.033, rel=1e-12)
        assert stroke.passed is passes
    # a nut length typed is the one that travels
    typed = Application(load_n=50.0, speed_m_s=0.1, length_m=0.8, stroke_m=0.7, nut_length_m=0.12)
    stroke = next(c for c in evaluate(typed, screw).checks if c.name == "stroke_travel")
    assert not stroke.passed and stroke.value == pytest.approx(0.82, rel=1e-12)


@pytest.mark.parametrize(("load_n", "passes"), [(900.0, True), (1000.0, False)])
def test_a_preloaded_nut_keeps_no_play_below_its_preload_release_force(
    catalog: Catalog, load_n: float, passes: bool
) -> None:
    """R16-16K2-FSC: Ca 6800 N, preloaded to 5 % of it (the catalog's assumed top of
    HIWIN's range), F_pr = 340 N, released at F_lim = 2^(3/2) x 340 = 961.7 N (HIWIN sec.
    3.7.2 F 3.7): an axis that must have no backlash keeps it at 900 N, not at 1000 N.
    Every preloaded nut passed "Anti-backlash" at any thrust (3000 N on it passed)."""
    screw = catalog.by_id["R16-16K2-FSC"]
    assert (screw.dynamic_load_n, screw.preload_n) == (6800.0, pytest.approx(340.0))
    app = light_app(load_n=load_n, require_anti_backlash=True)
    checks = {c.name: c for c in evaluate(app, screw).checks}
    assert checks["anti_backlash"].passed
    release = checks["preload_release"]
    assert release.capacity == pytest.approx(961.665, rel=1e-6)
    assert release.value == pytest.approx(load_n, rel=1e-9)  # light_app has no moving mass
    assert release.passed is passes
    # an axis that may have play does not ask
    free = evaluate(light_app(load_n=load_n), screw).checks
    assert "preload_release" not in {c.name for c in free}


def test_a_segment_the_load_drives_is_worked_at_the_low_end_of_the_friction(
    catalog: Catalog,
) -> None:
    """300 kg braked from 100 mm/s at 5 m/s² on R20-05K4-FSCDIN (horizontal, no load): the
    mass drives the screw, 1500 N through the thread. HIWIN gives the ball track an
    equivalent friction of 0.003 to 0.01: at 0.01 the back-driven efficiency is 0.874, at
    0.003 0.962, where the mass drives the motor hardest. The braking torque was worked at
    0.01, 7 % short: T = -1500 x 0.005 x eta_b / 2 pi - J_screw alpha, at eta_b(0.003)."""
    screw = catalog.by_id["R20-05K4-FSCDIN"]
    app = Application(
        load_n=0.0, speed_m_s=0.1, length_m=0.6, stroke_m=0.4, moving_mass_kg=300.0,
        accel_m_s2=0.5, decel_m_s2=5.0,
    )  # fmt: skip
    ev = evaluate(app, screw)
    tan_l = screw.lead_m / (math.pi * (screw.pitch_circle_diameter_m or 0.0))

    def eta_b(mu: float) -> float:  # HIWIN F 3.16, Shigley's lowering efficiency
        return (tan_l - mu) / (tan_l * (1.0 + mu * tan_l))

    assert (round(eta_b(0.01), 3), round(eta_b(0.003), 3)) == (0.874, 0.962)
    # the screw's inertia torque at the 5 m/s² ramp, from the breakdown's at 0.5 m/s²
    spin = ev.torque.inertia_screw_nm * 5.0 / 0.5
    braking = -1500.0 * screw.lead_m * eta_b(0.003) / (2 * math.pi) - spin
    decel = next(s for s in ev.segments if s.name == "decelerate" and s.direction == "out")
    assert decel.torque_nm == pytest.approx(braking, rel=1e-9)
    assert ev.quantities.torque.peak_torque_nm == pytest.approx(abs(braking), rel=1e-9)
    assert abs(braking) == pytest.approx(1.574, abs=5e-4)
