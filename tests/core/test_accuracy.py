"""Positioning accuracy terms (app.core.formulas.accuracy): lead error and thermal growth."""

import pytest

from app.core.formulas import accuracy


@pytest.mark.parametrize(
    ("lead_accuracy", "stroke_m", "error_mm"),
    [
        pytest.param(0.0006, 0.300, 0.18, id="standard-0.0006-over-300mm"),
        pytest.param(0.0001, 0.300, 0.03, id="precision-0.0001-over-300mm"),
        pytest.param(0.0006, 1.000, 0.60, id="standard-over-1m"),
    ],
)
def test_cumulative_lead_error(lead_accuracy: float, stroke_m: float, error_mm: float) -> None:
    """Seed, "Screw Accuracy": lead accuracy .0006 mm/mm standard, up to .0001 mm/mm;
    engineering.md section 8: cumulative lead error = lead accuracy x stroke."""
    assert accuracy.cumulative_lead_error(lead_accuracy, stroke_m) * 1000 == pytest.approx(
        error_mm, rel=1e-9
    )


@pytest.mark.parametrize(
    ("alpha_per_k", "length_m", "delta_k", "growth_mm"),
    [
        pytest.param(17.3e-6, 1.0, 10.0, 0.173, id="303SS-1m-10K"),
        pytest.param(3.3e-5, 0.05, 20.0, 0.033, id="nut-3.3e-5-50mm-20K"),
        pytest.param(17.3e-6, 0.5, -20.0, -0.173, id="303SS-cooling-contracts"),
    ],
)
def test_thermal_growth(
    alpha_per_k: float, length_m: float, delta_k: float, growth_mm: float
) -> None:
    """dL = alpha L dT; 303 stainless 17.3e-6 /C (ASM handbook), nut 3.3e-5 /C (seed, as
    catalogued)."""
    assert accuracy.thermal_growth(alpha_per_k, length_m, delta_k) * 1000 == pytest.approx(
        growth_mm, rel=1e-9
    )
