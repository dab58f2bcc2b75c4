"""Figure dicts: valid Plotly figures with the expected traces, axes and numbers."""

import json
import math
from typing import Any

import numpy as np
import plotly.graph_objects as go
import pytest

from app.catalog import Catalog
from app.contract.outputs import SelectOut
from app.contract.schemas import ApplicationIn
from app.contract.units import Display
from app.core.formulas.critical_speed import ball_screw_critical_speed_rpm, critical_speed_rpm
from app.report.charts import chart_data
from app.report.service import run_selection
from app.web.curves import TOP
from app.web.figures import chart_candidates, result_figures, torque_figure
from app.web.life_figures import LIFE_TOP
from tests.leadscrews import leadscrew_families
from tests.web import breakaway_lift

METRIC = {"force_unit": "N", "length_unit": "mm", "torque_unit": "N_m"}
IMPERIAL = {"force_unit": "lbf", "length_unit": "in", "torque_unit": "oz_in"}
LBF, INCH, OZ_IN = 4.4482216152605, 25.4, 0.0070615518142260435  # N, mm, N m (NIST SP 811)


#: Thomson's and Roton's end fixity factors C_s, times simple-simple, for a leadscrew.
THOMSON_CS = {"fixed-free": 0.36, "simple-simple": 1.0, "fixed-simple": 1.47, "fixed-fixed": 2.23}


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


def curve_members(figure: dict[str, Any], candidates: list[dict[str, Any]]) -> list[list[str]]:
    """The candidate ids each curve's legend names (series prefix written once)."""
    members = []
    for curve in figure["data"]:
        if curve["name"] in ("Operating point", "Your length"):
            continue
        members.append([c["id"] for c in candidates if c["id"] in full_ids(curve["name"])])
    return members


def full_ids(name: str) -> set[str]:
    """Ids a legend entry 'B14000: L60-TFE, L50-TFE' (or 'A, B') stands for."""
    series, colon, rest = name.partition(": ")
    if not colon:
        return set(name.split(", "))
    return {f"{series}-{part}" for part in rest.split(", ")}


def test_critical_speed_draws_one_line_per_distinct_curve(
    result: SelectOut, catalog: Catalog
) -> None:
    figure = result_figures(result, METRIC)["critical_speed"]
    candidates = plain(result)["candidates"]
    groups = curve_members(figure, candidates)
    allowed = [
        {round(c["critical_speed"]["allowed_rpm"], 1) for c in candidates if c["id"] in g}
        for g in groups
    ]
    assert all(len(a) == 1 for a in allowed)  # one curve: one allowed speed
    assert len({a.pop() for a in allowed}) == len(groups)  # no curve drawn twice
    assert sum(map(len, groups)) >= len(groups)
    assert figure["layout"]["xaxis"]["type"] == figure["layout"]["yaxis"]["type"] == "log"
    assert figure["layout"]["xaxis"]["title"]["text"].endswith("[mm]")
    factor = plain(result)["inputs"]["critical_speed_safety_factor"]
    for curve, group in zip(figure["data"], groups, strict=False):
        screw = catalog.by_id[group[0]]
        fixity = plain(result)["inputs"]["end_fixity"]
        for length_mm, rpm in zip(curve["x"][::10], curve["y"][::10], strict=True):
            beam = critical_speed_rpm(
                screw.root_diameter_m,
                length_mm / 1e3,
                screw.youngs_modulus_pa,
                screw.density_kg_m3,
                fixity,
            )
            # a ball screw's at most its maker's (HIWIN F 3.27), a leadscrew's at most its
            # makers' (Thomson, Roton: C_s times simple-simple)
            if screw.screw_type == "ball":
                hiwin = ball_screw_critical_speed_rpm(
                    screw.root_diameter_m, length_mm / 1e3, fixity
                )
                beam = min(beam, hiwin)
            else:
                simple = critical_speed_rpm(
                    screw.root_diameter_m,
                    length_mm / 1e3,
                    screw.youngs_modulus_pa,
                    screw.density_kg_m3,
                    "simple-simple",
                )
                beam = min(beam, THOMSON_CS[fixity] * simple)
            expected = factor * beam
            assert rpm == pytest.approx(expected, rel=1e-3)


