"""A family's rules as data: a limit that steps with the lead, and the temperature range.

The core knows no family: the bands and ranges come from the catalog (``ScrewSpec``).
"""

from collections.abc import Sequence
from itertools import pairwise
from typing import NamedTuple

from app.core.formulas.declare import SEED, formula

#: (lead from [m], lead to [m], recommended maximum linear speed [m/s]), ascending.
Bands = Sequence[tuple[float, float, float]]


class BandLimit(NamedTuple):
    """The limit of a lead's band, and whether the lead lies outside the table."""

    speed_m_s: float
    extrapolated: bool


def band_speed_m_s(lead_m: float, bands: Bands) -> float:
    """Recommended maximum linear speed [m/s] for a lead [m] from a band table.

    Written as a sum of steps so that it accepts floats or NumPy arrays: the first
    band's speed, plus each faster band's increase where lead >= its start. Band edges
    belong to the faster band; leads outside the table take the nearest band.

    >>> seed = ((0.0025, 0.012, 0.100), (0.012, 0.025, 0.250), (0.025, 0.060, 0.760))
    >>> band_speed_m_s(0.012, seed), band_speed_m_s(0.0119, seed)
    (0.25, 0.1)
    """
    speed = bands[0][2]
    for (_, _, slower), (start, _, faster) in pairwise(bands):
        speed = speed + (faster - slower) * (lead_m >= start)
    return speed


@formula("band table by lead (family data)", SEED + " (Traverse Speed)")
def band_limit(lead_m: float, bands: Bands) -> BandLimit:
    """The band limit [m/s] of a lead [m], marked extrapolated outside the table (floats
    or NumPy arrays of leads).

    >>> seed = ((0.0025, 0.012, 0.100), (0.012, 0.025, 0.250), (0.025, 0.060, 0.760))
    >>> band_limit(0.012, seed)
    BandLimit(speed_m_s=0.25, extrapolated=False)
    >>> band_limit(0.001, seed)
    BandLimit(speed_m_s=0.1, extrapolated=True)
    """
    low, high = bands[0][0], bands[-1][1]
    return BandLimit(band_speed_m_s(lead_m, bands), (lead_m < low) | (lead_m > high))


def temperature_ok(ambient_c: float, min_c: float, max_c: float) -> bool:
    """Ambient temperature within the assembly's operating range, T_min <= T <= T_max.

    Written with ``&`` so that it accepts floats or NumPy arrays of ranges.

    >>> temperature_ok(20.0, 0.0, 93.0), temperature_ok(-5.0, 0.0, 93.0)
    (True, False)
    """
    inside: bool = (min_c <= ambient_c) & (ambient_c <= max_c)
    return inside
