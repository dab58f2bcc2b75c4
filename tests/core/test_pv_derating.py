"""The permissible PV's temperature and lubrication factors (``formulas.pv_derating``)
against igus's published method.

igus, "iglide plastic bushings - p x v value and lubrication": the permitted p x v is a
heat balance whose only temperature term is Delta T = T_a - T_u (the highest application
temperature less the ambient), so at an ambient T_u the rating (taken at 68 F, iglide H and
T500 material data) keeps (T_a - T_u) / (T_a - 68 F). Table 1.4: lubrication factors dry 1,
at installation 1.3, continuous grease 2, water 4, oil 5.

No published permitted pv at a named raised ambient was found in text; these cases apply
igus's stated relation to its own published ratings and highest temperatures, in the
units igus prints them (F, psi fpm), and compare with the app's factor worked in C."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import pv_derating
from app.core.formulas.declare import formula_of

PSI_FPM_TO_PA_M_S = 6894.757 * 0.3048 / 60.0


def _c(fahrenheit: float) -> float:
    return (fahrenheit - 32.0) / 1.8


@pytest.mark.parametrize(
    ("rating_psi_fpm", "t_max_f", "ambient_f", "derated_psi_fpm"),
    [
        # iglide H: 39,000 psi fpm, upper long-term 392 F; at 212 F: 39,000 x 180 / 324
        (39_000.0, 392.0, 212.0, 21_666.7),
        # iglide T500: 37,700 psi fpm, long-term 482 F; at 302 F: 37,700 x 180 / 414
        (37_700.0, 482.0, 302.0, 16_391.3),
    ],
    ids=["iglide-H-212F", "iglide-T500-302F"],
)
def test_igus_ratings_derated_by_delta_t(
    rating_psi_fpm: float, t_max_f: float, ambient_f: float, derated_psi_fpm: float
) -> None:
    """igus's relation worked in F and the app's factor worked in C agree: the line is
    the same in either scale only because the reference is 68 F = 20 C exactly."""
    by_igus = rating_psi_fpm * (t_max_f - ambient_f) / (t_max_f - 68.0)
    assert by_igus == pytest.approx(derated_psi_fpm, abs=0.1)
    factor = pv_derating.temperature_factor(_c(ambient_f), _c(t_max_f))
    app_pa_m_s = rating_psi_fpm * PSI_FPM_TO_PA_M_S * factor
    assert app_pa_m_s == pytest.approx(derated_psi_fpm * PSI_FPM_TO_PA_M_S, rel=1e-5)


def test_the_seed_polyacetal_nut_at_a_warm_cabinet() -> None:
    """The seed nut (93 C highest, catalog) in a 45 C cabinet keeps (93 - 45) / (93 - 20)
    = 0.658 of its rating; at 93 C none."""
    assert pv_derating.temperature_factor(45.0, 93.0) == pytest.approx(48.0 / 73.0)
    assert pv_derating.temperature_factor(93.0, 93.0) == 0.0


@given(
    ambient_c=st.floats(-60.0, 400.0),
    max_c=st.floats(25.0, 350.0),
    warmer_k=st.floats(0.0, 100.0),
)
def test_the_factor_is_a_share_that_falls_with_the_ambient(
    ambient_c: float, max_c: float, warmer_k: float
) -> None:
    """Between 0 and 1, never rising with the ambient, and the array form equal to the
    scalar one."""
    f = pv_derating.temperature_factor(ambient_c, max_c)
    warmer = pv_derating.temperature_factor(ambient_c + warmer_k, max_c)
    assert 0.0 <= warmer <= f <= 1.0
    arrays = pv_derating.temperature_factors(ambient_c, np.array([max_c, np.nan]))
    assert arrays[0] == pytest.approx(f, abs=1e-12) and arrays[1] == 1.0


def test_no_credit_below_the_reference_and_none_left_past_the_highest() -> None:
    assert _c(68.0) == pytest.approx(pv_derating.REFERENCE_C)
    assert pv_derating.temperature_factor(-20.0, 93.0) == 1.0
    assert pv_derating.temperature_factor(150.0, 93.0) == 0.0
    assert math.isclose(pv_derating.temperature_factor(56.5, 93.0), 0.5)


def test_lubrication_factors_follow_igus_table_1_4_on_the_safe_side() -> None:
    """Dry 1 (igus 1); greased 1.3 (igus: greased at installation; continuous grease
    would be 2); oiled 2 (BNB's 'as much as 100 %', under igus's 5 for continuous oil)."""
    factors = {k: v[0] for k, v in pv_derating.LUBRICATION_FACTORS.items()}
    assert factors == {"dry": 1.0, "greased": 1.3, "oiled": 2.0}
    igus = {"dry": 1.0, "greased": (1.3, 2.0), "oiled": 5.0}
    assert factors["greased"] == igus["greased"][0] <= factors["oiled"] <= igus["oiled"]
    assert all(v[1] == "vendor" for v in pv_derating.LUBRICATION_FACTORS.values())


def test_the_formula_is_declared_with_its_source() -> None:
    declared = formula_of(pv_derating.temperature_factor)
    assert "T_max - T_ambient" in declared.text and "igus" in declared.source


@given(
    ambient_c=st.floats(-60.0, pv_derating.REFERENCE_C),
    max_c=st.floats(-60.0, 400.0),
)
def test_up_to_the_reference_ambient_the_array_form_skips_to_one(
    ambient_c: float, max_c: float
) -> None:
    """At an ambient up to the reference the array form answers 1 without working the
    share out; the clipped share it skips is 1 there too, to the bit (above the
    reference, below it, at it and unknown)."""
    highest = np.array([max_c, pv_derating.REFERENCE_C, np.nan])
    span = highest - pv_derating.REFERENCE_C
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.clip((highest - ambient_c) / span, 0.0, 1.0)
    worked_out = np.where(np.isfinite(share) & (span > 0), share, 1.0)
    skipped = pv_derating.temperature_factors(ambient_c, highest)
    assert skipped.tobytes() == worked_out.tobytes()
    assert skipped.tolist() == [1.0, 1.0, 1.0]
