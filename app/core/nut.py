"""The nut for many candidates at once: its PV and the limits PV sets, its engaged flanks and
the pressure and load they allow, and its wear life (Archard).
"""

from collections.abc import Sequence
from functools import partial
from typing import Any

import numpy as np

from app.core import motion
from app.core.axis_free import nut_rating, wear_geometry
from app.core.formulas import (
    bearing,
    geometry,
    life,
    pv,
    pv_derating,
    wear,
)
from app.core.model import Application
from app.core.table import Array, CandidateTable, filled, finite


def pv_limit(app: Application, t: CandidateTable) -> dict[str, Any]:
    """The nut's permissible PV at the ambient and its lubrication: the rating times the
    temperature factor (``pv_derating.temperature_factors`` at the ambient; 1 where the
    material's highest temperature is unknown) times the lubrication factor (of the
    lubrication counted: none in a vacuum, ``Application.lubrication_counted``).

    A PV rating is the PV whose own friction heat brings the nut to its highest
    temperature from the rating's room [pv_derating 1-3]: it already holds the nut's rise,
    so only the ambient above the room derates it (the rise itself is the nut heat
    check's, with the duty)."""
    temperature = pv_derating.temperature_factors(app.ambient_c, t.temperature_max_c)
    lubrication = pv_derating.LUBRICATION_FACTORS[app.lubrication_counted][0]
    return {
        "pv_temperature_factor": temperature,
        "pv_lubrication_factor": filled(len(t), lubrication),
        "pv_limit_pa_m_s": t.pv_limit_pa_m_s * temperature * lubrication,
    }


def seed_pv(
    app: Application, t: CandidateTable, force_n: float, rpm: Array, limit: Array
) -> dict[str, Any]:
    """PV of the nut (seed, three threads in contact) and its limits inverted at the
    permissible PV ``limit``, at the thrust ``force_n`` and screw speed ``rpm`` of
    ``quantities.pv_point``: the peak thrust at the top speed (an accelerating segment
    ends at the top speed still carrying m a)."""
    area, helix = t.contact_area_m2, t.helix_travel_m
    pressure = np.asarray(pv.contact_pressure(force_n, area), dtype=np.float64)
    speed = pv.surface_speed(rpm, helix)
    return {
        "pv_pa_m_s": pv.pv_value(force_n, rpm, helix, t.thread_depth_m, area, (pressure, speed)),
        "pressure_pa": pressure,
        "surface_speed_m_s": speed,
        "contact_area_m2": area,
        "pv_max_load_n": pv.max_load_for_pv(limit, rpm, t.thread_depth_m),
        "pv_max_speed_m_s": finite(
            geometry.linear_speed(pv.max_rpm_for_pv(limit, force_n, t.thread_depth_m), t.lead_m)
        ),
    }


def table_pressures(t: CandidateTable, speed_m_s: Array) -> Array:
    """Each candidate's pressure-speed table value at its sliding speed [Pa] (NaN without
    a table); candidates sharing a table are interpolated together."""
    out = filled(len(t), np.nan)
    for position, table in enumerate(t.pressure_tables):
        rows = (t.pressure_table == position).nonzero()[0]
        if rows.size:
            out[rows] = bearing.table_pressure(speed_m_s[rows], table)
    return out


def nut_allowed_pressures(t: CandidateTable, pv_limit_pa_m_s: Array, speed_m_s: Array) -> Array:
    """The pressure each nut's material allows at its sliding speed [Pa]: the lowest of
    its table value, p_max and the (derated) ``pv_limit_pa_m_s`` over the speed [m/s]
    (``bearing.allowable_pressure``); NaN for a nut with none of them."""
    allowed: Array = bearing.allowable_pressure(
        table_pressures(t, speed_m_s), t.max_pressure_pa, pv_limit_pa_m_s, speed_m_s
    )
    return allowed


def nut_length(app: Application, t: CandidateTable) -> Array:
    """The nut length whose engaged turns carry the load: the user's, else the catalog's
    (NaN where the catalog gives none) [m]."""
    if app.nut_length_m is None:
        return t.nut_length_m
    return np.where(np.isnan(t.nut_length_m), np.nan, app.nut_length_m)


def flank_area(app: Application, t: CandidateTable) -> Array:
    """The engaged flank area (L / P) pi d2 H1 of a standard thread's nut [m^2] (NaN
    without a thread pitch), with the nut length of ``nut_length`` (the catalog's, worked
    out with the table)."""
    if app.nut_length_m is None:
        return t.catalog_flank_area_m2
    area = bearing.engaged_flank_area(
        nut_length(app, t), t.pitch_m, t.flank_pitch_diameter_m, t.flank_height_m
    )
    return np.asarray(area, dtype=np.float64)


