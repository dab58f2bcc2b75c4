"""One catalog candidate, every check, against a hand calculation written out here.

ZBX8000 (1/2 in, root 0.78 OD assumed), 10 mm lead, uncoated; 200 N vertical load with a
2 kg moving mass, 80 mm/s, 600 mm between fixed-simple supports, 1 m/s^2; stroke 300 mm,
200 cycles/day, 1 year required, 0.5 mm tolerance, 0.5 N m drive. Hand arithmetic uses
only the formulas of the engineering reference, not the app's functions.
"""

import math

import pytest

from app.catalog import Catalog
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.record import Candidate

G = 9.80665
OD, RD, LEAD = 0.0127, 0.78 * 0.0127, 0.010
MU_D, MU_S, ALPHA_N = 0.15, 0.08, math.radians(14.5)
E, RHO = 193e9, 8000.0
F = 200.0 + 2.0 * G  # running thrust: load + m g
PEAK = F + 2.0 * 1.0  # peak thrust: + m a
V, L = 0.080, 0.600
APP = Application(
    load_n=200.0,
    speed_m_s=V,
    length_m=L,
    lead_m=LEAD,
    accel_m_s2=1.0,
    moving_mass_kg=2.0,
    end_fixity="fixed-simple",
    orientation="vertical",
    stroke_m=0.3,
    cycles_per_day=200.0,
    required_life_years=1.0,
    positioning_tolerance_m=0.5e-3,
    max_torque_nm=0.5,
)

D_P = (OD + RD) / 2
H = (OD - RD) / 2
TAN_L = LEAD / (math.pi * D_P)
C = math.cos(ALPHA_N)
ETA = (C - MU_D * TAN_L) / (C + MU_D / TAN_L)
ETA_S = (C - MU_S * TAN_L) / (C + MU_S / TAN_L)
RPM = 60 * V / LEAD
ALPHA = 2 * math.pi * 1.0 / LEAD
J_SCREW = 3.67e-7 / 0.0254 * L
T_MASS = 2.0 * 1.0 * LEAD / (2 * math.pi * ETA)  # m a through the thread
TOTAL = J_SCREW * ALPHA + T_MASS + 0.04 + F * LEAD / (2 * math.pi * ETA)
BREAK = PEAK * LEAD / (2 * math.pi * ETA_S) + J_SCREW * ALPHA + 0.04  # from rest
# a leadscrew's critical speed as its makers rate it (Thomson, Roton): C_s 1.47 times the
# simple-simple beam's (beta = pi) fixed-simple, below the beam's (3.9266 / pi)^2 = 1.562
N_C = 1.47 * (math.pi / L) ** 2 * math.sqrt(E / RHO) * RD / 4 * 60 / (2 * math.pi)
S_Y = 240e6  # 303 annealed
SLENDER = (L / math.sqrt(2)) / (RD / 4)  # 171, above sqrt(2 pi^2 E / S_y) = 126: Euler
# held to its makers' column rule for stainless, W.M. Berg's 13.4e6 K d^4 / D^2 [lb, in]
# (Euler's with E_m = 13.4e6 x 64 / pi^3 psi = 190.7 GPa, below 303's 193 GPa)
E_M = 13.4e6 * 64 / math.pi**3 * 6894.757293168
F_CR = 2 * math.pi**2 * E_M * (math.pi * RD**4 / 64) / L**2
# root: von Mises of the peak thrust's axial stress and the shear of the torque the screw
# carries with it, T = PEAK lead / (2 pi eta) (the lower of running and static: here
# running, mu_d 0.15 > mu_s 0.08) + J_screw alpha + drag (Shigley eqs. 8-7, 8-8, 5-15)
T_ROOT = PEAK * LEAD / (2 * math.pi * min(ETA, ETA_S)) + J_SCREW * ALPHA + 0.04
STRESS = math.hypot(PEAK / (math.pi * RD**2 / 4), math.sqrt(3) * 16 * T_ROOT / (math.pi * RD**3))
PV = PEAK / (3 * H) * RPM / 60  # H.T. cancels; the accelerating segment ends at V with m a
DESIGN = 3e6 * 3 * math.pi * D_P * H
# the nut's wear (Archard, polyacetal k = 1e-6 mm^3/(N m), a quarter of H allowed, over
# the seed's three threads 3 H.T. H, sliding H.T. per lead): travel = 0.25 H / (k F /
# (3 H.T. H)) x lead / H.T. = 0.75 H^2 lead / (k F), with the cycle's wear thrust F: the
# ramps' m a adds as much up as it takes off down (x_a = x_d = 3.2 mm each way), so F
# = 219.6 N and the travel 66.65 km, short of the seed's 1e6 m (100 million cm), which it
# caps: 66.65e3 / (2 x 0.3 x 200 x 365) = 1.522 years
WEAR_TRAVEL = 0.75 * H**2 * LEAD / (1e-15 * F)
LIFE_YEARS = min(100e6 * 0.01, WEAR_TRAVEL) / (2 * 0.3 * 200 * 365)
ERROR = 0.0006 * 0.3 + 0.0 + 0.0013e-3
SELF_LOCK_LEAD = math.pi * D_P * (0.5 * MU_S) / C  # static friction at half, the default

