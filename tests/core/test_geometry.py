"""Screw geometry and kinematics (app.core.formulas.geometry) against the seed and published
examples."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import geometry
from tests.core.conftest import IN


@pytest.mark.parametrize(
    ("pitch_m", "starts", "lead_m"),
    [
        pytest.param(0.004, 2, 0.008, id="shigley-8-1-double-start-p4"),
        pytest.param(0.002, 4, 0.008, id="seed-4-start-p2"),
        pytest.param(0.1 * IN, 1, 0.1 * IN, id="single-start-lead-equals-pitch"),
    ],
)
def test_lead_is_pitch_times_starts(pitch_m: float, starts: int, lead_m: float) -> None:
    """Seed, "Lead": "Lead = Pitch x Number of Starts"; Shigley ex. 8-1: p 4 mm, double, l 8 mm."""
    assert geometry.lead_from_pitch(pitch_m, starts) == pytest.approx(lead_m, rel=1e-12)


def test_shigley_8_1_mean_diameter_and_thread_depth() -> None:
    """Budynas & Nisbett, Shigley's MED 9th ed., Example 8-1: square thread, d = 32 mm,
    p = 4 mm: thread depth 2 mm, mean diameter d_m = 30 mm, minor diameter 28 mm.
    The seed's P_o = (O.D. + R.D.) / 2 is the same mean diameter."""
    assert geometry.pitch_diameter(0.032, 0.028) == pytest.approx(0.030, rel=1e-12)
    assert geometry.thread_depth(0.032, 0.028) == pytest.approx(0.002, rel=1e-12)


@pytest.mark.parametrize(
    ("lead_m", "d_p_m"),
    [
        pytest.param(0.008, 0.030, id="shigley-8-1"),
        pytest.param(0.001, 0.00565, id="quarter-inch-1mm"),
        pytest.param(0.0254, 0.0057, id="quarter-inch-25.4mm"),
    ],
)
def test_lead_angle_and_its_tangent_agree(lead_m: float, d_p_m: float) -> None:
    """engineering.md section 1: lambda = atan(lead / (pi d_p)); tan_lead_angle is its tangent."""
    lam = geometry.lead_angle(lead_m, d_p_m)
    assert math.tan(lam) == pytest.approx(lead_m / (math.pi * d_p_m), rel=1e-12)
    assert geometry.tan_lead_angle(lead_m, d_p_m) == pytest.approx(math.tan(lam), rel=1e-12)


def test_shigley_8_1_lead_angle() -> None:
    """Shigley ex. 8-1 geometry: l = 8 mm, d_m = 30 mm -> lambda = atan(8 / (30 pi)) = 4.85 deg."""
    assert math.degrees(geometry.lead_angle(0.008, 0.030)) == pytest.approx(4.852, abs=1e-3)


def test_nook_application_example_travel_rates() -> None:
    """Nook Industries, "Acme and lead screw assembly application selection example"
    (nookindustries.com/acme/AcmeApplication.cfm), steps 2-3: 36 in in 10 s; average
    3.6 in/s = 216 in/min; triangular profile (accel = decel, no dwell): peak = 2 x average
    = 7.2 in/s = 432 in/min.

    The core has no motion-profile function; the rates go through screw_speed_rpm with a
    1 in lead, where rpm equals in/min numerically (one inch per revolution)."""
    distance_m, time_s = 36 * IN, 10.0
    average = distance_m / time_s
    peak = 2.0 * average  # triangular profile: the area under v(t) is d = v_peak t / 2
    assert average / IN == pytest.approx(3.6, rel=0.01)
    assert peak / IN == pytest.approx(7.2, rel=0.01)
    assert geometry.screw_speed_rpm(average, 1 * IN) == pytest.approx(216.0, rel=0.01)
    assert geometry.screw_speed_rpm(peak, 1 * IN) == pytest.approx(432.0, rel=0.01)


@pytest.mark.parametrize(
    ("speed_m_s", "lead_m", "rpm"),
    [
        pytest.param(0.05, 0.002, 1500.0, id="seed-RS-x60-50mm_s-on-2mm"),
        pytest.param(7.2 * IN, 0.2 * IN, 2160.0, id="nook-peak-7.2in_s-on-0.2in"),
        pytest.param(0.1, 0.012, 500.0, id="100mm_s-on-12mm"),
    ],
)
def test_screw_speed_is_linear_speed_over_lead(speed_m_s: float, lead_m: float, rpm: float) -> None:
    """Seed, PV calculation: RS = Linear Speed / Lead (rev/s), RPM = RS x 60."""
    assert geometry.screw_speed_rpm(speed_m_s, lead_m) == pytest.approx(rpm, rel=1e-9)


def test_helix_travel_of_a_flat_thread_is_the_pitch_circumference() -> None:
    """Seed: H.T. = surface travel per rev; with lead 0 it is pi x P_o."""
    assert geometry.helix_travel(0.0, 0.01) == pytest.approx(math.pi * 0.01, rel=1e-12)


@given(
    lead=st.floats(1e-4, 0.1),
    d_p=st.floats(1e-3, 0.05),
)
def test_helix_travel_is_the_unrolled_helix_hypotenuse(lead: float, d_p: float) -> None:
    """H.T. = sqrt(lead^2 + (pi P_o)^2): longer than both legs of the unrolled triangle."""
    ht = geometry.helix_travel(lead, d_p)
    assert ht == pytest.approx(math.hypot(lead, math.pi * d_p), rel=1e-12)
    assert ht > math.pi * d_p
    assert ht > lead


@given(od=st.floats(2e-3, 0.1), ratio=st.floats(0.5, 0.99))
def test_pitch_diameter_and_thread_depth_rebuild_the_diameters(od: float, ratio: float) -> None:
    """P_o = (OD + RD) / 2 and h = (OD - RD) / 2 give back OD = P_o + h, RD = P_o - h."""
    rd = ratio * od
    d_p, h = geometry.pitch_diameter(od, rd), geometry.thread_depth(od, rd)
    assert d_p + h == pytest.approx(od, rel=1e-12)
    assert d_p - h == pytest.approx(rd, rel=1e-12)
    assert rd < d_p < od
