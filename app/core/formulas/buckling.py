"""Column buckling of a screw in compression (Euler) [4]."""

import math

#: Effective-length factor k in F_cr = k pi^2 E I / L^2 for each end fixity [4].
END_FIXITY_K: dict[str, float] = {
    "fixed-free": 0.25,
    "simple-simple": 1.0,
    "fixed-simple": 2.0,
    "fixed-fixed": 4.0,
}


def second_moment_round(diameter_m: float) -> float:
    """Second moment of area of a round section, I = pi d^4 / 64 [m^4].

    >>> round(second_moment_round(0.02) * 1e9, 4)
    7.854
    """
    return math.pi * diameter_m**4 / 64.0


def euler_critical_load(
    youngs_modulus_pa: float, second_moment_m4: float, length_m: float, end_fixity: str
) -> float:
    """Euler buckling load F_cr = k pi^2 E I / L^2 [N].

    youngs_modulus_pa: E [Pa]; second_moment_m4: I [m^4]; length_m: L [m];
    end_fixity: a key of END_FIXITY_K.
    Source: Timoshenko & Gere [4]; engineeringtoolbox "Euler's column formula" example:
    fixed-fixed, E = 69 GPa, I = 241e-8 m^4, L = 5 m gives 263 kN.

    >>> round(euler_critical_load(69e9, 241e-8, 5.0, "fixed-fixed") / 1000, 1)
    262.6
    """
    return (
        END_FIXITY_K[end_fixity] * math.pi**2 * youngs_modulus_pa * second_moment_m4 / (length_m**2)
    )


def allowed_buckling_load(critical_load_n: float, safety_factor: float) -> float:
    """Allowed compressive load = safety factor x F_cr [N] (default factor 0.5).

    Source: common lead-screw practice (Thomson [3] column-load charts use 0.5 x Euler).

    >>> allowed_buckling_load(1000.0, 0.5)
    500.0
    """
    return safety_factor * critical_load_n


def max_length_for_load(length_m: float, allowed_load_n: float, load_n: float) -> float:
    """Longest column at which the load is allowed: L sqrt(F_allowed / F) [m].

    >>> max_length_for_load(1.0, 400.0, 100.0)
    2.0
    """
    ratio: float = (allowed_load_n / load_n) ** 0.5
    return length_m * ratio


def min_root_diameter_for_load(
    root_diameter_m: float, allowed_load_n: float, load_n: float
) -> float:
    """Smallest root diameter carrying the load: d_r (F / F_allowed)^(1/4) [m].

    >>> round(min_root_diameter_for_load(0.01, 100.0, 1600.0), 6)
    0.02
    """
    ratio: float = (load_n / allowed_load_n) ** 0.25
    return root_diameter_m * ratio
