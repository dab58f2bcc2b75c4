"""A ball nut on a short stroke, under 3 nut lengths, is rated at HIWIN's operating
condition factor for short strokes, 3.0 to 5.0 (HIWIN GmbH, Ballscrews & Accessories,
BS-08-2-EN-1704-K, F 3.8), not at the 1.2 of smooth operation: its balls roll over few
circuits. The L10 falls as the cube of the factor, (1.2 / 3)^3 = 0.064 of it.

R16-05T3-FSIDIN (Ca 6500 N, a 40 mm nut with play, lead 5 mm), 1000 N over the stroke,
1000 cycles a day:

- 100 mm (under 3 x 40 mm): L10 = (6500 / (3.0 x 1000))^3 x 10^6 = 10.171e6 revolutions;
  2 x 100 / 5 = 40 revolutions a cycle, 1.46e7 a year: 0.6966 years, short of 1 required;
- 200 mm: (6500 / (1.2 x 1000))^3 x 10^6 = 158.93e6 revolutions over 2.92e7 a year:
  5.443 years.
"""

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.model import Application


def _life(catalog: Catalog, stroke_m: float) -> CheckResult:
    app = Application(
        load_n=1000.0, speed_m_s=0.1, length_m=0.5, stroke_m=stroke_m, cycles_per_day=1000.0,
        required_life_years=1.0,
    )  # fmt: skip
    checks = evaluate(app, catalog.by_id["R16-05T3-FSIDIN"]).checks
    return next(c for c in checks if c.name == "ball_life")


@pytest.mark.parametrize(
    ("stroke_m", "factor", "years"),
    [(0.1, 3.0, 0.6966), (0.2, 1.2, 5.443)],
    ids=["short-stroke", "long-stroke"],
)
def test_a_short_stroke_rates_the_ball_nut_at_hiwins_short_stroke_factor(
    catalog: Catalog, stroke_m: float, factor: float, years: float
) -> None:
    revolutions = (6500.0 / (factor * 1000.0)) ** 3 * 1e6
    per_year = 2.0 * stroke_m / 0.005 * 1000.0 * 365.0
    assert revolutions / per_year == pytest.approx(years, rel=1e-3)
    life = _life(catalog, stroke_m)
    assert life.capacity == pytest.approx(revolutions / per_year, rel=1e-9)
    assert life.passed is (years >= 1.0)
    said = render(life.message)
    assert f"times the load factor {factor:g}" in said
    assert ("a stroke under 3 nut lengths" in said) is (factor == 3.0)
