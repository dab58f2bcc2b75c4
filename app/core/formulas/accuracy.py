"""Positioning accuracy terms: lead error, thermal growth and their worst-case sum [1-5].

1. Seed catalog, "Screw Accuracy".
2. THK, Ball Screw, Point of Selection, "Studying the Positioning Accuracy": the causes of
   error in the positioning accuracy include the lead angle accuracy, the axial clearance
   and the axial rigidity of the feed screw system, and the thermal displacement from heat.
3. ISO 3408-3:2006, Ball screws, Part 3: Acceptance conditions and acceptance tests:
   positioning (P) and transport (T) tolerance classes; the limit deviation e_p of the
   mean travel over the useful travel l_u, the variation v300p over any 300 mm.
4. HIWIN GmbH, Ballscrews & Accessories, catalogue BS-08-2-EN-1704-K, sec. 3.5: Table 3.3
   (v300p by class: T3 12 um, T5 23, T7 52, T10 210), Table 3.4 (e_p of the peeled and
   ground classes T0-T5 by bands of useful path, T3 12 um up to 315 mm, 21 um at
   800-1,000 mm) and F 3.1 (e_p of the rolled transport classes from l_u / 300 and v300p).
5. Bosch Rexroth (Star), Precision Ball Screw Assemblies, RE 83 301, Acceptance
   Conditions and Tolerance Grades, p. 81: its transport grades' e_p = (l_u / 300) v300p
   are "improved values ... tolerance reduced by half" against DIN 69051-3 and
   ISO 3408-3, whose transport rule is so 2 (l_u / 300) v300p.
"""

import math
from collections.abc import Sequence

from app.core.formulas.declare import SEED, formula

#: ISO 3408-3's transport classes: e_p = 2 (l_u / 300 mm) v300p [5].
TRANSPORT_FACTOR = 2.0
#: The travel over which the variation v300p is stated [m].
VARIATION_TRAVEL_M = 0.3
#: A positioning class's limit deviation by useful travel, the maker's table: rows of
#: (useful travel up to [m], e_p [m]), ascending.
DeviationBands = Sequence[tuple[float, float]]


@formula("e = lead accuracy x stroke", SEED + " (Screw Accuracy)")
def cumulative_lead_error(lead_accuracy_m_per_m: float, stroke_m: float) -> float:
    """Cumulative lead error over a stroke = lead accuracy x stroke [m].

    Source: seed [1] "Screw Accuracy": 0.0006 mm/mm standard, to 0.0001 mm/mm precision.

    >>> round(cumulative_lead_error(0.0006, 0.3) * 1e3, 4)
    0.18
    """
    return lead_accuracy_m_per_m * stroke_m


