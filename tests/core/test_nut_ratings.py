"""The nut's contact-pressure rating over the catalog (app.core.checks.bearing_pressure):
a size with more engaged flank area that slides no faster never fails where a smaller
one passes, and when a larger size fails for sliding faster, its message says why."""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.catalog import Catalog
from app.contract.units import render
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.selection import screen
from tests.core.conftest import light_app

PROPERTY = settings(
    max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
#: Axes that load the ISO nuts near their ratings: thrust, speed, a moving mass.
iso_axes = st.builds(
    Application,
    load_n=st.floats(10.0, 20000.0),
    speed_m_s=st.floats(0.0005, 0.5),
    length_m=st.floats(0.1, 1.5),
    accel_m_s2=st.floats(0.0, 5.0),
    moving_mass_kg=st.floats(0.0, 50.0),
    nut_length_m=st.none() | st.floats(0.01, 0.1),
    families=st.just(("TR-C45", "TR-304")),
)


def violations(app: Application, catalog: Catalog) -> list[tuple[str, str]]:
    """Pairs (passes, fails) of one nut material where the failing one has at least the
    passing one's flank area and slides no faster."""
    s = screen(app, catalog.index)
    m = s.measures["bearing_pressure"]
    assert m.demand is not None and m.capacity is not None
    rated = np.flatnonzero(m.applicable)
    passes = m.demand[rated] <= m.capacity[rated]
    area = s.quantities.flank_area_m2[rated]
    speed = s.quantities.sliding_speed_m_s[rated]
    material = np.array([s.table.screws[i].variant for i in rated])
    worse = (
        (material[:, None] == material[None, :])
        & (area[None, :] >= area[:, None])
        & (speed[None, :] <= speed[:, None])
        & passes[:, None]
        & ~passes[None, :]
    )
    return [
        (s.table.screws[rated[i]].id, s.table.screws[rated[j]].id)
        for i, j in zip(*np.nonzero(worse), strict=True)
    ]


@PROPERTY
@given(app=iso_axes)
def test_more_flank_area_sliding_no_faster_never_fails_where_less_passes(
    catalog: Catalog, app: Application
) -> None:
    assert violations(app, catalog) == []


def test_the_property_compares_real_pairs(catalog: Catalog) -> None:
    """Not vacuous: on a 600 N axis at 20 mm/s, bronze pairs with more area and no more
    sliding speed exist (a fine-pitch size at high rpm against a coarse one at low rpm)."""
    app = Application(load_n=600.0, speed_m_s=0.02, length_m=0.5, families=("TR-C45",))
    s = screen(app, catalog.index)
    m = s.measures["bearing_pressure"]
    rated = np.flatnonzero(m.applicable)
    area = s.quantities.flank_area_m2[rated]
    speed = s.quantities.sliding_speed_m_s[rated]
    pairs = (area[None, :] > area[:, None]) & (speed[None, :] < speed[:, None])
    assert pairs.sum() > 100
    assert violations(app, catalog) == []


def test_a_larger_size_that_slides_faster_says_why_it_fails(catalog: Catalog) -> None:
    """Tr8x2 and Tr10x2 bronze at 540 rpm (18 mm/s), 500 N. Flanks slide 9 rev/s x the
    helix at d2: Tr8x2 sqrt(2^2 + (pi 7)^2) = 22.08 mm, 0.1987 m/s, where Shigley's table
    allows 5.5 MPa over 8 x pi x 7 x 1 = 175.9 mm^2: 967.6 N, passes. Tr10x2 slides
    sqrt(2^2 + (pi 9)^2) = 28.35 mm, 0.2551 m/s, past the table's 0.25 m/s row: 1 MPa
    over 10 x pi x 9 x 1 = 282.7 mm^2, 282.7 N, fails, and its message says the
    pressure falls with sliding speed and the larger size slides faster."""
    app = light_app(load_n=500.0, speed_m_s=0.018)
    small = next(
        c
        for c in evaluate(app, catalog.by_id["Tr8x2-bronze"]).checks
        if c.name == "bearing_pressure"
    )
    large = next(
        c
        for c in evaluate(app, catalog.by_id["Tr10x2-bronze"]).checks
        if c.name == "bearing_pressure"
    )
    assert small.passed and small.limit == pytest.approx(5.5e6 * 8 * math.pi * 7e-3 * 1e-3)
    assert not large.passed and large.limit == pytest.approx(1e6 * 10 * math.pi * 9e-3 * 1e-3)
    assert (small.limit, large.limit) == pytest.approx((967.6, 282.7), abs=0.1)
    text = render(large.message)
    assert "less than the 11 MPa it allows up to 50 mm/s" in text
    assert "a larger size slides faster at the same speed of turning" in text
