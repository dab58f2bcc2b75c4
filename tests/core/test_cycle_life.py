"""Nut life from the whole cycle: the thrust the nut carries in every segment of both
moves (Archard's law summed over the segments, the load-spectrum mean of Steinmeyer's
"duty cycle and its equivalent load" with the wear law's exponent 1), the seed's rated
travel capped by the same nut's wear, and the duty given as hours a day.

The seed nuts' wear by hand (catalog: polyacetal k = 1e-6 mm^3/(N m), a quarter of the
thread depth H allowed, over the seed's three threads of area 3 H.T. H, sliding H.T. per
lead): travel = 0.25 H / (k F / (3 H.T. H)) x lead / H.T. = 0.75 H^2 lead / (k F). A 1/2 in
seed screw (root 0.78 x 12.7 mm) has H = (12.7 - 9.906) / 2 = 1.397 mm, so on a 10 mm
lead 0.75 x 1.397e-3^2 x 0.01 = 1.4637e-8 m^3 over k F: 14,637 km at 1 N.
"""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core import load_caps, motion
from app.core.evaluate import evaluate
from app.core.model import STANDARD_GRAVITY_M_S2, Application
from app.core.record import Candidate

#: 0.75 H^2 lead of a 1/2 in seed screw on a 10 mm lead [m^3]; over k F it is the travel.
WEAR_VOLUME_M3 = 0.75 * ((12.7e-3 - 0.78 * 12.7e-3) / 2.0) ** 2 * 0.010
K_M2_N = 1e-15

#: The issue's pick-and-place axis: 1.5 kg, 300 mm/s, 10 m/s^2, 400 mm strokes, 20 000
#: cycles a day, no load. Each ramp: t = 0.3 / 10 = 0.03 s over 0.3 x 0.03 / 2 = 4.5 mm at
#: m a = 15 N; the cruise 400 - 9 = 391 mm.
PICK_AND_PLACE = Application(
    load_n=0.0,
    speed_m_s=0.3,
    length_m=0.5,
    moving_mass_kg=1.5,
    accel_m_s2=10.0,
    stroke_m=0.4,
    cycles_per_day=20000.0,
)
RAMP_M, CRUISE_M = 0.0045, 0.391


def _check(candidate: Candidate, name: str) -> tuple[float, bool, str]:
    found = next(c for c in candidate.checks if c.name == name)
    return found.limit, found.passed, render(found.message)


def test_the_pick_and_place_axis_wears_its_nut_by_m_a_alone(catalog: Catalog) -> None:
    """No load, but 15 N on each of the four ramps: F_w = 4 x 15 x 4.5 mm / 800 mm =
    0.3375 N. B8000-L10-TFE: 1.4637e-8 / (1e-15 x 0.3375) = 43,370 km, / (0.8 m x 20 000 x
    365 = 5,840 km a year) = 7.43 years: a finite life, where the running thrust alone (0)
    gave none."""
    assert motion.segment_travels(motion.move_profile(PICK_AND_PLACE)) == pytest.approx(
        (RAMP_M, CRUISE_M, RAMP_M)
    )
    assert motion.wear_thrust(PICK_AND_PLACE) == pytest.approx(4 * 15.0 * RAMP_M / 0.8)
    assert motion.wear_thrust(PICK_AND_PLACE) == pytest.approx(0.3375)
    c = evaluate(PICK_AND_PLACE, catalog.by_id["B8000-L10-TFE"])
    travel_m = WEAR_VOLUME_M3 / (K_M2_N * 0.3375)
    assert travel_m == pytest.approx(43.37e6, rel=1e-3)
    assert c.quantities.life.wear_travel_m == pytest.approx(travel_m, rel=1e-6)
    assert c.quantities.life.wear_life_years == pytest.approx(7.426, rel=1e-3)
    assert c.life is not None and c.life.model == "wear"
    # the band: the wear rate's high end 3e-6 and low end 3.3e-7
    assert c.life.travel_m == pytest.approx((travel_m / 3.0, travel_m / 0.33), rel=1e-6)


