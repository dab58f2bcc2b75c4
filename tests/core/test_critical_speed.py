"""Critical (whirling) speed from beam theory (app.core.formulas.critical_speed) and its
remedies."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.formulas import critical_speed as cs
from app.core.formulas import geometry
from app.core.model import Application
from tests.core.conftest import FIXITIES, IN, SS303_E, SS303_RHO, STEEL_E, STEEL_RHO


def test_thomson_476_rpm() -> None:
    """Thomson, "Screw critical speed (maximum RPM) calculation"
    (thomsonlinear.com/en/training/ball_screws/screw_critical_speed): n_c = C_s x 4.76e6 x
    d_r / L^2 [rpm, in]; engineering.md section 9: steel, simple-simple, d_r 1 in, L 100 in
    -> 476 rpm."""
    n = cs.critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, "simple-simple")
    assert n == pytest.approx(476.0, rel=0.01)


@pytest.mark.parametrize(
    ("fixity", "beta_over_pi_sq"),
    [
        pytest.param("fixed-free", 0.356, id="fixed-free"),
        pytest.param("simple-simple", 1.000, id="simple-simple"),
        pytest.param("fixed-simple", 1.562, id="fixed-simple"),
        pytest.param("fixed-fixed", 2.267, id="fixed-fixed"),
    ],
)
def test_end_fixity_factor_is_beta_over_pi_squared(fixity: str, beta_over_pi_sq: float) -> None:
    """engineering.md section 4, end-fixity table, column (beta / pi)^2 (Blevins table 8-1):
    the core's n_c relative to simple-simple is that factor."""
    ratio = cs.critical_speed_rpm(0.01, 1.0, STEEL_E, STEEL_RHO, fixity) / cs.critical_speed_rpm(
        0.01, 1.0, STEEL_E, STEEL_RHO, "simple-simple"
    )
    assert ratio == pytest.approx(beta_over_pi_sq, abs=5e-4)


@pytest.mark.parametrize(
    ("fixity", "thomson_cs", "rel"),
    [
        pytest.param("fixed-free", 0.36, 0.015, id="fixed-free-0.36"),
        pytest.param("simple-simple", 1.00, 0.01, id="simple-simple-1.00"),
        pytest.param("fixed-simple", 1.47, 0.065, id="fixed-simple-1.47-6pct-below-theory"),
        pytest.param("fixed-fixed", 2.23, 0.02, id="fixed-fixed-2.23-2pct-below-theory"),
    ],
)
def test_thomson_end_fixity_factors(fixity: str, thomson_cs: float, rel: float) -> None:
    """Thomson training page "Screw critical speed" end fixity factors C_s 0.36 / 1.00 /
    1.47 / 2.23 (also fxsolver "Critical speed for a leadscrew"). The beam's eigenvalues
    give (beta/pi)^2 = 0.356 / 1 / 1.562 / 2.267: Thomson's fixed-simple factor is 6 % and
    its fixed-fixed factor 2 % below the beam's, which is that much less conservative
    there (engineering.md section 4 lists both columns; a leadscrew is rated at the lower,
    ``test_a_leadscrews_rating_is_thomsons``). Tolerance per row is the measured gap; the
    beam must never fall below Thomson by more than rounding."""
    n_fix = cs.critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, fixity)
    thomson = thomson_cs * 4.76e6 * 1.0 / 100.0**2
    assert n_fix == pytest.approx(thomson, rel=rel)
    assert n_fix >= thomson * 0.985


