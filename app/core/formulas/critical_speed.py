"""Critical speed (shaft whirl) of the screw from beam theory, and its remedies.

omega_c = (beta / L)^2 sqrt(E I / (rho A)) with I / A = d_r^2 / 16 for a round shaft of
root diameter d_r (Euler-Bernoulli beam, Blevins [5] table 8-1). Reduces to Thomson's
n_c = 4.76e6 d_r / L^2 [rpm, in] for steel, simple-simple [3]. A screw is rated at no more
than its makers allow (``rated_critical_speed_rpm``): a leadscrew at Thomson's and Roton's
end fixity factors where they are below the beam's, a ball screw at HIWIN's. Arithmetic
only: each formula accepts floats or NumPy arrays.
"""

import math
from typing import Any

import numpy as np

from app.core.formulas.declare import formula
from app.core.units import from_si

#: First bending eigenvalue beta = lambda_1 for each end fixity [5].
END_FIXITY_BETA: dict[str, float] = {
    "fixed-free": 1.87510,
    "simple-simple": math.pi,
    "fixed-simple": 3.92660,
    "fixed-fixed": 4.73004,
}


@formula(
    "n_c = 60 / (2 pi) (beta / L)^2 sqrt(E / rho) d_r / 4",
    "Blevins, Formulas for Natural Frequency, table 8-1; Thomson n_c = 4.76e6 d_r / L^2",
)
def critical_speed_rpm(
    root_diameter_m: float,
    length_m: float,
    youngs_modulus_pa: float,
    density_kg_m3: float,
    end_fixity: str,
    shaft: tuple[float, float] | None = None,
) -> float:
    """First whirling speed n_c [rpm] of a round shaft.

    n_c = 60 / (2 pi) * (beta / L)^2 * sqrt(E / rho) * d_r / 4

    root_diameter_m: d_r [m]; length_m: unsupported length L [m]; youngs_modulus_pa:
    E [Pa]; density_kg_m3: rho [kg/m^3]; end_fixity: a key of END_FIXITY_BETA; shaft:
    sqrt(E / rho) [m/s] and d_r / 4 [m] when already worked out (``shaft_terms``: the
    candidate table's columns), the same numbers.
    Source: Blevins [5] table 8-1; Thomson [3] gives 476 rpm for a 1 in steel root at
    100 in, simple-simple.

    >>> round(critical_speed_rpm(0.0254, 2.54, 206e9, 7850.0, "simple-simple"), 1)
    475.2
    """
    beta = END_FIXITY_BETA[end_fixity]
    wave_m_s, gyration_m = (
        shaft_terms(root_diameter_m, youngs_modulus_pa, density_kg_m3) if shaft is None else shaft
    )
    omega: float = (beta / length_m) ** 2 * wave_m_s * gyration_m
    return omega * 60.0 / (2.0 * math.pi)


def shaft_terms(
    root_diameter_m: float, youngs_modulus_pa: float, density_kg_m3: float
) -> tuple[float, float]:
    """The shaft's own terms of ``critical_speed_rpm``: sqrt(E / rho) [m/s] and the root
    section's radius of gyration d_r / 4 [m].

    >>> [round(x, 5) for x in shaft_terms(0.0254, 206e9, 7850.0)]
    [5122.69833, 0.00635]
    """
    return (youngs_modulus_pa / density_kg_m3) ** 0.5, root_diameter_m / 4.0


#: Leadscrew makers' end-fixity factors C_s, times simple-simple (Thomson, "Screw critical
#: speed" training page; fxsolver "Critical speed for a leadscrew"; Roton, Screw
#: University, end fixity table 40): below the beam's (beta / pi)^2 for fixed-simple
#: (1.562) and fixed-fixed (2.267), a fixed end being less than rigid.
LEADSCREW_FIXITY_FACTOR: dict[str, float] = {
    "fixed-free": 0.36,
    "simple-simple": 1.0,
    "fixed-simple": 1.47,
    "fixed-fixed": 2.23,
}


