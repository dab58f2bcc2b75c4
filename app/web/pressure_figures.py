"""The nut-pressure charts as Plotly dicts: each nut's allowed pressure against sliding
speed with its operating point (``pressure_figure``), or, without the catalog's curves,
the PV-limited load against linear speed (``pv_figure``)."""

import math
from collections.abc import Sequence
from typing import Any

from app.contract.schemas import CandidateOut
from app.contract.units import Display, si_to_api
from app.core.formulas import pv
from app.report.charts import PressureLimit
from app.web.chart_style import PALETTE
from app.web.chart_style import axis as _axis
from app.web.chart_style import layout as _layout
from app.web.chart_style import rounded as _round
from app.web.curves import TOP, by_curve, curve_name, span

#: the PV curves span the user's speed divided and multiplied by this factor.
PV_SPAN = 10.0


def judged_point(c: CandidateOut) -> tuple[float, float] | None:
    """The linear speed [mm/s] and thrust [N] the PV check judges ``c``'s nut at (the
    peak thrust at the top speed; in a cycle of moves, the move whose product of the two
    is largest: ``quantities.pv_point``). None without a PV limit."""
    pv = c.pv
    if pv is None or not pv.limit_mpa_m_s:
        return None
    return pv.judged_speed_mm_s, pv.judged_thrust_n


def pv_figure(
    candidates: Sequence[CandidateOut], speed_mm_per_s: float, load_n: float, d: Display
) -> dict[str, Any]:
    """PV limit of each nut as the largest load vs linear speed (log-log), one line per
    distinct limit, and the operating point: the speed and thrust the PV check judges
    (``judged_point``; the axis's are the same for every screw), else, without a PV
    limit, ``speed_mm_per_s`` and ``load_n``.

    Each curve moves the PV-limited load at that speed to other speeds with
    ``app.core.formulas.pv.max_load_at_speed`` (F_max proportional to 1 / v).
    """
    pvs = {c.id: c.pv for c in candidates if judged_point(c) is not None and c.pv is not None}
    limited = by_curve([c for c in candidates if c.id in pvs], lambda c: pvs[c.id].max_load_n)
    if limited:
        speed_mm_per_s, load_n = judged_point(limited[0][0]) or (speed_mm_per_s, load_n)
    speeds = span(speed_mm_per_s, PV_SPAN)
    x = [_round(d.value(v, "speed")) for v in speeds]
    data: list[dict[str, Any]] = []
    for colour, group in zip(PALETTE, limited, strict=False):
        max_load = pvs[group[0].id].max_load_n or 0.0
        used = ", ".join(
            f"{c.id} {pvs[c.id].value_mpa_m_s / (pvs[c.id].limit_mpa_m_s or 1):.0%}" for c in group
        )
        data.append(
            {
                "type": "scatter",
                "mode": "lines",
                "name": curve_name(group),
                "x": x,
                "y": [
                    _round(d.value(pv.max_load_at_speed(max_load, speed_mm_per_s, v), "force"))
                    for v in speeds
                ],
                "line": {"color": colour, "width": 2},
                "hovertemplate": f"%{{x:.4g}} {d.label('speed')}<br>max %{{y:.4g}} "
                f"{d.label('force')}<extra>PV used: {used}</extra>",
            }
        )
    point_y = _round(d.value(load_n, "force"))
    data.append(
        {
            "type": "scatter",
            "mode": "markers",
            "name": "Operating point",
            "x": [_round(d.value(speed_mm_per_s, "speed"))],
            "y": [point_y],
            "marker": {"size": 12, "symbol": "x", "color": "#000000"},
            "hovertemplate": f"%{{x:.4g}} {d.label('speed')}<br>%{{y:.4g}} "
            f"{d.label('force')}<extra>operating</extra>",
        }
    )
    loads = [y for trace in data for y in trace["y"]]
    return {
        "data": data,
        "layout": _layout(
            _axis(f"Linear speed [{d.label('speed')}]", True, x),
            _axis(f"Axial load [{d.label('force')}]", True, loads),
        ),
    }


