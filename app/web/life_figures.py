"""Nut wear life against thrust as a Plotly figure (plain dict): for the top candidates
whose nut is rated by its wear rate, the life in years of the duty (or the travel in km,
without a duty) at thrusts from a quarter to four times the axis's, with the band of the
wear rate's scatter shaded. Archard's life is inversely proportional to the thrust, so the
core's one number per candidate gives the whole line."""

from collections.abc import Sequence
from typing import Any

import numpy as np

from app.catalog import Catalog
from app.contract.schemas import CandidateBaseOut
from app.contract.units import Display, from_si
from app.core.checks.wear_life import life_band
from app.core.model import Application
from app.core.quantities import operating_point
from app.web.chart_style import PALETTE, axis, layout

TOP = 5
#: thrusts from the axis's divided to multiplied by this factor.
SPAN = 4.0
POINTS = 25


def _life(app: Application, c: CandidateBaseOut, catalog: Catalog) -> tuple[float, float] | None:
    """(life at the axis's thrust, the thrust [N]) of a wear-rated candidate, else None."""
    position = catalog.index.positions.get(c.id)
    if position is None:
        return None
    q = operating_point(app, catalog.index.row(position)).row(0)
    years = q.wear_life_years
    life = years if np.isfinite(years) else from_si(q.wear_travel_m, "km")
    return (life, q.force_n) if np.isfinite(life) and q.force_n > 0.0 else None


def _traces(
    c: CandidateBaseOut, life: float, force_n: float, shares: tuple[float, float], d: Display
) -> list[dict[str, Any]]:
    """The band's low edge, its high edge filled down to it, and the life line."""
    thrusts = [force_n * SPAN ** (2 * i / (POINTS - 1) - 1) for i in range(POINTS)]
    x = [d.value(f, "force") for f in thrusts]

    def line(share: float, **style: Any) -> dict[str, Any]:
        y = [life * share * force_n / f for f in thrusts]
        return {"type": "scatter", "mode": "lines", "x": x, "y": y, **style}

    band = {"line": {"width": 0}, "showlegend": False, "hoverinfo": "skip"}
    return [
        line(shares[0], name=f"{c.id}, wear rate high", **band),
        line(shares[1], name=f"{c.id}, wear rate low", fill="tonexty", **band),
        line(1.0, name=c.id, line={"width": 2}),
    ]


def life_figure(
    candidates: Sequence[CandidateBaseOut], app: Application, catalog: Catalog, d: Display
) -> dict[str, Any] | None:
    """Life against thrust for the top wear-rated candidates; None when none is rated."""
    data: list[dict[str, Any]] = []
    for c in candidates:
        found = _life(app, c, catalog)
        if found is None:
            continue
        colour = PALETTE[len(data) // 3 % len(PALETTE)]
        traces = _traces(c, *found, life_band(catalog.by_id[c.id]), d)
        traces[1]["fillcolor"] = colour + "33"
        traces[2]["line"]["color"] = colour
        data += traces
        if len(data) == 3 * TOP:
            break
    if not data:
        return None
    rated = bool(app.stroke_m and app.cycles_per_day)
    y_title = "Wear life [years]" if rated else "Wear life [km of travel]"
    x_axis = axis(f"Axial thrust [{d.label('force')}]", True)
    return {"data": data, "layout": layout(x_axis, axis(y_title, True))}
