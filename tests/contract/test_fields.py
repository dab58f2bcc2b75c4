"""The field table (app/contract/fields.py) is the one declaration of every application input.

Checked here: it maps the core's Application field for field; the API model, the page
form, the share links, the printed summary and the CSV are generated from it; the page
reads number text exactly as the API's query string does; and outside the core no input
name is spelled in more than three files (issue 9).
"""

import csv
import dataclasses
import io
import math
import re
from pathlib import Path
from typing import Any, get_args
from urllib.parse import parse_qsl

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import BaseModel, ValidationError

import app.contract.schemas
import app.contract.sections
from app.catalog import Catalog
from app.contract.exact import link_number, page_value, read_number
from app.contract.fields import BY_API, BY_PAGE, FIELDS
from app.contract.form import parse_inputs, parse_units
from app.contract.input_field import GROUPS, InputField
from app.contract.inputs import ApplicationIn
from app.contract.move_table import ADD_MOVE, REMOVE_MOVE, is_cell
from app.contract.share_link import share_query
from app.contract.units import (
    ACCEL_UNITS,
    DEFAULT_UNITS,
    FORCE_UNITS,
    LENGTH_UNITS,
    TORQUE_UNITS,
)
from app.core import motion
from app.core.model import Application
from app.report.service import run_selection
from app.web.export import results_csv
from tests.motor_library import MOTORS

ROOT = Path(__file__).resolve().parents[2]
#: the first group, always open: the load and its direction, the moving mass and the
#: orientation beside the screw's lead, speed and length.
UP_FRONT = ["load", "load_direction", "moving_mass_kg", "orientation", "lead", "speed", "length"]
#: every input of the motor, in one group.
MOTOR_INPUTS = {
    "motor", "max_torque", "motor_curve", "motor_rms_torque", "motor_inertia", "step_angle",
    "microsteps", "max_step_rate", "motor_supply", "motor_phase_current",
    "motor_resistance", "motor_inductance", "motor_holding_torque",
}  # fmt: skip
REQUIRED = {"load_n": 100.0, "speed_mm_s": 50.0, "length_mm": 500.0}
SCANNED = ("app", "templates", "static")
#: third-party bundles, the SI core and the catalog are not the project's edge code (the
#: catalog sits below the contract and names its own values: a provenance key such as
#: ``nut_length`` is a catalog field's name, not the input's); a move of the cycle is a
#: model of its own whose fields share the scalar inputs' names by design (a move has its
#: own speed, mass and load: app/contract/cycle.py).
NOT_SCANNED = (
    ROOT / "app" / "core",
    ROOT / "app" / "catalog",
    ROOT / "static" / "vendor",
    ROOT / "app" / "contract" / "cycle.py",
)
MAX_FILES = 3
#: the form's templates are generated from the table and name no input at all.
FORM_TEMPLATES = ("form.html", "fields.html", "inputs.html", "fixity.html")


# --- the table against the core and the API model -------------------------------------


def test_each_core_attribute_is_mapped_once() -> None:
    # the cycle's moves are a list of their own model (app/contract/cycle.py), not a row
    core = [f.name for f in dataclasses.fields(Application) if f.name != "moves"]
    assert sorted(field.core for field in FIELDS) == sorted(core)
    assert len(BY_API) == len(BY_PAGE) == len(FIELDS) == len(core)


def test_share_link_names_are_plain_distinct_query_names() -> None:
    """Each input's share-link name is its own (not another field's, not a unit switch's)
    and survives a URL unescaped."""
    names = [field.page for field in FIELDS]
    assert len(set(names)) == len(names)
    assert not set(names) & set(DEFAULT_UNITS)
    assert all(re.fullmatch(r"[a-z][a-z0-9_]*", name) for name in names), names


def test_the_form_asks_in_the_order_of_thought() -> None:
    assert [field.page for field in FIELDS if field.group == GROUPS[0]] == UP_FRONT
    assert {BY_PAGE[name].group for name in MOTOR_INPUTS} == {"Motor and move"}
    groups = [field.group for field in FIELDS]
    assert sorted(groups, key=GROUPS.index) == groups  # each group's fields together


