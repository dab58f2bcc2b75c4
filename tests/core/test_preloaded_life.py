"""A preloaded ball nut's L10 life from both its sides (HIWIN GmbH, Ballscrews &
Accessories, BS-08-2-EN-1704-K, sec. 3.7.2 F 3.6, F 3.7 and d) 'Axial loading on both
sides' with its flow chart for calculating service life): in each moving segment the side
the thrust presses carries F_b = (1 + F / 2^(3/2) F_pr)^(3/2) F_pr and the other
F_b - F (0 from F_lim = 2^(3/2) F_pr on); each side's cubic mean over the travel gives
L1, L2 = (Ca / (f_w F_bm))^3 x 10^6, and the nut lives
L = (L1^(-10/9) + L2^(-10/9))^(-9/10), or the one-sided life (every segment at F_b on
one track) where that is shorter. A nut without preload keeps the one-sided life.

HIWIN's section gives no worked example of the two-sided life, so the cases here are
worked by hand. The references below are written out in plain Python, apart from the
code under test."""

import math
from itertools import product

import numpy as np
import pytest

from app.catalog import Catalog
from app.core.checks.ball_life import life_years
from app.core.duty import travel_thrusts
from app.core.evaluate import evaluate
from app.core.formulas import ballscrew
from app.core.model import Application

#: The load factor f_w the application takes by default.
F_W = 1.2


def _reference(
    ca: float, preload: float, forces: list[float], travels: list[float]
) -> tuple[float, float]:
    """HIWIN's two-sided life and the one-sided life [rev] of a nut of rating ``ca`` and
    preload ``preload`` under the segment thrusts ``forces`` over ``travels``, by the
    catalog's steps one segment at a time."""
    limit = 2.0**1.5 * preload
    cubes = [0.0, 0.0, 0.0]  # side 1, side 2, one track under every segment
    for force, travel in zip(forces, travels, strict=True):
        size = abs(force)
        pressed = (1.0 + size / limit) ** 1.5 * preload if size < limit else size
        other = pressed - size if size < limit else 0.0
        one, two = (pressed, other) if force >= 0.0 else (other, pressed)
        cubes = [
            cubes[0] + one**3 * travel,
            cubes[1] + two**3 * travel,
            cubes[2] + pressed**3 * travel,
        ]
    total = sum(travels)
    lives = [(ca / (F_W * (c / total) ** (1.0 / 3.0))) ** 3 * 1e6 if c else math.inf for c in cubes]
    damage = lives[0] ** (-10.0 / 9.0) + lives[1] ** (-10.0 / 9.0)
    both = damage ** (-9.0 / 10.0) if damage else math.inf
    return both, lives[2]


def test_out_and_back_on_a_preloaded_hiwin_nut_by_hand(catalog: Catalog) -> None:
    """R15-10K3-FSC (HIWIN ground, Ca 9,600 N, preload 5 % = 480 N, lead 10 mm), 200 N
    against the motion both ways, no moving mass: 200 N presses side 1 going out and
    side 2 coming back, over equal travel. F_lim = 2^1.5 x 480 = 1,357.65 N;
    F_b = (1 + 200 / 1357.65)^1.5 x 480 = 1.147314^1.5 x 480 = 589.88 N on the pressed
    side, 589.88 - 200 = 389.88 N on the other. Each side: F_bm = ((589.88^3 + 389.88^3)
    / 2)^(1/3) = 509.50 N, L1 = L2 = (9600 / (1.2 x 509.50))^3 x 10^6 = 3871.2e6 rev, and
    L = (2 L1^(-10/9))^(-9/10) = 2^(-9/10) L1 = 0.535887 x 3871.2e6 = 2074.5e6 rev.
    One-sided (every segment at 589.88 N): (9600 / 707.86)^3 x 10^6 = 2494.5e6 rev, 16.8 %
    longer. 300 mm strokes, 2,000 cycles a day: 60 rev a cycle, 43.8e6 a year: 47.36
    years (56.95 one-sided)."""
    app = Application(load_n=200.0, speed_m_s=0.3, length_m=0.5, stroke_m=0.3,
                      cycles_per_day=2000.0, required_life_years=5.0)  # fmt: skip
    c = evaluate(app, catalog.by_id["R15-10K3-FSC"])
    (check,) = [k for k in c.checks if k.name == "ball_life"]
    assert check.limit == pytest.approx(2074.5e6 / 43.8e6, rel=1e-4)
    assert check.limit == pytest.approx(47.363, abs=0.001)
    assert check.limit / 56.951 == pytest.approx(0.8316, abs=1e-4)  # 16.8 % below one-sided
    assert c.life is not None and c.life.years_min == pytest.approx(check.limit, rel=1e-12)


def test_the_sides_a_thrust_loads_by_hand() -> None:
    """F 3.7 and the flow chart's F_bn = F_b - F: 480 N of preload under 200 N out gives
    589.88 N to side 1 and 389.88 N to side 2, under 200 N back the other way round; past
    F_lim = 1,357.65 N the other side carries nothing; without preload the pressed side
    carries the thrust."""
    out = [float(x) for x in ballscrew.side_loads(200.0, 480.0)]
    back = [float(x) for x in ballscrew.side_loads(-200.0, 480.0)]
    assert out == pytest.approx([589.88, 389.88], abs=0.01)
    assert back == pytest.approx([389.88, 589.88], abs=0.01)
    assert [float(x) for x in ballscrew.side_loads(-1400.0, 480.0)] == [0.0, 1400.0]
    for preload in (0.0, math.nan):
        assert [float(x) for x in ballscrew.side_loads(-50.0, preload)] == [0.0, 50.0]


