"""The chart of motor torque over a cycle of moves: a step per segment at the core's
torque, the motor's usable torque at each segment's speed beside it, and the governing
segment marked; in the display torque unit."""

import numpy as np
import plotly.graph_objects as go
import pytest

from app.catalog import Catalog
from app.contract.outputs import SelectOut
from app.contract.schemas import ApplicationIn
from app.report.service import run_selection
from app.web.figures import result_figures
from tests.web import breakaway_lift

METRIC = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}
OZ_IN = {**METRIC, "torque_unit": "oz_in"}
OZ_IN_NM = 0.0070615518142260435  # N m: 4.4482216152605 N x 0.0254 m / 16 (NIST SP 811)
CURVE = [[0, 0.5], [600, 0.35], [3000, 0.1]]
#: out fast with a part, a slow return, a short jog: three moves that close
MOVES = "300:250:2500:2500:0.2:2.5:10:opposes;-200:100:500:500:0.1;-100:50:200:200:0.5"


@pytest.fixture(scope="module")
def selected(catalog: Catalog) -> SelectOut:
    inputs = ApplicationIn.model_validate(
        {"load_n": 10, "speed_mm_s": 250, "length_mm": 500, "lead_mm": 10,
         "motor_curve": CURVE, "torque_safety_factor": 1.5, "moves": MOVES}
    )  # fmt: skip
    return run_selection(inputs, catalog)


@pytest.mark.parametrize(
    ("units", "per_nm"), [(METRIC, 1.0), (OZ_IN, OZ_IN_NM)], ids=["N_m", "oz_in"]
)
def test_the_torque_steps_are_the_cores_segments(
    selected: SelectOut, units: dict[str, str], per_nm: float
) -> None:
    figure = result_figures(selected, units)["cycle_torque"]
    go.Figure(figure)
    top = selected.candidates[0]
    segments = top.segments
    assert (
        segments is not None and len(segments) == 3 * 4
    )  # accelerate, constant, decelerate, dwell
    torque = figure["data"][0]
    assert torque["y"][0::2] == pytest.approx([s.torque_nm / per_nm for s in segments], rel=1e-12)
    assert torque["y"][1::2] == torque["y"][0::2]
    ends = np.cumsum([s.duration_s for s in segments])
    assert torque["x"][1::2] == pytest.approx(list(ends))
    unit = "N m" if per_nm == 1.0 else "oz in"
    assert unit in figure["layout"]["yaxis"]["title"]["text"]


def test_the_usable_torque_is_the_curve_at_each_segments_speed(selected: SelectOut) -> None:
    """A typed curve is a servo's envelope (no stepper margin): read linearly between its
    points at the segment's top speed."""
    figure = result_figures(selected, METRIC)["cycle_torque"]
    segments = selected.candidates[0].segments or []
    usable, braking = figure["data"][1], figure["data"][2]
    speeds, torques = zip(*CURVE, strict=True)
    expected = [float(np.interp(s.rpm, speeds, torques)) for s in segments]
    assert usable["y"][0::2] == pytest.approx(expected, rel=1e-12)
    assert braking["y"][0::2] == pytest.approx([-t for t in expected], rel=1e-12)


def test_the_governing_segment_is_marked(selected: SelectOut) -> None:
    """The marked segment is the one with the largest share of the curve, |T| / curve."""
    figure = result_figures(selected, METRIC)["cycle_torque"]
    segments = selected.candidates[0].segments or []
    shares = [abs(s.torque_nm) / (s.curve_nm or 0.0) for s in segments]
    worst = int(np.argmax(shares))
    assert [s.governs for s in segments].count(True) == 1 and segments[worst].governs
    marker = figure["data"][-1]
    start = sum(s.duration_s for s in segments[:worst])
    assert marker["x"] == pytest.approx([start + segments[worst].duration_s / 2])
    assert marker["y"] == pytest.approx([segments[worst].torque_nm])
    assert segments[worst].name in marker["name"]


def test_the_start_from_rest_is_marked_where_it_governs(catalog: Catalog) -> None:
    """A bronze ISO nut lifting 150 N and 10 kg at 20 mm/s on the STEPPERONLINE
    23HS32-4004S (the case of test_figures' break-away test): starting from rest the oiled
    bronze thread is at its static friction, nearest the motor's curve of any point, so
    no moving segment governs. The marker sits at the cycle's start, at the break-away
    driving the up move (0.4550 N m), where before the chart marked nothing."""
    result = run_selection(breakaway_lift.INPUTS, catalog)
    top = result.candidates[0]
    assert top.torque.peak_segment == "starting from rest"
    assert not any(s.governs for s in top.segments or [])
    marker = result_figures(result, METRIC, catalog)["cycle_torque"]["data"][-1]
    assert marker["name"] == "Governs: starting from rest" and marker["x"] == [0.0]
    assert marker["y"] == pytest.approx([top.torque.breakaway_nm], rel=1e-12)
    assert marker["y"][0] == pytest.approx(0.4550, rel=1e-3)
