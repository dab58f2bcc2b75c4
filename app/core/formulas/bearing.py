"""Bearing (contact) pressure of a sliding nut on the engaged flanks, and its limit.

A metal nut is rated by its allowable contact pressure at a sliding speed (Shigley,
Table 8-4 after Rothbart); a polymer nut by a maximum pressure and a PV limit. Each
turn of the nut carries the load on the flank ring pi d2 H1, and the nut length over
the pitch gives the number of engaged turns. SI units; floats or NumPy arrays.
"""

from collections.abc import Sequence

import numpy as np


def engaged_flank_area(
    nut_length_m: float, pitch_m: float, pitch_diameter_m: float, flank_height_m: float
) -> float:
    """Projected bearing area of the engaged thread, A = (L_nut / P) pi d2 H1 [m^2].

    Source: Shigley, Mechanical Engineering Design, power-screw bearing stress
    sigma_B = 2 F / (pi d_m n_t p), i.e. the area pi d_m n_t (p / 2) with n_t = L_nut / P
    engaged turns; for the ISO trapezoidal profile the engaged flank height is H1 = 0.5 P
    (ISO 2904), and d_m is the pitch diameter d2.

    >>> round(engaged_flank_area(0.016, 0.002, 0.007, 0.001) * 1e6, 3)
    175.929
    """
    return nut_length_m / pitch_m * np.pi * pitch_diameter_m * flank_height_m


def bearing_pressure(load_n: float, area_m2: float) -> float:
    """Mean flank contact pressure p = F / A [Pa].

    >>> bearing_pressure(1000.0, 1e-4)
    10000000.0
    """
    return load_n / area_m2


def table_pressure(speed_m_s: float, table: Sequence[tuple[float, float]]) -> float:
    """Allowable pressure [Pa] at a sliding speed [m/s] from a material's table of
    (sliding speed, allowable pressure) rows, linearly interpolated; outside the table
    the nearest row's pressure holds. The catalog refuses a table whose pressure rises
    with speed, so the result never rises with the sliding speed: of two sizes at one
    speed of turning, the one with more flank area sliding no faster carries more.

    Source: the table's own (catalog), e.g. Shigley Table 8-4 for bronze on steel.

    >>> bronze = ((0.05, 11e6), (0.1, 5.5e6), (0.2, 5.5e6), (0.25, 1e6))
    >>> float(table_pressure(0.075, bronze)) / 1e6, float(table_pressure(0.01, bronze)) / 1e6
    (8.25, 11.0)
    """
    speeds = [row[0] for row in table]
    pressures = [row[1] for row in table]
    pressure: float = np.interp(speed_m_s, speeds, pressures)
    return pressure


def dynamic_load(dynamic_pressure_pa: float, area_m2: float) -> float:
    """Allowable dynamic axial load of a sliding nut, F_dyn = p_dyn A [N]: its flank
    pressure in motion [Pa] (its maker's allowable dynamic thrust over its catalog nut's
    engaged flanks, catalog/README.md rule 10) over the engaged flank area [m^2]
    (``engaged_flank_area``). NaN where the nut has no such rating.

    Tr20x4 acetal nut 40 mm long, MISUMI's 980 N over A = 10 turns x pi x 18 mm x 2 mm
    (1131 mm^2) is p_dyn = 0.8665 MPa; a 60 mm nut (15 turns) carries 1.5 x 980 N.

    >>> a_40 = 10 * 3.141592653589793 * 0.018 * 0.002
    >>> round(float(dynamic_load(980.0 / a_40, 1.5 * a_40)), 1)
    1470.0
    """
    return dynamic_pressure_pa * area_m2


def pv_pressure(pv_limit_pa_m_s: float, speed_m_s: float) -> float:
    """Largest pressure a PV limit allows at a sliding speed, p = PV_lim / v [Pa].

    >>> pv_pressure(0.1e6, 0.05)
    2000000.0
    """
    with np.errstate(divide="ignore"):
        return pv_limit_pa_m_s / speed_m_s


def allowable_pressure(
    table_pa: float, max_pressure_pa: float, pv_limit_pa_m_s: float, speed_m_s: float
) -> float:
    """The nut material's allowable pressure at a sliding speed [Pa]: the lowest of its
    table value, its maximum pressure and PV_lim / v. A term that is NaN is not given
    and drops out; with no term given the result is NaN (no limit).

    >>> float(allowable_pressure(np.nan, 10e6, 0.1e6, 0.02)) / 1e6
    5.0
    >>> bool(np.isnan(allowable_pressure(np.nan, np.nan, np.nan, 0.1)))
    True
    """
    least: float = np.fmin(
        np.fmin(table_pa, max_pressure_pa), pv_pressure(pv_limit_pa_m_s, speed_m_s)
    )
    return least
