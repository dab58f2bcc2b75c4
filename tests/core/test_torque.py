"""Drive torque: inertia + drag + load (app.core.formulas.torque), seed formulas and Shigley
ex. 8-1."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.core.formulas import efficiency, geometry, torque

SQUARE = 1.0


def test_shigley_8_1_raising_torque_of_the_thread() -> None:
    """Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed., sec. 8-2,
    Example 8-1: square thread, d = 32 mm, p = 4 mm, double start, f = f_c = 0.08,
    d_c = 40 mm, F = 6.4 kN. Published: T_R = 15.94 + 10.24 = 26.18 N m (thread + collar),
    e = F l / (2 pi T_R) = 0.311.

    Shigley's thread torque (F d_m / 2)(l + pi f d_m) / (pi d_m - f l) is the seed's
    F lead / (2 pi eta) with eta = forward_efficiency(alpha_n = 0). The core has no collar;
    the collar term F f_c d_c / 2 = 10.24 N m is added here to check the published e."""
    d_m = geometry.pitch_diameter(0.032, 0.028)
    lead = geometry.lead_from_pitch(0.004, 2)
    eta = efficiency.forward_efficiency(geometry.tan_lead_angle(lead, d_m), 0.08, SQUARE)
    t_thread = torque.load_torque(6400.0, lead, eta)
    assert t_thread == pytest.approx(15.94, rel=0.01)
    t_collar = 6400.0 * 0.08 * 0.040 / 2
    assert t_collar == pytest.approx(10.24, rel=1e-9)
    assert 6400.0 * lead / (2 * math.pi * (t_thread + t_collar)) == pytest.approx(0.311, rel=0.01)


def test_shigley_8_1_lowering_torque_of_the_thread() -> None:
    """Shigley's MED 9th ed., Example 8-1: T_L = -0.466 + 10.24 = 9.77 N m; the thread part
    is negative (the load alone turns the screw). Its magnitude is the physical holding
    torque F l eta_b / (2 pi) with the back-drive efficiency at f = 0.08."""
    d_m, lead = 0.030, 0.008
    eta_b = efficiency.backdrive_efficiency(geometry.tan_lead_angle(lead, d_m), 0.08, SQUARE)
    t_hold = efficiency.holding_torque(6400.0, lead, eta_b)
    assert -t_hold == pytest.approx(-0.466, rel=0.01)
    assert -t_hold + 6400.0 * 0.08 * 0.040 / 2 == pytest.approx(9.77, rel=0.01)


@pytest.mark.parametrize(
    ("load_n", "lead_m", "eta", "torque_nm"),
    [
        pytest.param(20_000.0, 0.01, 0.70, 45.5, id="engineeringprep-516-20kN-10mm-70%"),
        pytest.param(100.0, 0.002, 0.5, 0.063662, id="seed-formula-100N-2mm-50%"),
    ],
)
def test_torque_to_move_load(load_n: float, lead_m: float, eta: float, torque_nm: float) -> None:
    """Seed, "Torque To Move Load": TORQUE = Load x Lead / (2 pi x Efficiency).
    engineeringprep.com problem 516 "Power Screw Torque": 20 kN, lead 0.01 m, 70 %
    efficiency -> T = 45.5 N m."""
    assert torque.load_torque(load_n, lead_m, eta) == pytest.approx(torque_nm, rel=0.01)


def test_reflected_mass_inertia_matches_the_published_constant() -> None:
    """smallmotors.com "Lead screws" sizing page: J_reflected = M L^2 x 0.025 (L the lead),
    i.e. 1 / (2 pi)^2 = 0.02533 printed to two figures."""
    assert torque.reflected_mass_inertia(1.0, 1.0) == pytest.approx(0.025, abs=5e-4)
    assert torque.reflected_mass_inertia(10.0, 2 * math.pi * 0.001) == pytest.approx(
        1e-5, rel=1e-12
    )


def test_angular_acceleration_follows_the_lead() -> None:
    """alpha = 2 pi a / lead: 1 m/s^2 on a 2 pi mm lead is 1000 rad/s^2."""
    assert torque.angular_acceleration(1.0, 2 * math.pi * 0.001) == pytest.approx(1000.0)


def test_seed_inertia_torque_with_catalog_inertia() -> None:
    """Seed, "Inertia Torque": T = I alpha, I = screw inertia. B4000: 2.11e-8 kg m^2 per inch,
    so a 10 in screw at 1000 rad/s^2 needs 2.11e-4 N m."""
    per_m = 2.11e-8 / 0.0254
    inertia = torque.screw_inertia(per_m, 10 * 0.0254)
    assert inertia == pytest.approx(2.11e-7, rel=1e-9)
    assert torque.inertia_torque(inertia, 1000.0) == pytest.approx(2.11e-4, rel=1e-9)


def test_total_is_the_sum_of_the_seeds_three_components() -> None:
    """Seed, "Torque": the sum of inertia torque, static frictional torque and load torque."""
    assert torque.total_torque(0.001, 0.03, 0.05) == pytest.approx(0.081, rel=1e-12)


loads = st.floats(1.0, 5000.0)
leads = st.floats(5e-4, 0.06)
etas = st.floats(0.05, 0.95)


@given(load=loads, lead=leads, eta=etas, factor=st.floats(1.01, 10.0))
def test_torque_rises_with_load(load: float, lead: float, eta: float, factor: float) -> None:
    """T = F l / (2 pi eta) is proportional to the load."""
    low = torque.load_torque(load, lead, eta)
    high = torque.load_torque(factor * load, lead, eta)
    assert high > low
    assert high == pytest.approx(factor * low, rel=1e-9)


@given(load=loads, lead=leads, eta=etas, factor=st.floats(1.01, 1.0 / 0.95))
def test_torque_falls_with_efficiency(load: float, lead: float, eta: float, factor: float) -> None:
    assert torque.load_torque(load, lead, min(eta * factor, 1.0)) < torque.load_torque(
        load, lead, eta
    )


@given(load=loads, lead=leads, eta=etas)
def test_load_torque_inverts_the_efficiency_definition(
    load: float, lead: float, eta: float
) -> None:
    """Shigley eq. 8-4: e = F l / (2 pi T)."""
    t = torque.load_torque(load, lead, eta)
    assert load * lead / (2 * math.pi * t) == pytest.approx(eta, rel=1e-9)
