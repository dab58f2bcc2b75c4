"""Positioning accuracy (app.core.formulas.accuracy, app.core.checks.accuracy): lead error,
thermal growth, a ball screw's ISO 3408-3 class over the stroke, and the terms a catalog
does not give."""

import math

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core.batch import CheckResult
from app.core.evaluate import evaluate
from app.core.formulas import accuracy
from app.core.phrase import Phrase
from tests.core.conftest import light_app


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


#: HIWIN BS-08-2-EN-1704-K Table 3.4, class T3 (peeled and ground): the limit deviation
#: e_p [um] by useful path, rows of (up to [mm], e_p [um]); ISO 3408-3 class P3.
HIWIN_T3 = ((315, 12), (400, 13), (500, 15), (630, 16), (800, 18), (1000, 21), (1250, 24))
T3_BANDS = tuple((lu / 1e3, ep / 1e6) for lu, ep in HIWIN_T3)
#: HIWIN Table 3.3: v300p of the rolled class T7 [m].
T7_V300P_M = 52e-6


@pytest.mark.parametrize(
    ("travel_mm", "ep_um"),
    [
        pytest.param(100.0, 12.0, id="100mm-first-band-not-pro-rated"),
        pytest.param(315.0, 12.0, id="315mm-first-band-bound"),
        pytest.param(320.0, 13.0, id="320mm-second-band"),
        pytest.param(900.0, 21.0, id="900mm-steinmeyer-P3-21um"),
    ],
)
def test_a_positioning_class_reads_its_makers_table(travel_mm: float, ep_um: float) -> None:
    """HIWIN Table 3.4 (T3 = ISO 3408-3 P3): e_p by bands of useful travel, the first
    band's 12 um up to 315 mm (a 100 mm stroke is not 100/300 x 12 = 4 um); Steinmeyer,
    Lead Error over 300 mm: "the admissible deviation ep for such a screw [900 mm, P3] is
    21 um" (not 3 x 12 = 36 um)."""
    got = accuracy.ball_travel_deviation(travel_mm / 1e3, 12e-6, T3_BANDS)
    assert got * 1e6 == pytest.approx(ep_um, rel=1e-12)


def test_beyond_its_table_a_positioning_class_gives_no_lead_error() -> None:
    """Past the last band of the table the class states no e_p: not a number, so the
    accuracy check leaves the term out and says so, rather than extrapolating."""
    assert math.isnan(accuracy.ball_travel_deviation(1.3, 12e-6, T3_BANDS))


@pytest.mark.parametrize(
    ("travel_mm", "ep_um"),
    [
        pytest.param(100.0, 52.0, id="100mm-v300p"),
        pytest.param(150.0, 52.0, id="150mm-2x150-300-v300p"),
        pytest.param(320.0, 2 * 320 / 300 * 52, id="320mm"),
        pytest.param(600.0, 208.0, id="600mm-2x2x52"),
    ],
)
def test_a_transport_class_follows_iso_3408_3(travel_mm: float, ep_um: float) -> None:
    """Rolled T7, v300p 52 um (HIWIN Table 3.3): ISO 3408-3's transport rule
    e_p = 2 (l_u / 300) v300p (Bosch Rexroth RE 83 301 p. 81: its own (l_u / 300) v300p
    is the ISO tolerance 'reduced by half'), never below v300p, the variation allowed
    within any 300 mm (Steinmeyer's rolled T7: 52 um up to 315 mm)."""
    got = accuracy.ball_travel_deviation(travel_mm / 1e3, T7_V300P_M)
    assert got * 1e6 == pytest.approx(ep_um, rel=1e-12)


def _accuracy(catalog: Catalog, screw_id: str, **changes: object) -> CheckResult:
    ev = evaluate(light_app(**changes), catalog.by_id[screw_id])
    return next(c for c in ev.checks if c.name == "accuracy")


