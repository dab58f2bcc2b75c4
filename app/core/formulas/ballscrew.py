"""Ball screws: rated fatigue life, static safety, the d n speed limit and preload drag.

The basic dynamic load rating Ca is the axial load at which 90 % of a group of ball
screws run 10^6 revolutions; the basic static load rating C0a the axial load that leaves
a permanent dent of 0.0001 of the ball diameter (ISO 3408-5; HIWIN GmbH, Ballscrews &
Accessories, BS-08-2-EN-1704-K, sec. 3.7.1).
"""

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from app.core.formulas.declare import formula
from app.core.units import from_si

#: The makers' catalog the ball-screw rules come from.
HIWIN = "HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K"
#: The rated life's revolutions, 10^6 (ISO 3408-5).
REVOLUTIONS_RATED = 10.0**6
#: The highest forward (driving) efficiency HIWIN gives a ball screw in normal operation,
#: eta_1 = 0.85 to 0.95 (BS-08-2-EN-1704-K, F 3.15).
MAX_FORWARD_EFFICIENCY = 0.95


@formula("eta_1 = min(eta, 0.95)", HIWIN + ", F 3.15 (eta_1 = 0.85 to 0.95)")
def forward_efficiency(efficiency: ArrayLike) -> Any:
    """A ball screw's driving efficiency [-]: the thread's (tan lambda / tan(lambda + phi)
    at the ball track's equivalent friction), at most HIWIN's 0.95. At the lead angles of
    its fast leads, 12 to 26 degrees, the friction of HIWIN's Fig. 2.1 gives up to 0.975,
    past the curves it draws (to 10 degrees) and past the range F 3.15 states for the
    drive torque. Floats or arrays.

    >>> float(forward_efficiency(0.968)), float(forward_efficiency(0.84))
    (0.95, 0.84)
    """
    return np.minimum(efficiency, MAX_FORWARD_EFFICIENCY)


@formula(
    "F_m = (sum |F_i|^3 s_i / sum s_i)^(1/3)",
    HIWIN + ", sec. 3.7.2 F 3.9 (cubic mean load, weighted by revolutions)",
)
def cubic_mean_load(forces_n: ArrayLike, travels_m: Sequence[float]) -> Any:
    """The cubic mean axial load [N] of a cycle whose segments carry ``forces_n`` [N]
    over ``travels_m`` [m] of nut travel each (the revolutions in a segment are its travel
    over the lead, so weighting by travel is weighting by n_i t_i); ``forces_n`` may hold
    one row of segment loads per nut (the segments along its last axis), giving one mean
    each. The sign of a force does not matter: both flanks of the ball track roll. 0
    when nothing moves.

    (1000^3 x 0.1 + 100^3 x 0.8 + 500^3 x 0.1)^(1/3) = (1.133e8)^(1/3):

    >>> round(float(cubic_mean_load([1000.0, 100.0, 500.0], [0.1, 0.8, 0.1])), 1)
    483.9
    """
    travels = np.asarray(travels_m, dtype=np.float64)
    total = float(travels.sum())
    if total <= 0.0:
        return 0.0
    cubes = np.abs(np.asarray(forces_n, dtype=np.float64)) ** 3 @ travels
    return np.cbrt(cubes / total)


@formula("F_lim = 2^(3/2) F_pr", HIWIN + ", sec. 3.7.2 F 3.7 (the operating load's limit)")
def preload_release_force(preload_n: ArrayLike) -> Any:
    """The axial load [N] at which a preloaded ball nut's unloaded side goes slack, the
    disengagement force F_lim = 2^(3/2) F_pr of the preload F_pr [N]: beyond it the nut
    has play. Numbers or arrays alike.

    >>> round(float(preload_release_force(340.0)), 1)
    961.7
    """
    return 2.0**1.5 * np.asarray(preload_n, dtype=np.float64)


