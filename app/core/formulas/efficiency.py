"""Thread efficiency, back-driving and holding torque of an Acme/trapezoidal screw.

Shigley's power-screw form [2] with flank half-angle alpha_n (14.5 deg for 29-deg Acme,
15 deg for 30-deg ISO trapezoidal) and lead angle lambda, written in tan(lambda) and
cos(alpha_n) so that each formula is plain arithmetic and accepts floats or NumPy arrays.
The manufacturer's square-thread form is ``square_thread_efficiency`` for comparison.
"""

import math
from typing import Any

import numpy as np

from app.core.formulas.declare import SEED, SHIGLEY, formula


def _positive_part(x: float) -> float:
    """max(x, 0) by arithmetic, valid for floats and arrays."""
    return (x + abs(x)) * 0.5


@formula(
    "eta = (cos a_n - mu tan l) / (cos a_n + mu / tan l), mu dynamic", SHIGLEY + " (Acme form)"
)
def forward_efficiency(tan_lead: float, friction: float, cos_half_angle: float) -> float:
    """Efficiency of driving the load by turning the screw [-].

    eta = (cos a_n - mu tan l) / (cos a_n + mu / tan l)

    tan_lead: tan(lambda) [-]; friction: mu [-]; cos_half_angle: cos(a_n) [-].
    Returns 0 when the thread cannot advance (mu tan l >= cos a_n).
    Source: Shigley [2], eq. 8-1 and 8-4 with the Acme sec(alpha) term.
    Square-thread spot values (engineering reference): L/d_p 0.5, mu 0.09 -> 63.0 %;
    L/d_p 1.0, mu 0.15 -> 64.7 %.

    >>> round(forward_efficiency(0.5 / math.pi, 0.09, 1.0), 3)
    0.63
    >>> round(forward_efficiency(1 / math.pi, 0.15, 1.0), 3)
    0.647
    """
    eta = (cos_half_angle - friction * tan_lead) / (cos_half_angle + friction / tan_lead)
    return _positive_part(eta)


@formula("mu = (1 - eta) cos a_n / (eta / tan l + tan l)", SHIGLEY + " (Acme form)")
def friction_for_efficiency(tan_lead: float, efficiency: float, cos_half_angle: float) -> float:
    """The friction coefficient at which the thread drives at a stated efficiency [-]:
    ``forward_efficiency`` solved for mu, mu = (1 - eta) cos a_n / (eta / tan l + tan l).

    tan_lead: tan(lambda) [-]; efficiency: eta, 0 < eta < 1 [-]; cos_half_angle:
    cos(a_n) [-]. For a screw known by its efficiency alone (a ball screw's maker states
    eta): the friction that gives the thread that efficiency.
    Source: Shigley [2], eq. 8-4 (Acme form), rearranged.

    >>> tan_l = 1 / math.pi
    >>> round(forward_efficiency(tan_l, friction_for_efficiency(tan_l, 0.9, 1.0), 1.0), 12)
    0.9
    """
    return (1.0 - efficiency) * cos_half_angle / (efficiency / tan_lead + tan_lead)


@formula("eta_b = (cos a_n tan l - mu_s) / (tan l (cos a_n + mu_s tan l)), 0 if negative", SHIGLEY)
def backdrive_efficiency(tan_lead: float, friction: float, cos_half_angle: float) -> float:
    """Efficiency of the load turning the screw (back-driving) [-].

    eta_b = (cos a_n tan l - mu) / (tan l (cos a_n + mu tan l)), and 0 when the numerator
    is <= 0 (self-locking). With a_n = 0 it is tan(l - phi) / tan(l).
    Source: Shigley [2], sec. 8-2, lowering torque T_L set to the load's work.

    >>> round(backdrive_efficiency(0.5 / math.pi, 0.09, 1.0), 4)
    0.4284
    >>> backdrive_efficiency(0.001 / (math.pi * 0.0057), 0.08, math.cos(math.radians(14.5)))
    0.0
    """
    numerator = _positive_part(cos_half_angle * tan_lead - friction)
    return numerator / (tan_lead * (cos_half_angle + friction * tan_lead))


@formula("eta = tan l / tan(l + atan mu)", SHIGLEY + " (square thread, manufacturer's form)")
def square_thread_efficiency(tan_lead: float, friction: float) -> float:
    """Manufacturer-style square-thread efficiency tan(l) / tan(l + atan(mu)) [-].

    tan(l + phi) = (tan l + mu) / (1 - mu tan l). Shown beside Shigley's Acme form; it
    differs by under 1.5 points at mu 0.09-0.15. Source: Shigley [2] eq. 8-4, alpha = 0.

    >>> round(square_thread_efficiency(0.5 / math.pi, 0.09), 3)
    0.63
    """
    return tan_lead * (1.0 - friction * tan_lead) / (tan_lead + friction)