def test_groups_are_the_forms_and_every_field_has_one() -> None:
    assert {field.group for field in FIELDS} == set(GROUPS)
    assert all(field.label and field.help for field in FIELDS)


def test_api_model_fields_are_the_tables() -> None:
    model = ApplicationIn.model_fields
    # the table's fields, and the cycle's moves (their own model, app/contract/cycle.py)
    assert list(model) == ["moves", *(field.api for field in FIELDS)]
    for field in FIELDS:
        assert model[field.api].is_required() == field.required, field.api
        if not field.required:
            assert model[field.api].default == field.default, field.api
    schema = ApplicationIn.model_json_schema()
    assert sorted(schema["required"]) == sorted(REQUIRED)
    assert schema["additionalProperties"] is False


@pytest.mark.parametrize("field", [f for f in FIELDS if f.bounds], ids=lambda f: f.api)
def test_bounds_are_enforced_by_the_api_model(field: InputField) -> None:
    low, high = field.bounds or (0.0, 0.0)
    # the shortest stroke, fewest cycles and hardest ramps on the longest screw, so that
    # the rules across fields (the stroke and the nut on the screw, the cycles a day holds)
    # hold at every bound: each field's own bounds alone are judged here
    duty = {"stroke_mm": 0.01, "cycles_per_day": 1e-3, "length_mm": 1e5, "accel_mm_s2": 1e6}
    duty |= {"step_angle_deg": 1.8}
    if field.api == "hours_per_day":
        del duty["cycles_per_day"]  # the hours are the duty in the cycles' place
    duty |= {"motor_supply_v": 400.0, "motor_phase_current_a": 1.0}
    duty |= {"motor_resistance_ohm": 1.0, "motor_inductance_mh": 1.0}
    for value, valid in ((low, True), (high, True), (high * 2 + 1, False)):
        # the longest screw, so that a span from its thrust bearing to the nut lies on it
        data = {**REQUIRED, **duty, "length_mm": 1e5, field.api: value}
        try:
            ApplicationIn.model_validate(data)
            refused: list[str] = []
        except ValidationError as exc:
            refused = [str(error["loc"][0]) for error in exc.errors()]
        assert refused == ([] if valid else [field.api]), (field.api, value)


def test_choices_are_the_cores_literals() -> None:
    properties = ApplicationIn.model_json_schema()["properties"]
    for field in (f for f in FIELDS if f.kind == "choice"):
        values = [choice.value for choice in field.choices]
        assert values == list(get_args(field.options)), field.api
        assert properties[field.api]["enum"] == values, field.api


def test_choice_texts_must_match_the_literal() -> None:
    orientation = BY_API["orientation"]
    with pytest.raises(ValueError, match="do not match"):
        dataclasses.replace(orientation, texts={"horizontal": "Flat"})
    with pytest.raises(ValueError, match="do not match"):
        dataclasses.replace(orientation, texts={**orientation.texts, "diagonal": "Diagonal"})
    with pytest.raises(ValueError, match="needs bounds"):
        dataclasses.replace(BY_API["ambient_c"], bounds=None)


def test_every_default_round_trips_to_the_core() -> None:
    """Defaults through ApplicationIn and to_core equal the core's own defaults in SI."""
    core = ApplicationIn.model_validate(REQUIRED).to_core(MOTORS)
    core_defaults = {f.name: f.default for f in dataclasses.fields(Application)}
    for field in FIELDS:
        if field.required:
            continue
        value = getattr(core, field.core)
        assert value == pytest.approx(field.to_si(field.default)), field.api
        assert value == pytest.approx(core_defaults[field.core]), field.api


def test_to_core_converts_api_units_to_si() -> None:
    data = {**REQUIRED, "lead_mm": 10.0, "accel_mm_s2": 2000.0, "stroke_mm": 300.0}
    core = ApplicationIn.model_validate({**data, "positioning_tolerance_mm": 0.05}).to_core(MOTORS)
    assert (core.load_n, core.speed_m_s, core.length_m) == pytest.approx((100.0, 0.05, 0.5))
    assert (core.lead_m, core.accel_m_s2, core.stroke_m) == pytest.approx((0.01, 2.0, 0.3))
    assert core.positioning_tolerance_m == pytest.approx(5e-5)