@formula(
    "F_b = (1 + F / (2^(3/2) F_pr))^(3/2) F_pr below F_lim = 2^(3/2) F_pr, else F",
    HIWIN + ", sec. 3.7.2 F 3.7 (operating load of a preloaded nut)",
)
def preloaded_operating_load(force_n: ArrayLike, preload_n: ArrayLike) -> Any:
    """The load a preloaded ball nut's loaded ball track carries under an axial load
    ``force_n`` [N] (its size: the sign does not matter) and the preload F_pr [N]: below
    the disengagement force 2^(3/2) F_pr the preload raises it; at or above it, or with
    no preload (a nut with play: 0 or NaN), it is the axial load. Numbers or arrays alike.

    A 5 % preload of Ca 9,600 N (480 N) under 50.9 N carries 507 N; past 1,358 N the
    preload no longer counts:

    >>> round(float(preloaded_operating_load(50.9, 480.0)), 1)
    507.2
    >>> float(preloaded_operating_load(2000.0, 480.0)), float(preloaded_operating_load(50.9, 0.0))
    (2000.0, 50.9)
    >>> float(preloaded_operating_load(50.9, float("nan")))
    50.9
    """
    force = np.abs(np.asarray(force_n, dtype=np.float64))
    preload = np.asarray(preload_n, dtype=np.float64)
    limit = preload_release_force(preload)
    engaged = force < limit
    # raised to the 3/2 power only where the preload counts (NaN, a nut without one, is
    # slow to raise), the rest left 0 and not read
    zeros = np.zeros(engaged.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        raised = np.power(1.0 + force / limit, 1.5, out=zeros, where=engaged) * preload
    return np.where(engaged, raised, force)


@formula(
    "L = (Ca / (f_w F_m))^3 x 10^6 rev",
    "ISO 3408-5 rated life; " + HIWIN + ", sec. 3.7.2 F 3.10 (load factor f_p)",
)
def rated_life_revolutions(dynamic_load_n: float, load_factor: float, mean_load_n: float) -> float:
    """The L10 rated life [revolutions] of a ball nut of dynamic load rating Ca [N] under
    the cubic mean load F_m [N] times the load factor f_w [-] (1.1 to 1.2 for operation
    without impact, 1.3 to 1.8 in normal operation: HIWIN sec. 3.7.2). Valid for
    F_m well below Ca (HIWIN recommends at most Ca / 5).

    (6500 / 600)^3 x 10^6:

    >>> round(rated_life_revolutions(6500.0, 1.2, 500.0) / 1e6, 1)
    1271.4
    """
    return (dynamic_load_n / (load_factor * mean_load_n)) ** 3 * REVOLUTIONS_RATED


@formula(
    "F_b1 = F_b, F_b2 = F_b - |F| for a thrust F pressing side 1 below F_lim = 2^(3/2) F_pr "
    "(F_b1 = |F|, F_b2 = 0 at or above it); the sides swap for a thrust the other way",
    HIWIN + ", sec. 3.7.2 F 3.6, F 3.7 and the flow chart for calculating service life "
    "(F_bn1,2 = F_b1,2 - F_n1,2; past F_lim the other side carries 0)",
)
def side_loads(force_n: ArrayLike, preload_n: ArrayLike) -> tuple[Any, Any]:
    """The loads [N] the two sides of a ball nut carry under an axial thrust ``force_n``
    [N], signed along the axis (side 1: the balls a positive thrust presses, one half of a
    double nut or one flank of a preloaded single nut; side 2: the other), with the
    preload F_pr [N]. The pressed side carries F_b (``preloaded_operating_load``), the
    other what is left of its preload, F_b - |F|, which falls to 0 at the disengagement
    force 2^(3/2) F_pr and stays 0 beyond it. Without preload (0 or NaN) the pressed side
    carries the thrust and the other nothing. Numbers or arrays alike (broadcast).

    480 N of preload (F_lim = 1,357.6 N) under 500 N one way and the other:
    (1 + 500 / 1357.6)^1.5 x 480 = 768.3 N pressed, 768.3 - 500 = 268.3 N on the other:

    >>> [round(float(x), 1) for x in side_loads(500.0, 480.0)]
    [768.3, 268.3]
    >>> [round(float(x), 1) for x in side_loads(-500.0, 480.0)]
    [268.3, 768.3]
    >>> [float(x) for x in side_loads(2000.0, 480.0)], [float(x) for x in side_loads(-50.0, 0.0)]
    ([2000.0, 0.0], [0.0, 50.0])
    """
    force = np.asarray(force_n, dtype=np.float64)
    pressed = preloaded_operating_load(force, preload_n)
    other = pressed - np.abs(force)
    return np.where(force >= 0.0, pressed, other), np.where(force >= 0.0, other, pressed)


@formula(
    "L = (L_1^(-10/9) + L_2^(-10/9))^(-9/10), L_1,2 = (Ca / (f_w F_bm1,2))^3 x 10^6 rev",
    HIWIN + ", sec. 3.7.2 d) 'Axial loading on both sides' (L1, L2 and their combined "
    "life) and the flow chart for calculating service life (L_res)",
)
def two_sided_life_revolutions(
    dynamic_load_n: ArrayLike, load_factor: float, side1_mean_n: ArrayLike, side2_mean_n: ArrayLike
) -> Any:
    """The L10 life [revolutions] of a ball nut whose two sides carry the cubic mean loads
    F_bm1 and F_bm2 [N] over the cycle (``side_loads`` per segment, ``cubic_mean_load``):
    each side's life L_1,2 = (Ca / (f_w F_bm1,2))^3 x 10^6 for the rating Ca [N] and load
    factor f_w [-] (``rated_life_revolutions``), combined as both sides must survive. A
    side without load lives forever and leaves the other's life. Worked as 10^6 (sum
    (f_w F_bm / Ca)^(10/3))^(-9/10), the same sum without dividing by a zero load. Valid
    as ``rated_life_revolutions`` (F_bm well below Ca). Numbers or arrays alike.

    Both sides at 500 N, Ca 6,500 N, f_w 1.2: L_1 = L_2 = 1271.4e6, L = 2^(-9/10) L_1 =
    0.5359 x 1271.4e6 = 681.3e6; one side unloaded leaves L_1:

    >>> round(float(two_sided_life_revolutions(6500.0, 1.2, 500.0, 500.0)) / 1e6, 1)
    681.3
    >>> round(float(two_sided_life_revolutions(6500.0, 1.2, 500.0, 0.0)) / 1e6, 1)
    1271.4
    """
    rating = np.asarray(dynamic_load_n, dtype=np.float64)
    sides = [(load_factor * np.asarray(f, dtype=np.float64) / rating) ** (10.0 / 3.0)
             for f in (side1_mean_n, side2_mean_n)]  # fmt: skip
    with np.errstate(divide="ignore"):
        return (sides[0] + sides[1]) ** -0.9 * REVOLUTIONS_RATED


@formula(
    "L_nut = min(L, (Ca / (f_w F_m))^3 x 10^6) with a preload F_pr > 0, else "
    "(Ca / (f_w F_m))^3 x 10^6 rev",
    HIWIN + ", sec. 3.7.2 F 3.7 to F 3.10 (one side, F_m) and d) (both sides, L)",
)
def nut_life_revolutions(
    dynamic_load_n: ArrayLike,
    load_factor: float,
    mean_load_n: ArrayLike,
    side_means_n: tuple[ArrayLike, ArrayLike],
    preload_n: ArrayLike,
) -> Any:
    """A ball nut's L10 life [revolutions]: rating Ca [N], load factor f_w [-], the
    cycle's cubic mean F_m [N] of the load its loaded ball track carries (each segment's
    ``preloaded_operating_load``), the two sides' cubic means F_bm1, F_bm2 [N]
    (``side_loads``) and the preload F_pr [N]. A preloaded nut's two sides both roll under
    load and both must survive: its life is HIWIN's two-sided L
    (``two_sided_life_revolutions``), or the one-sided (Ca / (f_w F_m))^3 x 10^6 where that
    is shorter (thrust both ways near the disengagement force, where the two-sided L runs
    up to 2^(1/10) = 1.07 times longer), so the life is never above either. A nut without
    preload (0 or NaN) has the one-sided life. Infinite where nothing loads the nut.

    Ca 6,500 N, f_w 1.2, 300 N of preload (F_lim = 848.5 N). Moving without thrust,
    both sides carry 300 N: L = 2^(-9/10) (6500 / 360)^3 x 10^6 = 0.5359 x 5886.2e6 =
    3154.3e6, below the one-sided 5886.2e6. 500 N out and 500 N back over equal travel:
    F_b = (1 + 500 / 848.5)^1.5 x 300 = 601.05 N pressed, 101.05 N on the other side, so
    F_bm1 = F_bm2 = ((601.05^3 + 101.05^3) / 2)^(1/3) = 477.81 N and L = 0.5359 x
    (6500 / 573.37)^3 x 10^6 = 780.7e6; one side under 601.05 N all the way rates
    (6500 / 721.26)^3 x 10^6 = 731.9e6, the shorter, and is taken. Without preload,
    one-sided:

    >>> round(float(nut_life_revolutions(6500.0, 1.2, 300.0, (300.0, 300.0), 300.0)) / 1e6, 1)
    3154.3
    >>> round(float(nut_life_revolutions(6500.0, 1.2, 601.05, (477.81, 477.81), 300.0)) / 1e6, 1)
    731.9
    >>> round(float(nut_life_revolutions(6500.0, 1.2, 500.0, (500.0, 0.0), 0.0)) / 1e6, 1)
    1271.4
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        # each a number or an array: ``rated_life_revolutions`` is plain arithmetic
        rating: Any = np.asarray(dynamic_load_n, dtype=np.float64)
        mean: Any = np.asarray(mean_load_n, dtype=np.float64)
        one_sided = rated_life_revolutions(rating, load_factor, mean)
        both = two_sided_life_revolutions(dynamic_load_n, load_factor, *side_means_n)
        preloaded = np.asarray(preload_n, dtype=np.float64) > 0.0
    return np.where(preloaded, np.minimum(both, one_sided), one_sided)


@formula(
    "Ca_req = f_w F_m (L / 10^6)^(1/3)",
    "ISO 3408-5 rated life, solved for the dynamic load rating",
)
def required_dynamic_load(load_factor: float, mean_load_n: float, life_revolutions: float) -> float:
    """The dynamic load rating [N] a ball nut needs to run ``life_revolutions`` [rev]
    under the cubic mean load F_m [N] with load factor f_w [-].

    MITCalc's ball-screw example: F_m = 1000 N, 2400 rpm for 20,000 h, f_w = 1.2:

    >>> round(required_dynamic_load(1.2, 1000.0, 20000 * 60 * 2400.0), 1)
    17073.1
    """
    cube_root: float = (life_revolutions / REVOLUTIONS_RATED) ** (1.0 / 3.0)
    return load_factor * mean_load_n * cube_root


@formula("DN = d_s [mm] x n_max [rpm]", HIWIN + ", sec. 3.7.6 (DN value)")
def dn_value(diameter_m: float, rpm: float) -> float:
    """The speed value DN [mm rpm] of a ball screw of diameter ``diameter_m`` [m] at
    ``rpm`` [1/min]; HIWIN allows 70,000 for rolled and 90,000 for peeled and ground
    ball screws.

    >>> dn_value(0.032, 2400.0)
    76800.0
    """
    return from_si(diameter_m, "mm") * rpm


@formula(
    "d_DN = max(d_s, d_0)",
    "Roton and THK take the nominal (ball-centre) diameter d_0; HIWIN sec. 3.7.6 tables d_s",
)
def dn_diameter(outer_diameter_m: Any, pitch_circle_diameter_m: Any) -> Any:
    """The diameter a ball screw's DN value is taken on [m]: the larger of the shaft's
    outer diameter d_s (HIWIN sec. 3.7.6 writes DN = d_s x n_max) and its pitch circle
    (ball-centre, nominal) diameter d_0, on which Roton ("Ball Screws", 3,000 in rpm on a
    3/4 in screw: 4,000 rpm) and THK take it: the lower speed limit of the two readings.
    A missing d_0 (NaN) leaves d_s. Numbers or arrays alike.

    HIWIN's R16: d_s 15.5 mm, d_0 16 mm:

    >>> float(dn_diameter(0.0155, 0.016)), float(dn_diameter(0.0155, float("nan")))
    (0.016, 0.0155)
    """
    return np.fmax(outer_diameter_m, pitch_circle_diameter_m)


@formula("n_DN = DN_max / d_DN [mm]", HIWIN + ", sec. 3.7.6 (DN value)")
def dn_speed_limit(dn_limit_mm_rpm: float, diameter_m: float) -> float:
    """The highest screw speed [rpm] the DN limit [mm rpm] allows a screw of
    ``diameter_m`` [m].

    >>> round(dn_speed_limit(70000.0, 0.016), 1)
    4375.0
    """
    return dn_limit_mm_rpm / from_si(diameter_m, "mm")


@formula("T_d = K_p F_pr P / (2 pi)", HIWIN + ", sec. 3.6.3 F 3.2 (idle torque of a preloaded nut)")
def preload_drag_torque(friction_factor: float, preload_n: float, lead_m: float) -> float:
    """The idle (drag) torque [N m] of a preloaded ball nut: preload F_pr [N], lead P [m]
    and the preload friction coefficient K_p [-] (0.1 to 0.3, HIWIN F 3.2).

    A 5 % preload of a 30,800 N nut at 10 mm lead, K_p = 0.2:

    >>> round(preload_drag_torque(0.2, 0.05 * 30800.0, 0.010), 3)
    0.49
    """
    return friction_factor * preload_n * lead_m / (2.0 * 3.141592653589793)