def test_operating_points_do_not_overlap_and_carry_their_margin(result: SelectOut) -> None:
    figure = result_figures(result, METRIC)["critical_speed"]
    points, line = figure["data"][-2], figure["data"][-1]
    assert line["x"] == [500.0, 500.0]
    assert set(points["x"]) == {500.0}
    pairs = list(zip(points["y"], points["marker"]["color"], strict=True))
    assert len(pairs) == len(set(pairs))  # no two markers drawn on one spot
    by_id = {c["id"]: c for c in plain(result)["candidates"]}
    for rpm, text in zip(points["y"], points["text"], strict=True):
        for line_text in text.split("<br>"):
            cid, margin = line_text.split(": margin ")
            assert by_id[cid]["rpm"] == pytest.approx(rpm, rel=1e-4)
            expected = by_id[cid]["critical_speed"]["margin"]
            assert float(margin.rstrip("×")) == pytest.approx(expected, abs=0.006)


def test_log_axes_label_each_decade_and_steps_between(result: SelectOut) -> None:
    axis = result_figures(result, METRIC)["critical_speed"]["layout"]["xaxis"]
    assert axis["tickvals"] == [100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0]
    assert axis["ticktext"] == ["100", "200", "500", "1000", "2000", "5000"]
    pv_axis = result_figures(result, METRIC)["pv"]["layout"]["xaxis"]
    assert pv_axis["tickvals"] == [5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0]


def test_pv_curves_pass_through_the_limit_at_the_operating_speed(result: SelectOut) -> None:
    figure = result_figures(result, METRIC)["pv"]
    curves, point = figure["data"][:-1], figure["data"][-1]
    candidates = plain(result)["candidates"]
    groups = curve_members(figure, candidates)
    assert point["x"] == [50.0] and point["y"] == [100.0]
    by_id = {c["id"]: c for c in candidates}
    for curve, group in zip(curves, groups, strict=True):
        middle = len(curve["x"]) // 2
        assert curve["x"][middle] == pytest.approx(50.0)
        for cid in group:
            assert curve["y"][middle] == pytest.approx(by_id[cid]["pv"]["max_load_n"], rel=1e-4)
        products = {round(x * y, 1) for x, y in zip(curve["x"], curve["y"], strict=True)}
        assert max(products) / min(products) == pytest.approx(1.0, abs=1e-3)
    assert figure["layout"]["xaxis"]["type"] == "log"


def test_legend_sits_below_the_plot_clear_of_the_toolbar(result: SelectOut) -> None:
    for figure in result_figures(result, METRIC).values():
        legend = figure["layout"]["legend"]
        assert legend["yref"] == "container" and legend["y"] == 0
        assert figure["layout"]["margin"]["t"] >= 30