def test_required_life_needs_the_duty() -> None:
    with pytest.raises(ValueError, match="needs stroke_mm"):
        ApplicationIn.model_validate({**REQUIRED, "required_life_years": 3})
    with pytest.raises(ValueError, match="needs cycles_per_day or hours_per_day"):
        ApplicationIn.model_validate({**REQUIRED, "stroke_mm": 100, "required_life_years": 3})
    duty = {"stroke_mm": 100, "cycles_per_day": 10, "required_life_years": 3}
    assert (
        ApplicationIn.model_validate({**REQUIRED, **duty}).to_core(MOTORS).required_life_years == 3
    )
    hours = {"stroke_mm": 100, "hours_per_day": 8, "required_life_years": 3}
    assert ApplicationIn.model_validate({**REQUIRED, **hours}).to_core(MOTORS).hours_per_day == 8


def test_a_dwell_needs_a_stroke_or_moves_unless_it_is_none() -> None:
    """A dwell is the rest after each move: without a stroke or moves there is no move,
    and a dwell given is refused rather than read as nothing; 0, the default, is none."""
    with pytest.raises(ValueError, match="needs stroke_mm"):
        ApplicationIn.model_validate({**REQUIRED, "dwell_s": 1})
    assert ApplicationIn.model_validate({**REQUIRED, "dwell_s": 0}).dwell_s == 0
    moves = "100:50:500;-100:50:500"
    given = ApplicationIn.model_validate({**REQUIRED, "dwell_s": 1, "moves": moves})
    assert [m.dwell_s for m in given.to_core(MOTORS).moves] == [1.0, 1.0]


def test_the_duty_is_cycles_or_hours_never_both() -> None:
    """Both given could disagree: a field-level error on the hours."""
    both = {"stroke_mm": 100, "cycles_per_day": 10, "hours_per_day": 8}
    with pytest.raises(ValidationError) as refused:
        ApplicationIn.model_validate({**REQUIRED, **both})
    assert [e["loc"][0] for e in refused.value.errors()] == ["hours_per_day"]
    assert "not both" in refused.value.errors()[0]["msg"]


# --- the page form ----------------------------------------------------------------------


def test_form_renders_one_control_per_field(client: TestClient) -> None:
    form = BeautifulSoup(client.get("/").text, "html.parser").select_one("form#selector")
    assert form is not None
    for field in FIELDS:
        assert len(form.select(f"#w-{field.page}")) == 1, field.page
        controls = form.select(f"[name={field.page}]")
        if field.drawn:
            assert [c["value"] for c in controls] == [c.value for c in field.choices]
        else:
            assert len(controls) == 1 and controls[0]["id"] == f"f-{field.page}", field.page
        assert form.select_one(f"#h-{field.page}").text == field.help, field.page
    named = {str(c["name"]) for c in form.select("[name]")}
    # besides the fields and units: the table of moves' cells and buttons (move_table)
    table = {n for n in named if is_cell(n) or n in (ADD_MOVE, REMOVE_MOVE)}
    assert {n for n in named if not n.endswith("_unit")} - table == set(BY_PAGE)


def test_form_groups_follow_the_table(client: TestClient) -> None:
    form = BeautifulSoup(client.get("/").text, "html.parser").select_one("form#selector")
    assert form is not None
    legends = [legend.text for legend in form.select("legend")]
    for group in GROUPS:
        members = [f for f in FIELDS if f.group == group]
        expected = members[0].label if members[0].drawn else group
        assert expected in legends, group


def test_form_units_follow_the_display_units(client: TestClient) -> None:
    page = BeautifulSoup(client.get("/?length_unit=in").text, "html.parser")
    assert page.select_one("#w-speed .unit").text == "in/s"
    assert page.select_one("#w-moving_mass_kg .unit").text == "kg"
    # inches bring °F: the default 20 °C is 20 x 1.8 + 32 = 68 °F (NIST SP 811 B.9)
    assert page.select_one("#w-ambient_c .unit").text == "°F"
    assert page.select_one("#f-ambient_c")["placeholder"] == "68"
    assert page.select_one("#f-lead")["placeholder"] == "any"