@formula(
    "ratio = C_s / (beta / pi)^2 where below 1",
    "Thomson and Roton end fixity factors against the beam's eigenvalues",
)
def makers_table_ratio(end_fixity: str) -> float:
    """The leadscrew makers' critical speed over the beam's for an end fixity [-]: their
    factor C_s over (beta / pi)^2 where it is below 1 (fixed-simple 0.941, fixed-fixed
    0.984), else 1 (the beam's fixed-free 0.356 is already below their 0.36).

    >>> round(makers_table_ratio("fixed-simple"), 3), makers_table_ratio("fixed-free")
    (0.941, 1.0)
    """
    beam = (END_FIXITY_BETA[end_fixity] / math.pi) ** 2
    return min(1.0, LEADSCREW_FIXITY_FACTOR[end_fixity] / beam)


#: Thomson's constant for a steel screw [rpm in]: n_c = C_s 4.76e6 d_r / L^2 with d_r and L
#: in inches (Thomson, "Screw critical speed (maximum RPM) calculation"; fxsolver, "Critical
#: speed for a leadscrew", the same for a steel leadscrew).
THOMSON_CRITICAL_SPEED_RPM_IN = 4.76e6


@formula(
    "n_c = C_s 4.76e6 d_r / L^2 [rpm, in]",
    "Thomson, Screw critical speed (maximum RPM) calculation; fxsolver, Critical speed for "
    "a leadscrew",
)
def leadscrew_makers_critical_speed_rpm(
    root_diameter_m: Any, length_m: float, end_fixity: str
) -> Any:
    """A leadscrew's critical speed as its makers rate it [rpm]: Thomson's n_c = C_s x
    4.76e6 x d_r / L^2 with the root diameter d_r [m] and the length between the bearings
    L [m] (taken in inches, as the constant is), C_s the end fixity factor
    (``LEADSCREW_FIXITY_FACTOR``). The constant is the beam's with a steel's E / rho
    (about 206 GPa over 7850 kg/m^3); a stiffer or lighter steel's beam is above it, and
    a leadscrew is rated at no more than it (``rated_critical_speed_rpm``). Numbers or
    arrays alike.

    A 15.5 mm root (Tr20x4) over 1 m, simple-simple: 4.76e6 x 0.6102 / 39.37^2 = 1874 rpm:

    >>> round(float(leadscrew_makers_critical_speed_rpm(0.0155, 1.0, "simple-simple")), 1)
    1874.0
    """
    factor = LEADSCREW_FIXITY_FACTOR[end_fixity]
    per_root_in = THOMSON_CRITICAL_SPEED_RPM_IN * factor / from_si(length_m, "in") ** 2
    return per_root_in * from_si(1.0, "in") * root_diameter_m


#: HIWIN's mounting factors f_n for its ball screws' critical speed, n_k = 2.71e8 f_n d_k
#: / l_s^2 [rpm, mm] (HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, F 3.27):
#: 1.0 fixed-fixed, 0.692 fixed-simple, 0.446 simple-simple, 0.147 fixed-free.
BALL_SCREW_FIXITY_FACTOR: dict[str, float] = {
    "fixed-free": 0.147,
    "simple-simple": 0.446,
    "fixed-simple": 0.692,
    "fixed-fixed": 1.0,
}


#: HIWIN F 3.27's constant [rpm mm]: n_k = 2.71e8 f_n d_k / l_s^2 with d_k and l_s in mm.
HIWIN_CRITICAL_SPEED_RPM_MM = 2.71e8
#: The rule of HIWIN's ball screws (``ball_screw_critical_speed_rpm``), as a ball-screw
#: family declares it (``ScrewSpec.critical_speed_rule``).
HIWIN_RULE = "HIWIN F 3.27"
#: The makers' critical-speed rules a ball-screw family may declare.
MAKER_RULES = (HIWIN_RULE,)


