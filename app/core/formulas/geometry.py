"""Screw geometry: lead, pitch diameter, thread depth, lead angle, speed [1].

The formulas use arithmetic only, so each accepts floats or NumPy arrays alike.
"""

import math

from app.core.formulas.declare import SEED, SHIGLEY, formula


def lead_from_pitch(pitch_m: float, starts: int) -> float:
    """Lead [m] = pitch [m] x number of starts [-].

    Source: seed [1], "Lead = Pitch x Number of Starts".

    >>> lead_from_pitch(0.002, 4)
    0.008
    """
    return pitch_m * starts


@formula(
    "d_p = d2 of a standard thread (ISO 2904: d - 0.5 P), else (OD + RD) / 2", SEED + "; ISO 2904"
)
def pitch_diameter(outer_diameter_m: float, root_diameter_m: float) -> float:
    """Pitch (mean) diameter d_p = (d_o + d_r) / 2 [m].

    Source: seed [1] PV calculation, ``P_o = (O.D. + R.D.) / 2``.

    >>> round(pitch_diameter(0.00635, 0.004953), 6)
    0.005652
    """
    return 0.5 * (outer_diameter_m + root_diameter_m)


def thread_depth(outer_diameter_m: float, root_diameter_m: float) -> float:
    """Thread depth h = (d_o - d_r) / 2 [m], the seed's "thread thickness" term.

    Source: seed [1] PV calculation, ``AT = H.T. x (O.D. - R.D.) / 2``.

    >>> round(thread_depth(0.0127, 0.009906), 7)
    0.001397
    """
    return 0.5 * (outer_diameter_m - root_diameter_m)


@formula("lambda = atan(lead / (pi d_p))", SHIGLEY)
def lead_angle(lead_m: float, pitch_diameter_m: float) -> float:
    """Lead (helix) angle lambda = atan(lead / (pi d_p)) [rad].

    Source: Shigley [2], eq. 8-1 geometry.

    >>> round(math.degrees(lead_angle(0.001, 0.005652)), 3)
    3.223
    """
    return math.atan(lead_m / (math.pi * pitch_diameter_m))


def tan_lead_angle(lead_m: float, pitch_diameter_m: float) -> float:
    """tan(lambda) = lead / (pi d_p) [-], the form the efficiency formulas use.

    Source: Shigley [2], eq. 8-1 geometry.

    >>> round(tan_lead_angle(0.5 * math.pi, 1.0), 6)
    0.5
    """
    return lead_m / (math.pi * pitch_diameter_m)


@formula("n = 60 v / lead", SEED + " (RS = speed / lead)")
def screw_speed_rpm(linear_speed_m_s: float, lead_m: float) -> float:
    """Screw speed n [rpm] = 60 v / lead, v [m/s], lead [m].

    Source: seed [1], ``RS = Linear Speed / Lead``, ``RPM = RS x 60``.

    >>> round(screw_speed_rpm(0.05, 0.002), 6)
    1500.0
    """
    return 60.0 * linear_speed_m_s / lead_m


def linear_speed(screw_speed_rpm: float, lead_m: float) -> float:
    """Linear speed v [m/s] = n lead / 60 at a screw speed n [rpm]: ``screw_speed_rpm``
    turned round, for the speed a speed limit allows.

    >>> linear_speed(1500.0, 0.002)
    0.05
    """
    return screw_speed_rpm * lead_m / 60.0


def helix_travel(lead_m: float, pitch_diameter_m: float) -> float:
    """Thread surface travel per revolution H.T. = sqrt(lead^2 + (pi d_p)^2) [m].

    Source: seed [1] PV calculation, "H.T. = Surface Travel per Rev." (the printed
    formula is garbled by OCR; this is the helix length of one turn at the pitch
    diameter, which is what the seed's words describe).

    >>> round(helix_travel(0.0, 0.01), 6)
    0.031416
    """
    travel: float = (lead_m**2 + (math.pi * pitch_diameter_m) ** 2) ** 0.5
    return travel


@formula(
    "m = rho pi d_p^2 L / 4",
    "solid cylinder at the pitch diameter: the thread's flanks fill about half the "
    "annulus between root and outer diameter",
)
def screw_mass(density_kg_m3: float, pitch_diameter_m: float, length_m: float) -> float:
    """A threaded screw's mass m = rho pi d_p^2 L / 4 [kg]: density [kg/m^3], pitch
    (mean) diameter [m], length [m]. A symmetric thread's flanks fill about half the
    annulus between the root and outer diameters, so the cylinder at the mean diameter
    carries about the same metal; valid for solid screws.

    A Tr16x4 steel screw (d2 = 14 mm, 7850 kg/m^3), 1 m long: 1.21 kg.

    >>> round(screw_mass(7850.0, 0.014, 1.0), 3)
    1.208
    """
    return density_kg_m3 * math.pi * pitch_diameter_m**2 * length_m / 4.0
