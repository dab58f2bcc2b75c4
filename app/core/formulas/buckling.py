"""The screw as a column: Euler buckling [4], Johnson's parabola for short columns and
the stress at the root section (Shigley [2], sec. 4-11 to 4-13)."""

import math
from typing import cast

import numpy as np

from app.core.formulas.declare import formula

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


@formula("F = SF x F_cr", "lead-screw practice (0.5)")
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


def root_area(root_diameter_m: float) -> float:
    """Area of the root circle, A = pi d_r^2 / 4 [m^2].

    >>> round(root_area(0.02) * 1e6, 3)
    314.159
    """
    return math.pi * root_diameter_m**2 / 4.0


@formula("s = (L / sqrt(k)) / (d_r / 4)", "Shigley sec. 4-11")
def slenderness(
    root_diameter_m: float, length_m: float, end_fixity: str, gyration_m: float | None = None
) -> float:
    """Slenderness ratio of the screw as a column, s = (L / sqrt(k)) / (d_r / 4) [-].

    The effective length L / sqrt(k) turns each end fixity into the pinned-pinned column
    (Euler F_cr = k pi^2 E I / L^2 = pi^2 E I / (L / sqrt k)^2); r = d_r / 4 is the radius
    of gyration of a round section (``gyration_m`` when already worked out: the candidate
    table's column, ``critical_speed.shaft_terms``, the same number). Source: Shigley [2],
    sec. 4-11 (C = k).

    >>> slenderness(0.02, 1.0, "simple-simple")
    200.0
    """
    effective_length: float = length_m / END_FIXITY_K[end_fixity] ** 0.5
    return effective_length / (root_diameter_m / 4.0 if gyration_m is None else gyration_m)


@formula("s_1 = sqrt(2 pi^2 E / S_y)", "Shigley sec. 4-12")
def transition_slenderness(youngs_modulus_pa: float, yield_strength_pa: float) -> float:
    """Slenderness below which Euler over-predicts, s_1 = sqrt(2 pi^2 E / S_y) [-].

    Source: Shigley [2], sec. 4-12, eq. 4-45 (tangent point of the Johnson parabola).

    >>> round(transition_slenderness(207e9, 310e6), 1)
    114.8
    """
    ratio: float = (2.0 * math.pi**2 * youngs_modulus_pa / yield_strength_pa) ** 0.5
    return ratio


def johnson_critical_load(
    area_m2: float, yield_strength_pa: float, youngs_modulus_pa: float, slenderness_ratio: float
) -> float:
    """Johnson's parabola for intermediate columns, F_cr = A (S_y - (S_y s / 2 pi)^2 / E) [N].

    Valid below the transition slenderness; at s = 0 it is the squash load A S_y.
    Source: Shigley [2], sec. 4-13, eq. 4-46 (with the effective length, C = 1).

    >>> round(johnson_critical_load(1e-4, 310e6, 207e9, 50.0))
    28060
    """
    parabola: float = (yield_strength_pa * slenderness_ratio / (2.0 * math.pi)) ** 2
    return area_m2 * (yield_strength_pa - parabola / youngs_modulus_pa)


