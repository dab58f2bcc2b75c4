"""The screw's thrust bearing (the fixed-side support unit): its static load against its
static axial rating, and its rating life under the cycle's thrusts.

[1] THK, LM Guide Actuator selection, "Static Safety Factor", Ball Screw Unit / Bearing
    Unit (fixed side): fs = C0a / Fmax, lower limit 2 for general industrial machinery
    without vibration or impact, 5 with (thk.com/jp/en/products/lm_guide_actuator/
    selection/0003/).
[2] ISO 281:2007, basic rating life of ball bearings, L10 = (C / P)^3 million
    revolutions; Koyo, "Basic dynamic load rating" (koyousa.com/koyocatalog/technical/03/
    3_26.htm): Ca, the axial rating of a thrust bearing, under which L10 is 10^6 rev.
[3] THK, Ball Screw "Service Life", average axial load under varying loads:
    Fm = (sum Fi^3 li / sum li)^(1/3), li the distance travelled under Fi.
[4] IKO (Nippon Thompson), Needle Roller Bearings catalog, "Calculation of bearing
    loads", eq. (10) and Table 6: the bearing load is the calculated load times the load
    factor, F = fw Fc, fw 1 to 1.2 in smooth operation without shocks (machine tools,
    measuring instruments), 1.2 to 1.5 in ordinary operation, 1.5 to 3 with vibration
    and shocks (ikont.co.jp, technical service digital book, p. A22).
"""

from collections.abc import Sequence

import numpy as np

from app.core.formulas.declare import formula

#: Revolutions in one unit of L10 (ratings are for a life of a million revolutions) [2].
MILLION = 1e6


@formula("F_allowed = C0a / fs", "THK, static safety factor of the bearing unit (fs >= 2)")
def static_allowed_load(static_rating_n: float, safety_factor: float) -> float:
    """The largest peak thrust the thrust bearing may carry, C0a / fs [N].

    static_rating_n: the bearing's static axial load rating C0a (or its maker's
    permissible static axial load) [N]; safety_factor: the static safety factor fs [-],
    THK's lower limit 2 for general industrial machinery without vibration or impact, 5
    with [1]. Valid for fs >= 1.

    THK FK12 support unit, permissible load 3.25 kN, fs 2: 1625 N.

    >>> static_allowed_load(3250.0, 2.0)
    1625.0
    """
    return static_rating_n / safety_factor


@formula("F_m = (sum |F_i|^3 l_i / sum l_i)^(1/3)", "THK Ball Screw, average axial load")
def mean_axial_load(forces_n: Sequence[float], distances_m: Sequence[float]) -> float:
    """The cube-mean axial load over a cycle of varying thrusts [N]: each thrust |F_i|
    [N] weighted by the distance l_i [m] travelled under it (revolutions are distance
    over the lead, the same for every segment) [3]. 0 when nothing is travelled.

    A cycle of 300 mm at 100 N and 100 mm at 400 N: (100^3 x 0.3 + 400^3 x 0.1) / 0.4
    = 16,750,000 N^3, cube root 255.9 N.

    >>> round(mean_axial_load([100.0, -400.0], [0.3, 0.1]), 1)
    255.9
    """
    travelled = float(np.sum(distances_m))
    if travelled <= 0.0:
        return 0.0
    cubes = np.abs(np.asarray(forces_n, dtype=np.float64)) ** 3
    mean: float = float(np.dot(cubes, distances_m) / travelled) ** (1.0 / 3.0)
    return mean


@formula(
    "L10 = (C_a / (f_w F_m))^3 x 10^6 rev",
    "ISO 281, ball bearings; IKO, bearing load = load factor x calculated load",
)
def rating_life_revolutions(
    dynamic_rating_n: float, load_n: float, load_factor: float = 1.0
) -> float:
    """Basic rating life of a ball thrust bearing, L10 = (Ca / (fw Pa))^3 x 10^6 [rev].

    dynamic_rating_n: the basic dynamic axial load rating Ca [N]; load_n: the calculated
    equivalent axial load Pa [N], > 0 (here the cube-mean thrust); load_factor: fw [-],
    at least 1, the factor by which vibration and shocks raise the bearing's load above
    the calculated one (1 to 1.2 smooth, 1.2 to 1.5 ordinary, 1.5 to 3 with vibration
    and shocks [4]). Ball bearings (exponent 3) [2].

    Sarthaks eConnect, bearing life (sarthaks.com/2642436): C 16 kN, W 2 kN ->
    (16 / 2)^3 = 512 million revolutions; at fw 1.2, 512 / 1.2^3 = 296.3.

    >>> rating_life_revolutions(16e3, 2e3) / 1e6
    512.0
    >>> round(rating_life_revolutions(16e3, 2e3, 1.2) / 1e6, 1)
    296.3
    """
    return (dynamic_rating_n / (load_factor * load_n)) ** 3 * MILLION
