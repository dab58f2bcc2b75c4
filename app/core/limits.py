"""Seed limits: traverse speed by lead band, length, coating environment, temperature [1]."""

from itertools import pairwise
from typing import NamedTuple


class TraverseLimit(NamedTuple):
    """Recommended maximum linear speed for a lead, and whether the lead is off-table."""

    speed_m_s: float
    extrapolated: bool


#: Seed table "Traverse Speed": (lead from [m], lead to [m], max linear speed [m/s]).
TRAVERSE_BANDS: tuple[tuple[float, float, float], ...] = (
    (0.0025, 0.012, 0.100),
    (0.012, 0.025, 0.250),
    (0.025, 0.060, 0.760),
)


def traverse_speed_limit_m_s(lead_m: float) -> float:
    """Recommended maximum linear speed [m/s] for a lead [m], seed table [1].

    Written as a sum of steps so that it accepts floats or NumPy arrays: the first
    band's speed, plus each faster band's increase where lead >= its start.

    >>> traverse_speed_limit_m_s(0.012), traverse_speed_limit_m_s(0.0119)
    (0.25, 0.1)
    """
    speed = TRAVERSE_BANDS[0][2]
    for (_, _, slower), (start, _, faster) in pairwise(TRAVERSE_BANDS):
        speed = speed + (faster - slower) * (lead_m >= start)
    return speed


def traverse_speed_limit(lead_m: float) -> TraverseLimit:
    """Recommended maximum linear speed for optimum nut life [m/s], by lead band.

    Bands (seed [1] "Traverse Speed"): 2.5-12 mm: 100 mm/s; 12-25 mm: 250 mm/s;
    25-60 mm: 760 mm/s. Band edges belong to the faster band; leads outside 2.5-60 mm
    take the nearest band and are marked extrapolated.

    >>> traverse_speed_limit(0.012)
    TraverseLimit(speed_m_s=0.25, extrapolated=False)
    >>> traverse_speed_limit(0.001)
    TraverseLimit(speed_m_s=0.1, extrapolated=True)
    """
    low, high = TRAVERSE_BANDS[0][0], TRAVERSE_BANDS[-1][1]
    return TraverseLimit(traverse_speed_limit_m_s(lead_m), not low <= lead_m <= high)


def tfe_allowed(oil_present: bool) -> bool:
    """TFE-coated screws must not be used where oil contamination is possible.

    Source: seed [1] "TFE Coating": "should not be additionally lubricated or used in
    environments where oils or other lubricant contamination is possible".

    >>> tfe_allowed(True)
    False
    """
    return not oil_present


def temperature_ok(ambient_c: float, min_c: float, max_c: float) -> bool:
    """Ambient temperature within the assembly's operating range (seed: 0-93 C).

    >>> temperature_ok(20.0, 0.0, 93.0), temperature_ok(-5.0, 0.0, 93.0)
    (True, False)
    """
    return min_c <= ambient_c <= max_c
