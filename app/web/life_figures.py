"""Nut wear life against thrust as a Plotly figure (plain dict): for the top candidates
whose nut is rated by its wear rate, the life in years of the duty (or the travel, in km
or in miles with inches, without a duty) at wear thrusts (the cycle's,
``motion.wear_thrust``) from a quarter to four times the axis's, with the band of the
wear rate's scatter shaded. Archard's life is inversely proportional to the thrust, so the
core's one number per candidate gives the whole line. Screws whose lines coincide share
one line, named for all of them."""

from collections.abc import Sequence
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
    screw_id: str, life: float, force_n: float, shares: tuple[float, float], d: Display
) -> list[dict[str, Any]]:
    """The band's low edge, its high edge filled down to it, and the life line."""
    thrusts = [force_n * SPAN ** (2 * i / (POINTS - 1) - 1) for i in range(POINTS)]
    x = [d.value(f, "force") for f in thrusts]

    def line(share: float, **style: Any) -> dict[str, Any]:
        y = [life * share * force_n / f for f in thrusts]
        return {"type": "scatter", "mode": "lines", "x": x, "y": y, **style}

    band = {"line": {"width": 0}, "showlegend": False, "hoverinfo": "skip"}
    return [
        line(shares[0], name=f"{screw_id}, wear rate high", **band),
        line(shares[1], name=f"{screw_id}, wear rate low", fill="tonexty", **band),
        line(1.0, name=screw_id, line={"width": 2}),
    ]


def distinct_lines(wear: Sequence[WearLine]) -> list[tuple[str, WearLine]]:
    """Each distinct line of ``wear`` once, in order, with the ids of every screw it
    stands for joined (the same nut in two series or coatings wears alike: drawn apart,
    one line would hide the other under it)."""
    lines: dict[tuple[float, float, tuple[float, float]], tuple[WearLine, list[str]]] = {}
    for line in wear:
        lines.setdefault((line.life, line.force_n, line.band), (line, []))[1].append(line.id)
    return [(", ".join(ids), line) for line, ids in lines.values()]


def life_figure(wear: Sequence[WearLine], in_years: bool, d: Display) -> dict[str, Any] | None:
    """Life against thrust for the wear lines, each distinct line once
    (``distinct_lines``); None when there is none."""
    data: list[dict[str, Any]] = []
    for name, line in distinct_lines(wear):
        colour = PALETTE[len(data) // 3 % len(PALETTE)]
        life = line.life if in_years else d.value(line.life, "travel")
        traces = _traces(name, life, line.force_n, line.band, d)
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