def test_inputs_summary_shows_required_and_changed_inputs(client: TestClient) -> None:
    params = {"load": "100", "speed": "2", "length": "20", "force_unit": "lbf"}
    params |= {"length_unit": "in", "ambient_c": "40", "rank_by": "life"}
    page = BeautifulSoup(client.get("/", params=params).text, "html.parser")
    rows = {
        row.select_one("dt").text: row.select_one("dd").text for row in page.select("dl.inputs div")
    }
    assert rows == {
        "Axial load": "100 lbf",
        "Linear speed": "2 in/s",
        "Screw length": "20 in",
        "Ambient temperature": "40 °F",  # typed in °F with inches
        "Rank by": "Longest life",
    }


# --- share links ------------------------------------------------------------------------


def _six_figures(low: float, high: float) -> st.SearchStrategy[float]:
    """Numbers in [low, high] as a share link writes them (6 significant figures)."""
    return st.floats(low, high).map(lambda x: float(f"{x:.6g}")).filter(lambda x: low <= x <= high)


def _value(field: InputField) -> st.SearchStrategy[Any]:
    """Any valid API value of one table field."""
    if field.kind == "yes-no":
        return st.booleans()
    if field.kind == "choice":
        return st.sampled_from([choice.value for choice in field.choices])
    if field.api == "motor":
        return st.none() | st.sampled_from(sorted(MOTORS))
    if field.kind == "text":
        return st.none() | st.sampled_from(["bronze", "acetal", "PTFE-filled polymer"])
    if field.kind == "list":
        ids = st.sampled_from(["TR-C45", "TR-304", "B", "ZBX"])
        return st.none() | st.lists(ids, min_size=1, max_size=3)
    if field.kind == "curve":
        speeds = st.lists(st.integers(0, 6000), min_size=2, max_size=5, unique=True)
        torques = st.floats(0.01, 5.0).map(lambda x: float(f"{x:.4g}"))
        return st.none() | speeds.flatmap(
            lambda rpm: st.lists(torques, min_size=len(rpm), max_size=len(rpm)).map(
                lambda t: [[float(r), y] for r, y in zip(sorted(rpm), t, strict=True)]
            )
        )
    low, high = field.bounds or (0.0, 0.0)
    if field.kind == "whole number":
        return st.integers(int(low), int(high))
    number = _six_figures(low, high)
    return number if field.required or field.default is not None else st.none() | number


#: each field's strategy, built once: a strategy built anew for every draw is validated
#: anew by hypothesis each time, which was half the cost of an example
VALUES = {field.api: _value(field) for field in FIELDS}


@st.composite
def valid_inputs(draw: st.DrawFn) -> ApplicationIn:
    """Valid inputs over the whole table; a field with ``needs`` only with them (else at
    its default)."""
    data = {field.api: draw(VALUES[field.api]) for field in FIELDS}
    if (data["nut_length_mm"] or 0.0) > data["length_mm"]:
        data["nut_length_mm"] = None  # the nut lies on the screw
    if data["stroke_mm"] is not None:  # the nut travels between the screw's ends
        room = data["length_mm"] - (data["nut_length_mm"] or 0.0)
        data["stroke_mm"] = data["stroke_mm"] if data["stroke_mm"] <= room else None
    axis = Application(**{f.core: f.to_si(data[f.api]) for f in FIELDS})
    p = motion.move_profile(axis)
    if p is not None and (data["cycles_per_day"] or 0.0) * p.cycle_time_s > 86400.0:
        data["cycles_per_day"] = None  # more cycles than a day holds
    for field in FIELDS:
        if any(data[name] is None for name in field.needs):
            data[field.api] = field.default  # none given (a dwell's 0)
    if data["cycles_per_day"] is not None:
        data["hours_per_day"] = None  # the duty is cycles or hours a day, not both
    if data["cycles_per_day"] is None and data["hours_per_day"] is None:
        data["required_life_years"] = None  # a required life needs a duty
    if (data["bearing_to_nut_mm"] or 0.0) > data["length_mm"]:
        data["bearing_to_nut_mm"] = None  # the span from the thrust bearing lies on the screw
    if (data["bearing_to_nut_mm"] or math.inf) < (data["stroke_mm"] or 0.0):
        data["bearing_to_nut_mm"] = None  # and is at least the nut's travel
    if data["step_angle_deg"] is None and data["motor"] is None:
        data["max_step_rate_hz"] = None  # a step rate limit needs a step angle
    if data["motor_holding_torque_nm"] is not None:
        # the drive must exceed the winding's I R (else a 422 on the holding torque)
        resistive_v = data["motor_phase_current_a"] * data["motor_resistance_ohm"]
        if data["motor_supply_v"] <= resistive_v:
            data["motor_holding_torque_nm"] = None
    return ApplicationIn.model_validate(data)