@pytest.mark.parametrize(
    ("fixity", "thomson_cs"),
    [
        pytest.param("fixed-free", 0.36, id="fixed-free-0.36"),
        pytest.param("simple-simple", 1.00, id="simple-simple-1.00"),
        pytest.param("fixed-simple", 1.47, id="fixed-simple-1.47"),
        pytest.param("fixed-fixed", 2.23, id="fixed-fixed-2.23"),
    ],
)
def test_a_leadscrews_rating_is_thomsons(fixity: str, thomson_cs: float) -> None:
    """A leadscrew (not a ball screw) is rated at the lower of the beam's and Thomson's
    C_s x 4.76e6 d_r / L^2 [rpm, in]: 1 in root, 100 in, C_s x 476 rpm, within 1 % (the
    steel's E / rho against Thomson's constant) and never above it (fixed-free: the beam's
    0.356 is below Thomson's 0.36). Fixed-simple: the simple-simple beam's 475.2 rpm x
    1.47 = 698.5 rpm against Thomson's 1.47 x 476 = 699.7 rpm."""
    rated = cs.rated_critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, fixity, False)
    thomson = thomson_cs * 4.76e6 * 1.0 / 100.0**2
    assert rated == pytest.approx(thomson, rel=0.015 if fixity == "fixed-free" else 0.01)
    assert rated <= thomson
    simple = cs.critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, "simple-simple")
    beam = cs.critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, fixity)
    assert rated == pytest.approx(min(beam, thomson_cs * simple), rel=1e-12)


def test_misumi_allowable_rotational_speed_example() -> None:
    """MISUMI, Economy Series e-catalog 2025, "Selection of Ball Screws 2", 5-1 Critical
    Speed, Allowable Rotational Speed Calculation Example (p. 1677, th.c.misumi-ec.com):
    root diameter 12.5 mm, fixed-support, distance 790 mm, E 2.06e5 N/mm^2, specific
    gravity 7.8e-6 kg/mm^3, safety factor 0.8 -> N_c = 15.1 x 12.5 / 790^2 x 1e7 = 3024 rpm."""
    n_c = cs.critical_speed_rpm(0.0125, 0.790, STEEL_E, 7800.0, "fixed-simple")
    assert cs.allowed_speed_rpm(n_c, 0.8) == pytest.approx(3024.0, rel=0.01)


@pytest.mark.parametrize(
    ("fixity", "thk_lambda1", "thk_lambda2"),
    [
        pytest.param("fixed-free", 1.875, 3.4, id="fixed-free"),
        pytest.param("simple-simple", 3.142, 9.7, id="supported-supported"),
        pytest.param("fixed-simple", 3.927, 15.1, id="fixed-supported"),
        pytest.param("fixed-fixed", 4.73, 21.9, id="fixed-fixed"),
    ],
)
def test_thk_permissible_rotational_speed_factors(
    fixity: str, thk_lambda1: float, thk_lambda2: float
) -> None:
    """THK Ball Screw "Point of Selection: Permissible Rotational Speed", eq. (7)
    (thk.com/.../ball_screw/selection/0007, catalog A15-32): N1 = 60 l1^2 / (2 pi lb^2)
    sqrt(E 1e3 I / (gamma A)) x 0.8 = l2 d1 / lb^2 x 1e7 [rpm, mm], E 2.06e5 N/mm^2,
    gamma 7.85e-6 kg/mm^3. The core's beta equals l1; 0.8 n_c equals l2 printed to 0.1."""
    assert cs.END_FIXITY_BETA[fixity] == pytest.approx(thk_lambda1, abs=5e-4)
    d1_mm, lb_mm = 20.0, 1000.0
    n1 = cs.allowed_speed_rpm(
        cs.critical_speed_rpm(d1_mm / 1000, lb_mm / 1000, STEEL_E, STEEL_RHO, fixity), 0.8
    )
    assert n1 * lb_mm**2 / d1_mm / 1e7 == pytest.approx(thk_lambda2, abs=0.05)


def test_stainless_303_is_slower_than_carbon_steel() -> None:
    """engineering.md section 4: the material matters; n_c scales with sqrt(E / rho):
    303 stainless (193 GPa, 8000) runs at 0.959 of carbon steel (206 GPa, 7850)."""
    ss = cs.critical_speed_rpm(0.01, 1.0, SS303_E, SS303_RHO, "fixed-simple")
    steel = cs.critical_speed_rpm(0.01, 1.0, STEEL_E, STEEL_RHO, "fixed-simple")
    assert ss / steel == pytest.approx(math.sqrt((193 / 8000) / (206 / 7850)), rel=1e-9)
    assert ss / steel == pytest.approx(0.959, abs=5e-4)


