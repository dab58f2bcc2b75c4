"""The makers' column rules a screw's column and root are rated by, never above: HIWIN's
buckling rule where a ball-screw family declares it, else the lowest published ball-screw
rule (Rockford's and Thomson's), the leadscrew makers' rule for the screw's class of steel
(Thomson's and Nook's, W.M. Berg's) and THK's permissible root stress. The column's own
physics (Euler, Johnson, the root stresses) is ``app.core.formulas.buckling``'s."""

import math
from typing import Any

import numpy as np

from app.core.formulas.buckling import allowed_buckling_load, euler_critical_load
from app.core.formulas.declare import formula
from app.core.units import to_si

#: HIWIN's buckling rule, F_k = 4.072e5 f_k d_k^4 / l_s^2 [N, mm] with f_k = k / 4 (1.0
#: fixed-fixed, 0.5 fixed-supported, 0.25 supported-supported, 0.0625 fixed-free) and the
#: permissible F_kmax = 0.5 F_k (HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K,
#: sec. 3.7.4, F 3.25 and F 3.26), as a ball-screw family declares it.
HIWIN_BUCKLING_RULE = "HIWIN F 3.25"
#: The buckling rules a ball-screw family may declare.
BUCKLING_RULES = (HIWIN_BUCKLING_RULE,)
#: The Young's modulus HIWIN's constant is Euler's with: 4.072e5 N/mm^2 = 4 pi^3 E / 64,
#: E = 210.1 GPa.
HIWIN_COLUMN_MODULUS_PA = to_si(4.072e5 * 64.0 / (4.0 * math.pi**3), "MPa")
#: The lowest makers' column rule: Rockford Ball Screw ("How To Size A Ball Screw", step
#: 9) and Thomson (ball screw column buckling) F_c = 14.03e6 C d^4 / L^2 [lb, in], C the
#: Euler k of the end fixity: Euler's with E = 14.03e6 x 64 / pi^3 psi = 199.7 GPa, below
#: HIWIN's 210.1, NSK's 2.1e5 N/mm^2 and THK's 2.06e5 N/mm^2 (its P1 = eta_2 d^4 / l^2 x
#: 10^4 N, 0.5 of Euler's; General Catalog, Ball Screw, A15-30, formula 5).
LOWEST_COLUMN_MODULUS_PA = to_si(14.03e6 * 64.0 / math.pi**3, "psi")
#: W.M. Berg's column rule for its stainless leadscrews ("How to Calculate Lead Screw
#: Maximum Load, Speed & More", Maximum Column Load Formula): F = K C 10^6 d^4 / D^2 [lb,
#: in], K the Euler k of the end fixity, C = 13.4 for stainless steel: Euler's with E =
#: 13.4e6 x 64 / pi^3 psi = 190.7 GPa, below the handbook's 193 GPa for 303 and 304.
STAINLESS_COLUMN_MODULUS_PA = to_si(13.4e6 * 64.0 / math.pi**3, "psi")
#: The leadscrew makers' column rules as Euler's modulus, one per class of screw steel,
#: stiffest first: Thomson's and Nook's 14.03e6 F_c d^4 / L^2 [lb, in] for steel (199.7
#: GPa, ``LOWEST_COLUMN_MODULUS_PA``), Berg's 13.4e6 for stainless (190.7 GPa).
LEADSCREW_COLUMN_MODULI_PA = (LOWEST_COLUMN_MODULUS_PA, STAINLESS_COLUMN_MODULUS_PA)


def leadscrew_column_modulus(youngs_modulus_pa: Any) -> Any:
    """The Young's modulus a leadscrew's column is rated with [Pa]: the makers' rule of
    the class of steel its own modulus reaches (``LEADSCREW_COLUMN_MODULI_PA``: at least
    199.7 GPa, a steel's, Thomson's and Nook's; at least 190.7 GPa, a stainless steel's,
    Berg's), else its own (no maker's rule is that soft). So a C45 screw (207 GPa) is rated
    by Thomson's and Nook's constant, not 3.7 % above it, a 303 or 304 one (193 GPa) by
    Berg's, not 1.2 % above it. Numbers or arrays alike.

    >>> [round(float(leadscrew_column_modulus(e)) / 1e9, 1) for e in (207e9, 193e9, 70e9)]
    [199.7, 190.7, 70.0]
    """
    rated = youngs_modulus_pa
    for makers in sorted(LEADSCREW_COLUMN_MODULI_PA):
        rated = np.where(np.asarray(youngs_modulus_pa) >= makers, makers, rated)
    return rated


def makers_column_modulus(youngs_modulus_pa: Any, ball: Any, hiwin_rated: Any = False) -> Any:
    """The Young's modulus a screw's column is rated with [Pa], never above its makers':
    a leadscrew's the makers' rule of its class of steel (``leadscrew_column_modulus``);
    a ball screw's at most the E its maker's constant is Euler's with, HIWIN's 210.1 GPa
    where its family declares HIWIN's rule (``HIWIN_BUCKLING_RULE``), else the lowest
    published, Rockford's and Thomson's 199.7 GPa. With it the Euler load is the lower of
    the beam's and the maker's (F_cr proportional to E), and Johnson's parabola, below
    Euler's tangent to it, is lower too. Numbers or arrays alike.

    >>> [round(float(makers_column_modulus(207e9, b, h)) / 1e9, 1)
    ...  for b, h in ((False, False), (True, True), (True, False))]
    [199.7, 207.0, 199.7]
    """
    maker = np.where(hiwin_rated, HIWIN_COLUMN_MODULUS_PA, LOWEST_COLUMN_MODULUS_PA)
    ball_rated = np.minimum(youngs_modulus_pa, maker)
    return np.where(ball, ball_rated, leadscrew_column_modulus(youngs_modulus_pa))


