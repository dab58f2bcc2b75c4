"""Figure dicts: valid Plotly figures with the expected traces, axes and numbers."""

import json
import math
from typing import Any

import plotly.graph_objects as go
import pytest

from app.catalog import Catalog
from app.core.formulas.critical_speed import critical_speed_rpm
from app.schemas import ApplicationIn, SelectOut
from app.service import run_selection
from app.web.figures import TOP, chart_candidates, result_figures

METRIC = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}
IMPERIAL = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
LBF, INCH, OZ_IN = 4.4482216152605, 25.4, 0.0070615518333


def plain(result: SelectOut) -> dict[str, Any]:
    """The result as the API serves it (plain JSON values) for assertions."""
    data: dict[str, Any] = json.loads(result.model_dump_json())
    return data


@pytest.fixture(scope="module")
def result(catalog: Catalog) -> SelectOut:
    inputs = ApplicationIn(load_n=100, speed_mm_s=50, length_mm=500, lead_mm=10, max_torque_nm=0.3)
    return run_selection(inputs, catalog)


@pytest.mark.parametrize("units", [METRIC, IMPERIAL], ids=["metric", "imperial"])
def test_every_figure_is_a_valid_plotly_figure(result: SelectOut, units: Any) -> None:
    figures = result_figures(result, units)
    assert set(figures) == {"critical_speed", "pv", "torque"}
    for figure in figures.values():
        go.Figure(figure)
        json.dumps(figure, allow_nan=False)


def test_critical_speed_curves_follow_the_core_formula(
    result: dict[str, Any], catalog: Catalog
) -> None:
    figure = result_figures(result, METRIC)["critical_speed"]
    top = plain(result)["candidates"][:TOP]
    curves, points, line = figure["data"][:-2], figure["data"][-2], figure["data"][-1]
    assert [c["name"] for c in curves] == [c["id"] for c in top]
    assert figure["layout"]["xaxis"]["type"] == figure["layout"]["yaxis"]["type"] == "log"
    assert figure["layout"]["xaxis"]["title"]["text"].endswith("[mm]")
    assert points["x"] == [500.0] * len(top) and points["y"] == [c["rpm"] for c in top]
    assert line["x"] == [500.0, 500.0]
    for curve, candidate in zip(curves, top, strict=True):
        screw = catalog.by_id[candidate["id"]]
        factor = plain(result)["inputs"]["critical_speed_safety_factor"]
        for length_mm, rpm in zip(curve["x"][::10], curve["y"][::10], strict=True):
            expected = factor * critical_speed_rpm(
                screw.root_diameter_m,
                length_mm / 1e3,
                screw.youngs_modulus_pa,
                screw.density_kg_m3,
                plain(result)["inputs"]["end_fixity"],
            )
            assert rpm == pytest.approx(expected, rel=1e-3)


def test_pv_curves_pass_through_the_limit_at_the_operating_speed(result: SelectOut) -> None:
    figure = result_figures(result, METRIC)["pv"]
    curves, point = figure["data"][:-1], figure["data"][-1]
    top = [c for c in plain(result)["candidates"][:TOP] if c["pv"]["max_load_n"] is not None]
    assert len(curves) == len(top)
    assert point["x"] == [50.0] and point["y"] == [100.0]
    for curve, candidate in zip(curves, top, strict=True):
        middle = len(curve["x"]) // 2
        assert curve["x"][middle] == pytest.approx(50.0)
        assert curve["y"][middle] == pytest.approx(candidate["pv"]["max_load_n"], rel=1e-4)
        products = {round(x * y, 1) for x, y in zip(curve["x"], curve["y"], strict=True)}
        assert max(products) / min(products) == pytest.approx(1.0, abs=1e-3)
    assert figure["layout"]["xaxis"]["type"] == "log"


def test_torque_bars_stack_to_the_total(result: SelectOut) -> None:
    figure = result_figures(result, METRIC)["torque"]
    assert figure["layout"]["barmode"] == "stack"
    assert [t["name"] for t in figure["data"]] == ["Inertia", "Drag", "Load"]
    assert all(t["type"] == "bar" for t in figure["data"])
    for i, candidate in enumerate(plain(result)["candidates"]):
        stacked = sum(trace["y"][i] for trace in figure["data"])
        assert stacked == pytest.approx(candidate["torque"]["total_nm"], rel=1e-3)
    (limit,) = figure["layout"]["shapes"]
    assert limit["y0"] == limit["y1"] == 0.3


def test_axes_and_values_follow_the_display_units(result: SelectOut) -> None:
    metric = result_figures(result, METRIC)
    imperial = result_figures(result, IMPERIAL)
    assert imperial["critical_speed"]["layout"]["xaxis"]["title"]["text"].endswith("[in]")
    assert imperial["pv"]["layout"]["xaxis"]["title"]["text"].endswith("[in/s]")
    assert imperial["pv"]["layout"]["yaxis"]["title"]["text"].endswith("[lbf]")
    assert imperial["torque"]["layout"]["yaxis"]["title"]["text"].endswith("[oz in]")
    assert imperial["pv"]["data"][-1]["y"][0] == pytest.approx(100 / LBF, rel=1e-4)
    assert imperial["critical_speed"]["data"][-1]["x"][0] == pytest.approx(500 / INCH, rel=1e-4)
    metric_load = metric["torque"]["data"][2]["y"][0]
    assert imperial["torque"]["data"][2]["y"][0] == pytest.approx(metric_load / OZ_IN, rel=1e-3)


def test_nothing_passing_charts_the_nearest_rejected(catalog: Catalog) -> None:
    inputs = ApplicationIn(load_n=10000, speed_mm_s=500, length_mm=3000)
    result = run_selection(inputs, catalog)
    assert plain(result)["candidates"] == []
    candidates, passing = chart_candidates(result)
    assert not passing and candidates == result.rejected
    figures = result_figures(result, METRIC)
    names = [t["name"] for t in figures["critical_speed"]["data"][:-2]]
    assert names == [c["id"] for c in plain(result)["rejected"][:TOP]]
    assert "shapes" not in figures["torque"]["layout"]
    assert math.isfinite(figures["pv"]["data"][-1]["y"][0])
