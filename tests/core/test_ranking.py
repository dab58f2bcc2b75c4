"""``select`` ranks from the vectorised screen; its order must equal sorting the full
scalar evaluations by the documented key, for every ranking criterion. (Agreement of the
screen with ``evaluate`` candidate by candidate: test_selection.py.)"""

import dataclasses
import math

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.record import Candidate
from app.core.selection import select

#: the axis every ranking is checked on; ``rank_by`` set per test
APP = Application(load_n=150.0, speed_m_s=0.04, length_m=0.6, limit=100)


@pytest.fixture(scope="module")
def everything(catalog: Catalog) -> list[Candidate]:
    """The full scalar evaluation of every screw of the catalog, made once for the four
    rankings: ``evaluate`` reads no ``rank_by`` (only ``selection`` orders by it)."""
    return [evaluate(APP, s) for s in catalog.screws]


# one xdist worker evaluates the catalog for the four (``--dist loadgroup``)
@pytest.mark.xdist_group("ranking-evaluations")
@pytest.mark.parametrize("rank_by", ["torque", "margin", "life", "size"])
def test_select_equals_evaluating_everything(
    catalog: Catalog, everything: list[Candidate], rank_by: str
) -> None:
    """Ranking from the screen equals sorting full evaluations by the documented key."""
    app = dataclasses.replace(APP, rank_by=rank_by)  # type: ignore[arg-type]
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
    # a candidate with a warning (failed advice: a bronze nut run dry) comes after those
    # without, whatever the policy
    expected = [e.screw.id for e in sorted(passing, key=lambda e: (bool(e.warned), key(e)))][:100]
    result = select(app, catalog.index)
    assert [e.screw.id for e in result.candidates] == expected
    assert result.passed == len(passing)
    assert result.evaluated == len(everything)
