"""``select`` ranks from the vectorised screen; its order must equal sorting the full
scalar evaluations by the documented key, for every ranking criterion. (Agreement of the
screen with ``evaluate`` candidate by candidate: test_selection.py.)"""

import math

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.selection import select


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
        # the low end of the life band shown: the seed's rated life, else the wear life;
        # a nut with neither ranks last
        "life": lambda e: (
            -(e.life.travel_min_m if e.life and math.isfinite(e.life.travel_min_m) else 0.0),
            e.torque.total_nm,
        ),
        "size": lambda e: (e.screw.outer_diameter_m, e.torque.total_nm),
    }[rank_by]
    expected = [e.screw.id for e in sorted(passing, key=key)][:100]
    result = select(app, catalog.index)
    assert [e.screw.id for e in result.candidates] == expected
    assert result.passed == len(passing)
    assert result.evaluated == len(everything)
