"""Positioning accuracy terms: lead error, thermal growth and their worst-case sum [1, 2].

1. Seed catalog, "Screw Accuracy".
2. THK, Ball Screw, Point of Selection, "Studying the Positioning Accuracy": the causes of
   error in the positioning accuracy include the lead angle accuracy, the axial clearance
   and the axial rigidity of the feed screw system, and the thermal displacement from heat.
"""

from app.core.formulas.declare import SEED, formula


@formula("e = lead accuracy x stroke", SEED + " (Screw Accuracy)")
def cumulative_lead_error(lead_accuracy_m_per_m: float, stroke_m: float) -> float:
    """Cumulative lead error over a stroke = lead accuracy x stroke [m].

    Source: seed [1] "Screw Accuracy": 0.0006 mm/mm standard, to 0.0001 mm/mm precision.

    >>> round(cumulative_lead_error(0.0006, 0.3) * 1e3, 4)
    0.18
    """
    return lead_accuracy_m_per_m * stroke_m


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
    "e = e_lead + |dL_thermal| + b_max + r, summed as a worst case",
    "THK Ball Screw, Point of Selection: Studying the Positioning Accuracy (lead accuracy, "
    "axial clearance and thermal displacement are each causes of error)",
)
def worst_case_error(
    lead_error_m: float, thermal_growth_m: float, backlash_m: float, repeatability_m: float
) -> float:
    """Worst-case positioning error over a stroke [m]: the cumulative lead error, the
    screw's thermal growth over the stroke (either sign: a screw colder than the
    reference shrinks), the largest backlash and the repeatability, summed as if each
    were at its worst in the same direction.

    All arguments in metres. Source: THK [2] lists lead accuracy, axial clearance and
    thermal displacement as separate causes of positioning error; the sum is their
    worst case (no cancellation assumed).

    >>> round(worst_case_error(0.18e-3, 0.2076e-3, 0.0, 0.0013e-3) * 1e3, 4)
    0.3889
    >>> worst_case_error(0.18e-3, -0.2e-3, 0.0, 0.0) == worst_case_error(0.18e-3, 0.2e-3, 0.0, 0.0)
    True
    """
    return lead_error_m + abs(thermal_growth_m) + backlash_m + repeatability_m