def test_allowed_speed_is_the_safety_factor_times_critical() -> None:
    """engineering.md section 4 and Thomson: operate below 80 % of critical speed."""
    assert cs.allowed_speed_rpm(1000.0, 0.8) == pytest.approx(800.0)


diameters = st.floats(2e-3, 0.05)
lengths = st.floats(0.05, 4.0)
fixities = st.sampled_from(FIXITIES)


@given(d=diameters, length=lengths, fixity=fixities, factor=st.floats(1.01, 4.0))
def test_critical_speed_falls_with_length(
    d: float, length: float, fixity: str, factor: float
) -> None:
    """n_c ~ 1 / L^2."""
    short = cs.critical_speed_rpm(d, length, SS303_E, SS303_RHO, fixity)
    long = cs.critical_speed_rpm(d, factor * length, SS303_E, SS303_RHO, fixity)
    assert long < short
    assert long == pytest.approx(short / factor**2, rel=1e-9)


@given(d=diameters, length=lengths, fixity=fixities, factor=st.floats(1.01, 4.0))
def test_critical_speed_rises_with_root_diameter(
    d: float, length: float, fixity: str, factor: float
) -> None:
    """n_c ~ d_r (sqrt(I / A) = d_r / 4)."""
    thin = cs.critical_speed_rpm(d, length, SS303_E, SS303_RHO, fixity)
    thick = cs.critical_speed_rpm(factor * d, length, SS303_E, SS303_RHO, fixity)
    assert thick > thin
    assert thick == pytest.approx(factor * thin, rel=1e-9)


@given(d=diameters, length=lengths)
def test_critical_speed_rises_with_stiffer_fixity(d: float, length: float) -> None:
    """fixed-free < simple-simple < fixed-simple < fixed-fixed."""
    speeds = [cs.critical_speed_rpm(d, length, SS303_E, SS303_RHO, f) for f in FIXITIES]
    assert speeds == sorted(speeds)
    assert len(set(speeds)) == len(speeds)


operating = st.floats(10.0, 20_000.0)
allowed = st.floats(10.0, 20_000.0)


@given(d=diameters, length=lengths, fixity=fixities, rpm=operating, sf=st.floats(0.5, 1.0))
def test_max_length_remedy_brings_utilization_to_one(
    d: float, length: float, fixity: str, rpm: float, sf: float
) -> None:
    """Seed: "increase bearing mount support" (shorter span): at the returned length the
    operating speed is exactly the allowed speed."""
    n_allowed = cs.allowed_speed_rpm(cs.critical_speed_rpm(d, length, 193e9, 8e3, fixity), sf)
    l_max = cs.max_length_for_speed(length, n_allowed, rpm)
    at_max = cs.allowed_speed_rpm(cs.critical_speed_rpm(d, l_max, 193e9, 8e3, fixity), sf)
    assert rpm / at_max == pytest.approx(1.0, rel=1e-9)


@given(d=diameters, length=lengths, fixity=fixities, rpm=operating, sf=st.floats(0.5, 1.0))
def test_min_root_diameter_remedy_brings_utilization_to_one(
    d: float, length: float, fixity: str, rpm: float, sf: float
) -> None:
    """Seed: "choose a larger diameter"."""
    n_allowed = cs.allowed_speed_rpm(cs.critical_speed_rpm(d, length, 193e9, 8e3, fixity), sf)
    d_min = cs.min_root_diameter_for_speed(d, n_allowed, rpm)
    at_min = cs.allowed_speed_rpm(cs.critical_speed_rpm(d_min, length, 193e9, 8e3, fixity), sf)
    assert rpm / at_min == pytest.approx(1.0, rel=1e-9)