#: how each check's limit curve is named in the legend.
PRESSURE_LIMITS = {"bearing_pressure": "allowed pressure", "pv": "PV limit"}


def _pressure_groups(limits: Sequence[PressureLimit]) -> list[list[PressureLimit]]:
    """The first TOP distinct limit curves, each with the nuts it holds: nuts of one
    material (and derating) allow the same pressure at each speed, and draw one curve."""
    groups: dict[tuple[object, ...], list[PressureLimit]] = {}
    for line in limits:
        key = (line.check, *(_round(p) for p in line.allowed_pa))
        if key in groups or len(groups) < TOP:
            groups.setdefault(key, []).append(line)
    return list(groups.values())


def _pressure_traces(group: list[PressureLimit], colour: str, d: Display) -> list[dict[str, Any]]:
    """One curve of allowed pressure against sliding speed and, in its colour, a cross
    at each of its nuts' operating pressure and speed (one per spot, naming its nuts),
    under the curve's one legend entry."""
    line = group[0]
    pairs = [
        (
            _round(d.value(si_to_api(v, "speed"), "speed")),
            _round(d.value(si_to_api(p, "pressure"), "pressure")),
        )
        for v, p in zip(line.speeds_m_s, line.allowed_pa, strict=True)
        if math.isfinite(p) and p > 0
    ]
    spots: dict[tuple[float, float], list[str]] = {}
    for member in group:
        spot = (
            _round(d.value(si_to_api(member.speed_m_s, "speed"), "speed")),
            _round(d.value(si_to_api(member.pressure_pa, "pressure"), "pressure")),
        )
        spots.setdefault(spot, []).append(member.id)
    speed, pressure = d.label("speed"), d.label("pressure")
    name = ", ".join(member.id for member in group)
    return [
        {
            "type": "scatter",
            "mode": "lines",
            "name": f"{name}: {PRESSURE_LIMITS[line.check]}",
            "x": [x for x, _ in pairs],
            "y": [y for _, y in pairs],
            "line": {"color": colour, "width": 2},
            "legendgroup": name,
            "hovertemplate": f"%{{x:.4g}} {speed}<br>allowed %{{y:.4g}} {pressure}"
            f"<extra>{PRESSURE_LIMITS[line.check]}</extra>",
        },
        {
            "type": "scatter",
            "mode": "markers",
            "name": f"{name}: operating",
            "legendgroup": name,
            "showlegend": False,
            "x": [x for x, _ in spots],
            "y": [y for _, y in spots],
            "text": [", ".join(ids) for ids in spots.values()],
            "marker": {"size": 12, "symbol": "x", "color": colour},
            "hovertemplate": f"%{{text}}<br>%{{x:.4g}} {speed}, %{{y:.4g}} {pressure}"
            "<extra>operating</extra>",
        },
    ]


def pressure_figure(limits: Sequence[PressureLimit], d: Display) -> dict[str, Any]:
    """The pressure each top nut's material allows against the sliding speed (log-log),
    with each nut's operating pressure and speed as a cross in its colour: the gap
    between a cross and its line is the margin. The curves are the core's
    (``app.core.sweep.pressure_limits``): the PV limit's p = PV / v, capped by the
    material's maximum pressure and pressure-speed table where it has them."""
    data: list[dict[str, Any]] = []
    for colour, group in zip(PALETTE, _pressure_groups(limits), strict=False):
        data += _pressure_traces(group, colour, d)
    speeds = [x for trace in data for x in trace["x"]]
    pressures = [y for trace in data for y in trace["y"]]
    return {
        "data": data,
        "layout": _layout(
            _axis(f"Sliding speed at the thread [{d.label('speed')}]", True, speeds),
            _axis(f"Contact pressure [{d.label('pressure')}]", True, pressures),
        ),
    }