APPS = [
    Application(
        load_n=load,
        speed_m_s=0.3,
        length_m=1.0,
        stroke_m=0.45,
        cycles_per_day=500.0,
        required_life_years=1.0,
        moving_mass_kg=mass,
        accel_m_s2=accel,
        load_direction=direction,
        orientation=orientation,
    )
    for load, mass, accel, direction, orientation in product(
        (0.0, 50.0, 400.0, 1500.0, 6000.0),
        (0.0, 20.0),
        (0.5, 8.0),
        ("auto", "fixed"),
        ("horizontal", "vertical"),
    )
]


@pytest.mark.parametrize("app", APPS, ids=range(len(APPS)))
def test_a_preloaded_nut_is_never_rated_above_one_sided_and_play_is_unchanged(
    catalog: Catalog, app: Application
) -> None:
    """Over a grid of loads, masses, ramps and directions and every ball nut in the
    catalog: a preloaded nut's life is the smaller of HIWIN's two-sided life and the
    one-sided life, so never above the one-sided; a nut with play (0 or NaN preload) has
    exactly the one-sided life of its thrust."""
    table = catalog.index.table
    ball = np.flatnonzero(table.ball)
    ca, lead, preload = table.dynamic_load_n[ball], table.lead_m[ball], table.preload_n[ball]
    nut = table.nut_length_m[ball]
    assert (app.stroke_m or 0.0) >= 3.0 * nut.max()  # no short stroke: f_w stays 1.2
    forces, travels = travel_thrusts(app)
    per_year = sum(travels) * 500.0 * 365.0
    years = life_years(app, ca, lead, preload, nut)
    played = life_years(app, ca, lead, np.where(preload > 0.0, np.nan, 0.0), nut)
    assert (preload > 0.0).any() and (preload == 0.0).any()
    for i in range(len(ball)):
        both, one = _reference(float(ca[i]), float(preload[i]), forces, travels)
        expected = min(both, one) if preload[i] > 0.0 else one
        assert years[i] == pytest.approx(expected * lead[i] / per_year, rel=1e-9)
        assert years[i] <= one * lead[i] / per_year * (1.0 + 1e-12)
        _, bare = _reference(float(ca[i]), 0.0, forces, travels)
        assert played[i] == pytest.approx(bare * lead[i] / per_year, rel=1e-12)


def test_the_two_sided_life_governs_at_light_thrust_and_the_one_sided_near_disengagement() -> None:
    """Both ends of the grid above, worked by hand for Ca 6,500 N and 300 N of preload
    (F_lim = 848.5 N), equal travel out and back. Without thrust both sides carry 300 N:
    L = 2^(-9/10) (6500 / 360)^3 x 10^6 = 0.5359 x 5886.2e6 = 3154.3e6, 46 % below the
    one-sided. At 800 N each way (near F_lim) F_b = (1 + 800 / 848.53)^1.5 x 300 = 1.94281^1.5 x
    300 = 812.39 N pressed and 12.39 N on the other side: F_bm = ((812.39^3 + 12.39^3) /
    2)^(1/3) = 644.80 N, L = 0.5359 x (6500 / 773.76)^3 x 10^6 = 317.7e6, above the
    one-sided (6500 / 974.87)^3 x 10^6 = 296.4e6, which is taken."""
    light = ballscrew.nut_life_revolutions(6500.0, F_W, 300.0, (300.0, 300.0), 300.0)
    assert float(light) / 1e6 == pytest.approx(3154.3, abs=0.1)
    pressed, other = (float(x) for x in ballscrew.side_loads(800.0, 300.0))
    assert (pressed, other) == pytest.approx((812.39, 12.39), abs=0.005)
    side = ((pressed**3 + other**3) / 2.0) ** (1.0 / 3.0)
    assert side == pytest.approx(644.80, abs=0.005)
    both = float(ballscrew.two_sided_life_revolutions(6500.0, F_W, side, side))
    one = ballscrew.rated_life_revolutions(6500.0, F_W, pressed)
    assert both / 1e6 == pytest.approx(317.7, abs=0.1)
    assert one / 1e6 == pytest.approx(296.4, abs=0.1)
    taken = ballscrew.nut_life_revolutions(6500.0, F_W, pressed, (side, side), 300.0)
    assert float(taken) == pytest.approx(one, rel=1e-12)


def test_the_grid_reaches_both_branches(catalog: Catalog) -> None:
    """The grid above is not one-sided only: on it the two-sided life is the shorter for
    some preloaded nuts (light thrust) and the one-sided for others (thrust near F_lim)."""
    table = catalog.index.table
    preloaded = np.flatnonzero(table.ball & (table.preload_n > 0.0))
    shorter = set()
    for app in APPS:
        forces, travels = travel_thrusts(app)
        for i in preloaded:
            both, one = _reference(
                float(table.dynamic_load_n[i]), float(table.preload_n[i]), forces, travels
            )
            shorter.add("both" if both < one else "one" if one < both else "same")
    assert {"both", "one"} <= shorter
