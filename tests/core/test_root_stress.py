"""The screw's body at its root section under thrust and torque (app.core.formulas.buckling
root stresses, app.core.formulas.torque.root_torque, the root_stress check)."""

import math
from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.contract.units import render
from app.core.evaluate import evaluate
from app.core.formulas import buckling, torque
from app.core.model import Application

#: Shigley's Mechanical Engineering Design, 9th ed., Example 8-1: a square-thread power
#: screw, d = 32 mm, p = 4 mm, double thread (l = 8 mm), d_r = 28 mm, F = 6.4 kN raised
#: with T_R = 15.94 (thread) + 10.24 (collar) = 26.18 N m. Part (d), p. 420: body shear
#: tau = 16 T_R / (pi d_r^3) = 6.07 MPa, axial sigma = -4 F / (pi d_r^2) = -10.39 MPa.
#: (digilib.universitaspertamina.ac.id, Shigley's Mechanical Engineering Design, page 445
#: of the online copy)
SHIGLEY_F_N, SHIGLEY_T_NM, SHIGLEY_DR_M = 6.4e3, 26.18, 0.028


def test_shigley_example_8_1_body_stresses() -> None:
    """Shigley Ex. 8-1 (d): 6.07 MPa shear and 10.39 MPa axial, within 1 %; their von
    Mises combination (eq. 5-15 with sigma and tau only) from the published components:
    sqrt(10.39^2 + 3 x 6.07^2) = sqrt(107.95 + 110.53) = 14.78 MPa."""
    tau = buckling.root_shear_stress(SHIGLEY_T_NM, SHIGLEY_DR_M)
    sigma = buckling.root_stress(SHIGLEY_F_N, SHIGLEY_DR_M)
    assert tau / 1e6 == pytest.approx(6.07, rel=0.01)
    assert sigma / 1e6 == pytest.approx(10.39, rel=0.01)
    combined = buckling.root_von_mises_stress(SHIGLEY_F_N, SHIGLEY_T_NM, SHIGLEY_DR_M)
    assert combined / 1e6 == pytest.approx(math.sqrt(10.39**2 + 3 * 6.07**2), rel=0.01)
    assert combined / 1e6 == pytest.approx(14.78, rel=0.01)


def test_shigley_thread_torque_through_the_efficiency() -> None:
    """Shigley Ex. 8-1 (b): the thread alone needs 15.94 N m to raise 6.4 kN on an 8 mm
    lead, an efficiency F l / (2 pi T) = 6400 x 0.008 / (2 pi x 15.94) = 0.5112: the
    root torque with that efficiency gives the published thread torque back, and the
    collar's 10.24 N m added as drag gives T_R = 26.18 N m."""
    eta = 6400 * 0.008 / (2 * math.pi * 15.94)
    assert torque.root_torque(6400.0, 0.008, eta, 0.0, 0.0) == pytest.approx(15.94, rel=1e-9)
    assert torque.root_torque(6400.0, 0.008, eta, 10.24, 0.0) == pytest.approx(26.18, rel=1e-3)


def test_the_largest_load_inverts_the_combined_stress() -> None:
    """A property: at the load ``largest_root_load`` returns, the combined stress with
    T = a F + b is the allowed stress; a larger drag lowers it; a torque alone over the
    allowed stress leaves no load."""
    a, b, d_r, allowed = 0.004, 3.0, 0.02, 100e6
    f = buckling.largest_root_load(allowed, d_r, a, b)
    assert buckling.root_von_mises_stress(f, a * f + b, d_r) == pytest.approx(allowed, rel=1e-9)
    assert buckling.largest_root_load(allowed, d_r, a, 2 * b) < f
    assert buckling.root_shear_stress(200.0, d_r) * math.sqrt(3) > allowed
    assert buckling.largest_root_load(allowed, d_r, a, 200.0) == 0.0


def test_a_large_trapezoidal_screw_at_its_rating(catalog: Catalog) -> None:
    """Issue 29, item 5: Tr50x8 (d_r 41 mm) with an oiled bronze nut at the load its
    flanks carry (about 47 kN): the axial stress alone is about 25 % below the von
    Mises stress. By hand: tau / sigma = (16 T / (pi d_r^3)) / (4 F / (pi d_r^2)) =
    4 T / (F d_r) with T = F l / (2 pi eta) plus the screw's own inertia torque (no drag
    on a bronze nut), so sigma_vm / sigma = sqrt(1 + 3 (4 T / (F d_r))^2), eta the
    thread's at the starting friction 0.16 (flank angle 30 deg, d2 = 46 mm, Shigley
    eq. 8-4 with the sec(alpha) term)."""
    screw = catalog.by_id["Tr50x8-bronze"]
    oiled = Application(load_n=1000.0, speed_m_s=0.005, length_m=0.5, lubrication="oiled")
    probe = evaluate(oiled, screw)
    rated_n = probe.quantities.nut.nut_allowed_load_n
    ev = evaluate(replace(oiled, load_n=rated_n), screw)
    q = ev.quantities
    tan_l = 0.008 / (math.pi * 0.046)
    mu = 0.16 / math.cos(math.radians(15.0))
    eta = tan_l * (1 - mu * tan_l) / (tan_l + mu)
    torque_nm = rated_n * 0.008 / (2 * math.pi * eta) + abs(q.torque.inertia_screw_nm)
    by_hand = math.sqrt(1 + 3 * (4 * torque_nm / (rated_n * 0.041)) ** 2)
    assert q.column.root_stress_pa / q.column.root_axial_stress_pa == pytest.approx(
        by_hand, rel=1e-6
    )
    assert 1 - q.column.root_axial_stress_pa / q.column.root_stress_pa == pytest.approx(
        0.25, abs=0.01
    )
    c = next(c for c in ev.checks if c.name == "root_stress")
    assert c.value is not None and c.value == pytest.approx(q.column.root_stress_pa, rel=1e-9)
    text = render(c.message)
    assert "von Mises" in text and "MPa axial" in text and "MPa shear" in text


def test_the_check_judges_the_combined_stress(catalog: Catalog) -> None:
    """The check's value is sqrt(sigma^2 + 3 tau^2) of its own parts, not the axial
    stress: on a short, heavily loaded Tr12x3 (3 mm lead on a 8.5 mm root) the torque's
    shear lifts the figure it is judged by more than 20 % above the axial stress."""
    screw = catalog.by_id["Tr12x3-bronze"]
    ev = evaluate(Application(load_n=8000.0, speed_m_s=0.002, length_m=0.1), screw)
    q = ev.quantities
    c = next(c for c in ev.checks if c.name == "root_stress")
    sigma = 8000.0 / (math.pi * screw.root_diameter_m**2 / 4)
    assert q.column.root_axial_stress_pa == pytest.approx(sigma, rel=1e-9)
    tau = 16 * q.column.root_torque_nm / (math.pi * screw.root_diameter_m**3)
    assert q.column.root_shear_stress_pa == pytest.approx(tau, rel=1e-9)
    assert c.value is not None
    assert c.value == pytest.approx(math.sqrt(sigma**2 + 3 * tau**2), rel=1e-9)
    assert c.value > 1.2 * sigma
