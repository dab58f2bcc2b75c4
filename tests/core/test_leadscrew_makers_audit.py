"""Leadscrew (sliding nut, Acme and ISO trapezoidal) ratings against the makers' published
rules, for every leadscrew of the built-in catalog: the app's rating is never above them.

- Thomson, "Screw critical speed (maximum RPM) calculation"
  (thomsonlinear.com/en/training/ball_screws/screw_critical_speed): n_c = C_s x 4.76e6 x
  d_r / L^2 [rpm, in], C_s 0.36 fixed-free, 1.00 simple-simple, 1.47 fixed-simple, 2.23
  fixed-fixed, "operate below 80 % of the screw critical speed"; the same constant and
  factors for a steel leadscrew in fxsolver, "Critical speed for a leadscrew".
- Thomson, "Column buckling calculation"
  (thomsonlinear.com/en/training/ball_screws/column_buckling), and Nook Industries' column
  strength of its Acme lift shafts ("Worm Gear Essentials - Column Strength",
  makingmotionwork.com, after Nook's "How to Size a Worm Gear Jack"): P_cr = 14.03e6 F_c
  d^4 / L^2 [lb, in], d the root diameter, F_c 0.25 / 1 / 2 / 4; Thomson: operate below
  80 % of it.
- W.M. Berg, "How to Calculate Lead Screw Maximum Load, Speed & More"
  (wmberg.com/resources/tech-and-application-support/lead-screw-load), "Maximum Column
  Load Formula": F = K x C x 10^6 x d^4 / D^2 [lb, in], K 0.25 (printed ".025") one end
  fixed the other free, 1.00 simple both ends, 2.00 fixed-simple, 4.00 both fixed; C = 13.4
  for stainless steel screws (4.8 aluminium), d the root diameter, D from the nut to the
  support bearing: the lowest leadscrew maker's column constant found (Euler's with
  E = 13.4e6 x 64 / pi^3 psi = 190.7 GPa).
- Haydon Kerk, "Diverse Nut Materials" white paper, and THK, Lead Screw Nut, "Efficiency
  and Thrust" (thk.com/jp/en/products/other_power_transmission_elements/lead_screw_nut/
  selection/0002/): efficiency tan(lambda) / tan(lambda + atan f), the square thread's.
- Nook Industries, "Acme Screw Glossary and Technical Data" (nookindustries.com/resources/
  general-technical-references/acme-screw-glossary-and-technical-data/): "a nut with
  efficiency greater than 50% will have a tendency to backdrive".
"""

import math

import numpy as np
import pytest

from app.catalog import Catalog
from app.contract.units import DEFAULT_UNITS, render
from app.core.evaluate import evaluate
from app.core.formulas import critical_speed, efficiency
from app.core.model import Application, ScrewSpec
from app.core.table import CandidateTable
from app.core.units import from_si, to_si

#: Thomson's critical speed end fixity factors C_s.
THOMSON_CS = {"fixed-free": 0.36, "simple-simple": 1.0, "fixed-simple": 1.47, "fixed-fixed": 2.23}
#: The column end fixity factors of Thomson, Nook (F_c) and W.M. Berg (K).
COLUMN_K = {"fixed-free": 0.25, "simple-simple": 1.0, "fixed-simple": 2.0, "fixed-fixed": 4.0}
THOMSON_RPM_IN = 4.76e6
THOMSON_NOOK_COLUMN = 14.03e6
BERG_STAINLESS_COLUMN = 13.4e6


def _leadscrews(catalog: Catalog) -> list[ScrewSpec]:
    return [s for s in catalog.by_id.values() if s.screw_type != "ball"]


def _thomson_rpm(root_m: float, length_m: float, fixity: str) -> float:
    """Thomson's n_c = C_s 4.76e6 d_r / L^2 [rpm, in]."""
    root_in, length_in = from_si(root_m, "in"), from_si(length_m, "in")
    return THOMSON_CS[fixity] * THOMSON_RPM_IN * root_in / length_in**2