@formula(
    "F_cr = min(F_col, k pi^2 E_m I / L^2)",
    "a ball screw HIWIN BS-08-2-EN-1704-K F 3.25 where its family declares it, else "
    "Rockford Ball Screw, How To Size A Ball Screw, step 9 (14.03e6 C d^4 / L^2) and "
    "Thomson; a leadscrew Thomson's and Nook's 14.03e6 F_c d^4 / L^2 for steel, W.M. "
    "Berg's Maximum Column Load Formula (13.4e6 K d^4 / D^2) for stainless",
)
def rated_column_load(
    column_load_n: Any,
    second_moment_m4: Any,
    length_m: float,
    end_fixity: str,
    makers_modulus_pa: Any,
) -> Any:
    """A screw's critical column load as rated [N], never above its makers': the column's
    (``column_critical_load``) and at most the Euler load with its makers' modulus
    ``makers_modulus_pa`` (``makers_column_modulus``: a ball screw's HIWIN's F_k =
    4.072e5 f_k d_k^4 / l_s^2 where its family declares that rule, else Rockford's and
    Thomson's 14.03e6 C d^4 / L^2 [lb, in]; a leadscrew's its makers' for its class of
    steel, ``leadscrew_column_modulus``).
    second_moment_m4: I [m^4]; length_m: L [m]; end_fixity: a key of END_FIXITY_K.

    HIWIN R20-05 (d_k 16.9 mm) over 1000 mm, fixed-supported: HIWIN's F_k = 4.072e5 x 0.5
    x 16.9^4 / 1000^2 = 16,608 N; the column with E = 207 GPa, 16,361 N, is lower and
    stays; held to Rockford's rule it is 15,782 N:

    >>> from app.core.formulas.buckling import second_moment_round
    >>> i = second_moment_round(0.0169)
    >>> round(float(euler_critical_load(HIWIN_COLUMN_MODULUS_PA, i, 1.0, "fixed-simple")))
    16608
    >>> col = euler_critical_load(207e9, i, 1.0, "fixed-simple")
    >>> moduli = [makers_column_modulus(np.inf, True, h) for h in (True, False)]
    >>> [round(float(rated_column_load(col, i, 1.0, "fixed-simple", e))) for e in moduli]
    [16361, 15782]
    """
    maker = euler_critical_load(makers_modulus_pa, second_moment_m4, length_m, end_fixity)
    return np.minimum(column_load_n, maker)


#: THK's permissible tensile/compressive load of a ball screw shaft, P2 = 116 d1^2 [N, d1
#: the root diameter in mm] (General Catalog, Ball Screw, A15-30, formula 6): an allowed
#: axial stress of 116 x 4 / pi = 147.7 N/mm^2 on the root area, the lowest published.
#: HIWIN publishes no such cap.
THK_PERMISSIBLE_STRESS_PA = to_si(116.0 * 4.0 / math.pi, "MPa")


def makers_allowed_stress(ball: Any, hiwin_rated: Any = False) -> Any:
    """The highest stress a screw's makers allow at its root [Pa]: a ball screw's whose
    family declares no buckling rule, THK's P2 = 116 d1^2 [N, mm] over the root area,
    116 x 4 / pi = 147.7 MPa (General Catalog, Ball Screw, A15-30, formula 6); inf (none
    published) for a leadscrew and a ball screw rated by HIWIN's rule
    (``HIWIN_BUCKLING_RULE``). Numbers or arrays alike.

    >>> [round(float(makers_allowed_stress(b, h)) / 1e6, 1)
    ...  for b, h in ((False, False), (True, True), (True, False))]
    [inf, inf, 147.7]
    """
    capped = np.logical_and(ball, np.logical_not(hiwin_rated))
    return np.where(capped, THK_PERMISSIBLE_STRESS_PA, np.inf)


@formula(
    "F_allowed = min(SF x F_cr, sigma_P2 A) for a ball screw",
    "THK General Catalog, Ball Screw, A15-30, formula 6 (P2 = 116 d1^2 N) where its "
    "family declares no buckling rule",
)
def rated_allowed_load(
    critical_load_n: Any, safety_factor: float, area_m2: Any, makers_stress_pa: Any
) -> Any:
    """A screw's allowed column load [N], never above its makers': the buckling factor
    times the critical load (``allowed_buckling_load``) and at most its makers' allowed
    stress ``makers_stress_pa`` (``makers_allowed_stress``: for a ball screw whose family
    declares no buckling rule THK's permissible P2 = 116 d1^2 [N, mm], 147.7 MPa; inf,
    no cap, otherwise) on the root area ``area_m2`` [m^2].
    critical_load_n: F_cr [N]; safety_factor: SF [-].

    HIWIN R20-05 (d1 16.9 mm) as a short column: 0.5 x A x 310 MPa = 34,769 N; THK's
    P2 = 116 x 16.9^2 = 33,131 N:

    >>> from app.core.formulas.buckling import root_area
    >>> a = root_area(0.0169)
    >>> stresses = [makers_allowed_stress(True, h) for h in (True, False)]
    >>> [round(float(rated_allowed_load(a * 310e6, 0.5, a, s))) for s in stresses]
    [34769, 33131]
    """
    most = makers_stress_pa * area_m2
    return np.minimum(allowed_buckling_load(critical_load_n, safety_factor), most)