@settings(max_examples=150, deadline=None)
@given(valid_inputs())
def test_share_links_round_trip(inputs: ApplicationIn) -> None:
    params = dict(parse_qsl(share_query(inputs)))
    parsed, errors = parse_inputs(params, parse_units(params))
    assert errors == {}
    assert parsed is not None and parsed.model_dump() == inputs.model_dump()


@settings(max_examples=100, deadline=None)
@given(
    valid_inputs(),
    st.fixed_dictionaries(
        {
            "force_unit": st.sampled_from(list(FORCE_UNITS)),
            "length_unit": st.sampled_from(list(LENGTH_UNITS)),
            "torque_unit": st.sampled_from(list(TORQUE_UNITS)),
            "accel_unit": st.sampled_from(list(ACCEL_UNITS)),
        }
    ),
)
def test_share_links_round_trip_in_display_units(
    inputs: ApplicationIn, units: dict[str, str]
) -> None:
    """In any units the link reproduces the inputs exactly (the page reads a number as the
    decimal times the unit's factor, rounded once, and the link writes enough figures)."""
    params = dict(parse_qsl(share_query(inputs, units)))
    assert parse_units(params) == units
    parsed, errors = parse_inputs(params, units)
    assert errors == {}
    assert parsed is not None and parsed.model_dump() == inputs.model_dump()


@pytest.mark.parametrize(
    ("api", "value", "units"),
    [
        ("length_mm", 100000.0, {"length_unit": "in"}),  # 3937.0078 in: 6 figures exceed it
        ("load_n", 100.4824, {"force_unit": "lbf"}),
        ("load_n", 1e6, {"force_unit": "kgf"}),
        ("speed_mm_s", 1e-3, {"length_unit": "in"}),
        ("moving_mass_kg", 12.3456789, {"force_unit": "lbf"}),
    ],
    ids=["length-at-bound-in", "load-lbf", "load-bound-kgf", "speed-bound-in", "mass-lb"],
)
def test_a_link_number_reads_back_exactly(api: str, value: float, units: dict[str, str]) -> None:
    field = BY_API[api]
    shown = {**DEFAULT_UNITS, **units}
    assert page_value(field, link_number(field, value, shown), shown) == value


# --- CSV export --------------------------------------------------------------------------


def test_csv_rows_carry_the_inputs_in_display_units(catalog: Catalog) -> None:
    inputs = ApplicationIn.model_validate({**REQUIRED, "lead_mm": 10.0, "ambient_c": 35.0})
    units = {**DEFAULT_UNITS, "force_unit": "lbf", "length_unit": "in"}
    rows = list(csv.reader(io.StringIO(results_csv(run_selection(inputs, catalog), units))))
    header, first = rows[0], rows[1]
    assert header[:3] == ["status", "rank", "id"]
    columns = [
        (i, h.removeprefix("input:")) for i, h in enumerate(header) if h.startswith("input:")
    ]
    assert [h.split(" [")[0] for _, h in columns] == [field.page for field in FIELDS]
    by_name = {h.split(" [")[0]: (first[i], h.partition(" [")[2].rstrip("]")) for i, h in columns}
    assert float(by_name["load"][0]) == pytest.approx(100 / 4.4482216152605)
    assert by_name["load"][1] == "lbf"
    assert float(by_name["speed"][0]) == pytest.approx(50 / 25.4)
    assert by_name["speed"][1] == "in/s"
    assert by_name["ambient_c"] == ("95.0", "°F")  # 35 °C x 1.8 + 32 (NIST SP 811 B.9)
    assert by_name["stroke"] == ("", "in")
    assert by_name["end_fixity"] == ("fixed-simple", "")


# --- one number parser for the page and the API -----------------------------------------

