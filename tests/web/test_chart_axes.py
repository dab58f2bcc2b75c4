"""Charts that read: every log axis labelled within its data and not crowded, the wear
life labelled on both axes and in the unit chosen, the PV chart drawing each nut's
allowed pressure (the core's, app.core.sweep.pressure_limits) beside its operating point."""

import json
from typing import Any

import plotly.graph_objects as go
import pytest

from app.catalog import Catalog
from app.contract.schemas import ApplicationIn
from app.report.charts import PRESSURE_POINTS, PRESSURE_SPAN
from app.report.service import run_selection
from app.web.figures import result_figures
from tests.leadscrews import leadscrew_families

METRIC = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}
IMPERIAL = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
PSI = 6894.757293168  # Pa per psi (NIST SP 811)
MILE_KM = 1.609344  # km per international mile (exact)
#: a duty (wear life in years) and a motor (the motor and move charts).
DUTY = {
    "load_n": 100, "speed_mm_s": 50, "length_mm": 500, "stroke_mm": 200,
    "cycles_per_day": 1000, "motor_curve": [[0, 0.5], [1000, 0.3]],
}  # fmt: skip
#: no duty: the wear life as travel.
NO_DUTY = {"load_n": 200, "speed_mm_s": 20, "length_mm": 500, "nut_material": "acetal"}


def figures(catalog: Catalog, inputs: dict[str, Any], units: dict[str, str]) -> dict[str, Any]:
    """The result's figures over the leadscrews (a ball nut has no PV chart)."""
    inputs = {"family": list(leadscrew_families(catalog)), **inputs}
    result = run_selection(ApplicationIn.model_validate(inputs), catalog)
    return result_figures(result, units, catalog)


def axes(figure: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {k: v for k, v in figure["layout"].items() if k.startswith(("xaxis", "yaxis"))}


def axis_values(figure: dict[str, Any], name: str) -> list[float]:
    """The values a figure plots on axis ``name`` ('xaxis', 'yaxis' or 'yaxis2')."""
    letter, number = name[0], name[5:]
    values = []
    for trace in figure["data"]:
        if trace.get(f"{letter}axis", letter) == letter + number:
            values += [v for v in trace[letter] if isinstance(v, float | int)]
    return values


@pytest.mark.parametrize("units", [METRIC, IMPERIAL], ids=["metric", "imperial"])
def test_every_log_axis_is_labelled_within_its_data_and_not_crowded(
    catalog: Catalog, units: dict[str, str]
) -> None:
    """Each log axis of every chart has at least two labels inside the values it plots
    (a reader can read a value off it) and at most nine (they fit a printed chart);
    every axis is named, with its unit where it has one."""
    drawn = figures(catalog, DUTY, units)
    assert {"critical_speed", "pv", "life"} <= set(drawn)
    for key, figure in drawn.items():
        go.Figure(figure)
        json.dumps(figure, allow_nan=False)
        for name, axis in axes(figure).items():
            if axis.get("type") == "category":  # the candidates' ids
                assert axis["title"]["text"], (key, name)
            else:
                assert axis["title"]["text"].endswith("]"), (key, name)  # a unit
            if axis.get("type") != "log":
                continue
            values = [v for v in axis_values(figure, name) if v > 0]
            inside = [t for t in axis["tickvals"] if min(values) <= t <= max(values)]
            assert len(inside) >= 2, (key, name, axis["tickvals"])
            assert len(axis["ticktext"]) == len(axis["tickvals"]) <= 9, (key, name)


def test_the_wear_life_is_labelled_on_both_axes(catalog: Catalog) -> None:
    life = figures(catalog, DUTY, METRIC)["life"]
    for name in ("xaxis", "yaxis"):
        axis = life["layout"][name]
        assert axis["type"] == "log" and len(axis["ticktext"]) >= 2, name
    assert life["layout"]["yaxis"]["title"]["text"] == "Wear life [years]"


def test_the_wear_life_as_travel_follows_the_length_unit(catalog: Catalog) -> None:
    """Without a duty the life is travel: km with millimetres, miles with inches (1 mi =
    1.609344 km), the thrust in lbf with inches."""
    metric = figures(catalog, NO_DUTY, METRIC)["life"]
    imperial = figures(catalog, NO_DUTY, IMPERIAL)["life"]
    assert metric["layout"]["yaxis"]["title"]["text"] == "Wear life as travel [km]"
    assert imperial["layout"]["yaxis"]["title"]["text"] == "Wear life as travel [mi]"
    assert imperial["layout"]["xaxis"]["title"]["text"].endswith("[lbf]")
    km, mi = metric["data"][2]["y"], imperial["data"][2]["y"]
    assert mi == pytest.approx([v / MILE_KM for v in km], rel=1e-9)


def test_the_pv_chart_draws_each_nuts_limit_with_its_operating_point(catalog: Catalog) -> None:
    """Each limit curve has its operating crosses in its colour, under one legend entry,
    and spans the speeds the core evaluated it at, each cross's speed among them; a
    cross below its curve passes."""
    pv = figures(catalog, DUTY, METRIC)["pv"]
    limits = [t for t in pv["data"] if t["mode"] == "lines"]
    crosses = [t for t in pv["data"] if t["mode"] == "markers"]
    assert limits and len(limits) == len(crosses)
    for limit, cross in zip(limits, crosses, strict=True):
        assert limit["name"].endswith(("allowed pressure", "PV limit"))
        assert limit["legendgroup"] == cross["legendgroup"] and cross["showlegend"] is False
        assert cross["marker"]["color"] == limit["line"]["color"]
        assert len(limit["x"]) >= PRESSURE_POINTS
        assert limit["x"][-1] / limit["x"][0] >= PRESSURE_SPAN**2 * 0.999
        for x in cross["x"]:
            assert limit["x"][0] < x < limit["x"][-1]
            assert x in limit["x"]  # a point of the line: the check's limit at its speed
    assert pv["layout"]["xaxis"]["title"]["text"] == "Sliding speed at the thread [mm/s]"
    assert pv["layout"]["yaxis"]["title"]["text"] == "Contact pressure [MPa]"


def test_the_pv_chart_follows_the_unit_choice(catalog: Catalog) -> None:
    """With inches: speed in in/s (25.4 mm), pressure in psi (6894.757 Pa)."""
    metric = figures(catalog, DUTY, METRIC)["pv"]
    imperial = figures(catalog, DUTY, IMPERIAL)["pv"]
    assert imperial["layout"]["xaxis"]["title"]["text"].endswith("[in/s]")
    assert imperial["layout"]["yaxis"]["title"]["text"].endswith("[psi]")
    for m, i in zip(metric["data"], imperial["data"], strict=True):
        assert i["x"] == pytest.approx([x / 25.4 for x in m["x"]], rel=1e-4)
        assert i["y"] == pytest.approx([y * 1e6 / PSI for y in m["y"]], rel=1e-4)


def test_every_axis_grows_its_margin_to_hold_its_labels(catalog: Catalog) -> None:
    """Plotly is told that no tick label passes the chart's edge (it skips measuring each
    one on every draw to hide those that would), which holds only because each axis's
    margin grows to hold its labels: every axis of every chart has both."""
    drawn = figures(catalog, DUTY, METRIC)
    assert {"critical_speed", "torque", "move", "cycle_torque"} <= set(drawn)
    for key, figure in drawn.items():
        for name, spec in axes(figure).items():
            assert spec["automargin"] is True, (key, name)
            assert spec["ticklabeloverflow"] == "allow", (key, name)
