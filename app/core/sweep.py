"""Sweeps for the charts: one size and nut with every lead the catalog offers, screened
for an application, to show the trade-off that picks the lead (drive torque against the
speed and PV limits); and the wear life of the top candidates at the axis's thrust, from
which the life at any thrust follows."""

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from app.core.index import CatalogIndex, SizeKey
from app.core.model import Application
from app.core.quantities import operating_point
from app.core.screening import screen_table


@dataclass(frozen=True, slots=True)
class LeadPoint:
    """One lead of a size and nut for an application: the drive torque [N m], the screw
    speed as a share of the allowed speed and the PV as a share of its limit (None: no PV
    limit)."""

    lead_m: float
    total_nm: float
    speed_share: float
    pv_share: float | None


def lead_sweep(app: Application, index: CatalogIndex, size: SizeKey) -> list[LeadPoint]:
    """Every lead of ``size`` (``index.size_of`` a screw) in ``index``, screened for
    ``app`` at any lead, shortest lead first; empty for a size the index lacks.

    The speed share is n / n_allowed (the critical speed with its safety factor); the PV
    share is the PV check's utilisation, PV / PV_limit.
    """
    rows = index.sizes.get(size)
    if rows is None:
        return []
    sc = screen_table(replace(app, lead_m=None), index.table.take(rows), rows)
    q, pv_use = sc.quantities, sc.utilization.get("pv")
    pv_applies = sc.measures["pv"].applicable if "pv" in sc.measures else None
    return [
        LeadPoint(
            lead_m=float(sc.table.lead_m[k]),
            total_nm=float(q.total_nm[k]),
            speed_share=float(q.rpm[k] / q.allowed_rpm[k]),
            pv_share=None
            if pv_use is None or pv_applies is None or not pv_applies[k]
            else float(pv_use[k]),
        )
        for k in range(len(rows))
    ]


@dataclass(frozen=True, slots=True)
class WearPoint:
    """One wear-rated candidate at the cycle's wear thrust [N] (``motion.wear_thrust``):
    its wear life in years of the duty (None without a duty) and in travel [m]."""

    id: str
    force_n: float
    life_years: float | None
    travel_m: float


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
        travel, years, force = q.wear_travel_m[k], q.wear_life_years[k], q.wear_force_n[k]
        if np.isfinite(travel) and force > 0.0:
            life = float(years) if np.isfinite(years) else None
            screw = index.table.screws[position]
            points.append(WearPoint(screw.id, float(force), life, float(travel)))
    return points