NUMBER_TEXTS = [
    "100", "+100", "-5", "1e2", "1E+2", ".5", "5.", "  250 ", "0.001",
    "１００", "١٠٠", "1_000", "nan", "NaN", "inf", "-Infinity", "1e400", "0x10",
    "", "12x", "e5", ".", "+", "1e", "1.2.3",
]  # fmt: skip


def _page_accepts(text: str) -> bool:
    _, errors = parse_inputs({"load": text, "speed": "50", "length": "500"}, DEFAULT_UNITS)
    return "load" not in errors


def _api_accepts(client: TestClient, text: str) -> bool:
    params = {"load_n": text, "speed_mm_s": "50", "length_mm": "500"}
    response = client.get("/api/v1/select", params=params)
    assert response.status_code in (200, 422), response.text
    return response.status_code == 200 or not any(
        d["field"] == "load_n" for d in response.json()["detail"]
    )


@pytest.mark.parametrize("text", NUMBER_TEXTS)
def test_page_and_api_accept_the_same_number_text(client: TestClient, text: str) -> None:
    assert _page_accepts(text) == _api_accepts(client, text)


def test_number_text_is_ascii_decimal_only() -> None:
    assert read_number("250") == (250.0, "")
    assert read_number("-2.5e-3") == (-0.0025, "")
    for text in ("１００", "١٠٠", "1_000", "nan", "inf", "0x10", "12x"):
        assert read_number(text) == (None, "Enter a number."), text
    assert read_number("1e400") == (None, "Enter a finite number.")


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet="0123456789１٠.eE+-_ naif", max_size=8))
def test_page_and_api_agree_on_any_number_text(client: TestClient, text: str) -> None:
    """Wherever a number text comes from, the page and the API query agree on it."""
    if text.strip() == "":
        return  # an empty page field means "not given"; the API gets no such parameter
    assert _page_accepts(text) == _api_accepts(client, text), repr(text)


# --- issue 9: each pure input is spelled in at most three files ------------------------


def _output_field_names() -> set[str]:
    """Field names of the API's output models (…Out): an input name that is also one of
    these is spelled by the output side for the output's own meaning."""
    spaces = (vars(app.contract.schemas), vars(app.contract.sections))
    models = [m for space in spaces for m in space.values() if isinstance(m, type)]
    outputs = [m for m in models if issubclass(m, BaseModel) and m.__name__.endswith("Out")]
    return {name for model in outputs for name in model.model_fields}


def _is_pure(name: str) -> bool:
    """A pure input name names nothing else: not one English word (load, limit, stroke
    are prose, CSS and other quantities too) and not the name of an output field."""
    return "_" in name and name not in _output_field_names()


def _scanned_files() -> dict[Path, str]:
    files = (
        path
        for folder in SCANNED
        for path in (ROOT / folder).rglob("*")
        if path.is_file() and "__pycache__" not in path.parts
    )
    return {
        path: path.read_text(encoding="utf-8", errors="ignore")
        for path in files
        if not any(path.is_relative_to(skip) for skip in NOT_SCANNED)
    }


def spelling_files(name: str, texts: dict[Path, str]) -> list[str]:
    """Files that spell ``name`` as a whole identifier."""
    pattern = re.compile(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])")
    return sorted(str(p.relative_to(ROOT)) for p, text in texts.items() if pattern.search(text))


def test_each_pure_input_is_spelled_in_at_most_three_files() -> None:
    texts = _scanned_files()
    names = sorted({name for f in FIELDS for name in (f.api, f.page) if _is_pure(name)})
    assert {"moving_mass_kg", "rank_by", "ambient_c", "load_n", "speed_mm_s"} <= set(names)
    spelled = {name: spelling_files(name, texts) for name in names}
    for name, files in spelled.items():
        assert "app/contract/fields.py" in files, name
        assert len(files) <= MAX_FILES, (name, files)


def test_form_templates_name_no_input() -> None:
    texts = {ROOT / "templates" / "partials" / n: "" for n in FORM_TEMPLATES}
    texts = {path: path.read_text(encoding="utf-8") for path in texts}
    names = {name for f in FIELDS for name in (f.api, f.page)}
    for name in names:
        assert not spelling_files(name, texts), name
