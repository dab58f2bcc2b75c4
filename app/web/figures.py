"""Plotly figures of a selection result as plain dicts (cheap to build per request).

Each figure is ``{"data": [...], "layout": {...}}`` in the user's display units, ready for
``Plotly.react`` in the browser; ``plotly.graph_objects.Figure(figure)`` accepts it, which
the tests use to validate them.
"""

from collections.abc import Iterable, Sequence
from typing import Any

from app.catalog import Catalog
from app.contract.outputs import PageSelectionOut, SelectOut
from app.contract.schemas import CandidateOut
from app.contract.units import Display, api_value
from app.core.formulas import critical_speed
from app.core.wording import times
from app.report.charts import chart_data
from app.web.chart_style import PALETTE
from app.web.chart_style import axis as _axis
from app.web.chart_style import layout as _layout
from app.web.chart_style import rounded as _round
from app.web.curves import by_curve, curve_name, span
from app.web.life_figures import LIFE_TOP, life_figure
from app.web.motion_figures import cycle_torque_figure, motor_figure, move_figure
from app.web.pressure_figures import pressure_figure, pv_figure
from app.web.sweep_figures import lead_sweep_figure

TORQUE_PARTS = (("inertia_nm", "Inertia", "#56B4E9"), ("drag_nm", "Drag", "#E69F00"))
LOAD_PART = ("load_nm", "Load", "#0072B2")
#: the critical-speed curves span the user's length divided and multiplied by this.
CRITICAL_SPAN = 5.0
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


def chart_candidates(
    result: SelectOut | PageSelectionOut,
) -> tuple[Sequence[CandidateOut], bool]:
    """Candidates to chart: the passing ones, else the nearest rejected. (list, passing?)"""
    if result.candidates:
        return result.candidates, True
    return result.rejected, False


def _operating_points(groups: list[list[CandidateOut]], x: float, d: Display) -> dict[str, Any]:
    """One marker per distinct operating speed (screws of one lead share one), coloured as
    its curve, with each screw's margin in the hover text."""
    points: dict[tuple[int, float], list[CandidateOut]] = {}
    for index, group in enumerate(groups):
        for c in group:
            points.setdefault((index, _round(c.rpm)), []).append(c)
    texts = [
        "<br>".join(f"{c.id}: margin {times(c.critical_speed.margin)}" for c in members)
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
    lengths_mm = span(length_mm, CRITICAL_SPAN)
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


def torque_figure(
    candidates: Sequence[CandidateOut], line_nm: float | None, d: Display
) -> dict[str, Any]:
    """Stacked bars of the motor torque while accelerating per candidate: inertia + drag
    + load (``torque.total_nm``, before the torque safety factor), and a diamond at the
    peak torque the torque check judges (``torque.peak_motor_nm``: the peak of the moving
    segments, braking included, or of the start from rest), which the bars may sit
    under.

    A dashed line marks ``line_nm`` when the user gave a drive's maximum torque: that
    maximum over the torque safety factor, the most the peak, before that factor, may
    reach (``drive.torque_before_factor_nm``).
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
    data.append(
        {
            "type": "scatter",
            "mode": "markers",
            "name": "peak, judged",
            "x": ids,
            "y": [_round(d.value(c.torque.peak_motor_nm, "torque")) for c in candidates],
            "marker": {"color": "#000000", "symbol": "diamond", "size": 10},
            "hovertemplate": f"%{{x}}<br>peak %{{y:.4g}} {unit}<extra></extra>",
        }
    )
    extra: dict[str, Any] = {"barmode": "stack"}
    if line_nm is not None:
        limit = _round(d.value(line_nm, "torque"))
        extra["shapes"] = [
            {
                "type": "line",
                "xref": "paper",
                "x0": 0,
                "x1": 1,
                "yref": "y",
                "y0": limit,
                "y1": limit,
                "line": {"color": "#A00000", "dash": "dash", "width": 2},
            }
        ]
    return {
        "data": data,
        "layout": _layout(
            {**_axis("Screw"), "type": "category"},
            _axis(f"Motor torque [{unit}]"),
            **extra,
        ),
    }


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
    result: SelectOut | PageSelectionOut,
    units: dict[str, str],
    catalog: Catalog | None = None,
    focus: CandidateOut | None = None,
) -> dict[str, dict[str, Any]]:
    """The charts of a result, keyed 'critical_speed', 'pv', 'torque' and, given the
    catalog, 'lead_sweep' and 'life' (wear-rated nuts). Given the catalog, 'pv' is the
    top nuts' allowed pressure against sliding speed (none when no nut has such a
    limit); without it, the PV-limited load against linear speed. When nothing passes, the chart of
    the check that excludes the most screws comes first. The charts of one screw (the
    lead sweep, the move and its torque over the cycle) are those of ``focus`` (a
    report's screw), else of the first candidate charted; the charts of several draw
    ``focus`` first, so that the few they draw include it."""
    candidates, passing = chart_candidates(result)
    if not candidates:
        return {}
    top = focus or candidates[0]
    d = Display(units)
    candidates = [top, *(c for c in candidates if c.id != top.id)]
    data = chart_data(result.inputs, catalog, [c.id for c in candidates], LIFE_TOP)
    length_mm, _ = api_value(data.length_m, "length")
    speed_mm_per_s, _ = api_value(data.speed_m_s, "speed")
    figures = {"critical_speed": critical_speed_figure(candidates, length_mm, d)}
    if data.pressure:
        figures["pv"] = pressure_figure(data.pressure, d)
    elif catalog is None:
        figures["pv"] = pv_figure(candidates, speed_mm_per_s, candidates[0].axial_load_n, d)
    figures["torque"] = torque_figure(candidates, data.torque_line_nm, d)
    if len(data.sweep) > 1:
        figures["lead_sweep"] = lead_sweep_figure(data.sweep, top, d)
    life = life_figure(data.wear, data.wear_in_years, d)
    if life is not None:
        figures["life"] = life
    if top.segments:
        if data.curve:
            figures["motor"] = motor_figure(
                candidates,
                data.curve,
                data.torque_safety_factor,
                d,
                data.curve_margin,
                data.curve_origin,
                data.continuous,
            )
        figures["move"] = move_figure(top, d)
        figures["cycle_torque"] = cycle_torque_figure(top, d)
    first = None if passing else result.summary.most_excluding_check
    return {key: figures[key] for key in chart_order(figures, first)}
