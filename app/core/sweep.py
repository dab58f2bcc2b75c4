"""Sweeps for the charts: one size and nut with every lead the catalog offers, screened
for an application, to show the trade-off that picks the lead (drive torque against the
speed and PV limits); the wear life of the top candidates at the axis's thrust, from
which the life at any thrust follows; and the pressure each top candidate's nut allows
against the sliding speed, beside its operating pressure and speed."""

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from app.core.formulas import bearing
from app.core.index import CatalogIndex, SizeKey
from app.core.model import Application
from app.core.nut import nut_allowed_pressures
from app.core.quantities import Quantities, operating_point
from app.core.screening import Screening, screen_table
from app.core.selection import shown_torque
from app.core.table import Array


@dataclass(frozen=True, slots=True)
class LeadPoint:
    """One lead of a size and nut for an application: the drive torque the results show
    [N m] (``selection.shown_torque``: the peak of the moving segments and of the
    break-away), the screw speed as a share of
    the allowed speed, the PV as a share of its limit (None: no PV limit) and an ISO
    nut's flank pressure as a share of the pressure its material allows at the sliding
    speed (None: no flank data)."""

    lead_m: float
    torque_nm: float
    speed_share: float
    pv_share: float | None
    pressure_share: float | None = None


def lead_sweep(app: Application, index: CatalogIndex, size: SizeKey) -> list[LeadPoint]:
    """Every lead of ``size`` (``index.size_of`` a screw) in ``index``, screened for
    ``app`` at any lead, shortest lead first; empty for a size the index lacks.

    The speed share is n / n_allowed (the critical speed with its safety factor); the PV
    and pressure shares are the utilisations of the PV and nut contact pressure checks
    (``_share``).
    """
    rows = index.sizes.get(size)
    if rows is None:
        return []
    sc = screen_table(replace(app, lead_m=None), index.table.take(rows), rows)
    q, torque_nm = sc.quantities, shown_torque(sc)
    return [
        LeadPoint(
            lead_m=float(sc.table.lead_m[k]),
            torque_nm=float(torque_nm[k]),
            speed_share=float(q.axis.rpm[k] / q.column.allowed_rpm[k]),
            pv_share=_share(sc, "pv", k),
            pressure_share=_share(sc, "bearing_pressure", k),
        )
        for k in range(len(rows))
    ]


def _share(sc: Screening, check: str, k: int) -> float | None:
    """Row ``k``'s utilisation of ``check`` in ``sc``; None where the check does not apply
    to it (or did not run)."""
    use, measure = sc.utilization.get(check), sc.measures.get(check)
    if use is None or measure is None or not measure.applicable[k]:
        return None
    return float(use[k])


@dataclass(frozen=True, slots=True)
class WearPoint:
    """One wear-rated candidate at the cycle's wear thrust [N] (``motion.wear_thrust``):
    its wear life in years of the duty (None without a duty) and in travel [m], and the
    seed's rated travel band [m] where the catalog gives one (None: no rating), which
    caps the life the results show at any thrust (``sections.Life.travel_m``)."""

    id: str
    force_n: float
    life_years: float | None
    travel_m: float
    rated_m: tuple[float, float] | None = None


def wear_points(app: Application, index: CatalogIndex, ids: Sequence[str]) -> list[WearPoint]:
    """The candidates ``ids`` of ``index`` whose nut has a wear life at this thrust, in
    the order given, their numbers from one pass over all of them. Archard's life is
    inversely proportional to the wear thrust, so one point gives the life at any."""
    rows = np.array([index.positions[i] for i in ids if i in index.positions], dtype=np.intp)
    if not rows.size:
        return []
    q = operating_point(app, index.table.take(rows))
    points = []
    for k, position in enumerate(rows.tolist()):
        travel, years, force = (
            q.life.wear_travel_m[k],
            q.life.wear_life_years[k],
            q.life.wear_force_n[k],
        )
        if np.isfinite(travel) and force > 0.0:
            life = float(years) if np.isfinite(years) else None
            screw = index.table.screws[position]
            rated = None
            if screw.life_min_m is not None and screw.life_max_m is not None:
                rated = (screw.life_min_m, screw.life_max_m)
            points.append(WearPoint(screw.id, float(force), life, float(travel), rated))
    return points