#: check name -> (hand value, hand limit); SI units as the core reports them.
HAND = {
    "torque": (max(TOTAL, BREAK), 0.5),
    "critical_speed": (RPM, 0.8 * N_C),
    "buckling": (PEAK, 0.5 * F_CR),
    "root_stress": (STRESS, 0.5 * S_Y),
    "pv": (PV, 0.105e6),
    "traverse_speed": (V, 0.100),
    "design_load": (PEAK, DESIGN),
    "length": (L, 4.0),
    "back_driving": (LEAD, SELF_LOCK_LEAD),
    "life": (1.0, LIFE_YEARS),
    "accuracy": (ERROR, 0.5e-3),
}


@pytest.fixture(scope="module")
def worked(catalog: Catalog) -> Candidate:
    return evaluate(APP, catalog.by_id["ZBX8000-L10"])


@pytest.mark.parametrize("name", sorted(HAND))
def test_check_matches_hand_calculation(worked: Candidate, name: str) -> None:
    check = next(c for c in worked.checks if c.name == name)
    value, limit = HAND[name]
    assert check.value == pytest.approx(value, rel=1e-3)
    assert check.limit == pytest.approx(limit, rel=1e-3)
    assert check.passed == (value <= limit)


def test_yes_no_checks(worked: Candidate) -> None:
    flags = {c.name: c.passed for c in worked.checks if c.value is None}
    assert flags == {"temperature": True}  # 20 C within 0-93 C; uncoated: no oil check


def test_torque_breakdown_by_hand(worked: Candidate) -> None:
    t = worked.torque
    assert t.inertia_screw_nm == pytest.approx(J_SCREW * ALPHA, rel=1e-9)
    assert t.inertia_mass_nm == pytest.approx(T_MASS, rel=1e-9)
    assert t.drag_nm == 0.04  # top of the seed's 0.020-0.04 N m for ZBX8000
    assert t.load_nm == pytest.approx(F * LEAD / (2 * math.pi * ETA), rel=1e-9)
    assert t.total_nm == pytest.approx(TOTAL, rel=1e-9)
    assert t.breakaway_nm == pytest.approx(BREAK, rel=1e-9)


def test_backdriving_by_hand(worked: Candidate) -> None:
    """lambda = 15.6 deg > friction angle: back-drivable; the d/8 rule agrees."""
    eta_b = (C * TAN_L - MU_S) / (TAN_L * (C + MU_S * TAN_L))
    assert worked.backdrive_efficiency == pytest.approx(eta_b, rel=1e-9)
    assert not worked.self_locking and not worked.seed_rule_no_backdrive
    assert worked.holding_torque_seed_nm == pytest.approx(F * LEAD * ETA / (2 * math.pi))
    assert math.sqrt(2 * math.pi**2 * E / S_Y) < SLENDER
    assert worked.buckling.mode == "euler"
    assert worked.buckling.slenderness == pytest.approx(SLENDER, rel=1e-9)
    assert worked.holding_torque_physics_nm == pytest.approx(F * LEAD * eta_b / (2 * math.pi))
