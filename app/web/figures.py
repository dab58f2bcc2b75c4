"""Plotly figures of a selection result as plain dicts (cheap to build per request).

Each figure is ``{"data": [...], "layout": {...}}`` in the user's display units, ready for
``Plotly.react`` in the browser; ``plotly.graph_objects.Figure(figure)`` accepts it, which
the tests use to validate them.
"""

from typing import Any

from app.core.formulas import critical_speed, pv
from app.schemas import CandidateOut, SelectOut
from app.units import Display, api_value

#: Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
PALETTE = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")
TORQUE_PARTS = (("inertia_nm", "Inertia", "#56B4E9"), ("drag_nm", "Drag", "#E69F00"))
LOAD_PART = ("load_nm", "Load", "#0072B2")
CURVE_POINTS = 41
#: the curves span the user's value divided and multiplied by this factor.
CRITICAL_SPAN = 5.0
PV_SPAN = 10.0
TOP = 5


def _round(value: float) -> float:
    return float(f"{value:.5g}")


def _span(centre: float, factor: float) -> list[float]:
    """CURVE_POINTS values spaced evenly in log from centre / factor to centre * factor."""
    steps = CURVE_POINTS - 1
    return [centre * factor ** (2 * i / steps - 1) for i in range(CURVE_POINTS)]


def _axis(title: str, log: bool = False) -> dict[str, Any]:
    axis: dict[str, Any] = {"title": {"text": title}, "automargin": True, "zeroline": False}
    if log:
        axis.update(type="log", dtick=1, minor={"showgrid": True, "gridcolor": "#f0f0f0"})
    return axis


def _layout(xaxis: dict[str, Any], yaxis: dict[str, Any], **extra: Any) -> dict[str, Any]:
    return {
        "xaxis": xaxis,
        "yaxis": yaxis,
        "margin": {"l": 8, "r": 8, "t": 8, "b": 8},
        "legend": {
            "orientation": "h",
            "x": 0,
            "y": 1.02,
            "yanchor": "bottom",
            "traceorder": "normal",
        },
        "font": {"size": 12},
        "hovermode": "closest",
        "autosize": True,
        "paper_bgcolor": "#ffffff",
        "plot_bgcolor": "#ffffff",
        **extra,
    }


def chart_candidates(result: SelectOut) -> tuple[list[CandidateOut], bool]:
    """Candidates to chart: the passing ones, else the nearest rejected. (list, passing?)"""
    if result.candidates:
        return result.candidates, True
    return result.rejected, False


def critical_speed_figure(
    candidates: list[CandidateOut], length_mm: float, d: Display
) -> dict[str, Any]:
    """Allowed speed vs unsupported length (log-log) with the operating points.

    Each curve moves the candidate's allowed speed at the user's length to other lengths
    with ``app.core.formulas.critical_speed.speed_at_length`` (n proportional to 1 / L^2).
    """
    lengths_mm = _span(length_mm, CRITICAL_SPAN)
    x = [_round(d.value(length, "length")) for length in lengths_mm]
    data: list[dict[str, Any]] = []
    for colour, c in zip(PALETTE, candidates[:TOP], strict=False):
        allowed = c.critical_speed.allowed_rpm
        data.append(
            {
                "type": "scatter",
                "mode": "lines",
                "name": c.id,
                "x": x,
                "y": [
                    _round(critical_speed.speed_at_length(allowed, length_mm, length))
                    for length in lengths_mm
                ],
                "line": {"color": colour, "width": 2},
                "hovertemplate": f"%{{x:.4g}} {d.label('length')}<br>%{{y:.4g}} rpm"
                f"<extra>{c.id} allowed</extra>",
            }
        )
    shown = candidates[:TOP]
    user_x = _round(d.value(length_mm, "length"))
    rpms = [_round(c.rpm) for c in shown]
    data.append(
        {
            "type": "scatter",
            "mode": "markers",
            "name": "Operating point",
            "x": [user_x] * len(shown),
            "y": rpms,
            "text": [c.id for c in shown],
            "marker": {"size": 11, "symbol": "x", "color": list(PALETTE[: len(shown)])},
            "hovertemplate": "%{text}<br>%{y:.4g} rpm at %{x:.4g} "
            f"{d.label('length')}<extra>operating</extra>",
        }
    )
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
            _axis(f"Screw length between supports [{d.label('length')}]", log=True),
            _axis("Screw speed [rpm]", log=True),
        ),
    }


