"""Plotly figures of a selection result as plain dicts (cheap to build per request).

Each figure is ``{"data": [...], "layout": {...}}`` in the user's display units, ready for
``Plotly.react`` in the browser; ``plotly.graph_objects.Figure(figure)`` accepts it, which
the tests use to validate them.
"""

import math
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from app.catalog import Catalog
from app.contract.outputs import PageSelectionOut, SelectOut
from app.contract.schemas import CandidateOut
from app.contract.units import Display, api_value, si_to_api, sig
from app.core.formulas import critical_speed, pv
from app.report.charts import LeadPoint, PressureLimit, chart_data
from app.web.chart_style import PALETTE
from app.web.chart_style import axis as _axis
from app.web.chart_style import layout as _layout
from app.web.chart_style import rounded as _round
from app.web.life_figures import LIFE_TOP, life_figure
from app.web.motion_figures import cycle_torque_figure, motor_figure, move_figure

TORQUE_PARTS = (("inertia_nm", "Inertia", "#56B4E9"), ("drag_nm", "Drag", "#E69F00"))
LOAD_PART = ("load_nm", "Load", "#0072B2")
CURVE_POINTS = 41
#: the curves span the user's value divided and multiplied by this factor.
CRITICAL_SPAN = 5.0
PV_SPAN = 10.0
TOP = 5
#: chart key -> the check whose failures it explains.
CHART_CHECKS = {"critical_speed": "critical_speed", "pv": "pv", "torque": "torque"}
CHART_KEYS = (
    "critical_speed",
    "pv",
    "torque",
    "lead_sweep",
    "motor",
    "move",
    "cycle_torque",
    "life",
)


def _span(centre: float, factor: float) -> list[float]:
    """CURVE_POINTS values spaced evenly in log from centre / factor to centre * factor."""
    steps = CURVE_POINTS - 1
    return [centre * factor ** (2 * i / steps - 1) for i in range(CURVE_POINTS)]


def chart_candidates(
    result: SelectOut | PageSelectionOut,
) -> tuple[Sequence[CandidateOut], bool]:
    """Candidates to chart: the passing ones, else the nearest rejected. (list, passing?)"""
    if result.candidates:
        return result.candidates, True
    return result.rejected, False


def by_curve(
    candidates: Sequence[CandidateOut], key: Callable[[CandidateOut], float | None]
) -> list[list[CandidateOut]]:
    """The first TOP distinct curves among ``candidates``, each with the screws it holds:
    screws of one size and nut share a curve, and draw it once under all their ids."""
    groups: dict[float, list[CandidateOut]] = {}
    for c in candidates:
        value = key(c)
        if value is None:
            continue
        rounded = _round(value)
        if rounded in groups or len(groups) < TOP:
            groups.setdefault(rounded, []).append(c)
    return list(groups.values())


def curve_name(group: Sequence[CandidateOut]) -> str:
    """Legend text of a shared curve: the series, then each screw's id after it.

    The ids are kept whole when they do not start with the series.
    """
    series = group[0].series
    rest = [c.id.removeprefix(series).lstrip("-") or c.id for c in group]
    return (
        f"{series}: {', '.join(rest)}"
        if all(c.id.startswith(series) for c in group)
        else (", ".join(c.id for c in group))
    )


def _operating_points(groups: list[list[CandidateOut]], x: float, d: Display) -> dict[str, Any]:
    """One marker per distinct operating speed (screws of one lead share one), coloured as
    its curve, with each screw's margin in the hover text."""
    points: dict[tuple[int, float], list[CandidateOut]] = {}
    for index, group in enumerate(groups):
        for c in group:
            points.setdefault((index, _round(c.rpm)), []).append(c)
    texts = [
        "<br>".join(f"{c.id}: margin {c.critical_speed.margin:.2f}×" for c in members)
        for members in points.values()
    ]
    return {
        "type": "scatter",
        "mode": "markers",
        "name": "Operating point",
        "x": [x] * len(points),
        "y": [rpm for _, rpm in points],
        "text": texts,
        "marker": {"size": 11, "symbol": "x", "color": [PALETTE[i] for i, _ in points]},
        "hovertemplate": "%{text}<br>%{y:.4g} rpm at %{x:.4g} "
        f"{d.label('length')}<extra>operating</extra>",
    }


