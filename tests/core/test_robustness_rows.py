"""Which variant rows a select screens with its candidates (``index.Eligible.joint``):
those that move only values the nut's wear life alone reads (``wear_life.WEAR_ONLY``)
are left out where no life is judged, and the robustness found is the same as with every
variant row screened."""

from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.core.checks.wear_life import WEAR_ONLY
from app.core.model import Application
from app.core.robustness import robustness
from app.core.selection import select

AXES = {
    "default": Application(load_n=100.0, speed_m_s=0.05, length_m=0.5, lead_m=0.01),
    "stroke-no-life": Application(
        load_n=300.0, speed_m_s=0.1, length_m=0.6, stroke_m=0.4, cycles_per_day=2000.0
    ),
    "vertical-any-lead": Application(
        load_n=50.0, speed_m_s=0.05, length_m=0.4, orientation="vertical", moving_mass_kg=5.0
    ),
}


@pytest.mark.parametrize("name", sorted(AXES))
def test_without_a_judged_life_the_wear_rows_change_no_robustness(
    catalog: Catalog, name: str
) -> None:
    """Every returned candidate's robustness as a select finds it (its wear-only variant
    rows left out) equals the robustness of all its variant rows screened."""
    app, index = AXES[name], catalog.index
    joint = index.eligible(app).joint
    if joint is not None:
        assert not any(moved <= WEAR_ONLY for moved in joint.variants.moved)
    sel = select(replace(app, limit=30), index)
    variants = index.variants
    assert variants is not None and sel.candidates
    positions = [index.positions[c.screw.id] for c in sel.candidates]
    every = robustness(app, variants, positions)
    assert [(c.robust, c.hinges_on) for c in sel.candidates] == [
        (r.robust, r.hinges_on) for r in every
    ]


def test_with_a_judged_life_the_wear_rows_are_screened(catalog: Catalog) -> None:
    """A required life and a duty: the wear rows are among those screened."""
    app = Application(
        load_n=100.0,
        speed_m_s=0.05,
        length_m=0.5,
        lead_m=0.01,
        stroke_m=0.3,
        cycles_per_day=2000.0,
        required_life_years=1.0,
    )
    joint = catalog.index.eligible(app).joint
    assert joint is not None
    assert any(moved <= WEAR_ONLY for moved in joint.variants.moved)