@pytest.mark.parametrize(
    ("screw_id", "stroke_mm", "tolerance_mm", "error_mm", "passed"),
    [
        # rolled T7 (v300p 52 um), Table 4.4 play 0.02 mm: 0.052 + 0.02
        pytest.param("R12-05K4-FSCDIN", 100.0, 0.05, 0.052 + 0.02, False, id="T7-100mm"),
        # rolled T7, play 0.04 mm: 2 x (600 / 300) x 0.052 + 0.04
        pytest.param("R16-05T3-FSIDIN", 600.0, 0.15, 0.208 + 0.04, False, id="T7-600mm"),
        # ground T3, preloaded (no play): Table 3.4's 12 um up to 315 mm
        pytest.param("R16-16K2-FSC", 100.0, 0.01, 0.012, False, id="T3-100mm"),
        # ground T3: Table 3.4's 21 um at 800-1000 mm
        pytest.param("R16-16K2-FSC", 900.0, 0.05, 0.021, True, id="T3-900mm"),
    ],
)
def test_a_ball_screws_accuracy_takes_its_class_over_the_stroke(
    catalog: Catalog,
    screw_id: str,
    stroke_mm: float,
    tolerance_mm: float,
    error_mm: float,
    passed: bool,
) -> None:
    """HIWIN BS-08-2-EN-1704-K sec. 3.5.3 and ISO 3408-3, at the 20 C reference (no
    thermal growth): the lead error is the class's e_p over the stroke, not v300p
    pro-rated by stroke / 300 mm (which gave 0.0373, 0.144 and 0.004 mm, passes)."""
    c = _accuracy(
        catalog,
        screw_id,
        length_m=stroke_mm / 1e3 + 0.2,
        stroke_m=stroke_mm / 1e3,
        positioning_tolerance_m=tolerance_mm / 1e3,
    )
    assert c.value == pytest.approx(error_mm / 1e3, rel=1e-9)
    assert c.passed is passed


def test_a_trapezoidal_screws_known_terms_alone_fail_a_tight_tolerance(catalog: Catalog) -> None:
    """Tr22x10(P5)-acetal over a 1500 mm stroke at 60 C, 0.1 mm tolerance: no lead
    accuracy is given for an ISO trapezoidal screw, but its C45 screw grows
    11.7e-6 x 1500 x 40 = 0.702 mm (ASM Metals Handbook) and its nut's play is up to
    0.3 mm (catalog, assumed): 1.002 mm of known error, ten times the tolerance, and the
    growth from its nut's friction heat on top. The check ran before only where a lead
    accuracy is given, so this screw passed."""
    c = _accuracy(
        catalog,
        "Tr22x10(P5)-acetal",
        length_m=1.8,
        stroke_m=1.5,
        ambient_c=60.0,
        positioning_tolerance_m=0.1e-3,
    )
    heated_m = c.message.values["heat"].value
    assert heated_m > 0.0
    assert c.value == pytest.approx((11.7e-6 * 1500 * 40 + 0.3) * 1e-3 + heated_m, rel=1e-9)
    assert not c.passed
    text = render(c.message)
    assert "of the known terms" in text and "even without the lead error" in text
    assert "precision lead grade" not in render(c.fix or Phrase(""))


def test_a_trapezoidal_screws_pass_says_it_leaves_the_lead_error_out(catalog: Catalog) -> None:
    """The same screw against a 2 mm tolerance passes on its known 1.002 mm and the
    growth from its nut's friction heat; its message
    and its verdict's summary say the lead error is left out, and the summary never says
    it passes every check."""
    ev = evaluate(
        light_app(length_m=1.8, stroke_m=1.5, ambient_c=60.0, positioning_tolerance_m=2e-3),
        catalog.by_id["Tr22x10(P5)-acetal"],
    )
    c = next(c for c in ev.checks if c.name == "accuracy")
    heated_m = ev.accuracy.heat_growth_m
    assert heated_m is not None and heated_m > 0.0
    assert c.passed and c.value == pytest.approx(1.002e-3 + heated_m, rel=1e-9)
    assert "leaving out the lead error" in render(c.message)
    summary = render(ev.verdict.summary)
    assert "Positioning accuracy (no lead accuracy)" in summary
    assert "Passes every check" not in summary
    assert [(p.check, p.missing) for p in ev.verdict.partial] == [("accuracy", ("lead accuracy",))]