def critical_speed_figure(
    candidates: Sequence[CandidateOut], length_mm: float, d: Display
) -> dict[str, Any]:
    """Allowed speed vs unsupported length (log-log), one line per distinct size, with the
    operating points and their margins.

    Each curve moves the allowed speed at the user's length to other lengths with
    ``app.core.formulas.critical_speed.speed_at_length`` (n proportional to 1 / L^2).
    """
    lengths_mm = _span(length_mm, CRITICAL_SPAN)
    x = [_round(d.value(length, "length")) for length in lengths_mm]
    groups = by_curve(candidates, lambda c: c.critical_speed.allowed_rpm)
    data: list[dict[str, Any]] = []
    for colour, group in zip(PALETTE, groups, strict=False):
        allowed = group[0].critical_speed.allowed_rpm
        data.append(
            {
                "type": "scatter",
                "mode": "lines",
                "name": curve_name(group),
                "x": x,
                "y": [
                    _round(critical_speed.speed_at_length(allowed, length_mm, length))
                    for length in lengths_mm
                ],
                "line": {"color": colour, "width": 2},
                "hovertemplate": f"%{{x:.4g}} {d.label('length')}<br>%{{y:.4g}} rpm"
                f"<extra>{group[0].series} allowed</extra>",
            }
        )
    user_x = _round(d.value(length_mm, "length"))
    data.append(_operating_points(groups, user_x, d))
    curve_values = [y for trace in data for y in trace["y"]]
    data.append(
        {
            "type": "scatter",
            "mode": "lines",
            "name": "Your length",
            "x": [user_x, user_x],
            "y": [min(curve_values), max(curve_values)],
            "line": {"color": "#444444", "dash": "dash", "width": 1},
            "hoverinfo": "skip",
        }
    )
    return {
        "data": data,
        "layout": _layout(
            _axis(f"Screw length between supports [{d.label('length')}]", True, x),
            _axis("Screw speed [rpm]", True, curve_values),
        ),
    }