@formula(
    "F_cr = pi^2 E A / s^2 (Euler) for s >= s_1, else A (S_y - (S_y s / 2 pi)^2 / E)",
    "Euler (Timoshenko & Gere); Johnson, Shigley sec. 4-13",
)
def column_critical_load(
    youngs_modulus_pa: float,
    root_diameter_m: float,
    length_m: float,
    end_fixity: str,
    yield_strength_pa: float,
    *,
    section: tuple[float, float, float] | None = None,
    slenderness_ratio: float | None = None,
) -> float:
    """Critical load of the screw as a column [N]: Euler when slender, Johnson when short.

    F_cr = pi^2 E A / s^2 for s >= s_1, else A (S_y - (S_y s / 2 pi)^2 / E); Euler alone
    when the yield strength is unknown (NaN). Works on floats or NumPy arrays.
    ``section``: the root's area A [m^2], second moment I [m^4] and the transition
    slenderness s_1, and ``slenderness_ratio``: s, when already worked out with these
    same functions (``root_area``, ``second_moment_round``, ``transition_slenderness``,
    ``slenderness``: the candidate table's columns), the same numbers.
    Source: Shigley [2], sec. 4-11 to 4-13.

    >>> round(column_critical_load(207e9, 0.02, 2.0, "simple-simple", 310e6))
    4011
    >>> round(column_critical_load(207e9, 0.025, 0.1, "fixed-simple", 310e6))
    151432
    """
    if section is None:
        with np.errstate(invalid="ignore", divide="ignore"):
            transition = transition_slenderness(youngs_modulus_pa, yield_strength_pa)
        section = (root_area(root_diameter_m), second_moment_round(root_diameter_m), transition)
    area, second_moment_m4, transition = section
    s = (
        slenderness(root_diameter_m, length_m, end_fixity)
        if slenderness_ratio is None
        else slenderness_ratio
    )
    euler = euler_critical_load(youngs_modulus_pa, second_moment_m4, length_m, end_fixity)
    johnson = johnson_critical_load(area, yield_strength_pa, youngs_modulus_pa, s)
    return cast(float, np.where(s < transition, johnson, euler)[()])


@formula("sigma = F_peak / (pi d_r^2 / 4)", "axial stress")
def root_stress(load_n: float, root_diameter_m: float, area_m2: float | None = None) -> float:
    """Axial stress at the root section, sigma = F / (pi d_r^2 / 4) [Pa]; ``area_m2``: the
    root area when already worked out (``root_area``: the candidate table's column), the
    same number.

    The example of a 25 mm root carrying 200 kN: 407 MPa.

    >>> round(root_stress(200e3, 0.025) / 1e6, 1)
    407.4
    """
    return load_n / (root_area(root_diameter_m) if area_m2 is None else area_m2)


@formula("tau = 16 T / (pi d_r^3)", "Shigley 9th ed., eq. (8-7), torsion of the screw body")
def root_shear_stress(
    torque_nm: float, root_diameter_m: float, pi_d_cubed_m3: float | None = None
) -> float:
    """Torsional shear stress at the surface of the root section, tau = 16 T / (pi d_r^3)
    [Pa].

    torque_nm: the torque the section carries, T [N m]; root_diameter_m: d_r [m];
    pi_d_cubed_m3: pi d_r^3 [m^3] when already worked out (``root_pi_d_cubed``: the
    candidate table's column), the same number. A solid round section in elastic
    torsion. Source: Shigley [2], eq. (8-7); its Example 8-1 (d): T_R = 26.18 N m on
    d_r = 28 mm gives 6.07 MPa.

    >>> round(root_shear_stress(26.18, 0.028) / 1e6, 2)
    6.07
    """
    section = root_pi_d_cubed(root_diameter_m) if pi_d_cubed_m3 is None else pi_d_cubed_m3
    return 16.0 * torque_nm / section


def root_pi_d_cubed(root_diameter_m: float) -> float:
    """pi d_r^3 [m^3], the root section's term of the torsional shear stress
    (``root_shear_stress``: 16 over it is one over the polar section modulus).

    >>> round(root_pi_d_cubed(0.028) * 1e6, 4)
    68.9642
    """
    return math.pi * root_diameter_m**3