def flanks(
    app: Application,
    t: CandidateTable,
    rpm: Array,
    derate: Array,
    points: Sequence[tuple[float, float]],
) -> dict[str, Any]:
    """The engaged flanks of the nut: their sliding speed at the top speed (``rpm``), n /
    60 times the helix of one turn at d2; the pressure the nut material allows (the lowest
    of its table value, p_max and PV_lim / v, the PV limit derated by ``derate``, the
    temperature and lubrication factors of ``pv_limit``) and that pressure over the
    engaged flank area, at the thrust and speed of the move each nut carries worst
    (``worst_point`` of the moves' ``points``: thrust [N], linear speed [m/s])."""
    pv_limit = t.nut_pv_limit_pa_m_s * derate
    area = flank_area(app, t)
    force, speed, allowed = worst_point(t, pv_limit, area, points)
    return {
        "nut_pv_limit_pa_m_s": pv_limit,
        "flank_area_m2": area,
        "sliding_speed_m_s": pv.surface_speed(rpm, t.flank_helix_travel_m),
        "bearing_force_n": force,
        "bearing_sliding_speed_m_s": speed,
        "nut_allowed_pressure_pa": allowed,
        "nut_allowed_load_n": allowed * area,
        **dict(zip(("rated_load_n", "nut_length_m"), rating(app, t, area), strict=True)),
    }


def worst_point(
    t: CandidateTable, pv_limit: Array, area_m2: Array, points: Sequence[tuple[float, float]]
) -> tuple[Array, Array, Array]:
    """Of the moves' (thrust [N], linear speed [m/s]), the one each nut carries worst: its
    thrust over the load its flanks carry at that move's sliding speed, the largest (a
    heavy slow move may govern a bronze nut, a light fast one a polymer's PV): the thrust,
    the flanks' sliding speed [m/s] and the pressure allowed there [Pa], per nut."""
    if len(points) == 1:  # out and back over the stroke: one point, as the PV's
        ((force_n, speed_m_s),) = points
        rpm = geometry.screw_speed_rpm(speed_m_s, t.lead_m)
        sliding = np.asarray(pv.surface_speed(rpm, t.flank_helix_travel_m), dtype=np.float64)
        return filled(len(t), force_n), sliding, nut_allowed_pressures(t, pv_limit, sliding)
    # the heaviest first: a nut its flanks rate for no load (no flank area) shows it
    points = sorted(points, key=lambda point: -point[0])
    forces = np.array([force for force, _ in points])[:, None]
    helix = t.flank_helix_travel_m
    speeds = np.array(
        [pv.surface_speed(geometry.screw_speed_rpm(v, t.lead_m), helix) for _, v in points]
    )
    allowed = np.array([nut_allowed_pressures(t, pv_limit, speed) for speed in speeds])
    with np.errstate(divide="ignore", invalid="ignore"):
        share = forces / (allowed * area_m2)
    worst = np.where(np.isnan(share), -np.inf, share).argmax(axis=0)
    at = (worst, np.arange(len(t)))
    return np.broadcast_to(forces, share.shape)[at], speeds[at], allowed[at]


def rating(app: Application, t: CandidateTable, area_m2: Array) -> tuple[Array, Array]:
    """The nut's rated load in motion and its engaged length (``axis_free.nut_rating``):
    the table's at the catalog's nut length, else worked out at the user's (flank area
    ``area_m2``), at most the catalog nut's: a maker rates the nut it sells, and a longer
    nut's turns do not share the thrust evenly, so a nut longer than the catalog's is held
    to its rating (a shorter one carries less, in proportion to its turns)."""
    if app.nut_length_m is None:
        return t.catalog_rated_load_n, t.catalog_engaged_length_m
    rated, length = nut_rating(area_m2, nut_length(app, t), partial(getattr, t))
    return np.fmin(rated, t.catalog_rated_load_n), length


def wear_life(
    app: Application,
    t: CandidateTable,
    flank_area_m2: Array,
    force_n: float,
    cycles: float | None,
) -> dict[str, Any]:
    """Nut travel until its flanks have worn the allowed depth (Archard's law at the
    cycle's wear thrust ``force_n``, ``motion.wear_thrust``): over the engaged flanks and
    flank height of a standard thread, else over the seed's three threads and thread
    depth; in years at ``cycles`` a day (``motion.cycles_per_day``). A nut typed longer
    than the catalog's wears over the catalog nut's flanks at most, as its rating holds
    it to the catalog nut's (``rating``: the turns of a longer nut do not share the
    thrust evenly)."""
    if app.nut_length_m is None:  # the catalog's flanks, whose geometry the table holds
        area, depth, per_travel = t.wear_area_m2, t.wear_depth_m, t.wear_sliding_per_travel
    else:
        flanks = np.fmin(flank_area_m2, t.catalog_flank_area_m2)
        area, depth, per_travel = wear_geometry(flanks, partial(getattr, t))
    # a vanishing thrust: an unbounded life (``operating_point`` silences the overflow),
    # NaN below
    sliding = wear.wear_life_sliding(depth, t.wear_rate_m2_n, pv.contact_pressure(force_n, area))
    travel = finite(wear.wear_life_travel(sliding, per_travel))
    stroke = motion.equivalent_stroke(app)
    rated = bool(stroke and cycles)
    years = life.life_years(travel, stroke, cycles) if rated else travel * np.nan
    return {
        "wear_force_n": filled(len(t), force_n),
        "wear_travel_m": travel,
        "wear_life_years": years,
    }