def test_lead_sweep_evaluates_every_lead_of_the_top_size(catalog: Catalog) -> None:
    """A leadscrew's sweep (a ball nut has no PV, so its sweep has no PV trace)."""
    inputs = ApplicationIn(
        load_n=100, speed_mm_s=50, length_mm=500, lead_mm=10, max_torque_nm=0.3,
        family=list(leadscrew_families(catalog)),
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    figure = result_figures(result, METRIC, catalog)["lead_sweep"]
    top = result.candidates[0]
    same = [
        s
        for s in catalog.series[top.series].screws
        if s.coated == top.coated and s.anti_backlash == top.anti_backlash
    ]
    torque, speed, pv_used, limit = figure["data"]
    assert torque["x"] == sorted(round(s.lead_m * 1e3, 6) for s in same)
    chosen = torque["x"].index(top.lead_mm)
    assert torque["y"][chosen] == pytest.approx(top.torque.total_nm, rel=1e-4)
    assert speed["y"][chosen] == pytest.approx(100 / top.critical_speed.margin, rel=1e-3)
    pv_check = next(k for k in top.checks if k.name == "pv")
    assert pv_used["y"][chosen] == pytest.approx(pv_check.utilization * 100, rel=1e-3)
    band, marker = figure["layout"]["shapes"]
    assert band["type"] == "rect" and band["x1"] == pytest.approx(
        min(top.max_self_locking_lead_with_margin_mm, max(torque["x"])), rel=1e-4
    )
    assert limit["y"] == [100, 100] and limit["yaxis"] == "y2" and marker["x0"] == top.lead_mm
    assert (
        figure["layout"]["yaxis2"]["type"] == "log"
        and 100.0 in figure["layout"]["yaxis2"]["tickvals"]
    )


def test_an_iso_nuts_lead_sweep_shows_its_flank_pressure(catalog: Catalog) -> None:
    """300 N at 20 mm/s on the 304 steel ISO screws with a bronze nut, lead 4 mm: the top
    screw is Tr8x4(P2), made in leads 2, 4 and 8 mm. Its nut has no PV rating (no PV
    trace) but a flank pressure check: the sweep draws its share of the allowed pressure
    at each lead, the chosen lead's equal to the check's utilisation."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 300, "speed_mm_s": 20, "length_mm": 500, "lead_mm": 4,
         "family": ["TR-304"], "nut_material": "bronze"}
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    top = result.candidates[0]
    assert top.id == "Tr8x4(P2)-304-bronze"
    data = {t["name"]: t for t in result_figures(result, METRIC, catalog)["lead_sweep"]["data"]}
    assert "PV, % of limit" not in data
    flank = data["Flank pressure, % of allowed"]
    assert flank["x"] == [2.0, 4.0, 8.0] and flank["yaxis"] == "y2"
    check = next(k for k in top.checks if k.name == "bearing_pressure")
    assert flank["y"][flank["x"].index(top.lead_mm)] == pytest.approx(
        check.utilization * 100, rel=1e-3
    )


def test_a_size_with_one_lead_of_its_nut_has_no_sweep(catalog: Catalog) -> None:
    """Tr8x1.5 is made in one lead, with a bronze, an acetal or a PTFE nut: the top
    (bronze) screw's size and nut has nothing to sweep, so the chart is left out rather
    than drawn as three nuts stacked on one lead. At 20 mm/s (800 rpm) its bronze nut
    slides at 800 / 60 x pi x 7.25 mm = 0.30 m/s, within bronze's 0.42 m/s (greased, as
    its ratings are a lubricated nut's)."""
    inputs = ApplicationIn(
        load_n=100,
        speed_mm_s=20,
        length_mm=500,
        family=list(leadscrew_families(catalog)),
        lubrication="greased",
    )
    result = run_selection(inputs, catalog)
    assert result.candidates[0].id == "Tr8x1.5-bronze"
    assert "lead_sweep" not in result_figures(result, METRIC, catalog)


def test_torque_bars_stack_to_the_total(result: SelectOut) -> None:
    figure = result_figures(result, METRIC)["torque"]
    assert figure["layout"]["barmode"] == "stack"
    bars, peak = figure["data"][:3], figure["data"][3]
    assert [t["name"] for t in bars] == ["Inertia", "Drag", "Load"]
    assert all(t["type"] == "bar" for t in bars) and peak["type"] == "scatter"
    for i, candidate in enumerate(plain(result)["candidates"]):
        stacked = sum(trace["y"][i] for trace in bars)
        assert stacked == pytest.approx(candidate["torque"]["total_nm"], rel=1e-3)
        assert peak["y"][i] == pytest.approx(candidate["torque"]["peak_motor_nm"], rel=1e-3)
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


#: 10 kN at 500 mm/s over 3 m: no leadscrew passes (a 50 x 40 ball screw does).
NOTHING_PASSES = {"load_n": 10000, "speed_mm_s": 500, "length_mm": 3000}


def test_nothing_passing_charts_the_nearest_rejected(catalog: Catalog) -> None:
    inputs = ApplicationIn(**NOTHING_PASSES, family=list(leadscrew_families(catalog)))
    result = run_selection(inputs, catalog)
    assert plain(result)["candidates"] == []
    candidates, passing = chart_candidates(result)
    assert not passing and candidates == result.rejected
    figures = result_figures(result, METRIC)
    groups = curve_members(figures["critical_speed"], plain(result)["rejected"])
    assert groups[0][0] == plain(result)["rejected"][0]["id"]
    assert 1 < len(groups) <= TOP
    assert list(result_figures(result, METRIC)) == ["critical_speed", "pv", "torque"]
    assert result.summary.most_excluding_check == "critical_speed"
    assert "shapes" not in figures["torque"]["layout"]
    assert math.isfinite(figures["pv"]["data"][-1]["y"][0])


def test_nothing_passing_puts_the_most_excluding_checks_chart_first(catalog: Catalog) -> None:
    inputs = ApplicationIn(**NOTHING_PASSES, family=list(leadscrew_families(catalog)))
    result = run_selection(inputs, catalog)
    summary = result.summary.model_copy(update={"most_excluding_check": "pv"})
    by_pv = result.model_copy(update={"summary": summary})
    assert list(result_figures(by_pv, METRIC, catalog))[:3] == ["pv", "critical_speed", "torque"]


def test_motor_and_move_charts_follow_the_segments(catalog: Catalog) -> None:
    """Given a stroke and a motor curve: the curve drawn as given, each moving segment of
    each top screw at (rpm, |torque| x safety factor), and the top screw's cycle over time
    lasting the profile's cycle time, its constant segment at the top rpm."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10, "stroke_mm": 200,
         "motor_curve": [[0, 0.4], [600, 0.3], [1200, 0.1]], "torque_safety_factor": 1.5}
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    figures = result_figures(result, METRIC)
    assert {"motor", "move"} <= set(figures)
    motor, move = figures["motor"], figures["move"]
    go.Figure(motor)
    go.Figure(move)
    assert motor["data"][0]["x"] == [0, 600, 1200] and motor["data"][0]["y"] == [0.4, 0.3, 0.1]
    top = result.candidates[0]
    assert top.segments is not None and top.profile is not None
    moving = [s for s in top.segments if s.name != "dwell"]
    points = motor["data"][1]
    assert points["name"] == top.id
    demands = [abs(s.torque_nm) for s in moving] + [top.torque.breakaway_nm]
    assert points["x"] == [s.rpm for s in moving] + [0.0]
    assert points["y"] == pytest.approx([t * 1.5 for t in demands])
    times = move["data"][0]["x"]
    assert times[-1] == pytest.approx(top.profile.cycle_time_s)
    constant = next(i for i, s in enumerate(top.segments) if s.name == "constant")
    assert move["data"][0]["y"][2 * constant] == pytest.approx(top.segments[constant].rpm)
    # the back move turns the shaft the other way: speed and torque both change sign, and
    # the two axes share their zero (ranges symmetric about it)
    back = next(i for i, s in enumerate(top.segments) if s.direction == "back")
    speed, torque = move["data"][0]["y"], move["data"][1]["y"]
    assert speed[2 * back + 1] < 0 and torque[2 * back] == pytest.approx(
        -top.segments[back].torque_nm
    )
    for axis in ("yaxis", "yaxis2"):
        low, high = move["layout"][axis]["range"]
        assert low == -high and high > 0
    assert move["layout"]["yaxis"]["range"][1] >= max(abs(v) for v in speed)
    assert move["layout"]["yaxis2"]["range"][1] >= max(abs(v) for v in torque)


def test_no_stroke_no_move_charts(result: SelectOut) -> None:
    assert not {"motor", "move"} & set(result_figures(result, METRIC))


def test_life_chart_falls_as_one_over_thrust(catalog: Catalog) -> None:
    """With a duty, each wear-rated top screw's life in years against thrust: Archard's
    life is inversely proportional to the thrust, so thrust x life is the same all along
    the line, and at the axis's thrust it is the wear check's number; the band spans the
    wear rate's range (3.3e-7 to 3e-6 against 1e-6 for acetal: 1/3 to 3.03 times)."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 200, "speed_mm_s": 20, "length_mm": 500, "stroke_mm": 200,
         "cycles_per_day": 100, "required_life_years": 1, "family": ["TR-C45"],
         "nut_material": "acetal"}
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    figures = result_figures(result, METRIC, catalog)
    life = figures["life"]
    go.Figure(life)
    json.dumps(life, allow_nan=False)
    low, high, line = life["data"][:3]
    top = result.candidates[0]
    assert line["name"] == top.id
    products = [x * y for x, y in zip(line["x"], line["y"], strict=True)]
    assert products == pytest.approx([products[0]] * len(products))
    wear = next(c for c in top.checks or [] if c.name == "wear_life")
    middle = len(line["x"]) // 2
    assert line["x"][middle] == pytest.approx(top.axial_load_n)
    assert line["y"][middle] == pytest.approx(wear.limit)
    assert high["y"][middle] / line["y"][middle] == pytest.approx(1e-6 / 3.3e-7)
    assert low["y"][middle] / line["y"][middle] == pytest.approx(1 / 3)
    assert life["layout"]["yaxis"]["title"]["text"] == "Wear life [years]"