def pv_figure(
    candidates: list[CandidateOut], speed_mm_s: float, load_n: float, d: Display
) -> dict[str, Any]:
    """PV limit of each nut as the largest load vs linear speed (log-log), and the operating point.

    Each curve moves the PV-limited load at the user's speed to other speeds with
    ``app.core.formulas.pv.max_load_at_speed`` (F_max proportional to 1 / v).
    """
    speeds = _span(speed_mm_s, PV_SPAN)
    x = [_round(d.value(v, "speed")) for v in speeds]
    data: list[dict[str, Any]] = []
    limited = [(c, c.pv.max_load_n) for c in candidates[:TOP] if c.pv.max_load_n is not None]
    for colour, (c, max_load) in zip(PALETTE, limited, strict=False):
        data.append(
            {
                "type": "scatter",
                "mode": "lines",
                "name": c.id,
                "x": x,
                "y": [
                    _round(d.value(pv.max_load_at_speed(max_load, speed_mm_s, v), "force"))
                    for v in speeds
                ],
                "line": {"color": colour, "width": 2},
                "hovertemplate": f"%{{x:.4g}} {d.label('speed')}<br>max %{{y:.4g}} "
                f"{d.label('force')}<extra>{c.id} PV limit</extra>",
            }
        )
    data.append(
        {
            "type": "scatter",
            "mode": "markers",
            "name": "Operating point",
            "x": [_round(d.value(speed_mm_s, "speed"))],
            "y": [_round(d.value(load_n, "force"))],
            "marker": {"size": 12, "symbol": "x", "color": "#000000"},
            "hovertemplate": f"%{{x:.4g}} {d.label('speed')}<br>%{{y:.4g}} "
            f"{d.label('force')}<extra>operating</extra>",
        }
    )
    return {
        "data": data,
        "layout": _layout(
            _axis(f"Linear speed [{d.label('speed')}]", log=True),
            _axis(f"Axial load [{d.label('force')}]", log=True),
        ),
    }


def torque_figure(
    candidates: list[CandidateOut], max_torque_nm: float | None, d: Display
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
    if max_torque_nm is not None:
        extra["shapes"] = [
            {
                "type": "line",
                "xref": "paper",
                "x0": 0,
                "x1": 1,
                "yref": "y",
                "y0": _round(d.value(max_torque_nm, "torque")),
                "y1": _round(d.value(max_torque_nm, "torque")),
                "line": {"color": "#A00000", "dash": "dash", "width": 2},
            }
        ]
    return {
        "data": data,
        "layout": _layout(_axis(""), _axis(f"Running torque [{unit}]"), **extra),
    }


def result_figures(result: SelectOut, units: dict[str, str]) -> dict[str, dict[str, Any]]:
    """The three charts of a result, keyed 'critical_speed', 'pv' and 'torque'."""
    candidates, _ = chart_candidates(result)
    if not candidates:
        return {}
    d = Display(units)
    app = result.inputs.to_core()
    length_mm, _ = api_value(app.length_m, "length")
    speed_mm_s, _ = api_value(app.speed_m_s, "speed")
    return {
        "critical_speed": critical_speed_figure(candidates, length_mm, d),
        "pv": pv_figure(candidates, speed_mm_s, candidates[0].axial_load_n, d),
        "torque": torque_figure(candidates, app.max_torque_nm, d),
    }
