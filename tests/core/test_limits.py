"""A family's band table and temperature range (app.core.formulas.limits), on the seed's data."""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import limits

#: Seed "Traverse Speed" table as the seed family's catalog data gives it.
SEED_BANDS = ((0.0025, 0.012, 0.100), (0.012, 0.025, 0.250), (0.025, 0.060, 0.760))


@pytest.mark.parametrize(
    ("lead_mm", "speed_mm_s", "extrapolated"),
    [
        pytest.param(2.5, 100, False, id="2.5mm-band-start"),
        pytest.param(8.0, 100, False, id="8mm"),
        pytest.param(11.99, 100, False, id="just-below-12"),
        pytest.param(12.0, 250, False, id="12mm-edge-faster-band"),
        pytest.param(20.0, 250, False, id="20mm"),
        pytest.param(25.0, 760, False, id="25mm-edge-faster-band"),
        pytest.param(25.4, 760, False, id="1in"),
        pytest.param(60.0, 760, False, id="60mm-table-end"),
        pytest.param(1.0, 100, True, id="1mm-below-table"),
        pytest.param(2.49, 100, True, id="just-below-2.5"),
        pytest.param(60.1, 760, True, id="just-above-60"),
        pytest.param(100.0, 760, True, id="100mm-above-table"),
    ],
)
def test_seed_traverse_speed_table(lead_mm: float, speed_mm_s: float, extrapolated: bool) -> None:
    """Seed "Traverse Speed" table: lead 2.5-12 mm: 100 mm/s; 12-25 mm: 250 mm/s;
    25-60 mm: 760 mm/s. engineering.md section 7: band edges (12, 25) belong to the faster
    band; leads outside 2.5-60 mm take the nearest band and are marked extrapolated."""
    result = limits.band_limit(lead_mm / 1000, SEED_BANDS)
    assert result.speed_m_s == pytest.approx(speed_mm_s / 1000)
    assert result.extrapolated is extrapolated
    assert limits.band_speed_m_s(lead_mm / 1000, SEED_BANDS) == pytest.approx(speed_mm_s / 1000)


@given(st.floats(1e-4, 0.2), st.floats(1e-4, 0.2))
def test_traverse_limit_never_falls_with_a_longer_lead(a: float, b: float) -> None:
    """The seed's table is monotone: a longer lead is never allowed a lower speed."""
    short, long = sorted((a, b))
    assert limits.band_speed_m_s(short, SEED_BANDS) <= limits.band_speed_m_s(long, SEED_BANDS)


@pytest.mark.parametrize(
    ("ambient_c", "ok"),
    [
        pytest.param(0.0, True, id="0C-lower-edge"),
        pytest.param(20.0, True, id="20C"),
        pytest.param(93.0, True, id="93C-upper-edge"),
        pytest.param(-0.1, False, id="below-0C"),
        pytest.param(93.5, False, id="above-93C"),
    ],
)
def test_seed_temperature_range(ambient_c: float, ok: bool) -> None:
    """Seed, physical properties: standard operating temperature 32-200 F (0-93 C)."""
    assert limits.temperature_ok(ambient_c, 0.0, 93.0) is ok