@pytest.mark.parametrize(
    ("extra", "name"),
    [
        ({"motor": "23hs32-4004s"}, "Pull-out (maker's published curve)"),
        ({"motor": "23hs32-4004s", "motor_curve": [[0, 1.0], [600, 0.5]]}, "Pull-out (as entered)"),
        ({"motor_curve": [[0, 1.0], [600, 0.5]]}, "Motor curve (as entered)"),
    ],
    ids=["library-published", "library-curve-entered", "entered"],
)
def test_the_motor_chart_names_where_its_curve_comes_from(
    catalog: Catalog, extra: dict[str, object], name: str
) -> None:
    """The 23HS32-4004S carries STEPPERONLINE's published curve (catalog/motors.toml): the
    chart names it the maker's, with its first point held to standstill, 1.841 N m at the
    chart's 4.2 A peak, 4.0 / 4.2 of it at the library's rated 4.0 A; a curve typed in is
    named as entered, over a library motor's too."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10, "stroke_mm": 200,
         **extra}
    )  # fmt: skip
    curve = result_figures(run_selection(inputs, catalog), METRIC, catalog)["motor"]["data"][0]
    assert curve["name"] == name
    if "motor_curve" not in extra:
        assert curve["y"][:2] == pytest.approx([1.841 * 4.0 / 4.2] * 2)


def test_a_library_motor_draws_its_model_curve(catalog: Catalog) -> None:
    """The motor chart draws the library motor's pull-out curve from the microstepping
    model: the 17HS19-2004S1 (0.59 N m) gives 0.59 / sqrt 2 = 0.417 N m from standstill
    (points at 0 and 30 rpm, each carrying the next speed's torque), and its drawn
    torque never rises. Beside it, dashed, the usable torque the checks hold the move
    against: the pull-out over the stepper torque margin, 0.417 / 1.5 = 0.278 N m."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10, "stroke_mm": 200,
         "motor": "17hs19-2004s1"}
    )  # fmt: skip
    figures = result_figures(run_selection(inputs, catalog), METRIC, catalog)
    curve = figures["motor"]["data"][0]
    assert curve["x"][:2] == pytest.approx([0.0, 30.0])
    assert curve["y"][:2] == pytest.approx([0.59 / 2**0.5] * 2)
    assert list(curve["y"]) == sorted(curve["y"], reverse=True)
    usable = figures["motor"]["data"][1]
    assert curve["name"] == "Pull-out (model, from datasheet values)"
    assert usable["name"] == "Usable (pull-out / 1.5)"
    assert usable["x"] == curve["x"]
    assert usable["y"] == pytest.approx([t / 1.5 for t in curve["y"]])


