"""Anti-backlash nut life converted to service years (app.core.formulas.life)."""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import life

MILLION_CM = 1e6 * 0.01  # m


@pytest.mark.parametrize(
    ("rated_million_cm", "stroke_m", "cycles_per_day", "years"),
    [
        pytest.param(100, 0.1, 100, 137.0, id="ZBX4000-uncoated-low-100Mcm"),
        pytest.param(500, 0.3, 200, 114.2, id="ZBX4000-TFE-high-500Mcm"),
        pytest.param(500, 0.3, 200 * 24, 4.757, id="VHD-uncoated-low-24h-duty"),
    ],
)
def test_life_years_from_the_seed_life_table(
    rated_million_cm: float, stroke_m: float, cycles_per_day: float, years: float
) -> None:
    """engineering.md section 8: life in years = life distance / (stroke x 2 x cycles per
    year), seed anti-backlash life table in million cm (1 million cm = 10 km). Hand
    arithmetic: 1e6 m / (2 x 0.1 m x 100 x 365) = 137.0 years."""
    travel = rated_million_cm * MILLION_CM
    assert life.life_years(travel, stroke_m, cycles_per_day) == pytest.approx(years, rel=1e-3)


def test_one_cycle_is_out_and_back() -> None:
    """A cycle travels the stroke twice: 0.1 m x 2 x 100 a day x 365 = 7300 m a year."""
    assert life.travel_per_year(0.1, 100.0) == pytest.approx(7300.0)


@given(
    travel=st.floats(1e5, 1e8),
    stroke=st.floats(1e-3, 4.0),
    cycles=st.floats(1.0, 1e5),
    k=st.floats(1.01, 10.0),
)
def test_life_is_inversely_proportional_to_stroke_and_duty(
    travel: float, stroke: float, cycles: float, k: float
) -> None:
    base = life.life_years(travel, stroke, cycles)
    assert life.life_years(travel, k * stroke, cycles) == pytest.approx(base / k, rel=1e-9)
    assert life.life_years(travel, stroke, k * cycles) == pytest.approx(base / k, rel=1e-9)
    assert life.life_years(k * travel, stroke, cycles) == pytest.approx(base * k, rel=1e-9)