def _column_n(constant: float, root_m: float, length_m: float, fixity: str) -> float:
    """The makers' column load constant x K d^4 / L^2 [lb, in], in newtons."""
    root_in, length_in = from_si(root_m, "in"), from_si(length_m, "in")
    return to_si(constant * COLUMN_K[fixity] * root_in**4 / length_in**2, "lbf")


def _check(app: Application, screw: ScrewSpec, name: str) -> float:
    return next(c.capacity for c in evaluate(app, screw).checks if c.name == name)


@pytest.mark.parametrize("fixity", list(THOMSON_CS))
def test_no_leadscrew_whirls_above_thomsons_rule(catalog: Catalog, fixity: str) -> None:
    """Every leadscrew's rated critical speed over 1 m is at most Thomson's C_s x 4.76e6
    d_r / L^2: a C45 trapezoidal screw (207 GPa, 7800 kg/m^3) was 0.39 % above it (Tr20x4,
    d3 15.5 mm, simple-simple: 1881.4 rpm against 1874.0), its E / rho above the steel
    Thomson's constant is worked with; 303 and 304 stainless (193 GPa, 8000) are 4.3 %
    below it."""
    screws = _leadscrews(catalog)
    t = CandidateTable.build(screws)
    rated = critical_speed.rated_critical_speed_rpm(
        t.root_diameter_m, 1.0, t.youngs_modulus_pa, t.density_kg_m3, fixity, t.ball
    )
    thomson = np.array([_thomson_rpm(s.root_diameter_m, 1.0, fixity) for s in screws])
    assert np.all(rated <= thomson * (1.0 + 1e-12))


@pytest.mark.parametrize("fixity", list(THOMSON_CS))
def test_a_steel_trapezoidal_screw_whirls_at_thomsons_rule(catalog: Catalog, fixity: str) -> None:
    """Tr20x4 in C45 steel (d3 = 20 - 4 - 0.5 = 15.5 mm) over 1 m: the allowed speed, 0.8 x
    critical (Thomson's 80 %), is Thomson's 0.8 x C_s x 4.76e6 x 0.6102 / 39.37^2 within
    1 %: 539.7 / 1499.2 / 2203.8 / 3343.2 rpm (fixed-free: the beam's 0.356 lies below
    Thomson's 0.36, 1.1 %)."""
    screw = catalog.by_id["Tr20x4-bronze"]
    assert from_si(screw.root_diameter_m, "mm") == pytest.approx(15.5, rel=1e-9)
    allowed = _check(Application(100.0, 0.01, 1.0, end_fixity=fixity), screw, "critical_speed")
    thomson = 0.8 * _thomson_rpm(screw.root_diameter_m, 1.0, fixity)
    assert allowed == pytest.approx(thomson, rel=0.015 if fixity == "fixed-free" else 0.01)
    assert allowed <= thomson * (1.0 + 1e-12)


@pytest.mark.parametrize("fixity", list(COLUMN_K))
@pytest.mark.parametrize(
    ("screw_id", "constant"),
    [
        ("Tr20x4-bronze", THOMSON_NOOK_COLUMN),
        ("Tr12x3-acetal", THOMSON_NOOK_COLUMN),
        ("Tr20x4-304-bronze", BERG_STAINLESS_COLUMN),
        ("ZBX8000-L10", BERG_STAINLESS_COLUMN),
    ],
)
def test_a_leadscrew_column_is_rated_by_its_makers_rule(
    catalog: Catalog, screw_id: str, constant: float, fixity: str
) -> None:
    """A slender column, 1.5 m from the thrust bearing to the nut: the allowed compressive
    load (0.5 x the critical, the app's default) is 0.5 x the makers' critical load for
    the screw's class of steel, within 1 % and never above: Thomson's and Nook's 14.03e6
    F_c d^4 / L^2 for a C45 screw, Berg's 13.4e6 K d^4 / L^2 for a 303 or 304 one. Before:
    a C45 Tr20x4 (207 GPa) was 3.67 % above Thomson's and Nook's (simple-simple 2894 N
    against 2792 N), a stainless screw (193 GPa) 1.2 % above Berg's."""
    screw = catalog.by_id[screw_id]
    app = Application(100.0, 0.01, 1.5, end_fixity=fixity)
    allowed = _check(app, screw, "buckling")
    makers = 0.5 * _column_n(constant, screw.root_diameter_m, 1.5, fixity)
    assert allowed <= makers * (1 + 1e-9)
    assert allowed == pytest.approx(makers, rel=0.01)


