"""The vectorised screen and the scalar evaluation must agree on every candidate.

``select`` ranks and counts from ``screen`` but reports ``evaluate``; if the two ever
disagreed, a listed candidate could contradict its own checks.
"""

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.screening import screen
from app.core.selection import select

applications = st.builds(
    Application,
    load_n=st.floats(1.0, 5000.0),
    speed_m_s=st.floats(0.001, 1.5),
    length_m=st.floats(0.05, 5.0),
    lead_m=st.sampled_from([None, 0.002, 0.01, 0.0254]),
    accel_m_s2=st.floats(0.01, 20.0),
    moving_mass_kg=st.floats(0.0, 50.0),
    end_fixity=st.sampled_from(["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"]),
    orientation=st.sampled_from(["horizontal", "vertical"]),
    compression=st.booleans(),
    require_anti_backlash=st.booleans(),
    coating=st.sampled_from(["auto", "tfe", "none"]),
    oil_present=st.booleans(),
    ambient_c=st.floats(-20.0, 120.0),
    stroke_m=st.one_of(st.none(), st.floats(0.01, 2.0)),
    cycles_per_day=st.one_of(st.none(), st.floats(1.0, 10000.0)),
    critical_speed_safety_factor=st.floats(0.5, 1.0),
    buckling_safety_factor=st.floats(0.3, 1.0),
    torque_safety_factor=st.floats(1.0, 2.0),
    max_torque_nm=st.one_of(st.none(), st.floats(0.05, 5.0)),
    required_life_years=st.one_of(st.none(), st.floats(0.1, 50.0)),
    positioning_tolerance_m=st.one_of(st.none(), st.floats(1e-5, 1e-3)),
    rank_by=st.sampled_from(["torque", "margin", "life", "size"]),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(app=applications)
def test_screen_agrees_with_evaluate(catalog: Catalog, app: Application) -> None:
    s = screen(app, catalog.table)
    for pos, index in enumerate(s.index):
        ev = evaluate(app, catalog.screws[index])
        assert bool(s.passed[pos]) == ev.passed, ev.screw.id
        assert math.isclose(s.max_utilization[pos], ev.max_utilization, rel_tol=1e-9)
        assert math.isclose(s.total_torque_nm[pos], ev.torque.total_nm, rel_tol=1e-12)
        screened_fails = {name for name, mask in s.failed_by_check.items() if mask[pos]}
        assert screened_fails == {c.name for c in ev.failed_checks}, ev.screw.id


@pytest.mark.parametrize("rank_by", ["torque", "margin", "life", "size"])
def test_select_equals_evaluating_everything(catalog: Catalog, rank_by: str) -> None:
    """Ranking from the screen equals sorting full evaluations by the documented key."""
    app = Application(
        load_n=150.0,
        speed_m_s=0.04,
        length_m=0.6,
        rank_by=rank_by,  # type: ignore[arg-type]
        limit=100,
    )
    everything = [evaluate(app, s) for s in catalog.screws]
    passing = [e for e in everything if e.passed]
    key = {
        "torque": lambda e: (e.torque.total_nm, e.max_utilization),
        "margin": lambda e: (e.max_utilization, e.torque.total_nm),
        "life": lambda e: (-(e.life.travel_min_m if e.life else 0.0), e.torque.total_nm),
        "size": lambda e: (e.screw.outer_diameter_m, e.torque.total_nm),
    }[rank_by]
    expected = [e.screw.id for e in sorted(passing, key=key)][:100]
    result = select(app, catalog.table)
    assert [e.screw.id for e in result.candidates] == expected
    assert result.passed == len(passing)
    assert result.evaluated == len(everything)