@pytest.mark.parametrize(
    ("changes", "thrust_n"),
    [
        # against the motion both ways (a horizontal axis's default): out 16, 1, |-14|;
        # back |-16|, |-1|, 14: (2 x (16 + 14) x 4.5 mm + 2 x 1 x 391 mm) / 800 mm
        pytest.param({"load_n": 1.0}, (2 * 30 * RAMP_M + 2 * CRUISE_M) / 0.8, id="opposes"),
        # one way (a spring): out 16, 1, |-14|; back |-14|, 1, 16: the same here
        pytest.param(
            {"load_n": 1.0, "load_direction": "fixed"},
            (2 * 30 * RAMP_M + 2 * CRUISE_M) / 0.8,
            id="fixed",
        ),
        # a 1 N friction load with m a below it: the ramps take from one flank what they
        # add to the other, |F + m a| + |F - m a| = 2 F only when m a <= F; 0.1 kg: 1 N
        pytest.param({"load_n": 1.0, "moving_mass_kg": 0.1}, 1.0, id="opposes-m-a-below-the-load"),
        # vertical, no load: W = 14.71 N is below m a = 15 N, so the ramps give
        # |W + m a| + |W - m a| = 2 m a = 30 N a move, the cruise W
        pytest.param(
            {"orientation": "vertical"},
            (2 * 30 * RAMP_M + 2 * 1.5 * STANDARD_GRAVITY_M_S2 * CRUISE_M) / 0.8,
            id="vertical-m-a-above-the-weight",
        ),
        # vertical at 5 m/s^2: m a = 7.5 N below W, so the ramps cancel to W: F_w = W
        pytest.param(
            {"orientation": "vertical", "accel_m_s2": 5.0},
            1.5 * STANDARD_GRAVITY_M_S2,
            id="vertical-m-a-below-the-weight",
        ),
    ],
)
def test_the_wear_thrust_follows_the_load_direction(
    changes: dict[str, object], thrust_n: float
) -> None:
    app = replace(PICK_AND_PLACE, **changes)  # type: ignore[arg-type]
    assert motion.wear_thrust(app) == pytest.approx(thrust_n, rel=1e-9)


def test_the_wear_thrust_is_above_the_running_thrust_and_below_the_peak() -> None:
    """A mean over the segments: never below the cruise's thrust (the ramps add m a to one
    flank at least as much as they take off), never above the largest segment's."""
    for load_n in (0.0, 1.0, 10.0, 100.0):
        for orientation in ("horizontal", "vertical"):
            app = replace(PICK_AND_PLACE, load_n=load_n, orientation=orientation)
            forces = [abs(f) for f in motion.nut_forces(app)]
            assert forces[1] - 1e-12 <= motion.wear_thrust(app) <= max(forces) + 1e-12


def test_hours_a_day_give_the_cycles_by_the_cycle_time(catalog: Catalog) -> None:
    """8 hours a day: the cycle is 2 x (0.03 + 1.3033 + 0.03) = 2.7267 s (each cruise
    391 mm at 0.3 m/s), so 8 x 3600 / 2.7267 = 10,562 cycles a day; with a 0.5 s dwell
    after each move 3.7267 s, 7,728 cycles. The life in years scales with them."""
    hours = replace(PICK_AND_PLACE, cycles_per_day=None, hours_per_day=8.0)
    assert motion.cycles_per_day(hours) == pytest.approx(8 * 3600 / 2.72667, rel=1e-5)
    assert motion.cycles_per_day(hours) == pytest.approx(10562.3, rel=1e-5)
    dwell = replace(hours, dwell_s=0.5)
    assert motion.cycles_per_day(dwell) == pytest.approx(7728.0, rel=1e-4)
    screw = catalog.by_id["B8000-L10-TFE"]
    by_cycles = evaluate(PICK_AND_PLACE, screw).quantities.life.wear_life_years
    by_hours = evaluate(hours, screw).quantities.life.wear_life_years
    assert by_hours == pytest.approx(by_cycles * 20000.0 / 10562.3, rel=1e-5)
    # without a stroke there is no cycle to time: no duty
    assert motion.cycles_per_day(replace(hours, stroke_m=None)) is None


def test_a_life_short_of_the_required_fails_with_its_numbers(catalog: Catalog) -> None:
    """The pick-and-place axis at 1 N (friction): F_w = 1.315 N, B8000-L10-TFE 1.4637e-8 /
    (1e-15 x 1.315) = 11,131 km, 1.906 years: short of 5 years asked, a failed check (a
    limit, which rejects the candidate) saying so."""
    app = replace(PICK_AND_PLACE, load_n=1.0, required_life_years=5.0)
    c = evaluate(app, catalog.by_id["B8000-L10-TFE"])
    limit, passed, text = _check(c, "wear_life")
    assert limit == pytest.approx(WEAR_VOLUME_M3 / (K_M2_N * 1.315) / 5.84e6, rel=1e-6)
    assert limit == pytest.approx(1.906, rel=1e-3)
    assert not passed and not c.passed
    assert "1.315 N" in text and "falls short of the 5 years required" in text