def test_screws_whose_wear_lines_coincide_share_one_line(catalog: Catalog) -> None:
    """At lead 10 mm the top wear-rated nuts include the same nut in several series (one
    life, one band): each distinct line is drawn once, named for every screw it stands
    for, so no line hides another and every wear-rated top screw is named."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10}
    )
    result = run_selection(inputs, catalog)
    ids = [c.id for c in chart_candidates(result)[0]]
    wear = {w.id: (w.life, w.band) for w in chart_data(inputs, catalog, ids, LIFE_TOP).wear}
    data = result_figures(result, METRIC, catalog)["life"]["data"]
    named = [t["name"].split(", ") for t in data if t.get("showlegend", True)]
    assert sorted(i for group in named for i in group) == sorted(wear)
    assert any(len(group) > 1 for group in named)  # this query's top nuts do coincide
    assert all({wear[i] for i in group} == {wear[group[0]]} for group in named)
    assert len({wear[group[0]] for group in named}) == len(named)  # none drawn twice


def test_the_torque_chart_stacks_the_torque_while_accelerating(catalog: Catalog) -> None:
    """Each candidate's bars (inertia, drag, load) sum to its torque while accelerating
    (``torque.total_nm``, the table's torque without a move): not a running torque, which
    has no inertia part. Beside them, a diamond at the peak the torque check judges: with
    a 2 m/s^2 move of 5 kg on a horizontal axis, the move's peak (its acceleration), at
    least the bars."""
    inputs = ApplicationIn(
        load_n=50, speed_mm_s=100, length_mm=500, accel_mm_s2=2000, moving_mass_kg=5
    )
    result = run_selection(inputs, catalog)
    figure = result_figures(result, METRIC)["torque"]
    assert figure["layout"]["yaxis"]["title"]["text"] == "Motor torque [N m]"
    candidates = plain(result)["candidates"]
    bars, peak = figure["data"][:3], figure["data"][3]
    for i, c in enumerate(candidates):
        parts = [trace["y"][i] for trace in bars]
        assert parts[0] > 0  # the inertia
        assert sum(parts) == pytest.approx(c["torque"]["total_nm"], rel=1e-3)
        assert peak["y"][i] == pytest.approx(c["torque"]["peak_motor_nm"], rel=1e-3)
        assert peak["y"][i] >= sum(parts) * (1 - 1e-3)


def test_a_servos_continuous_zone_is_drawn_beside_its_peak_envelope(catalog: Catalog) -> None:
    """The Yaskawa SGM7J-01A (catalog/motors.toml): peak 1.11 N m to its rated 3000 rpm,
    down to 0.318 N m at 6000 rpm; its continuous zone the rated 0.318 N m to 3000 rpm,
    then straight to 0.159 N m at 6000 rpm (the assumed end the RMS check holds the cycle
    to, ``segments.continuous_torque``). A motor with a continuous rating and no zone has
    the rating drawn flat over its curve; one with neither has no such line."""
    axis = {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10, "stroke_mm": 200}
    runs = {
        "servo": {"motor": "yaskawa-sgm7j-01a"},
        "rated": {"motor_curve": [[0, 0.9], [3000, 0.6]], "motor_rms_torque_nm": 0.3},
        "curve alone": {"motor_curve": [[0, 0.9], [3000, 0.6]]},
    }
    lines = {}
    for name, extra in runs.items():
        inputs = ApplicationIn.model_validate({**axis, **extra})
        data = result_figures(run_selection(inputs, catalog), METRIC, catalog)["motor"]["data"]
        lines[name] = [t for t in data if t["name"].startswith("Continuous")]
    (servo,) = lines["servo"]
    assert servo["x"] == [0.0, 3000.0, 6000.0]
    assert servo["y"] == pytest.approx([0.318, 0.318, 0.159], rel=1e-12)
    assert servo["line"]["dash"] == "dot"
    (rated,) = lines["rated"]
    assert (rated["x"], rated["y"]) == ([0.0, 3000.0], pytest.approx([0.3, 0.3]))
    assert lines["curve alone"] == []


def test_the_motor_chart_draws_the_break_away_the_check_holds_to_the_curve(
    catalog: Catalog,
) -> None:
    """A bronze ISO nut lifting 150 N and 10 kg at 20 mm/s on the STEPPERONLINE
    23HS32-4004S (its published 48 V curve: 1.841 N m held from standstill to 90 rpm,
    1.729 N m at 390 and 1.498 N m at 510 rpm, at the chart's 4.2 A peak: 4.0 / 4.2 of it
    at the library's rated 4.0 A; usable over the 1.5 torque margin). The top screw,
    Tr14x3-bronze, turns at 400 rpm: its largest moving segment, accelerating up, needs
    0.4044 N m against 1.709 x 4.0 / 4.2 / 1.5 = 1.0851 N m there (37.3 %), but starting
    from rest the oiled bronze thread is at its static friction: 0.4550 N m against
    1.841 x 4.0 / 4.2 / 1.5 = 1.1689 N m at standstill, 38.9 %, the motor-curve check's
    utilization and the results' peak torque ('starting from rest'). The chart draws
    that point at 0 rpm, so its highest point against the usable line is the check's
    38.9 %, not the segments' 37.3 %."""
    result = run_selection(breakaway_lift.INPUTS, catalog)
    data = result_figures(result, METRIC, catalog)["motor"]["data"]
    usable = next(t for t in data if t["name"].startswith("Usable"))
    for c in result.candidates[:TOP]:
        points = next(t for t in data if t["name"] == c.id)
        start = points["text"].index("start from rest")
        assert (points["x"][start], points["y"][start]) == (0.0, c.torque.peak_motor_nm)
        shares = [
            y / float(np.interp(x, usable["x"], usable["y"]))
            for x, y in zip(points["x"], points["y"], strict=True)
        ]
        assert max(shares) == pytest.approx(c.utilization["motor_curve"])
    top = result.candidates[0]
    assert top.id == "Tr14x3-bronze" and top.torque.peak_segment == "starting from rest"
    assert top.torque.peak_motor_nm == pytest.approx(0.4550, abs=5e-5)
    assert top.utilization["motor_curve"] == pytest.approx(0.3892, abs=5e-5)


def test_a_rated_nuts_life_line_stays_within_the_results_band(catalog: Catalog) -> None:
    """The seed rates its KHD nuts' travel and the results cap that rating by the wear
    law at either end (``sections.Life.travel_m``). At 1 N and 0.1 kg, 2000 cycles a day
    of a 200 mm stroke, the wear alone would give KHD6000-L8-TFE 7.52-68.4 years (22.6
    nominal), but its rated travel caps the high end: the results say 7.52-19.86 years.
    The chart drew the nominal wear line at 22.6 years at this thrust, above the band;
    it now stops at the rated travel, and each band edge at the axis's thrust (the
    middle point) is the results' band, for every nut drawn."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 1, "moving_mass_kg": 0.1, "speed_mm_s": 20, "length_mm": 300,
         "stroke_mm": 200, "accel_mm_s2": 500, "cycles_per_day": 2000, "family": ["KHD"],
         "max_torque_nm": 2.0, "limit": 20}
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    by_id = {c.id: c for c in result.candidates}
    data = result_figures(result, METRIC, catalog)["life"]["data"]
    for k in range(0, len(data), 3):
        low, high, line = data[k : k + 3]
        life = by_id[line["name"].split(", ")[0]].life
        assert life is not None and life.years is not None
        assert [low["y"][12], high["y"][12]] == pytest.approx(life.years, rel=1e-12)
        assert max(line["y"] + high["y"]) <= life.years[1] * (1 + 1e-12)
    l8 = by_id["KHD6000-L8-TFE"].life
    assert l8 is not None and l8.years == pytest.approx([7.519, 19.863], abs=5e-4)


def test_the_move_chart_holds_a_weight_the_same_way_after_either_move(
    catalog: Catalog,
) -> None:
    """A HIWIN rolled ball screw lifting 100 N and 10 kg (vertical, 1 s dwells, a brake
    for the power-off hold) on the Yaskawa SGM7J-01A. The ball screw does not self-lock,
    so in each dwell the motor holds the 198.07 N on the nut up: the same torque turning
    the shaft the up way at the top and at the bottom of the stroke (the results' two
    dwells, for R16-05T3-FSIDIN: 198.07 N x 5 mm x eta_b / 2 pi, eta_b 0.984773 back-
    driven at half HIWIN's low friction 0.003 on its 16 mm ball circle, +0.155216 N m
    each). The chart signs torque by the shaft's direction (up positive), and drew the
    dwell after the down move negative, as if the motor pushed the weight down; now both
    dwells are positive."""
    inputs = ApplicationIn.model_validate(
        {"load_n": 100, "moving_mass_kg": 10, "orientation": "vertical", "speed_mm_s": 250,
         "length_mm": 800, "accel_mm_s2": 5000, "stroke_mm": 600, "cycles_per_day": 5000,
         "motor": "yaskawa-sgm7j-01a", "family": ["HIWIN-ROLLED"], "brake_torque_nm": 1.0,
         "dwell_s": 1.0}
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    top = result.candidates[0]
    assert top.segments is not None
    dwells = [i for i, s in enumerate(top.segments) if s.name == "dwell"]
    assert [top.segments[i].direction for i in dwells] == ["up", "down"]
    held = [top.segments[i].torque_nm for i in dwells]
    assert held[0] == held[1] > 0.0
    torque = result_figures(result, METRIC, catalog)["move"]["data"][1]["y"]
    assert [torque[2 * i] for i in dwells] == [held[0], held[0]]
    assert [torque[2 * i + 1] for i in dwells] == [held[0], held[0]]
    assert top.id == "R16-05T3-FSIDIN" and held[0] == pytest.approx(0.155216, abs=5e-7)


def test_the_torque_limit_line_is_the_drive_over_the_safety_factor(catalog: Catalog) -> None:
    """The bars are before the torque safety factor; the torque check holds the torque
    times the factor to the drive's 0.3 N m. With a factor of 3 no screw passes (the
    lightest, R12-10K3-FSCDIN, needs 0.1722 x 3 = 0.517 N m) and the chart shows the
    nearest rejected: the line the bars are held to is 0.3 / 3 = 0.1 N m, and every bar
    (0.17 N m and up) stands above it. Drawn at 0.3 N m, the line stood above every bar
    of screws that all fail on torque. Where break-away is no larger than the torque
    while accelerating, as here, a bar above the line is a failed torque check."""
    inputs = ApplicationIn(
        load_n=100, speed_mm_s=50, length_mm=500, lead_mm=10, max_torque_nm=0.3,
        torque_safety_factor=3.0,
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    assert not result.candidates
    figure = result_figures(result, METRIC, catalog)["torque"]
    (line,) = figure["layout"]["shapes"]
    assert line["y0"] == line["y1"] == pytest.approx(0.1)
    charted = chart_candidates(result)[0]
    for i, c in enumerate(charted):
        top = sum(trace["y"][i] for trace in figure["data"])
        assert c.torque.breakaway_nm <= c.torque.total_nm
        assert (top > line["y0"]) == ((c.utilization["torque"] or 0.0) > 1.0)
    assert all((c.utilization["torque"] or 0.0) > 1.0 for c in charted)


def test_the_torque_chart_marks_a_break_away_above_the_bars(catalog: Catalog) -> None:
    """200 N lifted at 20 mm/s on a vertical axis, with no move: a sliding nut starts
    from rest at its static friction, so its peak (the break-away, what the torque check
    judges) stands above the bars of its torque while accelerating. Tr14x3-bronze, oiled
    (d2 12.5 mm, tan l = 3 / (pi 12.5) = 0.07639, friction 0.13 running, 0.16 static):
    bars 200 x 0.003 / (2 pi x 0.35837) = 0.2665 N m plus the screw's inertia 0.0157,
    0.2821 N m; diamond 200 x 0.003 / (2 pi x 0.31163) = 0.3064 plus 0.0157, 0.3221 N m;
    with a drive of 0.30 N m, the line sits between them, and the diamond shows why the
    screw fails."""
    inputs = ApplicationIn(
        load_n=200, speed_mm_s=20, length_mm=400, orientation="vertical", max_torque_nm=0.30,
        lubrication="oiled",
    )  # fmt: skip
    result = run_selection(inputs, catalog)
    c = next(c for c in [*result.candidates, *result.rejected] if c.id == "Tr14x3-bronze")
    figure = torque_figure([c], 0.30, Display(METRIC))
    bars = sum(trace["y"][0] for trace in figure["data"][:3])
    peak = figure["data"][3]["y"][0]
    assert bars == pytest.approx(0.2821, abs=1e-4) and peak == pytest.approx(0.3221, abs=1e-4)
    assert bars < figure["layout"]["shapes"][0]["y0"] < peak
    assert not c.passed and c.governing_check == "torque"


def test_the_motor_chart_marks_each_candidates_rms_as_the_rms_check_judges_it(
    catalog: Catalog,
) -> None:
    """Beside a continuous rating, each top candidate's RMS torque is a square at the
    rating line's standstill end: with a flat rating (0.3 N m typed), the cycle's RMS
    torque times the safety factor (1.5), the RMS check's demand; with the Yaskawa
    SGM7J-01A's continuous zone, which narrows above 3000 rpm, the check's demand (each
    segment scaled up by the zone), not the plain RMS. A square sits above the line's end
    exactly where the candidate fails the RMS check (a 0.01 N m rating fails them all);
    without a continuous rating there is no square."""
    axis = {"load_n": 50, "speed_mm_s": 50, "length_mm": 500, "lead_mm": 10,
            "stroke_mm": 200, "torque_safety_factor": 1.5}  # fmt: skip
    runs = {
        "flat": {"motor_curve": [[0, 0.9], [3000, 0.6]], "motor_rms_torque_nm": 0.3},
        "zone": {"motor": "yaskawa-sgm7j-01a", "speed_mm_s": 900, "lead_mm": None},
        "too small": {"motor_curve": [[0, 0.9], [3000, 0.6]], "motor_rms_torque_nm": 0.01},
        "no rating": {"motor_curve": [[0, 0.9], [3000, 0.6]]},
    }
    for name, extra in runs.items():
        inputs = ApplicationIn.model_validate({**axis, **extra})
        result = run_selection(inputs, catalog)
        shown, _ = chart_candidates(result)
        data = result_figures(result, METRIC, catalog)["motor"]["data"]
        line = [t for t in data if t["name"].startswith("Continuous")]
        squares = 0
        for c in shown[:TOP]:
            trace = next(t for t in data if t["name"] == c.id)
            at = [i for i, s in enumerate(trace["marker"]["symbol"]) if s == "square"]
            if not line:
                assert at == []
                continue
            (i,) = at
            check = next(k for k in c.checks if k.name == "motor_rms")
            assert check.unit == "N m" and trace["x"][i] == line[0]["x"][0] == 0.0
            assert trace["y"][i] == pytest.approx(check.value, rel=1e-9)
            assert check.limit == pytest.approx(line[0]["y"][0], rel=1e-12)
            assert (trace["y"][i] > line[0]["y"][0]) == (not check.passed)
            if name == "flat":
                assert check.value == pytest.approx(1.5 * c.torque.rms_nm, rel=1e-9)
            if name == "too small":
                assert not check.passed
            squares += 1
        assert squares == (0 if name == "no rating" else min(TOP, len(shown)))
    zone = run_selection(ApplicationIn.model_validate({**axis, **runs["zone"]}), catalog)
    scaled = [c for c in [*zone.candidates, *zone.rejected] if c.segments]
    assert any(
        next(k for k in c.checks if k.name == "motor_rms").value > 1.5 * c.torque.rms_nm * 1.01
        for c in scaled
    ), "the zone run reaches where the continuous zone narrows"
