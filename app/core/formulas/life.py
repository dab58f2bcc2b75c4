"""Nut life of the anti-backlash assemblies, converted to service time [1]."""

from app.core.formulas.declare import SEED, formula

DAYS_PER_YEAR = 365.0
SECONDS_PER_HOUR = 3600.0
#: The hours of a day: the most an axis can run in one.
HOURS_PER_DAY = 24.0
SECONDS_PER_DAY = HOURS_PER_DAY * SECONDS_PER_HOUR


@formula("cycles/day = hours/day x 3600 / t_cycle", "duty: running time over the cycle time")
def cycles_per_day(hours_per_day: float, cycle_time_s: float) -> float:
    """Cycles a day [1/day] from the hours a day the axis runs [h/day] and the time of one
    cycle [s] (both moves and both dwells).

    8 hours a day of a 2.5 s cycle:

    >>> cycles_per_day(8.0, 2.5)
    11520.0
    """
    return hours_per_day * SECONDS_PER_HOUR / cycle_time_s


@formula(
    "hours = cycles x t_cycle / 3600",
    "duty: every cycle of the life, each its moves, ramps and dwells",
)
def operating_hours(cycles: float, cycle_time_s: float) -> float:
    """Hours of operation [h] of ``cycles`` cycles of ``cycle_time_s`` [s] each.

    11,520 cycles of 2.5 s: one 8-hour day.

    >>> operating_hours(11520.0, 2.5)
    8.0
    """
    return cycles * cycle_time_s / SECONDS_PER_HOUR


def travel_per_year(stroke_m: float, cycles_per_day: float) -> float:
    """Nut travel per year [m]: one cycle is out and back, 2 x stroke.

    >>> travel_per_year(0.1, 100.0)
    7300.0
    """
    return 2.0 * stroke_m * cycles_per_day * DAYS_PER_YEAR


@formula("years = rated travel / (2 stroke x cycles/day x 365)", SEED + " (Anti-Backlash Life)")
def life_years(life_travel_m: float, stroke_m: float, cycles_per_day: float) -> float:
    """Service life [years] = life travel / (2 stroke x cycles per year).

    life_travel_m: rated life distance [m] (seed table, million cm);
    stroke_m [m]; cycles_per_day [1/day].
    Source: seed [1] anti-backlash life table; the seed warns that life varies with
    load, environment and duty cycle, and longer leads generally last longer.

    >>> round(life_years(100e6 * 0.01, 0.1, 100.0), 1)
    137.0
    """
    return life_travel_m / travel_per_year(stroke_m, cycles_per_day)