def pv_figure(
    candidates: Sequence[CandidateOut], speed_mm_per_s: float, load_n: float, d: Display
) -> dict[str, Any]:
    """PV limit of each nut as the largest load vs linear speed (log-log), one line per
    distinct limit, and the operating point.

    Each curve moves the PV-limited load at the user's speed to other speeds with
    ``app.core.formulas.pv.max_load_at_speed`` (F_max proportional to 1 / v).
    """
    speeds = _span(speed_mm_per_s, PV_SPAN)
    x = [_round(d.value(v, "speed")) for v in speeds]
    data: list[dict[str, Any]] = []
    for colour, group in zip(
        PALETTE, by_curve(candidates, lambda c: c.pv.max_load_n), strict=False
    ):
        max_load = group[0].pv.max_load_n or 0.0
        used = ", ".join(
            f"{c.id} {c.pv.value_mpa_m_s / (c.pv.limit_mpa_m_s or 1):.0%}" for c in group
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


def torque_figure(
    candidates: Sequence[CandidateOut], limit_nm: float | None, d: Display
) -> dict[str, Any]:
    """Stacked bars of the running torque per candidate: inertia + drag + load.

    A dashed line marks the drive's maximum torque when the user gave one.
    """
    ids = [c.id for c in candidates]
    unit = d.label("torque")
    data = [
        {
            "type": "bar",
            "name": name,
            "x": ids,
            "y": [_round(d.value(getattr(c.torque, key), "torque")) for c in candidates],
            "marker": {"color": colour},
            "hovertemplate": f"%{{x}}<br>{name} %{{y:.4g}} {unit}<extra></extra>",
        }
        for key, name, colour in (*TORQUE_PARTS, LOAD_PART)
    ]
    extra: dict[str, Any] = {"barmode": "stack"}
    if limit_nm is not None:
        extra["shapes"] = [
            {
                "type": "line",
                "xref": "paper",
                "x0": 0,
                "x1": 1,
                "yref": "y",
                "y0": _round(d.value(limit_nm, "torque")),
                "y1": _round(d.value(limit_nm, "torque")),
                "line": {"color": "#A00000", "dash": "dash", "width": 2},
            }
        ]
    return {
        "data": data,
        "layout": _layout(
            {**_axis("Screw"), "type": "category"}, _axis(f"Running torque [{unit}]"), **extra
        ),
    }


def _sweep_shapes(leads: list[float], locking: float, chosen: float) -> list[dict[str, Any]]:
    """The self-locking band (leads up to the longest that self-locks) and the chosen lead."""
    shapes: list[dict[str, Any]] = [
        {
            "type": "line",
            "xref": "x",
            "x0": chosen,
            "x1": chosen,
            "yref": "paper",
            "y0": 0,
            "y1": 1,
            "line": {"color": "#000000", "dash": "dash", "width": 1},
        },
    ]
    if locking >= leads[0]:
        shapes.insert(
            0,
            {
                "type": "rect",
                "xref": "x",
                "x0": leads[0],
                "x1": min(locking, leads[-1]),
                "yref": "paper",
                "y0": 0,
                "y1": 1,
                "fillcolor": "#009E73",
                "opacity": 0.12,
                "line": {"width": 0},
                "layer": "below",
            },
        )
    return shapes


def _percent(share: float | None) -> float | None:
    return None if share is None else _round(share * 100)


def _sweep_traces(sweep: list[LeadPoint], leads: list[float], d: Display) -> list[dict[str, Any]]:
    """Torque on the left axis; speed and PV as shares of their limits on the right."""
    unit = d.label("torque")
    series: list[tuple[str, str, list[float | None], str, str]] = [
        (
            "Drive torque",
            "y",
            [_round(d.value(p.total_nm, "torque")) for p in sweep],
            "#0072B2",
            f"%{{y:.4g}} {unit}",
        ),
        (
            "Speed, % of allowed",
            "y2",
            [_round(p.speed_share * 100) for p in sweep],
            "#D55E00",
            "%{y:.3g} %",
        ),
        ("PV, % of limit", "y2", [_percent(p.pv_share) for p in sweep], "#009E73", "%{y:.3g} %"),
    ]
    return [
        {
            "type": "scatter",
            "mode": "lines+markers",
            "name": name,
            "x": leads,
            "y": y,
            "yaxis": axis,
            "line": {"color": colour, "width": 2},
            "hovertemplate": f"lead %{{x:.4g}} {d.label('length')}<br>{hover}<extra>{name}</extra>",
        }
        for name, axis, y, colour, hover in series
        if any(v is not None for v in y)
    ]


def _sweep_annotations(leads: list[float], locking: float, chosen: float) -> list[dict[str, Any]]:
    """Labels of the chosen lead and of the self-locking band."""
    notes: list[dict[str, Any]] = [
        {
            "x": chosen,
            "xref": "x",
            "y": 1,
            "yref": "paper",
            "yanchor": "bottom",
            "text": f"chosen {sig(chosen)}",
            "showarrow": False,
            "font": {"size": 11},
        },
    ]
    if locking >= leads[0]:
        notes.append(
            {
                "x": leads[0],
                "xref": "x",
                "y": 1,
                "yref": "paper",
                "yanchor": "top",
                "xanchor": "left",
                "text": "self-locking",
                "showarrow": False,
                "font": {"size": 11, "color": "#0a5c2a"},
            }
        )
    return notes


def lead_sweep_figure(sweep: list[LeadPoint], top: CandidateOut, d: Display) -> dict[str, Any]:
    """Torque, speed against the critical speed and PV use across the leads of one size:
    the trade-off that picks the lead. Torque on the left axis, the two shares of their
    limits (per cent) on the right; the self-locking band (with the friction margin)
    shaded, the chosen lead dashed."""
    leads = [_round(d.value(si_to_api(p.lead_m, "length"), "length")) for p in sweep]
    data = _sweep_traces(sweep, leads, d)
    locking = _round(d.value(top.max_self_locking_lead_with_margin_mm, "length"))
    chosen = _round(d.value(top.lead_mm, "length"))
    layout = _layout(
        _axis(f"Lead of {top.series} [{d.label('length')}]"),
        _axis(f"Drive torque [{d.label('torque')}]"),
    )
    shares = [float(v) for trace in data if trace["yaxis"] == "y2" for v in trace["y"] if v]
    data.append(
        {
            "type": "scatter",
            "mode": "lines",
            "name": "Limit, 100 %",
            "x": [leads[0], leads[-1]],
            "y": [100, 100],
            "yaxis": "y2",
            "line": {"color": "#A00000", "dash": "dot", "width": 1},
            "hoverinfo": "skip",
        }
    )
    layout["yaxis2"] = {
        **_axis("Share of limit [%]", True, [*shares, 100.0]),
        "overlaying": "y",
        "side": "right",
    }
    layout["shapes"] = _sweep_shapes(leads, locking, chosen)
    layout["annotations"] = _sweep_annotations(leads, locking, chosen)
    return {"data": data, "layout": layout}


def chart_order(keys: Iterable[str], first_check: str | None) -> list[str]:
    """Chart keys in page order; the chart of ``first_check`` first when it has one.

    >>> chart_order(["critical_speed", "pv", "torque"], "pv")
    ['pv', 'critical_speed', 'torque']
    """
    ordered = [k for k in CHART_KEYS if k in keys]
    lead = next((k for k, check in CHART_CHECKS.items() if check == first_check), None)
    if lead in ordered:
        ordered.remove(lead)
        ordered.insert(0, lead)
    return ordered


def result_figures(
    result: SelectOut | PageSelectionOut, units: dict[str, str], catalog: Catalog | None = None
) -> dict[str, dict[str, Any]]:
    """The charts of a result, keyed 'critical_speed', 'pv', 'torque' and, given the
    catalog, 'lead_sweep' and 'life' (wear-rated nuts). Given the catalog, 'pv' is the
    top nuts' allowed pressure against sliding speed (none when no nut has such a
    limit); without it, the PV-limited load against linear speed. When nothing passes, the chart of
    the check that excludes the most screws comes first."""
    candidates, passing = chart_candidates(result)
    if not candidates:
        return {}
    d = Display(units)
    data = chart_data(result.inputs, catalog, [c.id for c in candidates], LIFE_TOP)
    length_mm, _ = api_value(data.length_m, "length")
    speed_mm_per_s, _ = api_value(data.speed_m_s, "speed")
    figures = {"critical_speed": critical_speed_figure(candidates, length_mm, d)}
    if data.pressure:
        figures["pv"] = pressure_figure(data.pressure, d)
    elif catalog is None:
        figures["pv"] = pv_figure(candidates, speed_mm_per_s, candidates[0].axial_load_n, d)
    figures["torque"] = torque_figure(candidates, data.torque_limit_nm, d)
    if len(data.sweep) > 1:
        figures["lead_sweep"] = lead_sweep_figure(data.sweep, candidates[0], d)
    life = life_figure(data.wear, data.wear_in_years, d)
    if life is not None:
        figures["life"] = life
    if candidates[0].segments:
        if data.curve:
            figures["motor"] = motor_figure(
                candidates, data.curve, data.torque_safety_factor, d, data.curve_margin
            )
        figures["move"] = move_figure(candidates[0], d)
        figures["cycle_torque"] = cycle_torque_figure(candidates[0], d)
    first = None if passing else result.summary.most_excluding_check
    return {key: figures[key] for key in chart_order(figures, first)}
