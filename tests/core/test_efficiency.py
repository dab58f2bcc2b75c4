"""Thread efficiency, back-driving, self-locking and holding torque
(app.core.formulas.efficiency)."""

import math

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from app.core.formulas import efficiency, geometry
from tests.core.conftest import COS_ACME

SQUARE = 1.0  # cos(0): square thread, no flank angle

#: realistic lead angles (0.5 to 60 deg, as tan) and thread friction (seed 0.08-0.15)
tan_leads = st.floats(math.tan(math.radians(0.5)), math.tan(math.radians(60.0)))
frictions = st.floats(0.05, 0.25)
cos_half_angles = st.sampled_from([SQUARE, COS_ACME, math.cos(math.radians(15.0))])


@pytest.mark.parametrize(
    ("lead_over_dp", "friction", "expected"),
    [
        pytest.param(0.5, 0.09, 0.630, id="L/dp=0.5-mu=0.09-63.0%"),
        pytest.param(1.0, 0.15, 0.647, id="L/dp=1.0-mu=0.15-64.7%"),
    ],
)
def test_square_thread_spot_values(lead_over_dp: float, friction: float, expected: float) -> None:
    """engineering.md section 2, spot values of the square-thread form (computed, printed to
    0.1 point): tan(lambda) = (L / d_p) / pi. Both the manufacturer's tan l / tan(l + phi)
    and Shigley's form with alpha_n = 0 must give them."""
    tan_l = lead_over_dp / math.pi
    assert efficiency.square_thread_efficiency(tan_l, friction) == pytest.approx(expected, abs=5e-4)
    assert efficiency.forward_efficiency(tan_l, friction, SQUARE) == pytest.approx(
        expected, abs=5e-4
    )


def test_shigley_8_1_thread_efficiency_and_not_self_locking() -> None:
    """Shigley's MED 9th ed., Example 8-1 (square, d_m 30 mm, l 8 mm, f 0.08): the thread's
    lowering torque is negative (-0.466 N m), "the screw alone is not self-locking". The
    core must agree, and its thread-only efficiency is F l / (2 pi T_R) = 6400 x 0.008 /
    (2 pi 15.94) = 0.511 (derived from the published T_R; the published e = 0.311 includes
    the collar, which the core does not model)."""
    tan_l = geometry.tan_lead_angle(0.008, 0.030)
    assert not efficiency.is_self_locking(tan_l, 0.08, SQUARE)
    published_thread_eta = 6400 * 0.008 / (2 * math.pi * 15.94)
    assert efficiency.forward_efficiency(tan_l, 0.08, SQUARE) == pytest.approx(
        published_thread_eta, rel=0.01
    )


@given(tan_l=tan_leads, mu=st.floats(0.08, 0.15))
def test_acme_and_square_forms_differ_by_under_1_5_points(tan_l: float, mu: float) -> None:
    """engineering.md section 2: the manufacturer's square-thread form differs from Shigley's
    Acme form (alpha_n 14.5 deg) by under 1.5 points at the seed's friction values."""
    diff = efficiency.square_thread_efficiency(tan_l, mu) - efficiency.forward_efficiency(
        tan_l, mu, COS_ACME
    )
    assert 0.0 <= diff < 0.015


@given(tan_l=tan_leads, mu=frictions, cos_a=cos_half_angles)
def test_forward_efficiency_is_a_fraction(tan_l: float, mu: float, cos_a: float) -> None:
    """Forward efficiency lies in (0, 1) wherever the thread can be driven at all."""
    assume(mu * tan_l < 0.9 * cos_a)
    assert 0.0 < efficiency.forward_efficiency(tan_l, mu, cos_a) < 1.0


@given(tan_l=tan_leads, mu=frictions, cos_a=cos_half_angles)
def test_backdrive_efficiency_is_zero_exactly_when_self_locking(
    tan_l: float, mu: float, cos_a: float
) -> None:
    """engineering.md section 2: eta_b in [0, 1), and eta_b = 0 exactly when
    mu_static >= cos(alpha_n) tan(lambda) (self-locking)."""
    eta_b = efficiency.backdrive_efficiency(tan_l, mu, cos_a)
    assert 0.0 <= eta_b < 1.0
    assert (eta_b == 0.0) == efficiency.is_self_locking(tan_l, mu, cos_a)