@formula(
    "e_p = the class's table value for the band holding l_u (a positioning class); "
    "e_p = v300p max(1, 2 l_u / 300 mm) (a transport class)",
    "ISO 3408-3; HIWIN BS-08-2-EN-1704-K sec. 3.5.3, Table 3.4 and F 3.1; the factor 2: "
    "Bosch Rexroth RE 83 301 p. 81 (its transport grades' (l_u / 300) v300p are half of "
    "ISO 3408-3's); v300p is the variation over any 300 mm, not a rate: Steinmeyer's "
    "rolled classes keep e_p = v300p up to 315 mm (T7 52 um)",
)
def ball_travel_deviation(
    useful_travel_m: float, v300p_m: float, bands: DeviationBands = ()
) -> float:
    """Limit deviation e_p [m] of a ball screw's travel over the useful travel l_u [m]
    (the stroke), by its ISO 3408-3 tolerance class [3, 4].

    A positioning class (ground, peeled: T0-T5) is given by its maker's table ``bands``,
    rows of (l_u up to [m], e_p [m]): e_p is the value of the first band reaching l_u,
    the first band's below its bound (a short travel is not pro-rated), and not a number
    beyond the last band (the class states none there). A transport class (rolled: T5-T10)
    has no table: e_p = 2 (l_u / 300 mm) v300p (ISO 3408-3, whose factor 2 is the one
    Bosch Rexroth halves for its own grades [5]; HIWIN F 3.1 gives its rolled screws'
    e_p from l_u / 300 and v300p), and at least v300p, the variation the class allows
    within any 300 mm: a shorter travel may lie anywhere in it. ``v300p_m`` [m] may be a
    NumPy array (the transport rule scales it; a table ignores it).

    Valid for the classes' own tables and travels. The transport rule is ISO's, the
    upper bound a rolled screw ordered to its class may reach; a maker promising less
    gives its own table as ``bands`` (Steinmeyer's rolled T7: 52 um to 315 mm, 69 um to
    400 mm: (l_u / 300) v300p, half of ISO's).

    HIWIN T3 (Table 3.4): 12 um over 100 mm (not 100/300 x 12 = 4 um), 21 um over 900 mm.
    Rolled T7, v300p 52 um: 52 um over 100 mm, 2 x 2 x 52 = 208 um over 600 mm.

    >>> t3 = ((0.315, 12e-6), (0.4, 13e-6), (0.5, 15e-6), (0.63, 16e-6), (0.8, 18e-6),
    ...       (1.0, 21e-6))
    >>> [round(ball_travel_deviation(lu, 12e-6, t3) * 1e6, 3) for lu in (0.1, 0.315, 0.9)]
    [12.0, 12.0, 21.0]
    >>> ball_travel_deviation(1.2, 12e-6, t3)
    nan
    >>> [round(ball_travel_deviation(lu, 52e-6) * 1e6, 3) for lu in (0.1, 0.15, 0.6)]
    [52.0, 52.0, 208.0]
    """
    if bands:
        return next((ep_m for upper_m, ep_m in bands if useful_travel_m <= upper_m), math.nan)
    return v300p_m * max(1.0, TRANSPORT_FACTOR * useful_travel_m / VARIATION_TRAVEL_M)


@formula(
    "dL = alpha stroke (T - 20 C)",
    "alpha the screw material's (catalog, with its provenance; 303 stainless 17.3e-6 /K, "
    "ASM Handbook); 20 C the reference temperature of lengths (ISO 1)",
)
def thermal_growth(expansion_per_k: float, length_m: float, delta_t_k: float) -> float:
    """Free thermal growth dL = alpha L dT [m]; alpha [1/K] the screw material's, L [m],
    dT [K] from the 20 C reference.

    For example 303 stainless: alpha = 17.3e-6 /K (handbook); polyacetal nut 3.3e-5 /K
    (seed [1]).

    >>> round(thermal_growth(17.3e-6, 1.0, 10.0) * 1e3, 4)
    0.173
    """
    return expansion_per_k * length_m * delta_t_k


@formula(
    "e = e_lead + |dL_thermal| + dL_heat + b_max + r, summed as a worst case",
    "THK Ball Screw, Point of Selection: Studying the Positioning Accuracy (lead accuracy, "
    "axial clearance and thermal displacement are each causes of error)",
)
def worst_case_error(
    lead_error_m: float,
    thermal_growth_m: float,
    backlash_m: float,
    repeatability_m: float,
    heat_growth_m: float = 0.0,
) -> float:
    """Worst-case positioning error over a stroke [m]: the cumulative lead error, the
    screw's thermal growth over the stroke at the ambient (either sign: a screw colder
    than the reference shrinks), its growth from its own friction heat (``heat_growth_m``,
    ``heat.heated_growth``; 0: not counted), the largest backlash and the repeatability,
    summed as if each were at its worst in the same direction.

    All arguments in metres. Source: THK [2] lists lead accuracy, axial clearance and
    thermal displacement as separate causes of positioning error; the sum is their
    worst case (no cancellation assumed: a cold ambient's shrinking does not offset the
    friction heat's growth).

    >>> round(worst_case_error(0.18e-3, 0.2076e-3, 0.0, 0.0013e-3) * 1e3, 4)
    0.3889
    >>> worst_case_error(0.18e-3, -0.2e-3, 0.0, 0.0) == worst_case_error(0.18e-3, 0.2e-3, 0.0, 0.0)
    True
    >>> round(worst_case_error(0.0, -0.1e-3, 0.3e-3, 0.0, 0.35e-3) * 1e3, 4)
    0.75
    """
    return lead_error_m + abs(thermal_growth_m) + heat_growth_m + backlash_m + repeatability_m