@formula(
    "n_k = 2.71e8 f_n d_k / l_s^2 [rpm, mm]",
    "HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, F 3.27",
)
def ball_screw_critical_speed_rpm(root_diameter_m: Any, length_m: float, end_fixity: str) -> Any:
    """A ball screw's critical speed as its maker rates it [rpm]: HIWIN F 3.27 with the
    root diameter d_k [m] and the unsupported length l_s [m] (taken in mm, as the
    formula's constant is), and the mounting factor f_n of the end fixity
    (``BALL_SCREW_FIXITY_FACTOR``). HIWIN's constant holds for its steel; a ball screw's
    critical speed is the lower of this and the beam's (``critical_speed_rpm``), so it
    is never above its maker's. Numbers or arrays alike.

    A 17.32 mm root over 1000 mm, fixed-free: 2.71e8 x 0.147 x 17.32 / 1000^2 = 690 rpm
    (the beam, 8.1 % higher, rates the fixed end rigid):

    >>> round(ball_screw_critical_speed_rpm(0.01732, 1.0, "fixed-free"), 1)
    690.0
    """
    root_mm, length_mm = from_si(1.0, "mm") * root_diameter_m, from_si(length_m, "mm")
    factor = BALL_SCREW_FIXITY_FACTOR[end_fixity]
    return HIWIN_CRITICAL_SPEED_RPM_MM * factor * root_mm / length_mm**2


@formula(
    "n_c = min(n_beam, C_s n_ss, C_s 4.76e6 d_r / L^2 [rpm, in]); a ball screw's "
    "min(n_c, n_k), or min(n_beam, n_k) where its maker rates it by HIWIN F 3.27",
    "the beam (Blevins table 8-1); a leadscrew at most Thomson's and Roton's end fixity "
    "factors C_s and Thomson's steel constant 4.76e6; a ball screw at most HIWIN "
    "BS-08-2-EN-1704-K F 3.27, and at most the factors C_s too unless its maker rates it "
    "by HIWIN's rule (Rockford Ball Screw, How to Size a Ball Screw, rates its ball "
    "screws by C_s)",
)
def rated_critical_speed_rpm(
    root_diameter_m: Any,
    length_m: float,
    youngs_modulus_pa: Any,
    density_kg_m3: Any,
    end_fixity: str,
    ball: Any,
    shaft: tuple[Any, Any] | None = None,
    hiwin_rated: Any = False,
) -> Any:
    """The critical speed a screw is rated at [rpm], never above its makers': the beam's
    (``critical_speed_rpm``, ``shaft`` its terms when already worked out) times
    ``makers_table_ratio`` for a leadscrew (the lower of the beam's and the leadscrew
    makers' C_s times simple-simple), and at most Thomson's C_s x 4.76e6 d_r / L^2
    (``leadscrew_makers_critical_speed_rpm``: a C45 screw's 207 GPa over 7800 kg/m^3 is
    0.39 % above the steel that constant is worked with). Where ``ball`` (a ball
    screw), also at most HIWIN's rule (``ball_screw_critical_speed_rpm``); where
    ``hiwin_rated`` too (its maker rates it by that rule, ``HIWIN_RULE``), the lower of
    the beam's and HIWIN's alone. A ball screw of another maker is held to the lowest
    published rule: Rockford, like the leadscrew makers, rates fixed-simple ends at 1.47
    times simple-simple where HIWIN's mounting factors give 0.692 / 0.446 = 1.55. The
    factor is constant for an end fixity, so the rating keeps the beam's d_r / L^2 (so
    does Thomson's constant). Numbers or arrays alike.

    A leadscrew with a 1 in steel root (206 GPa, 7850 kg/m^3) over 100 in, fixed-simple:
    simple-simple 475.2 rpm (``critical_speed_rpm``) x C_s 1.47 = 698.5 rpm, where the
    beam's (beta / pi)^2 = 1.562 would give 742.4 rpm:

    >>> n_c = rated_critical_speed_rpm(0.0254, 2.54, 206e9, 7850.0, "fixed-simple", False)
    >>> round(float(n_c), 1)
    698.5
    >>> round(float(rated_critical_speed_rpm(0.01732, 1.0, 207e9, 7800.0, "fixed-free", True)), 1)
    690.0

    Fixed-simple, the same root over 1 m: HIWIN's 2.71e8 x 0.692 x 17.32 / 1000^2 = 3248
    rpm for a HIWIN screw; any other ball screw the makers' 1.47 x 4.76e6 x 0.6819 /
    39.37^2 = 3078 rpm (the beam's simple-simple 2102 rpm x 1.47 is 3090):

    >>> args = (0.01732, 1.0, 207e9, 7800.0, "fixed-simple", True)
    >>> [round(float(rated_critical_speed_rpm(*args, hiwin_rated=h))) for h in (True, False)]
    [3248, 3078]
    """
    beam = critical_speed_rpm(
        root_diameter_m, length_m, youngs_modulus_pa, density_kg_m3, end_fixity, shaft
    )
    makers = leadscrew_makers_critical_speed_rpm(root_diameter_m, length_m, end_fixity)
    leadscrew = np.minimum(beam * makers_table_ratio(end_fixity), makers)
    if not np.asarray(ball).any():
        return leadscrew
    hiwin = ball_screw_critical_speed_rpm(root_diameter_m, length_m, end_fixity)
    return np.where(ball, np.minimum(np.where(hiwin_rated, beam, leadscrew), hiwin), leadscrew)


