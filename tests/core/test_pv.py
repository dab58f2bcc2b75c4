"""PV of the plastic nut by the seed's three-thread method (app.core.formulas.pv)."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import geometry, pv
from tests.core.conftest import FT_PER_MIN, IN, LBF, PSI, PSI_FT_MIN


def test_bnb_industries_bushing_pv_arithmetic() -> None:
    """bnb-industries, "Bearing Technical Information - Load Ratings", Measuring Operating
    PV (bnb-industries.com/technical-information-1/): shaft 5/8 in, bearing 1-1/32 in long,
    35 lb, 120 rpm: P = 35 / (0.625 x 1.03125) = 54.3 psi on the projected area d x length,
    V = 0.2618 x 0.625 x 120 = 19.635 ft/min, PV = 1066.2 (engineering.md section 9).

    Through the core in SI: P with contact_pressure over the projected area; V with
    surface_speed over one revolution's surface travel pi d (helix_travel with no lead)."""
    d, length = 0.625 * IN, (1 + 1 / 32) * IN
    p = pv.contact_pressure(35 * LBF, d * length)
    v = pv.surface_speed(120.0, geometry.helix_travel(0.0, d))
    assert p / PSI == pytest.approx(54.3, rel=0.01)
    assert v / FT_PER_MIN == pytest.approx(19.635, rel=0.01)
    assert p * v / PSI_FT_MIN == pytest.approx(1066.2, rel=0.01)


def test_contact_area_is_three_threads_of_helix_times_depth() -> None:
    """Seed: AT = H.T. x (O.D. - R.D.) / 2, ATA = AT x 3 (assuming 3 thread contact)."""
    assert pv.contact_area(0.02, 0.001) == pytest.approx(3 * 0.02 * 0.001, rel=1e-12)


def seed_pv_psi_ft_min(od: float, rd: float, lead: float, load: float, speed: float) -> float:
    """The seed's PV procedure verbatim, in its inch units (in, lb, in/s)."""
    p_o = (od + rd) / 2
    ht = math.sqrt(lead**2 + (math.pi * p_o) ** 2)
    at = ht * (od - rd) / 2
    ata = 3 * at
    rpm = speed / lead * 60
    ts = rpm * ht / 12
    return ts * load / ata


inch_screws = st.tuples(
    st.floats(0.2, 1.5),  # OD [in]
    st.floats(0.6, 0.95),  # RD / OD
    st.floats(0.02, 2.5),  # lead [in]
    st.floats(1.0, 500.0),  # load [lb]
    st.floats(0.05, 30.0),  # linear speed [in/s]
)


@given(inch_screws)
def test_seed_pv_procedure_matches_the_core(case: tuple[float, float, float, float, float]) -> None:
    """engineering.md section 6: H.T. cancels, PV = RPM x Load / (36 h) [psi ft/min,
    h in inches], and the core's pv_value in SI equals it after conversion
    (1 psi ft/min = 6894.757 Pa x 0.00508 m/s)."""
    od, ratio, lead, load, speed = case
    rd = ratio * od
    seed = seed_pv_psi_ft_min(od, rd, lead, load, speed)
    rpm = speed / lead * 60
    h = (od - rd) / 2
    assert seed == pytest.approx(rpm * load / (36 * h), rel=1e-9)

    d_p = geometry.pitch_diameter(od * IN, rd * IN)
    core = pv.pv_value(
        load * LBF,
        geometry.screw_speed_rpm(speed * IN, lead * IN),
        geometry.helix_travel(lead * IN, d_p),
        geometry.thread_depth(od * IN, rd * IN),
    )
    assert core / PSI_FT_MIN == pytest.approx(seed, rel=1e-9)


pv_cases = st.tuples(
    st.floats(1.0, 5000.0),  # load [N]
    st.floats(1.0, 5000.0),  # rpm
    st.floats(5e-3, 0.3),  # helix travel [m]
    st.floats(1e-4, 5e-3),  # thread depth [m]
)


@given(pv_cases, st.floats(1.01, 10.0))
def test_pv_is_linear_in_load(case: tuple[float, float, float, float], k: float) -> None:
    load, rpm, ht, h = case
    assert pv.pv_value(k * load, rpm, ht, h) == pytest.approx(
        k * pv.pv_value(load, rpm, ht, h), rel=1e-9
    )


@given(pv_cases, st.floats(1.01, 10.0))
def test_pv_is_linear_in_rpm(case: tuple[float, float, float, float], k: float) -> None:
    load, rpm, ht, h = case
    assert pv.pv_value(load, k * rpm, ht, h) == pytest.approx(
        k * pv.pv_value(load, rpm, ht, h), rel=1e-9
    )


@given(pv_cases, st.floats(1.01, 10.0))
def test_pv_does_not_depend_on_helix_travel(
    case: tuple[float, float, float, float], k: float
) -> None:
    """P falls and V rises by the same H.T.: PV = n F / (3 h)."""
    load, rpm, ht, h = case
    assert pv.pv_value(load, rpm, k * ht, h) == pytest.approx(
        pv.pv_value(load, rpm, ht, h), rel=1e-9
    )


@given(pv_cases, st.floats(1e4, 1e6))
def test_max_load_and_max_rpm_invert_pv(
    case: tuple[float, float, float, float], limit: float
) -> None:
    """At max_load_for_pv (this speed) or max_rpm_for_pv (this load) PV equals the limit."""
    load, rpm, ht, h = case
    f_max = pv.max_load_for_pv(limit, rpm, h)
    assert pv.pv_value(f_max, rpm, ht, h) == pytest.approx(limit, rel=1e-9)
    n_max = pv.max_rpm_for_pv(limit, load, h)
    assert pv.pv_value(load, n_max, ht, h) == pytest.approx(limit, rel=1e-9)


@given(pv_cases)
def test_pv_is_pressure_times_speed(case: tuple[float, float, float, float]) -> None:
    load, rpm, ht, h = case
    p = pv.contact_pressure(load, pv.contact_area(ht, h))
    assert pv.pv_value(load, rpm, ht, h) == pytest.approx(p * pv.surface_speed(rpm, ht), rel=1e-12)
