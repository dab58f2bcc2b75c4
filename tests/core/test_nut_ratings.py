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
    area = s.quantities.nut.flank_area_m2[rated]
    speed = s.quantities.nut.sliding_speed_m_s[rated]
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
    area = s.quantities.nut.flank_area_m2[rated]
    speed = s.quantities.nut.sliding_speed_m_s[rated]
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


#: Published allowable dynamic thrust [N] of a nut of each size and material, with its
#: source: MISUMI, Lead Screws - Overview, "Nuts for Lead Screw" comparison table,
#: Allowable Dynamic Thrust (N) (catalog pp. 685-688; text at docslib.org/doc/8572561):
#: the standard (copper-alloy) nut and the plastic nut, the lower of MISUMI's two plastic
#: nuts (its high-strength one: Tr10x2 278 N, Tr20x4 1,071 N). Every row whose diameter and
#: pitch is an ISO size of the catalog is here. Filled PTFE has no maker's rating and is
#: held to 0.7 x MISUMI's plastic value (Neale, Tribology Handbook A5: filled PTFE 7 MPa
#: against a thermoplastic's 10 MPa).
MISUMI_STANDARD_N = {
    "Tr8x1.5": 1470.0,
    "Tr10x2": 2550.0,
    "Tr14x3": 4900.0,
    "Tr18x4": 8720.0,
    "Tr20x4": 9810.0,
    "Tr22x5": 12360.0,
    "Tr28x5": 17950.0,
    "Tr32x6": 21080.0,
    "Tr36x6": 25780.0,
}
MISUMI_PLASTIC_N = {
    "Tr10x2": 255.0,
    "Tr14x3": 490.0,
    "Tr18x4": 873.0,
    "Tr20x4": 980.0,
    "Tr28x5": 1765.0,
    "Tr32x6": 2050.0,
}
PUBLISHED = [
    *(
        pytest.param(s, "bronze", n, id=f"MISUMI standard nut {s} {n:g} N")
        for s, n in MISUMI_STANDARD_N.items()
    ),
    *(
        pytest.param(s, "acetal", n, id=f"MISUMI plastic nut {s} {n:g} N")
        for s, n in MISUMI_PLASTIC_N.items()
    ),
    *(
        pytest.param(s, "ptfe", 0.7 * n, id=f"0.7 x MISUMI plastic {s}")
        for s, n in MISUMI_PLASTIC_N.items()
    ),
]
SLOW_AXIS = Application(load_n=100.0, speed_m_s=0.0005, length_m=0.5)


@pytest.mark.parametrize(("size", "nut", "published_n"), PUBLISHED)
@pytest.mark.parametrize("screw", ["", "-304"], ids=["C45", "304"])
def test_a_listed_nut_rates_at_its_published_thrust(
    catalog: Catalog, size: str, nut: str, published_n: float, screw: str
) -> None:
    """The design-load check's limit for the catalog nut of a listed size is the maker's
    value: never above it, and not below it by more than rounding."""
    result = evaluate(SLOW_AXIS, catalog.by_id[f"{size}{screw}-{nut}"])
    rated = next(c for c in result.checks if c.name == "design_load")
    assert rated.limit <= published_n * (1 + 1e-12)
    assert rated.limit == pytest.approx(published_n, rel=1e-9)


@pytest.mark.parametrize("nut", ["acetal", "bronze", "ptfe"])
def test_no_size_rates_above_the_flank_pressure_of_a_listed_one(catalog: Catalog, nut: str) -> None:
    """Every ISO size's flank pressure in motion is at most that of a size its maker lists
    (the lowest listed one governs the sizes not listed), so no unlisted size is rated
    more generously per unit of flank than a part the maker publishes; and every ISO
    nut of the three materials has a rating."""
    screws = [s for s in catalog.screws if s.family_id in ("TR-C45", "TR-304")]
    rated = [s for s in screws if s.variant == nut]
    assert rated and all(s.dynamic_pressure_pa for s in rated)
    unlisted = "this size is not in the maker's table"
    listed = [s for s in rated if not s.provenance["dynamic_pressure"].source.startswith(unlisted)]
    assert {s.id.split("-")[0] for s in listed} >= {"Tr20x4"}
    lowest = min(s.dynamic_pressure_pa or 0.0 for s in listed)
    for s in rated:
        prov = s.provenance["dynamic_pressure"]
        if prov.source.startswith(unlisted):
            assert s.dynamic_pressure_pa == pytest.approx(lowest), s.id
            assert prov.kind == "derived", s.id