@formula(
    "f mu_s >= cos a_n tan l (f: the self-locking friction factor)",
    SHIGLEY + "; margin as the seed's d/8 rule",
)
def self_locking_limit_friction(tan_lead: float, cos_half_angle: float) -> float:
    """Static friction at and above which the screw cannot be back-driven [-].

    mu_lock = cos a_n tan l; self-locking when mu_static >= mu_lock.
    Source: Shigley [2], sec. 8-2, self-locking condition pi mu d_m > l, Acme form.

    >>> round(self_locking_limit_friction(0.1, 1.0), 6)
    0.1
    """
    return cos_half_angle * tan_lead


@formula("mu_s >= cos a_n tan l", SHIGLEY)
def is_self_locking(tan_lead: float, friction_static: float, cos_half_angle: float) -> bool:
    """True when mu_static >= cos(a_n) tan(lambda): the load cannot turn the screw.

    Source: Shigley [2], sec. 8-2.

    >>> is_self_locking(0.05, 0.08, math.cos(math.radians(14.5)))
    True
    """
    return friction_static >= self_locking_limit_friction(tan_lead, cos_half_angle)


@formula("lead < OD / 8", SEED + " (Back Driving)")
def seed_backdrive_rule(lead_m: float, outer_diameter_m: float) -> bool:
    """Seed rule of thumb: back-driving will not occur when lead < diameter / 8.

    Source: seed [1], "Back Driving": "when the screw lead is less than 1/8 the diameter,
    back driving will not occur". Diameter taken as the outer diameter.

    >>> seed_backdrive_rule(0.0007, 0.00635), seed_backdrive_rule(0.001, 0.00635)
    (True, False)
    """
    return lead_m < outer_diameter_m / 8.0


@formula("lead = pi d_p mu / cos a_n", SHIGLEY)
def max_self_locking_lead(
    pitch_diameter_m: float, friction_static: float, cos_half_angle: float
) -> float:
    """Largest lead that is still self-locking [m]: lead = pi d_p mu_s / cos a_n.

    Inverse of the self-locking condition (Shigley [2], sec. 8-2).

    >>> round(max_self_locking_lead(0.01, 0.08, 1.0) * 1000, 4)
    2.5133
    """
    return math.pi * pitch_diameter_m * friction_static / cos_half_angle


@formula(
    "m_hold = max(lead_max / lead, T_unpowered / T_needed)",
    SHIGLEY + " (self-locking); " + SEED + " (Back Driving)",
)
def hold_margin(max_lock_lead_m: Any, lead_m: Any, unpowered_nm: Any, needed_nm: Any) -> Any:
    """Margin of holding a load with the power off [-], at 1 or more it holds: the larger
    of the thread's, lead_max / lead (lead_max [m] the longest lead that self-locks at the
    trusted static friction f mu_s, lead [m] the screw's: the ratio is f mu_s over the
    friction that just locks), and the unpowered torque's, T_unpowered / T_needed (a
    brake's or a stepper's detent torque [N m] over the holding torque needed with its
    safety factor [N m]; NaN for no such torque). Floats or arrays; valid for lead > 0.

    Source: Shigley [2] sec. 8-2, self-locking condition mu >= cos a_n tan lambda (with
    lead = pi d_p tan lambda); seed [1] "Back Driving" for the holding torque.

    >>> float(hold_margin(4.0e-3, 2.0e-3, float("nan"), 1.0))
    2.0
    >>> round(float(hold_margin(1.0e-3, 2.0e-3, 0.3, 0.2)), 9)
    1.5
    """
    return np.fmax(np.divide(max_lock_lead_m, lead_m), np.divide(unpowered_nm, needed_nm))


@formula("T_b = F lead eta / (2 pi)", SEED + " (Back Driving)")
def holding_torque(load_n: float, lead_m: float, efficiency: float) -> float:
    """Torque to hold a back-drivable load, T_b = F lead eta / (2 pi) [N m].

    With eta = forward efficiency this is the seed's formula; with eta = back-drive
    efficiency (static friction) it is the physically consistent value. Neither bounds the
    other: at the seed's frictions the physics value is the larger for uncoated screws
    (mu_d 0.15 > mu_s 0.08), so a brake is sized on the larger of the two.
    Source: seed [1], "Back Driving".

    >>> round(holding_torque(100.0, 0.01, 0.5), 5)
    0.07958
    """
    return load_n * lead_m * efficiency / (2.0 * math.pi)
