"""Thread efficiency, back-driving and holding torque of an Acme/trapezoidal screw.

Shigley's power-screw form [2] with flank half-angle alpha_n (14.5 deg for 29-deg Acme,
15 deg for 30-deg ISO trapezoidal) and lead angle lambda; the manufacturer's square-thread
form is ``square_thread_efficiency`` for comparison.
"""

import math


def forward_efficiency(lead_angle_rad: float, friction: float, half_angle_rad: float) -> float:
    """Efficiency of driving the load by turning the screw [-].

    eta = (cos a_n - mu tan l) / (cos a_n + mu / tan l)

    lead_angle_rad: lambda [rad]; friction: mu [-]; half_angle_rad: a_n [rad].
    Returns 0 when the thread cannot advance (mu tan l >= cos a_n).
    Source: Shigley [2], eq. 8-1 and 8-4 with the Acme sec(alpha) term.

    >>> round(forward_efficiency(math.atan(0.5 / math.pi), 0.09, 0.0), 3)
    0.63
    >>> round(forward_efficiency(math.atan(1 / math.pi), 0.15, 0.0), 3)
    0.647
    """
    t = math.tan(lead_angle_rad)
    c = math.cos(half_angle_rad)
    eta = (c - friction * t) / (c + friction / t)
    return max(eta, 0.0)


def backdrive_efficiency(lead_angle_rad: float, friction: float, half_angle_rad: float) -> float:
    """Efficiency of the load turning the screw (back-driving) [-].

    eta_b = (cos a_n tan l - mu) / (tan l (cos a_n + mu tan l)), and 0 when the numerator
    is <= 0 (self-locking). With a_n = 0 it is tan(l - phi) / tan(l).
    Source: Shigley [2], sec. 8-2, lowering torque T_L set to the load's work.

    >>> round(backdrive_efficiency(math.atan(0.5 / math.pi), 0.09, 0.0), 4)
    0.4284
    >>> backdrive_efficiency(math.atan(0.001 / (math.pi * 0.0057)), 0.08, math.radians(14.5))
    0.0
    """
    t = math.tan(lead_angle_rad)
    c = math.cos(half_angle_rad)
    numerator = c * t - friction
    if numerator <= 0.0:
        return 0.0
    return numerator / (t * (c + friction * t))


def square_thread_efficiency(lead_angle_rad: float, friction: float) -> float:
    """Manufacturer-style square-thread efficiency tan(l) / tan(l + atan(mu)) [-].

    Shown beside Shigley's Acme form; it differs by under 1.5 points at mu 0.09-0.15.
    Source: Shigley [2] eq. 8-4 with alpha = 0.

    >>> round(square_thread_efficiency(math.atan(0.5 / math.pi), 0.09), 3)
    0.63
    """
    return math.tan(lead_angle_rad) / math.tan(lead_angle_rad + math.atan(friction))


def self_locking_limit_friction(lead_angle_rad: float, half_angle_rad: float) -> float:
    """Static friction at and above which the screw cannot be back-driven [-].

    mu_lock = cos a_n tan l; self-locking when mu_static >= mu_lock.
    Source: Shigley [2], sec. 8-2, self-locking condition pi mu d_m > l, Acme form.

    >>> round(self_locking_limit_friction(math.atan(0.1), 0.0), 6)
    0.1
    """
    return math.cos(half_angle_rad) * math.tan(lead_angle_rad)


def is_self_locking(lead_angle_rad: float, friction_static: float, half_angle_rad: float) -> bool:
    """True when mu_static >= cos(a_n) tan(lambda): the load cannot turn the screw.

    Source: Shigley [2], sec. 8-2.

    >>> is_self_locking(math.atan(0.05), 0.08, math.radians(14.5))
    True
    """
    return friction_static >= self_locking_limit_friction(lead_angle_rad, half_angle_rad)


def seed_backdrive_rule(lead_m: float, outer_diameter_m: float) -> bool:
    """Seed rule of thumb: back-driving will not occur when lead < diameter / 8.

    Source: seed [1], "Back Driving": "when the screw lead is less than 1/8 the diameter,
    back driving will not occur". Diameter taken as the outer diameter.

    >>> seed_backdrive_rule(0.0007, 0.00635), seed_backdrive_rule(0.001, 0.00635)
    (True, False)
    """
    return lead_m < outer_diameter_m / 8.0


def max_self_locking_lead(
    pitch_diameter_m: float, friction_static: float, half_angle_rad: float
) -> float:
    """Largest lead that is still self-locking [m]: lead = pi d_p mu_s / cos a_n.

    Inverse of the self-locking condition (Shigley [2], sec. 8-2).

    >>> round(max_self_locking_lead(0.01, 0.08, 0.0) * 1000, 4)
    2.5133
    """
    return math.pi * pitch_diameter_m * friction_static / math.cos(half_angle_rad)


def holding_torque(load_n: float, lead_m: float, efficiency: float) -> float:
    """Torque to hold a back-drivable load, T_b = F lead eta / (2 pi) [N m].

    With eta = forward efficiency this is the seed's formula (safe side for sizing a
    brake); with eta = back-drive efficiency it is the physically consistent value.
    Source: seed [1], "Back Driving".

    >>> round(holding_torque(100.0, 0.01, 0.5), 5)
    0.07958
    """
    return load_n * lead_m * efficiency / (2.0 * math.pi)