@dataclass(frozen=True, slots=True)
class PressureLimit:
    """One candidate's nut: the check that judges its pressure ('bearing_pressure': the
    engaged flanks against the material's table, p_max and PV; 'pv': the seed's three
    threads against its PV limit), its operating sliding speed [m/s] and pressure [Pa],
    and the pressure its material allows [Pa] at each of ``speeds_m_s`` [m/s]."""

    id: str
    check: str
    speed_m_s: float
    pressure_pa: float
    speeds_m_s: tuple[float, ...]
    allowed_pa: tuple[float, ...]


def _operating(q: Quantities[Array], k: int) -> tuple[str, float, float] | None:
    """The check judging candidate ``k``'s nut pressure with its sliding speed [m/s] and
    pressure [Pa] as that check takes them; None without such a limit or speed."""
    flank_speed, pv_speed = float(q.nut.sliding_speed_m_s[k]), float(q.nut.surface_speed_m_s[k])
    area = float(q.nut.flank_area_m2[k])
    if np.isfinite(q.nut.nut_allowed_pressure_pa[k]) and flank_speed > 0.0 and area > 0.0:
        return "bearing_pressure", flank_speed, float(q.axis.peak_force_n[k]) / area
    if np.isfinite(q.nut.pv_limit_pa_m_s[k]) and q.nut.pv_limit_pa_m_s[k] > 0.0 and pv_speed > 0.0:
        return "pv", pv_speed, float(q.nut.pressure_pa[k])
    return None


def chart_speeds(
    operating: Sequence[float], corners: Sequence[float], span: float, points: int
) -> Array:
    """The sliding speeds [m/s] the pressure limits are drawn at: ``points`` spaced evenly
    in log from the lowest ``operating`` speed over ``span`` to the highest times
    ``span``, and, between those ends, each operating speed and each row speed of the
    nuts' pressure-speed tables (``corners``). A chart joins its points with straight
    lines: with the table's corners among them, no line cuts above a corner where the
    table turns flat, and the line at each operating speed is the check's limit there.

    >>> chart_speeds([0.1], [0.05, 0.25, 2.0], 10.0, 3).tolist()
    [0.01, 0.05, 0.1, 0.25, 1.0]
    """
    low, high = min(operating) / span, max(operating) * span
    inside = [v for v in (*operating, *corners) if low < v < high]
    speeds: Array = np.unique(np.concatenate([np.geomspace(low, high, points), inside]))
    return speeds


def pressure_limits(
    app: Application, index: CatalogIndex, ids: Sequence[str], span: float, points: int
) -> list[PressureLimit]:
    """The candidates ``ids`` whose nut has a pressure limit that moves with the sliding
    speed, in the order given, each with the pressure it allows at the same speeds
    (``chart_speeds``: ``points`` spaced evenly in log from the lowest operating sliding
    speed over ``span`` to the highest times ``span``, with the operating speeds and the
    tables' corners; so nuts of one material draw one curve): the limits the checks use
    (``nut_allowed_pressures`` for the flanks, PV_lim / v for the seed's PV), derated as
    the checks derate them."""
    rows = np.array([index.positions[i] for i in ids if i in index.positions], dtype=np.intp)
    if not rows.size:
        return []
    q = operating_point(app, index.table.take(rows))
    found = [(k, op) for k in range(len(rows)) if (op := _operating(q, k)) is not None]
    if not found:
        return []
    operating_speeds = [speed for _, (_, speed, _) in found]
    tables = {int(index.table.pressure_table[rows[k]]) for k, _ in found} - {-1}
    corners = [v for i in tables for v, _ in index.table.pressure_tables[i]]
    speeds = chart_speeds(operating_speeds, corners, span, points)
    points = len(speeds)
    out = []
    for k, (check, speed, pressure) in found:
        position = int(rows[k])
        if check == "bearing_pressure":
            same = index.table.take(np.full(points, position, dtype=np.intp))
            limit = np.full(points, q.nut.nut_pv_limit_pa_m_s[k])
            allowed = nut_allowed_pressures(same, limit, speeds)
        else:
            pv_limit = float(q.nut.pv_limit_pa_m_s[k])
            allowed = np.array([bearing.pv_pressure(pv_limit, float(v)) for v in speeds])
        screw = index.table.screws[position]
        out.append(
            PressureLimit(
                screw.id,
                check,
                speed,
                pressure,
                tuple(float(v) for v in speeds),
                tuple(float(p) for p in allowed),
            )
        )
    return out
