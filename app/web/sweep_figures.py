"""The lead-sweep chart as a Plotly dict: one size of the top screw at every lead the
catalog offers, its drive torque and its speed and PV as shares of their limits."""

from typing import Any

from app.contract.figures import sig
from app.contract.schemas import CandidateOut
from app.contract.units import Display, si_to_api
from app.report.charts import LeadPoint
from app.web.chart_style import axis as _axis
from app.web.chart_style import layout as _layout
from app.web.chart_style import rounded as _round


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
    """Torque on the left axis; speed, PV and an ISO nut's flank pressure as shares of
    their limits on the right (each drawn where some lead has it)."""
    unit = d.label("torque")
    series: list[tuple[str, str, list[float | None], str, str]] = [
        (
            "Drive torque",
            "y",
            [_round(d.value(p.torque_nm, "torque")) for p in sweep],
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
        (
            "Flank pressure, % of allowed",
            "y2",
            [_percent(p.pressure_share) for p in sweep],
            "#CC79A7",
            "%{y:.3g} %",
        ),
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
