"""Nut wear life against thrust as a Plotly figure (plain dict): for the top candidates
whose nut is rated by its wear rate, the life in years of the duty (or the travel, in km
or in miles with inches, without a duty) at wear thrusts (the cycle's,
``motion.wear_thrust``) from a quarter to four times the axis's, with the band of the
wear rate's scatter shaded. Archard's life is inversely proportional to the thrust, so the
core's one number per candidate gives the whole line. Screws whose lines coincide share
one line, named for all of them. A nut the seed rates has its lines capped by its rated
travel, as its life in the results is."""

import math
from collections.abc import Callable, Sequence
from typing import Any

from app.contract.units import Display
from app.report.charts import WearLine
from app.web.chart_style import PALETTE, axis, layout

#: the wear-rated candidates drawn, at most.
LIFE_TOP = 5
#: thrusts from the axis's divided to multiplied by this factor.
SPAN = 4.0
POINTS = 25


def _traces(
    screw_id: str, line: WearLine, scale: Callable[[float], float], d: Display
) -> list[dict[str, Any]]:
    """The band's low edge, its high edge filled down to it, and the life line, each
    ``scale``d to the unit shown; for a nut the seed rates, the low edge at most the low
    end of its rated travel, the high edge and the line at most the high end, as the
    results' life band is capped at any thrust."""
    thrusts = [line.force_n * SPAN ** (2 * i / (POINTS - 1) - 1) for i in range(POINTS)]
    x = [d.value(f, "force") for f in thrusts]
    cap = line.cap or (math.inf, math.inf)

    def trace(share: float, most: float, **style: Any) -> dict[str, Any]:
        y = [scale(min(line.life * share * line.force_n / f, most)) for f in thrusts]
        return {"type": "scatter", "mode": "lines", "x": x, "y": y, **style}

    band = {"line": {"width": 0}, "showlegend": False, "hoverinfo": "skip"}
    shares = line.band
    return [
        trace(shares[0], cap[0], name=f"{screw_id}, wear rate high", **band),
        trace(shares[1], cap[1], name=f"{screw_id}, wear rate low", fill="tonexty", **band),
        trace(1.0, cap[1], name=screw_id, line={"width": 2}),
    ]


def _drawn_cap(line: WearLine) -> tuple[float, float] | None:
    """The rated travel cap of ``line`` where it cuts the lines drawn (at a quarter of the
    thrust they rise to SPAN times the life), else None: a cap above them all draws as
    none."""
    top = line.life * SPAN
    if line.cap is None or (
        line.cap[0] >= top * line.band[0] and line.cap[1] >= top * max(line.band[1], 1.0)
    ):
        return None
    return line.cap


def distinct_lines(wear: Sequence[WearLine]) -> list[tuple[str, WearLine]]:
    """Each distinct line of ``wear`` once, in order, with the ids of every screw it
    stands for joined (the same nut in two series or coatings wears alike: drawn apart,
    one line would hide the other under it)."""
    lines: dict[tuple[object, ...], tuple[WearLine, list[str]]] = {}
    for line in wear:
        key = (line.life, line.force_n, line.band, _drawn_cap(line))
        lines.setdefault(key, (line, []))[1].append(line.id)
    return [(", ".join(ids), line) for line, ids in lines.values()]


def life_figure(wear: Sequence[WearLine], in_years: bool, d: Display) -> dict[str, Any] | None:
    """Life against thrust for the wear lines, each distinct line once
    (``distinct_lines``); None when there is none."""
    data: list[dict[str, Any]] = []

    def scale(life: float) -> float:
        return life if in_years else d.value(life, "travel")

    for name, line in distinct_lines(wear):
        colour = PALETTE[len(data) // 3 % len(PALETTE)]
        traces = _traces(name, line, scale, d)
        traces[1]["fillcolor"] = colour + "33"
        traces[2]["line"]["color"] = colour
        data += traces
    if not data:
        return None
    y_title = "Wear life [years]" if in_years else f"Wear life as travel [{d.label('travel')}]"
    thrusts = [x for trace in data for x in trace["x"]]
    lives = [y for trace in data for y in trace["y"]]
    x_axis = axis(f"Wear thrust over the cycle [{d.label('force')}]", True, thrusts)
    return {"data": data, "layout": layout(x_axis, axis(y_title, True, lives))}
