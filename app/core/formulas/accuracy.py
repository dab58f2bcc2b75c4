"""Positioning accuracy terms: lead error, thermal growth [1]."""

from app.core.formulas.declare import SEED, formula


@formula("e = lead accuracy x stroke", SEED + " (Screw Accuracy)")
def cumulative_lead_error(lead_accuracy_m_per_m: float, stroke_m: float) -> float:
    """Cumulative lead error over a stroke = lead accuracy x stroke [m].

    Source: seed [1] "Screw Accuracy": 0.0006 mm/mm standard, to 0.0001 mm/mm precision.

    >>> round(cumulative_lead_error(0.0006, 0.3) * 1e3, 4)
    0.18
    """
    return lead_accuracy_m_per_m * stroke_m


@formula("dL = alpha stroke (T - 20 C)", "303 stainless 17.3e-6 /K (ASM Handbook)")
def thermal_growth(expansion_per_k: float, length_m: float, delta_t_k: float) -> float:
    """Free thermal growth dL = alpha L dT [m].

    303 stainless: alpha = 17.3e-6 /K (handbook); polyacetal nut 3.3e-5 /K (seed [1]).

    >>> round(thermal_growth(17.3e-6, 1.0, 10.0) * 1e3, 4)
    0.173
    """
    return expansion_per_k * length_m * delta_t_k