@pytest.mark.parametrize(
    ("load_n", "seed_governs"),
    [
        pytest.param(1.0, True, id="1N"),  # wear 14,637 km > seed 3,800 km
        pytest.param(100.0, False, id="100N"),  # wear 146.4 km
        pytest.param(400.0, False, id="400N"),  # wear 36.59 km
    ],
)
def test_the_seed_rating_falls_with_the_load_as_the_same_nuts_wear(
    catalog: Catalog, load_n: float, seed_governs: bool
) -> None:
    """ZBX8000-L10-TFE (seed 380-500 million cm = 3,800-5,000 km, no load stated) and
    B8000-L10-TFE, the same polyacetal nut on the same screw: horizontal, no moving mass,
    F_w = the load. The rating counts for no more than the nut's wear at that thrust, so
    the two nuts' life checks agree wherever the wear governs, and the seed's figure
    caps it at light loads: 200 mm strokes, 1000 a day (146 km a year)."""
    app = Application(
        load_n=load_n,
        speed_m_s=0.05,
        length_m=0.5,
        stroke_m=0.2,
        cycles_per_day=1000.0,
        required_life_years=1.0,
    )
    year_m = 2 * 0.2 * 1000 * 365
    wear_m = WEAR_VOLUME_M3 / (K_M2_N * load_n)
    rated, _, text = _check(evaluate(app, catalog.by_id["ZBX8000-L10-TFE"]), "life")
    assert rated == pytest.approx(min(3.8e6, wear_m) / year_m, rel=1e-6)
    worn, _, _ = _check(evaluate(app, catalog.by_id["B8000-L10-TFE"]), "wear_life")
    assert worn == pytest.approx(wear_m / year_m, rel=1e-6)
    if seed_governs:
        assert rated == pytest.approx(3.8e6 / year_m) and rated < worn
        assert "cut to" not in text
    else:
        assert rated == pytest.approx(worn, rel=1e-9)
        assert "cut to" in text and "assumed wear rate's central value" in text
        # the wear rate's high end gives less: the cut life is no "at least"
        assert not text.startswith("At least")


def test_the_largest_load_for_a_wear_thrust_inverts_it() -> None:
    """The pick-and-place axis with a friction load F below m a: the ramps add
    |15 + F| + |15 - F| = 30 N a move whatever F, the cruises 2 F x 391 mm, so F_w =
    0.3375 + 0.9775 F; a wear thrust of 0.5 N allows F = 0.1625 / 0.9775 = 0.1662 N. Past
    15 N the ramps grow with F too (a corner): F_w = (4 F x 4.5 + 2 F x 391) / 800 = F, so
    20 N allows F = 20 N. Below the 0.3375 N that m a alone gives, no load does."""
    assert load_caps.largest_load_for_wear(PICK_AND_PLACE, 0.5) == pytest.approx(0.1625 / 0.9775)
    assert load_caps.largest_load_for_wear(PICK_AND_PLACE, 20.0) == pytest.approx(20.0)
    assert load_caps.largest_load_for_wear(PICK_AND_PLACE, 0.3) is None
    for allowed_n in (0.5, 5.0, 14.9, 20.0, 100.0):
        load_n = load_caps.largest_load_for_wear(PICK_AND_PLACE, allowed_n)
        assert load_n is not None
        at = replace(PICK_AND_PLACE, load_n=load_n)
        assert motion.wear_thrust(at) == pytest.approx(allowed_n, rel=1e-12)


def test_a_nut_typed_longer_than_the_catalogs_wears_no_slower(catalog: Catalog) -> None:
    """Tr16x4-acetal, 300 N and 5 kg, 500 cycles of 300 mm a day: its 32 mm catalog nut
    wears through in 0.62 to 5.7 years (Archard, the 3:1 band of its wear rate). Typed 64
    or 160 mm long, its rating stays the catalog nut's (a longer nut's turns do not share
    the thrust evenly), but its wear life grew in proportion to the length (9.4 years at
    160 mm, passing a 5 year life). It wears over the catalog nut's flanks at most now; a
    shorter nut still over its own, in proportion."""
    screw = catalog.by_id["Tr16x4-acetal"]
    app = Application(
        load_n=300.0, speed_m_s=0.02, length_m=0.5, stroke_m=0.3, moving_mass_kg=5.0,
        cycles_per_day=500.0, required_life_years=5.0,
    )  # fmt: skip
    travel = {
        nut: float(evaluate(replace(app, nut_length_m=nut), screw).quantities.life.wear_travel_m)
        for nut in (None, 0.016, 0.064, 0.16)
    }
    assert travel[0.064] == pytest.approx(travel[None], rel=1e-12)
    assert travel[0.16] == pytest.approx(travel[None], rel=1e-12)
    assert travel[0.016] == pytest.approx(travel[None] / 2, rel=1e-12)
    assert not evaluate(replace(app, nut_length_m=0.16), screw).passed