@given(tan_l=tan_leads, mu=frictions, cos_a=cos_half_angles)
def test_backdriving_is_less_efficient_than_driving_below_45_degrees(
    tan_l: float, mu: float, cos_a: float
) -> None:
    """At the same friction, eta_b <= eta for lead angles up to 45 deg and eta_b > eta
    above (for the square thread tan^2 l = tan(l + phi) tan(l - phi) only at l = 45 deg).
    So the seed's holding torque (forward eta) is the safe side only up to 45 deg."""
    assume(mu * tan_l < 0.9 * cos_a)
    eta = efficiency.forward_efficiency(tan_l, mu, cos_a)
    eta_b = efficiency.backdrive_efficiency(tan_l, mu, cos_a)
    if tan_l <= 0.999:
        assert eta_b <= eta
    elif tan_l >= 1.001 and cos_a == SQUARE:
        assert eta_b > eta


@given(tan_l=tan_leads, mu=frictions, cos_a=cos_half_angles)
def test_more_friction_never_raises_efficiency(tan_l: float, mu: float, cos_a: float) -> None:
    assume(1.1 * mu * tan_l < 0.9 * cos_a)
    assert efficiency.forward_efficiency(tan_l, 1.1 * mu, cos_a) < efficiency.forward_efficiency(
        tan_l, mu, cos_a
    )


def test_square_thread_backdrive_is_tan_lambda_minus_phi_over_tan_lambda() -> None:
    """engineering.md section 2: with alpha_n = 0, eta_b = tan(lambda - phi) / tan(lambda)."""
    lam, mu = math.atan(0.5 / math.pi), 0.09
    expected = math.tan(lam - math.atan(mu)) / math.tan(lam)
    assert efficiency.backdrive_efficiency(math.tan(lam), mu, SQUARE) == pytest.approx(
        expected, rel=1e-12
    )


@given(d_p=st.floats(2e-3, 0.05), mu=frictions, cos_a=cos_half_angles)
def test_max_self_locking_lead_is_the_self_locking_boundary(
    d_p: float, mu: float, cos_a: float
) -> None:
    """Shigley sec. 8-2: self-locking when pi mu d_m >= l (Acme: l <= pi d_p mu / cos a_n).
    Just below the largest self-locking lead the screw locks, just above it does not."""
    lead = efficiency.max_self_locking_lead(d_p, mu, cos_a)
    assert efficiency.is_self_locking(geometry.tan_lead_angle(0.999 * lead, d_p), mu, cos_a)
    assert not efficiency.is_self_locking(geometry.tan_lead_angle(1.001 * lead, d_p), mu, cos_a)


@pytest.mark.parametrize(
    ("lead_m", "od_m", "rule_says_no_backdrive"),
    [
        pytest.param(0.0007, 0.00635, True, id="quarter-inch-0.7mm-below-d/8"),
        pytest.param(0.001, 0.00635, False, id="quarter-inch-1mm-above-d/8"),
        pytest.param(0.0015875, 0.0127, False, id="half-inch-at-d/8-not-below"),
    ],
)
def test_seed_rule_of_thumb_lead_below_diameter_over_8(
    lead_m: float, od_m: float, rule_says_no_backdrive: bool
) -> None:
    """Seed, "Back Driving": "when the screw lead is less than 1/8 the diameter, back
    driving will not occur" (strictly less)."""
    assert efficiency.seed_backdrive_rule(lead_m, od_m) is rule_says_no_backdrive


@pytest.mark.parametrize("od_in", [0.25, 0.375, 0.4375, 0.5, 0.625, 0.75, 0.875])
def test_seed_rule_is_conservative_by_about_2x_against_the_physics(od_in: float) -> None:
    """engineering.md section 2: the d/8 rule and the physics (mu_s 0.08, Acme 14.5 deg, root
    0.78 OD) agree with about a 2x margin: the physical limit lead is 1.5-2.5 x OD/8."""
    od = od_in * 0.0254
    d_p = geometry.pitch_diameter(od, 0.78 * od)
    ratio = efficiency.max_self_locking_lead(d_p, 0.08, COS_ACME) / (od / 8)
    assert 1.5 < ratio < 2.5


@pytest.mark.parametrize(
    ("load_n", "lead_m", "eta", "torque_nm"),
    [
        pytest.param(100.0, 0.01, 0.5, 0.0795775, id="100N-10mm-eta0.5"),
        pytest.param(35 * 4.4482216, 0.5 * 0.0254, 0.8, 0.25175, id="35lbf-0.5in-eta0.8"),
    ],
)
def test_holding_torque_seed_formula(
    load_n: float, lead_m: float, eta: float, torque_nm: float
) -> None:
    """Seed, "Back Driving": Tb = Load x Lead x Efficiency / (2 pi) (hand arithmetic)."""
    assert efficiency.holding_torque(load_n, lead_m, eta) == pytest.approx(torque_nm, rel=1e-3)