@given(
    d=diameters,
    length=lengths,
    fixity=fixities,
    rpm=operating,
    ball=st.booleans(),
    scale=st.floats(0.3, 3.0),
)
def test_the_rated_speed_keeps_the_remedies_scaling(
    d: float, length: float, fixity: str, rpm: float, ball: bool, scale: float
) -> None:
    """The rating's makers' factor is constant for an end fixity (a leadscrew's C_s, a
    ball screw's HIWIN f_n, each against the beam's d_r / L^2), so the rated speed keeps
    n_c ~ d_r / L^2: the shortest-length and the least-root remedies bring the rated
    utilisation to one."""

    def rated(d_r: float, span: float) -> float:
        n_c = cs.rated_critical_speed_rpm(d_r, span, 207e9, 7800.0, fixity, ball)
        return cs.allowed_speed_rpm(float(n_c), 0.8)

    n_allowed = rated(d, length)
    l_max = cs.max_length_for_speed(length, n_allowed, rpm)
    assert rpm / rated(d, l_max) == pytest.approx(1.0, rel=1e-9)
    d_min = cs.min_root_diameter_for_speed(d, n_allowed, rpm)
    assert rpm / rated(d_min, length) == pytest.approx(1.0, rel=1e-9)
    assert rated(d, scale * length) == pytest.approx(n_allowed / scale**2, rel=1e-9)


@given(speed=st.floats(1e-3, 1.0), n_allowed=allowed)
def test_min_lead_remedy_brings_utilization_to_one(speed: float, n_allowed: float) -> None:
    """Seed: "use a longer lead": at the returned lead n = 60 v / lead is the allowed speed."""
    lead = cs.min_lead_for_speed(speed, n_allowed)
    assert geometry.screw_speed_rpm(speed, lead) / n_allowed == pytest.approx(1.0, rel=1e-9)


#: HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, F 3.27: n_k = 2.71e8 f_n d_k /
#: l_s^2 [rpm, mm], f_n 1.0 fixed-fixed, 0.692 fixed-simple, 0.446 simple-simple, 0.147
#: fixed-free.
HIWIN_FN = {"fixed-fixed": 1.0, "fixed-simple": 0.692, "simple-simple": 0.446, "fixed-free": 0.147}


@pytest.mark.parametrize("fixity", list(HIWIN_FN))
def test_a_ball_screws_critical_speed_is_at_most_hiwins(catalog: Catalog, fixity: str) -> None:
    """R20-05K4-FSC (HIWIN, 17.32 mm root, E 207 GPa, 7800 kg/m^3) over 1000 mm: its
    critical speed is the lower of the beam's and HIWIN's F 3.27, so never above HIWIN's;
    the beam alone is 8.1 % above it fixed-free (HIWIN's fixed end is not rigid) and
    up to 1.5 % above at the other ends (its E / rho against HIWIN's constant)."""
    screw = catalog.by_id["R20-05K4-FSC"]
    d_mm, l_mm = 17.32, 1000.0
    hiwin = 2.71e8 * HIWIN_FN[fixity] * d_mm / l_mm**2
    assert cs.ball_screw_critical_speed_rpm(d_mm / 1e3, l_mm / 1e3, fixity) == pytest.approx(
        hiwin, rel=1e-12
    )
    beam = cs.critical_speed_rpm(d_mm / 1e3, l_mm / 1e3, screw.youngs_modulus_pa,
                                 screw.density_kg_m3, fixity)  # fmt: skip
    app = Application(load_n=1.0, speed_m_s=0.01, length_m=l_mm / 1e3, end_fixity=fixity)
    ours = evaluate(app, screw).quantities.column.critical_rpm
    assert ours == pytest.approx(min(beam, hiwin), rel=1e-12)
    assert ours <= hiwin * (1.0 + 1e-12)
    if fixity == "fixed-free":
        assert beam / hiwin == pytest.approx(1.081, abs=0.005)
    else:
        assert beam / hiwin == pytest.approx(1.0, abs=0.02)