@formula(
    "sigma_vm = sqrt((F / (pi d_r^2 / 4))^2 + 3 (16 T / (pi d_r^3))^2)",
    "Shigley 9th ed., eqs. (8-7), (8-8) and (5-15): the body of a power screw under thrust "
    "and torque, combined by the distortion-energy (von Mises) criterion",
)
def root_von_mises_stress(load_n: float, torque_nm: float, root_diameter_m: float) -> float:
    """Von Mises stress at the root section of a screw carrying an axial force and a
    torque, sigma_vm = sqrt(sigma^2 + 3 tau^2) [Pa], with sigma = F / (pi d_r^2 / 4) and
    tau = 16 T / (pi d_r^3).

    load_n: axial force F [N] (pushed or pulled: the sign does not matter); torque_nm: the
    torque the same section carries, T [N m]; root_diameter_m: d_r [m]. Valid while the
    section is elastic (sigma_vm below yield). Source: Shigley [2], eqs. (8-7)
    and (8-8) for the body stresses and eq. (5-15) for their von Mises combination; with
    its Example 8-1 (F = 6.4 kN, T_R = 26.18 N m, d_r = 28 mm: sigma = -10.39 MPa,
    tau = 6.07 MPa) the body's combined stress is 14.79 MPa (14.78 from the rounded
    components).

    >>> round(root_von_mises_stress(6.4e3, 26.18, 0.028) / 1e6, 2)
    14.79
    >>> root_von_mises_stress(1000.0, 0.0, 0.01) == root_stress(1000.0, 0.01)
    True
    """
    sigma = root_stress(load_n, root_diameter_m)
    tau = root_shear_stress(torque_nm, root_diameter_m)
    return von_mises_stress(sigma, tau)


@formula("sigma_vm = sqrt(sigma^2 + 3 tau^2)", "Shigley 9th ed., eq. (5-15)")
def von_mises_stress(axial_pa: float, shear_pa: float) -> float:
    """Von Mises stress of a normal stress and a shear stress on the same section,
    sigma_vm = sqrt(sigma^2 + 3 tau^2) [Pa]; axial_pa: sigma [Pa], shear_pa: tau [Pa]
    (either sign). Valid while the section is elastic. Source: Shigley [2], eq. (5-15)
    with one normal and one shear stress; its Example 8-1 body stresses
    (sigma = -10.39 MPa, tau = 6.07 MPa) give 14.78 MPa.

    >>> round(von_mises_stress(-10.39e6, 6.07e6) / 1e6, 2)
    14.78
    """
    return cast(float, (axial_pa**2 + 3.0 * shear_pa**2) ** 0.5)


def largest_root_load(
    allowed_pa: float, root_diameter_m: float, torque_per_n_m: float, fixed_torque_nm: float
) -> float:
    """The largest axial force F whose von Mises root stress, with the torque
    T = a F + b the section carries with it, is ``allowed_pa`` [N]: the positive root of
    (F / A)^2 + 3 c^2 (a F + b)^2 = S^2, A = pi d_r^2 / 4, c = 16 / (pi d_r^3); 0 when even
    no thrust meets it (the torque alone is too much).

    allowed_pa: S [Pa]; root_diameter_m: d_r [m]; torque_per_n_m: a, the torque per newton
    of thrust, lead / (2 pi eta) [m]; fixed_torque_nm: b, the torque that does not grow
    with the thrust (drag, inertia) [N m]. The inverse of ``root_von_mises_stress``.

    >>> stress = root_von_mises_stress(6.4e3, 26.18, 0.028)
    >>> round(largest_root_load(stress, 0.028, 26.18 / 6.4e3, 0.0), 6)
    6400.0
    >>> largest_root_load(1e6, 0.01, 0.001, 1000.0)
    0.0
    """
    area = root_area(root_diameter_m)
    c2 = 3.0 * (16.0 / (math.pi * root_diameter_m**3)) ** 2
    quadratic = 1.0 / area**2 + c2 * torque_per_n_m**2
    linear = 2.0 * c2 * torque_per_n_m * fixed_torque_nm
    constant = c2 * fixed_torque_nm**2 - allowed_pa**2
    discriminant = linear**2 - 4.0 * quadratic * constant
    if constant > 0.0 or discriminant < 0.0:
        return 0.0
    return (-linear + math.sqrt(discriminant)) / (2.0 * quadratic)