@formula("n = SF x n_c", "Thomson (80 % of critical)")
def allowed_speed_rpm(critical_rpm: float, safety_factor: float) -> float:
    """Allowed screw speed n_allowed = safety factor x n_c [rpm] (default factor 0.8).

    Source: Thomson [3] (operate at most 80 % of critical speed).

    >>> allowed_speed_rpm(1000.0, 0.8)
    800.0
    """
    return safety_factor * critical_rpm


def speed_at_length(rpm_at_length: float, length_m: float, new_length_m: float) -> float:
    """A critical (or allowed) speed moved to another unsupported length [rpm].

    n_c is proportional to 1 / L^2 for a given root diameter, material and end fixity,
    so n(L_new) = n(L) (L / L_new)^2 (Blevins [5] table 8-1). Draws the critical-speed
    chart from one evaluated point.

    >>> speed_at_length(1000.0, 1.0, 2.0)
    250.0
    """
    return rpm_at_length * (length_m / new_length_m) ** 2


@formula("margin = n_allowed / n", "inverse of the critical-speed utilization")
def speed_margin(allowed_rpm: float, operating_rpm: float) -> float:
    """How many times the operating speed fits under the allowed speed [-].

    margin = n_allowed / n, the inverse of the critical-speed check's utilization.

    >>> speed_margin(900.0, 300.0)
    3.0
    """
    return allowed_rpm / operating_rpm


def max_length_for_speed(length_m: float, allowed_rpm: float, operating_rpm: float) -> float:
    """Longest unsupported length at which the operating speed is allowed [m].

    n_c is proportional to 1 / L^2, so L_max = L sqrt(n_allowed / n).

    >>> max_length_for_speed(1.0, 400.0, 100.0)
    2.0
    """
    ratio: float = (allowed_rpm / operating_rpm) ** 0.5
    return length_m * ratio


def min_root_diameter_for_speed(
    root_diameter_m: float, allowed_rpm: float, operating_rpm: float
) -> float:
    """Smallest root diameter at which the operating speed is allowed [m].

    n_c is proportional to d_r, so d_r,min = d_r n / n_allowed.

    >>> min_root_diameter_for_speed(0.01, 500.0, 1000.0)
    0.02
    """
    return root_diameter_m * operating_rpm / allowed_rpm


def min_lead_for_speed(linear_speed_m_s: float, allowed_rpm: float) -> float:
    """Shortest lead that keeps the screw at or below the allowed speed [m].

    lead_min = 60 v / n_allowed (from n = 60 v / lead, seed [1]).

    >>> min_lead_for_speed(0.1, 600.0)
    0.01
    """
    return 60.0 * linear_speed_m_s / allowed_rpm