def test_berg_stainless_column_is_reproduced_within_one_percent(catalog: Catalog) -> None:
    """W.M. Berg's maximum column load of a stainless screw, K x 13.4e6 x d^4 / D^2: the
    ZBX8000 (root 0.78 x 1/2 in = 0.39 in) over 1.5 m (59.06 in), simple-simple, 1 x 13.4e6
    x 0.39^4 / 59.06^2 = 88.8 lb (395 N); the app's allowed load is half its critical load
    and that is Berg's within 1 %."""
    screw = catalog.by_id["ZBX8000-L10"]
    berg = _column_n(BERG_STAINLESS_COLUMN, screw.root_diameter_m, 1.5, "simple-simple")
    assert from_si(berg, "lbf") == pytest.approx(88.8, rel=0.01)
    app = Application(10.0, 0.01, 1.5, end_fixity="simple-simple")
    assert 2.0 * _check(app, screw, "buckling") == pytest.approx(berg, rel=0.01)


@pytest.mark.parametrize("friction", [0.08, 0.09, 0.13, 0.15, 0.25])
@pytest.mark.parametrize("lead_to_pitch_diameter", [0.1, 0.25, 0.5, 1.0])
def test_efficiency_is_at_most_the_square_thread_makers(
    friction: float, lead_to_pitch_diameter: float
) -> None:
    """Haydon Kerk's and THK's efficiency tan(lambda) / tan(lambda + atan f) is the square
    thread's; the core's Acme (14.5 deg) and trapezoidal (15 deg) thread efficiency is at
    most it (the flank raises the friction), so its drive torque is at least theirs; with
    no flank angle it is theirs. engineering.md's spot values: L / d_p 0.5, f 0.09: 63.0 %;
    L / d_p 1.0, f 0.15: 64.7 %."""
    tan_lead = lead_to_pitch_diameter / math.pi
    square = math.tan(math.atan(tan_lead)) / math.tan(math.atan(tan_lead) + math.atan(friction))
    assert efficiency.square_thread_efficiency(tan_lead, friction) == pytest.approx(square)
    assert efficiency.forward_efficiency(tan_lead, friction, 1.0) == pytest.approx(square)
    for half_angle_deg in (14.5, 15.0):
        cos_half = math.cos(math.radians(half_angle_deg))
        assert efficiency.forward_efficiency(tan_lead, friction, cos_half) <= square
    spots = {(0.5, 0.09): 0.630, (1.0, 0.15): 0.647}
    if (lead_to_pitch_diameter, friction) in spots:
        assert square == pytest.approx(spots[lead_to_pitch_diameter, friction], abs=5e-4)


@pytest.mark.parametrize(
    ("screw_id", "said"),
    [
        ("Tr20x4-bronze", "with E 199,700 MPa, Thomson's and Nook's rule for steel"),
        ("Tr20x4-304-bronze", "with E 190,700 MPa, W.M. Berg's rule for stainless"),
        ("R20-05K4-FSCDIN", ""),
    ],
)
def test_the_column_says_which_modulus_its_euler_load_is_worked_with(
    catalog: Catalog, screw_id: str, said: str
) -> None:
    """A slender column (1.5 m, simple-simple) rated by its makers' rule names the modulus
    its Euler load is worked with, so the figure can be worked again by hand from what the
    check says: a C45 screw's 207 GPa is held to Thomson's and Nook's 199.7 GPa, a 304
    one's 193 GPa to Berg's 190.7 GPa; a HIWIN ball screw's own 207 GPa, below HIWIN's
    210.1, is its own and needs no words."""
    screw = catalog.by_id[screw_id]
    app = Application(100.0, 0.01, 1.5, end_fixity="simple-simple")
    result = next(c for c in evaluate(app, screw).checks if c.name == "buckling")
    text = render(result.message, DEFAULT_UNITS)
    assert ("with E " in text) is bool(said) and said in text, text