def max_length_for_column(
    critical_load_n: float,
    youngs_modulus_pa: float,
    root_diameter_m: float,
    end_fixity: str,
    yield_strength_pa: float,
) -> float:
    """Longest column whose critical load is ``critical_load_n`` [m]: the inverse of
    ``column_critical_load``; 0 when even a zero length cannot carry it (above A S_y).

    Euler: s = pi sqrt(E A / F_cr); if that is below the transition slenderness, Johnson:
    s = (2 pi / S_y) sqrt(E (S_y - F_cr / A)). L = s (d_r / 4) sqrt(k).

    >>> round(max_length_for_column(4011.437, 207e9, 0.02, "simple-simple", 310e6), 4)
    2.0
    >>> round(max_length_for_column(151432.0, 207e9, 0.025, "fixed-simple", 310e6), 4)
    0.1
    """
    area = root_area(root_diameter_m)
    s: float = math.pi * (youngs_modulus_pa * area / critical_load_n) ** 0.5
    if not math.isnan(yield_strength_pa) and s < transition_slenderness(
        youngs_modulus_pa, yield_strength_pa
    ):
        squash = yield_strength_pa - critical_load_n / area
        s = 2 * math.pi / yield_strength_pa * (youngs_modulus_pa * max(squash, 0.0)) ** 0.5
    length: float = s * (root_diameter_m / 4.0) * END_FIXITY_K[end_fixity] ** 0.5
    return length


@formula(
    "d_r = (64 F_cr L^2 / (k pi^3 E))^(1/4) (Euler); when short, "
    "d_r = sqrt(4 (F_cr + S_y^2 L_e^2 / (pi E)) / (pi S_y)), L_e = L / sqrt(k)",
    "inverse of Euler (Timoshenko & Gere) and Johnson (Shigley sec. 4-13)",
)
def min_root_diameter_for_column(
    critical_load_n: float,
    youngs_modulus_pa: float,
    length_m: float,
    end_fixity: str,
    yield_strength_pa: float,
) -> float:
    """Smallest root diameter whose column of ``length_m`` has the critical load
    ``critical_load_n`` [m]: the inverse of ``column_critical_load`` in the diameter.

    Euler: I = pi d^4 / 64 gives d = (64 F_cr L^2 / (k pi^3 E))^(1/4). When that column is
    short (s = 4 L_e / d below the transition slenderness), Johnson: with A s^2 = 4 pi L_e^2,
    F_cr = A S_y - S_y^2 L_e^2 / (pi E), so A = (F_cr + S_y^2 L_e^2 / (pi E)) / S_y and
    d = sqrt(4 A / pi); the parabola lies below Euler, so this d is the larger. Euler alone
    when the yield strength is unknown (NaN). critical_load_n [N], youngs_modulus_pa [Pa],
    length_m [m], end_fixity a key of END_FIXITY_K, yield_strength_pa [Pa].
    Source: Shigley [2], sec. 4-11 to 4-13, solved for d.

    >>> round(min_root_diameter_for_column(4011.437, 207e9, 2.0, "simple-simple", 310e6), 5)
    0.02
    >>> round(min_root_diameter_for_column(151432.0, 207e9, 0.1, "fixed-simple", 310e6), 5)
    0.025
    """
    k = END_FIXITY_K[end_fixity]
    euler: float = (
        64.0 * critical_load_n * length_m**2 / (k * math.pi**3 * youngs_modulus_pa)
    ) ** 0.25
    if math.isnan(yield_strength_pa):
        return euler
    effective_m = length_m / k**0.5
    if 4.0 * effective_m / euler >= transition_slenderness(youngs_modulus_pa, yield_strength_pa):
        return euler
    parabola = yield_strength_pa**2 * effective_m**2 / (math.pi * youngs_modulus_pa)
    area_m2 = (critical_load_n + parabola) / yield_strength_pa
    johnson: float = (4.0 * area_m2 / math.pi) ** 0.5
    return johnson
