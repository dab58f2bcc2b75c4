"""Euler column buckling (app.core.formulas.buckling) against published examples, and its
remedies."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import buckling
from tests.core.conftest import FIXITIES, STEEL_E


@pytest.mark.parametrize(
    ("e_pa", "i_m4", "length_m", "fixity", "f_cr_n"),
    [
        pytest.param(69e9, 241e-8, 5.0, "fixed-fixed", 263e3, id="engineeringtoolbox-263kN"),
        pytest.param(10e9, 400e-8, 5.0, "fixed-fixed", 63e3, id="engineeringprep-410-63kN"),
    ],
)
def test_euler_worked_examples(
    e_pa: float, i_m4: float, length_m: float, fixity: str, f_cr_n: float
) -> None:
    """Engineering ToolBox, "Euler's Column Formula", example "A column fixed in both ends"
    (engineeringtoolbox.com/euler-column-formula-d_1813.html): aluminium, E 69 GPa,
    I = 241e-8 m^4, L 5 m, n = 4 -> 262,594 N = 263 kN (engineering.md section 9).
    engineeringprep.com problem 410 "Column": E 10 GPa, I 400 cm^4, L 5 m, fixed-fixed
    (K = 0.5) -> 63 kN."""
    assert buckling.euler_critical_load(e_pa, i_m4, length_m, fixity) == pytest.approx(
        f_cr_n, rel=0.01
    )


def test_misumi_allowable_axial_load_example() -> None:
    """MISUMI, Economy Series e-catalog 2025, "Selection of Ball Screws 2", 4. Allowable
    Axial Load, calculation example (p. 1676, th.c.misumi-ec.com): root diameter 12.5 mm,
    fixed-support, 820 mm between buckling points, E 2.06e5 N/mm^2, safety 0.5:
    P = m d^4 / l^2 x 1e4 = 10 x 12.5^4 / 820^2 x 1e4 = 3630 N."""
    f_cr = buckling.euler_critical_load(
        STEEL_E, buckling.second_moment_round(0.0125), 0.820, "fixed-simple"
    )
    assert buckling.allowed_buckling_load(f_cr, 0.5) == pytest.approx(3630.0, rel=0.01)


def test_makishinko_screw_jack_allowable_buckling_load() -> None:
    """Makishinko, "All products guide", screw jacks E-19 "Allowable axial direction load",
    example JA050 (makishinko.co.jp/catalog/pageindices/index226.html): root d 31.5 mm,
    I = pi 31.5^4 / 64 = 48329 mm^4, L 1000 mm, fixed-free n_f = 1/4, E 2.06e5 N/mm^2,
    safety factor 0.25 -> W = 6135 N (6.1 kN)."""
    i_m4 = buckling.second_moment_round(0.0315)
    assert i_m4 == pytest.approx(48329e-12, rel=0.01)
    f_cr = buckling.euler_critical_load(STEEL_E, i_m4, 1.0, "fixed-free")
    assert buckling.allowed_buckling_load(f_cr, 0.25) == pytest.approx(6135.0, rel=0.01)


@pytest.mark.parametrize(
    ("fixity", "thk_eta2", "rel"),
    [
        pytest.param("fixed-simple", 10.0, 0.01, id="fixed-supported-10"),
        pytest.param("fixed-fixed", 20.0, 0.01, id="fixed-fixed-20"),
        pytest.param("fixed-free", 1.3, 0.045, id="fixed-free-1.3-THK-rounds-1.25-up"),
    ],
)
def test_thk_buckling_load_factors(fixity: str, thk_eta2: float, rel: float) -> None:
    """THK Ball Screw "Permissible Axial Load", eq. (5) (catalog A15-30): P1 = eta1 pi^2 E I
    / la^2 x 0.5 = eta2 d1^4 / la^2 x 1e4 [N, mm], E 2.06e5 N/mm^2, eta1 0.25 / 2 / 4 and
    eta2 1.3 / 10 / 20. The core gives 1.248 / 9.98 / 19.96: THK prints fixed-free as 1.3,
    4 % above the Euler value; the other two agree within 0.2 %."""
    d_mm, la_mm = 20.0, 1000.0
    f_cr = buckling.euler_critical_load(
        STEEL_E, buckling.second_moment_round(d_mm / 1000), la_mm / 1000, fixity
    )
    eta2 = buckling.allowed_buckling_load(f_cr, 0.5) * la_mm**2 / d_mm**4 / 1e4
    assert eta2 == pytest.approx(thk_eta2, rel=rel)


@pytest.mark.parametrize(
    ("fixity", "k"),
    [
        pytest.param("fixed-free", 0.25, id="fixed-free"),
        pytest.param("simple-simple", 1.0, id="simple-simple"),
        pytest.param("fixed-simple", 2.0, id="fixed-simple"),
        pytest.param("fixed-fixed", 4.0, id="fixed-fixed"),
    ],
)
def test_end_fixity_k_table(fixity: str, k: float) -> None:
    """engineering.md section 5: F_cr = k pi^2 E I / L^2 with k 0.25 / 1 / 2 / 4."""
    assert buckling.euler_critical_load(1.0, 1.0, 1.0, fixity) == pytest.approx(k * math.pi**2)


def test_second_moment_of_a_round_section() -> None:
    """I = pi d^4 / 64: 20 mm -> 7854 mm^4."""
    assert buckling.second_moment_round(0.02) == pytest.approx(7.854e-9, rel=1e-4)


diameters = st.floats(2e-3, 0.05)
lengths = st.floats(0.05, 4.0)
fixities = st.sampled_from(FIXITIES)


@given(d=diameters, length=lengths, fixity=fixities, factor=st.floats(1.01, 4.0))
def test_buckling_load_falls_with_length_squared(
    d: float, length: float, fixity: str, factor: float
) -> None:
    i = buckling.second_moment_round(d)
    short = buckling.euler_critical_load(STEEL_E, i, length, fixity)
    long = buckling.euler_critical_load(STEEL_E, i, factor * length, fixity)
    assert long == pytest.approx(short / factor**2, rel=1e-9)


@given(d=diameters, length=lengths, fixity=fixities, load=st.floats(1.0, 1e5))
def test_max_length_remedy_brings_utilization_to_one(
    d: float, length: float, fixity: str, load: float
) -> None:
    """At the returned column length the load equals the allowed load."""
    i = buckling.second_moment_round(d)
    allowed = buckling.allowed_buckling_load(
        buckling.euler_critical_load(STEEL_E, i, length, fixity), 0.5
    )
    l_max = buckling.max_length_for_load(length, allowed, load)
    at_max = buckling.allowed_buckling_load(
        buckling.euler_critical_load(STEEL_E, i, l_max, fixity), 0.5
    )
    assert load / at_max == pytest.approx(1.0, rel=1e-9)


@given(
    d=diameters,
    length=lengths,
    fixity=fixities,
    yield_pa=st.none() | st.floats(200e6, 900e6),
    ratio=st.floats(0.05, 20.0),
)
def test_min_root_diameter_carries_the_critical_load_it_is_asked_for(
    d: float, length: float, fixity: str, yield_pa: float | None, ratio: float
) -> None:
    """The inverse of ``column_critical_load`` in the diameter, in Euler's range and in
    Johnson's: the column of the returned diameter has the critical load asked for (a
    load ``ratio`` times that of a column of diameter ``d``)."""
    sy = math.nan if yield_pa is None else yield_pa
    wanted = ratio * buckling.column_critical_load(STEEL_E, d, length, fixity, sy)
    d_min = buckling.min_root_diameter_for_column(wanted, STEEL_E, length, fixity, sy)
    at_min = buckling.column_critical_load(STEEL_E, d_min, length, fixity, sy)
    assert at_min == pytest.approx(wanted, rel=1e-9)
