"""Contract tests of the JSON API under /api/v1, against the API contract issue (issue 4).

Every response these tests see passes through ``Api``, which fails on a 5xx and on any
non-finite number in a JSON body: the contract says "never a 500, never a non-finite
number in a response" for every request, valid or not.
"""

import json
import math
from collections.abc import Iterator
from typing import Any, get_args

import httpx
import pytest
from bs4 import BeautifulSoup
from fastapi import FastAPI
from fastapi.testclient import TestClient
from pydantic import BaseModel

from app.catalog import Catalog
from app.contract.fields import BY_API, FIELDS
from app.contract.input_types import describe
from app.contract.inputs import ApplicationIn
from app.contract.outputs import EvaluateOut, SelectOut, SeriesListOut, SeriesOut
from app.core.model import ProvenanceKind
from tests.builtin_catalog import builtin_catalog
from tests.leadscrews import leadscrew_families

API = "/api/v1"
#: The select response in its full form (every number, message and formula).
FULL = {"detail": "full"}
BASE = {"load_n": 100.0, "speed_mm_s": 50.0, "length_mm": 500.0}
CATALOG_SCREW = "ZBX8000-L10"
SERIES_IDS = sorted(builtin_catalog().series)
PROVENANCE_KINDS = set(get_args(ProvenanceKind))

#: Defaults of the optional application fields, as the issue states them.
ISSUE_DEFAULTS: dict[str, Any] = {
    "lead_mm": None,
    "accel_mm_s2": 1000.0,
    "moving_mass_kg": 0.0,
    "end_fixity": "fixed-simple",
    "orientation": "horizontal",
    "compression": True,
    "require_anti_backlash": False,
    "coating": "auto",
    "oil_present": False,
    "vacuum": False,
    "ambient_c": 20.0,
    "stroke_mm": None,
    "cycles_per_day": None,
    "critical_speed_safety_factor": 0.8,
    "buckling_safety_factor": 0.5,
    "torque_safety_factor": 1.0,
    "rank_by": "torque",
    "limit": 10,
}
#: Custom screw fields of evaluate with their defaults (required ones map to ...).
ISSUE_CUSTOM_SCREW: dict[str, Any] = {
    "outer_diameter_mm": ...,
    "root_diameter_mm": ...,
    "lead_mm": ...,
    "thread_half_angle_deg": 14.5,
    "friction_dynamic": ...,
    "friction_static": ...,
    "material": "steel",
    "drag_torque_nm": 0.0,
    "inertia_kg_m2_per_m": None,
    "pv_limit_mpa_m_s": None,
}

# The fields every candidate carries "at least" (issue 4), by JSON type.
NUMBER, BOOL, TEXT = "number", "bool", "text"
CANDIDATE_FIELDS = {
    "id": TEXT,
    "series": TEXT,
    "outer_diameter_mm": NUMBER,
    "root_diameter_mm": NUMBER,
    "lead_mm": NUMBER,
    "coated": BOOL,
    "rpm": NUMBER,
    "efficiency": NUMBER,
    "backdrive_efficiency": NUMBER,
    "self_locking": BOOL,
    "traverse_speed_limit_mm_s": NUMBER,
    "passed": BOOL,
}
CANDIDATE_GROUPS = {
    "torque": ("inertia_nm", "drag_nm", "load_nm", "total_nm", "breakaway_nm"),
    "critical_speed": ("theoretical_rpm", "allowed_rpm"),
    "buckling": ("critical_load_n", "allowed_load_n"),
    "pv": ("value_mpa_m_s", "limit_mpa_m_s"),
}
CHECK_FIELDS = {
    "name": TEXT,
    "passed": BOOL,
    "value": NUMBER,
    "limit": NUMBER,
    "unit": TEXT,
    "utilization": NUMBER,
    "message": TEXT,
}
# a family without a traverse-speed table (a custom screw) has no traverse limit
#: a ball nut, and a standard thread's nut judged on its flanks, have no seed PV: "pv" null
NULLABLE = {"value", "limit", "utilization", "limit_mpa_m_s", "traverse_speed_limit_mm_s", "pv"}

CUSTOM_SCREW: dict[str, Any] = {
    "outer_diameter_mm": 12.7,
    "root_diameter_mm": 9.906,
    "lead_mm": 10.0,
    "friction_dynamic": 0.15,
    "friction_static": 0.2,
}


# --- helpers ---------------------------------------------------------------------------


def non_finite(value: Any, path: str = "$") -> Iterator[str]:
    """JSON paths of every NaN or infinity in a parsed JSON document."""
    if isinstance(value, float) and not math.isfinite(value):
        yield f"{path} = {value}"
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from non_finite(item, f"{path}.{key}")
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from non_finite(item, f"{path}[{index}]")


def test_non_finite_walk_finds_nested_values() -> None:
    doc = json.loads('{"a": [1.0, {"b": NaN}], "c": Infinity, "d": -Infinity, "e": 1e308}')
    assert list(non_finite(doc)) == ["$.a[1].b = nan", "$.c = inf", "$.d = -inf"]


class Api:
    """A test client that fails on any 5xx or non-finite JSON number it receives."""

    def __init__(self, client: TestClient) -> None:
        self.client = client

    def request(self, method: str, url: str, **kwargs: Any) -> httpx.Response:
        response = self.client.request(method, url, **kwargs)
        where = f"{method} {url} {kwargs}"[:400]
        assert response.status_code < 500, f"{where} -> {response.status_code} {response.text}"
        if response.headers.get("content-type", "").startswith("application/json"):
            bad = list(non_finite(json.loads(response.text)))
            assert not bad, f"{where}: non-finite numbers in the response: {bad[:10]}"
        return response

    def get(self, url: str, **kwargs: Any) -> httpx.Response:
        return self.request("GET", url, **kwargs)

    def post(self, url: str, **kwargs: Any) -> httpx.Response:
        return self.request("POST", url, **kwargs)

    def post_raw(
        self, url: str, body: str, content_type: str = "application/json"
    ) -> httpx.Response:
        """POST a body as written, e.g. with NaN literals that httpx's json= refuses."""
        return self.post(url, content=body.encode(), headers={"content-type": content_type})


@pytest.fixture(scope="module")
def api(app: FastAPI) -> Iterator[Api]:
    with TestClient(app, raise_server_exceptions=False) as client:
        yield Api(client)


def ok(response: httpx.Response, model: type[BaseModel] | None = None) -> Any:
    """The JSON body of a 200 response, validated against the documented output model."""
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "application/json"
    body = response.json()
    if model is not None:
        model.model_validate(body)
    return body


def assert_error(response: httpx.Response, status: int, field: str) -> list[dict[str, str]]:
    """A 4xx with {"error": str, "detail": [{"field", "message"}]} naming ``field``."""
    assert response.status_code == status, response.text
    assert response.headers["content-type"] == "application/json", response.headers
    body = response.json()
    assert set(body) == {"error", "detail"}, body
    assert isinstance(body["error"], str) and body["error"]
    detail = body["detail"]
    assert isinstance(detail, list) and detail, body
    for item in detail:
        assert set(item) == {"field", "message"}, item
        assert isinstance(item["field"], str) and item["field"], item
        assert isinstance(item["message"], str) and item["message"], item
    assert field in [item["field"] for item in detail], detail
    return detail


def is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def assert_type(value: Any, kind: str, where: str, nullable: bool = False) -> None:
    if value is None:
        assert nullable, f"{where} is null"
        return
    expected = {
        NUMBER: is_number,
        BOOL: lambda v: isinstance(v, bool),
        TEXT: lambda v: isinstance(v, str),
    }
    assert expected[kind](value), f"{where} = {value!r} is not a {kind}"


def assert_candidate(candidate: dict[str, Any]) -> None:
    """Every field the issue lists for a candidate, with its JSON type."""
    name = candidate.get("id", "?")
    for field, kind in CANDIDATE_FIELDS.items():
        assert field in candidate, f"{name}: no {field}"
        assert_type(candidate[field], kind, f"{name}.{field}", field in NULLABLE)
    for group, fields in CANDIDATE_GROUPS.items():
        if candidate[group] is None:
            assert group in NULLABLE, f"{name}.{group} is null"
            continue
        for field in fields:
            assert field in candidate[group], f"{name}: no {group}.{field}"
            assert_type(
                candidate[group][field], NUMBER, f"{name}.{group}.{field}", field in NULLABLE
            )
    assert candidate["checks"], f"{name}: no checks"
    for check in candidate["checks"]:
        for field, kind in CHECK_FIELDS.items():
            assert field in check, f"{name}: check without {field}: {check}"
            where = f"{name}.checks[{check['name']}].{field}"
            assert_type(check[field], kind, where, field in NULLABLE)
        if check["value"] is not None and check["limit"] is not None:
            # only yes/no checks go without a utilization, and a demand on a limit of 0
            # (unbounded: it fails); any other null hides a non-finite one
            unbounded = check["limit"] == 0 and check["value"] > 0
            assert check["utilization"] is not None or unbounded, f"{name}: {check}"
            assert not unbounded or not check["passed"], f"{name}: {check}"
    names = [c["name"] for c in candidate["checks"]]
    assert len(names) == len(set(names)), names
    assert "governing_check" in candidate
    assert candidate["governing_check"] is None or candidate["governing_check"] in names
    # a failed advice check only warns (advice "warn" by default): a ball screw in a vacuum
    # has no outgassing data, and passes with that warning
    assert candidate["passed"] == all(
        c["passed"] for c in candidate["checks"] if c["kind"] == "limit"
    )


def max_utilization(candidate: dict[str, Any]) -> float:
    """The worst utilisation of the limits (advice rejects nothing by default)."""
    used = [c["utilization"] for c in candidate["checks"] if c["kind"] == "limit"]
    return max(u for u in used if u is not None)


def shown_life(candidate: dict[str, Any]) -> float:
    """Low end of the life band shown [million cm], rated or wear; a nut with neither
    counts as 0."""
    life = candidate["life"]
    return 0.0 if life is None else float(life["travel_million_cm"][0])


_selections: dict[str, Any] = {}


def select(api: Api, **fields: Any) -> Any:
    """POST /select, validated against SelectOut; cached per input for the module."""
    key = json.dumps(fields, sort_keys=True)
    if key not in _selections:
        _selections[key] = ok(api.post(f"{API}/select", json=fields, params=FULL), SelectOut)
    return _selections[key]


def evaluate(api: Api, screw: dict[str, Any], **application: Any) -> Any:
    body = {"application": {**BASE, **application}, "screw": screw}
    return ok(api.post(f"{API}/evaluate", json=body), EvaluateOut)


def query(fields: dict[str, Any]) -> dict[str, str]:
    """Application fields as GET query parameters (booleans as true/false)."""
    text = {True: "true", False: "false"}
    return {k: text[v] if isinstance(v, bool) else str(v) for k, v in fields.items()}


# --- OpenAPI: the names other tools rely on ----------------------------------------------


@pytest.mark.parametrize(
    ("method", "path"),
    [
        ("get", "/api/v1/series"),
        ("get", "/api/v1/series/{series_id}"),
        ("post", "/api/v1/select"),
        ("get", "/api/v1/select"),
        ("post", "/api/v1/evaluate"),
    ],
    ids=lambda v: str(v),
)
def test_openapi_documents_endpoint_and_errors(api: Api, method: str, path: str) -> None:
    schema = ok(api.get("/openapi.json"))
    operation = schema["paths"][path][method]
    responses = operation["responses"]
    assert "200" in responses
    for status in ("404", "422"):
        content = responses[status]["content"]["application/json"]["schema"]
        assert content == {"$ref": "#/components/schemas/ErrorOut"}


def test_openapi_application_fields_and_defaults(api: Api) -> None:
    component = ok(api.get("/openapi.json"))["components"]["schemas"]["ApplicationIn"]
    properties = component["properties"]
    assert sorted(component["required"]) == ["length_mm", "load_n", "speed_mm_s"]
    for field, default in ISSUE_DEFAULTS.items():
        assert field in properties, field
        assert properties[field].get("default") == default, field
    assert component.get("additionalProperties") is False


def test_openapi_custom_screw_fields_and_defaults(api: Api) -> None:
    component = ok(api.get("/openapi.json"))["components"]["schemas"]["CustomScrewIn"]
    properties = component["properties"]
    required = sorted(k for k, v in ISSUE_CUSTOM_SCREW.items() if v is ...)
    assert sorted(component["required"]) == required
    for field, default in ISSUE_CUSTOM_SCREW.items():
        assert field in properties, field
        if default is not ...:
            assert properties[field].get("default") == default, field


def _number_schemas(node: object) -> list[dict[str, object]]:
    """Every schema of type number or integer anywhere under ``node``."""
    if isinstance(node, list):
        return [found for item in node for found in _number_schemas(item)]
    if not isinstance(node, dict):
        return []
    own = [node] if node.get("type") in ("number", "integer") else []
    return own + [found for value in node.values() for found in _number_schemas(value)]


def test_openapi_bounds_are_json_schema_minimum_and_maximum(api: Api) -> None:
    """JSON Schema names bounds minimum/maximum; pydantic's ge/le would be unknown keywords
    that clients and schemathesis ignore."""
    schema = ok(api.get("/openapi.json"))
    numbers = _number_schemas(schema)
    assert not [n for n in numbers if {"ge", "le", "gt", "lt"} & set(n)]
    properties = schema["components"]["schemas"]["ApplicationIn"]["properties"]
    for field in FIELDS:
        if field.kind in ("number", "whole number"):
            bounded = _number_schemas(properties[field.api])
            assert bounded, field.api
            low, high = field.bounds or (None, None)
            assert bounded[0].get("minimum") == low, field.api
            assert bounded[0].get("maximum") == high, field.api


def test_get_select_documents_every_query_parameter(api: Api) -> None:
    """Each parameter of GET /select carries its description (label, unit and help from
    the field table), optional ones included."""
    schema = ok(api.get("/openapi.json"))
    for parameter in schema["paths"]["/api/v1/select"]["get"]["parameters"]:
        if parameter["name"] == "detail":
            continue
        text = parameter.get("description") or parameter["schema"].get("description")
        if parameter["name"] == "moves":  # the cycle's moves: their own model, not a row
            assert text == ApplicationIn.model_fields["moves"].description
            continue
        assert text == describe(BY_API[parameter["name"]]), parameter["name"]


def test_get_select_query_parameters_are_the_application_fields(api: Api) -> None:
    schema = ok(api.get("/openapi.json"))
    names = {p["name"] for p in schema["paths"]["/api/v1/select"]["get"]["parameters"]}
    body = set(schema["components"]["schemas"]["ApplicationIn"]["properties"])
    assert names == body | {"detail"}


# --- GET /api/v1/series -----------------------------------------------------------------


def test_series_lists_every_catalog_series(api: Api, catalog: Catalog) -> None:
    body = ok(api.get(f"{API}/series"), SeriesListOut)
    assert [s["id"] for s in body["series"]] == list(catalog.series)
    assert body["catalog_version"] == catalog.version
    listed = {cid for s in body["series"] for cid in s["candidate_ids"]}
    assert listed == {screw.id for screw in catalog.screws}


@pytest.fixture(scope="module")
def listed_series(api: Api) -> dict[str, dict[str, Any]]:
    """GET /api/v1/series, validated against its model: each series' entry by its id (the
    first one of an id), read once for the tests of every series below."""
    entries: dict[str, dict[str, Any]] = {}
    for entry in ok(api.get(f"{API}/series"), SeriesListOut)["series"]:
        entries.setdefault(entry["id"], entry)
    return entries


@pytest.mark.parametrize("series_id", SERIES_IDS)
def test_series_every_field_has_value_unit_and_provenance(
    listed_series: dict[str, dict[str, Any]], series_id: str
) -> None:
    series = listed_series[series_id]
    for key in ("name", "family", "family_name", "type", "file"):
        assert isinstance(series[key], str) and series[key], key
    assert series["fields"], series_id
    for name, field in series["fields"].items():
        assert set(field) == {"value", "unit", "provenance"}, name
        assert isinstance(field["unit"], str), name
        assert field["provenance"]["kind"] in PROVENANCE_KINDS, name
        source = field["provenance"]["source"]
        assert isinstance(source, str) and source.strip(), f"{series_id}.{name}: no source"
    assert series["candidate_ids"], series_id


# --- GET /api/v1/series/{series_id} --------------------------------------------------------


@pytest.mark.parametrize("series_id", SERIES_IDS)
def test_series_by_id_is_the_listed_entry(
    api: Api, listed_series: dict[str, dict[str, Any]], series_id: str
) -> None:
    one = ok(api.get(f"{API}/series/{series_id}"), SeriesOut)
    assert one == listed_series[series_id]


@pytest.mark.parametrize(
    "series_id",
    ["NOPE", "zbx8000", "ZBX8000-L10", "ZBX8000 ", "x" * 300, "%E2%98%83", "ZBX8000;drop"],
    ids=["unknown", "wrong-case", "screw-id", "trailing-space", "long", "unicode", "semicolon"],
)
def test_series_unknown_id_is_404_naming_series_id(api: Api, series_id: str) -> None:
    detail = assert_error(api.get(f"{API}/series/{series_id}"), 404, "series_id")
    assert len(detail[0]["message"]) < 200


# --- POST and GET /api/v1/select --------------------------------------------------------------

SELECT_INPUTS = {
    "minimal": BASE,
    "lead-10": {**BASE, "lead_mm": 10.0},
    "non-defaults": {
        **BASE,
        "lead_mm": 12.7,
        "accel_mm_s2": 500.0,
        "moving_mass_kg": 3.0,
        "end_fixity": "fixed-fixed",
        "orientation": "horizontal",
        "compression": False,
        "require_anti_backlash": True,
        "coating": "tfe",
        "vacuum": True,
        "ambient_c": 35.0,
        "stroke_mm": 300.0,
        "cycles_per_day": 500.0,
        "critical_speed_safety_factor": 0.7,
        "buckling_safety_factor": 0.4,
        "torque_safety_factor": 1.5,
        "rank_by": "size",
        "limit": 4,
    },
    "nothing-passes": {"load_n": 5000.0, "speed_mm_s": 800.0, "length_mm": 2000.0},
}


@pytest.mark.parametrize("name", SELECT_INPUTS)
def test_select_get_and_post_give_the_same_result(api: Api, name: str) -> None:
    fields = SELECT_INPUTS[name]
    post = select(api, **fields)
    get = ok(api.get(f"{API}/select", params={**query(fields), **FULL}), SelectOut)
    assert get == post


@pytest.mark.parametrize("name", SELECT_INPUTS)
def test_select_is_deterministic(api: Api, name: str) -> None:
    fields = SELECT_INPUTS[name]
    assert ok(api.post(f"{API}/select", json=fields, params=FULL)) == select(api, **fields)


def test_select_echoes_inputs_with_the_issue_defaults(api: Api) -> None:
    inputs = select(api, **BASE)["inputs"]
    assert {k: inputs[k] for k in (*BASE, *ISSUE_DEFAULTS)} == {**BASE, **ISSUE_DEFAULTS}
    # fields beyond the issue's list echo the default of their row of the field table
    # (app/contract/fields.py), and the cycle's moves none (out and back over the stroke)
    later = {f.api: f.default for f in FIELDS if f.api not in ISSUE_DEFAULTS}
    later = {k: v for k, v in later.items() if v is not None} | {"moves": []}
    # the defaults with a published basis, not only the table's word: the thrust bearing's
    # static safety factor is THK's lower limit without vibration
    assert later["support_static_safety_factor"] == 2.0
    assert {k: inputs[k] for k in later} == later
    rest = set(inputs) - set(BASE) - set(ISSUE_DEFAULTS) - set(later)
    assert all(inputs[k] is None for k in rest)


def test_select_echoes_given_inputs(api: Api) -> None:
    fields = SELECT_INPUTS["non-defaults"]
    inputs = select(api, **fields)["inputs"]
    assert {k: inputs[k] for k in fields} == fields


@pytest.mark.parametrize("name", SELECT_INPUTS)
def test_select_response_shape_and_counts(api: Api, name: str, catalog: Catalog) -> None:
    body = select(api, **SELECT_INPUTS[name])
    limit = body["inputs"]["limit"]
    counts = body["counts"]
    assert counts["evaluated"] == counts["passed"] + counts["rejected"]
    assert len(body["candidates"]) == min(limit, counts["passed"])
    assert len(body["rejected"]) == min(limit, counts["rejected"])
    assert body["catalog_version"] == catalog.version
    assert body["share_url"].startswith("/?")
    failed = [
        c["name"]
        for r in body["rejected"]
        for c in r["checks"]
        if not c["passed"] and c["kind"] == "limit"
    ]
    assert set(failed) <= set(counts["failed_by_check"])


@pytest.mark.parametrize("name", SELECT_INPUTS)
def test_every_candidate_has_every_issue_field(api: Api, name: str) -> None:
    body = select(api, **SELECT_INPUTS[name])
    for candidate in body["candidates"] + body["rejected"]:
        assert_candidate(candidate)
    assert all(c["passed"] for c in body["candidates"])


@pytest.mark.parametrize("name", SELECT_INPUTS)
def test_rejected_carry_failed_checks_and_a_fix(api: Api, name: str) -> None:
    rejected = select(api, **SELECT_INPUTS[name])["rejected"]
    for candidate in rejected:
        failed = [c for c in candidate["checks"] if not c["passed"]]
        assert not candidate["passed"] and failed, candidate["id"]
        assert isinstance(candidate["fix"], str) and candidate["fix"].strip(), candidate["id"]
        assert candidate["governing_check"] in {c["name"] for c in failed}, candidate["id"]


def test_nothing_passes_still_answers_with_rejected(api: Api) -> None:
    # the leadscrews by name: a ball screw carries this axis
    lead = ",".join(leadscrew_families(builtin_catalog()))
    body = select(api, **SELECT_INPUTS["nothing-passes"], family=lead)
    assert body["candidates"] == [] and body["counts"]["passed"] == 0
    assert body["rejected"] and body["summary"]["best_rejected_id"] == body["rejected"][0]["id"]


def test_catalog_version_matches_health_and_series(api: Api) -> None:
    version = ok(api.get(f"{API}/health"))["catalog_version"]
    assert ok(api.get(f"{API}/series"))["catalog_version"] == version
    assert select(api, **BASE)["catalog_version"] == version


def _page_top_candidate(html: str) -> str | None:
    first = BeautifulSoup(html, "html.parser").select_one("table.candidates [data-id]")
    return None if first is None else str(first["data-id"])


@pytest.mark.parametrize("name", ["minimal", "lead-10", "non-defaults"])
def test_share_url_page_shows_the_same_top_candidate(api: Api, name: str) -> None:
    body = select(api, **SELECT_INPUTS[name])
    page = api.get(body["share_url"])
    assert page.status_code == 200, page.text
    assert page.headers["content-type"].startswith("text/html")
    assert body["candidates"], "need a passing candidate to compare"
    assert _page_top_candidate(page.text) == body["candidates"][0]["id"]


@pytest.mark.parametrize("lead_mm", [2.0, 10.0, 12.7, 25.4], ids=lambda v: f"lead-{v:g}")
def test_lead_limits_candidates_to_that_lead(api: Api, catalog: Catalog, lead_mm: float) -> None:
    body = select(api, **BASE, lead_mm=lead_mm, limit=100)
    # the core matches a lead within 0.5 % (12.7 mm and 12.5 mm are different leads)
    matching = [s for s in catalog.screws if abs(s.lead_m * 1e3 - lead_mm) <= 0.005 * lead_mm]
    assert matching
    assert body["counts"]["evaluated"] == len(matching)
    for candidate in body["candidates"] + body["rejected"]:
        assert math.isclose(candidate["lead_mm"], lead_mm, rel_tol=0.005), candidate["id"]


RANKINGS = {
    # rank_by: (sort key of a passing candidate, descending?)
    "torque": (lambda c: c["torque"]["total_nm"], False),
    "margin": (max_utilization, False),
    "life": (shown_life, True),
    "size": (lambda c: c["outer_diameter_mm"], False),
}


@pytest.mark.parametrize("lead", [None, 10.0], ids=["any-lead", "lead-10"])
@pytest.mark.parametrize("rank_by", RANKINGS)
def test_rank_by_orders_as_documented(api: Api, rank_by: str, lead: float | None) -> None:
    key, descending = RANKINGS[rank_by]
    body = select(api, **BASE, lead_mm=lead, rank_by=rank_by, limit=100)
    values = [key(c) for c in body["candidates"]]
    assert len(set(values)) > 1, "ordering is only tested when the key varies"
    # those with a warning (failed advice: a bronze nut run dry) come after the others,
    # each group in the policy's order
    warned = [bool(c["warned"]) for c in body["candidates"]]
    assert warned == sorted(warned)
    for group in (False, True):
        part = [v for v, w in zip(values, warned, strict=True) if w == group]
        assert part == sorted(part, reverse=descending)
    if body["counts"]["passed"] <= 100:
        # every passing candidate is listed, so the ranking is over all of them
        assert len(values) == body["counts"]["passed"]


def test_rank_by_changes_the_order(api: Api) -> None:
    orders = {
        rank_by: tuple(c["id"] for c in select(api, **BASE, rank_by=rank_by)["candidates"])
        for rank_by in RANKINGS
    }
    assert len(set(orders.values())) == len(RANKINGS), orders


@pytest.mark.parametrize("limit", [1, 3, 10, 100])
def test_limit_is_respected(api: Api, limit: int) -> None:
    body = select(api, **BASE, limit=limit)
    assert body["counts"]["passed"] > 3 and body["counts"]["rejected"] > 3
    assert len(body["candidates"]) == min(limit, body["counts"]["passed"])
    assert len(body["rejected"]) == min(limit, body["counts"]["rejected"])
    full = select(api, **BASE, limit=100)
    assert body["candidates"] == full["candidates"][:limit]


# --- POST /api/v1/evaluate --------------------------------------------------------------------


def test_evaluate_catalog_screw_matches_its_select_entry(api: Api) -> None:
    body = select(api, **BASE, lead_mm=10.0, limit=100)
    for entry in (body["candidates"][0], body["rejected"][0]):
        result = evaluate(api, {"catalog_id": entry["id"]}, lead_mm=10.0, limit=100)
        assert result["candidate"] == entry
        assert result["inputs"] == body["inputs"]
        assert result["catalog_version"] == body["catalog_version"]


def test_evaluate_catalog_screw_has_every_issue_field(api: Api) -> None:
    candidate = evaluate(api, {"catalog_id": CATALOG_SCREW})["candidate"]
    assert_candidate(candidate)
    assert candidate["id"] == CATALOG_SCREW and candidate["series"] == "ZBX8000"


#: one pound-force per square inch [Pa] (NIST SP 811)
PSI_PA = 6894.757293168
MATERIALS: dict[str, tuple[Any, float, float, str]] = {
    # request value: (value, E [Pa], rho [kg/m3], provenance kind of E)
    "steel": ("steel", 206e9, 7850.0, "handbook"),
    "stainless-303": ("stainless-303", 193e9, 8000.0, "handbook"),
    "custom": ({"youngs_modulus_pa": 110e9, "density_kg_m3": 8900.0}, 110e9, 8900.0, "user"),
}


@pytest.mark.parametrize("material", MATERIALS)
def test_evaluate_custom_screw_per_material(api: Api, material: str) -> None:
    """Critical speed and Euler load follow the material's E and rho.

    A leadscrew fixed-simple is rated as its makers rate it (Thomson, Roton): n_c = C_s
    n_ss, C_s = 1.47, with the simple-simple beam n_ss = 60 / (2 pi) (pi / L)^2 sqrt(E /
    rho) d_r / 4 (Blevins, Formulas for natural frequency and mode shape, table 8-1,
    beta = pi); F_cr = k pi^2 E (pi d_r^4 / 64) / L^2, k = 2 fixed-simple (Timoshenko &
    Gere), E at most its makers' column modulus: steel's 206 GPa Thomson's and Nook's
    14.03e6 F_c d^4 / L^2 [lb, in], 199.7 GPa; 303's 193 GPa W.M. Berg's 13.4e6 K d^4 /
    D^2 for stainless, 190.7 GPa; the custom 110 GPa its own.
    """
    value, e, rho, kind = MATERIALS[material]
    # the makers' column constant [lb in^2 / in^4] is pi^3 E / 64: E = C x 64 / pi^3 psi
    makers = {"steel": 14.03e6, "stainless-303": 13.4e6}.get(material)
    e_column = e if makers is None else makers * 64 / math.pi**3 * PSI_PA
    candidate = evaluate(api, {**CUSTOM_SCREW, "material": value})["candidate"]
    assert_candidate(candidate)
    assert candidate["id"] == "custom"
    d_r, length = 9.906e-3, 0.5
    n_c = 1.47 * 60 / (2 * math.pi) * (math.pi / length) ** 2 * math.sqrt(e / rho) * d_r / 4
    f_cr = 2 * math.pi**2 * e_column * (math.pi * d_r**4 / 64) / length**2
    assert math.isclose(candidate["critical_speed"]["theoretical_rpm"], n_c, rel_tol=1e-9)
    assert math.isclose(candidate["buckling"]["critical_load_n"], f_cr, rel_tol=1e-5)
    assert candidate["provenance"]["youngs_modulus"]["kind"] == kind
    assert candidate["provenance"]["outer_diameter"]["kind"] == "user"


def test_custom_material_equal_to_steel_gives_steel_numbers(api: Api) -> None:
    steel = evaluate(api, {**CUSTOM_SCREW, "material": "steel"})["candidate"]
    same = {"youngs_modulus_pa": 206e9, "density_kg_m3": 7850.0, "yield_strength_pa": 310e6}
    custom = evaluate(api, {**CUSTOM_SCREW, "material": same})["candidate"]
    for group in ("torque", "critical_speed", "buckling", "pv"):
        assert custom[group] == steel[group], group


def test_evaluate_custom_screw_against_hand_calculation(api: Api) -> None:
    """Every headline number of one custom screw, recomputed here from the formulas.

    Screw: d_o 12.7 mm, d_r 9.906 mm, lead 10 mm, mu 0.15 running / 0.20 static,
    Acme half-angle 14.5 deg, steel (E 206 GPa, rho 7850), nut drag 0.05 N m.
    Axis: F 100 N, v 50 mm/s, L 500 mm, a 1 m/s^2, 2 kg moving mass, fixed-simple.
    Sources: rpm, torque and PV from the manufacturer's seed formulas; efficiencies from
    Shigley, Mechanical Engineering Design, eq. 8-1 to 8-4 (Acme form).
    """
    f, v, length, accel, mass = 100.0, 0.050, 0.500, 1.0, 2.0
    d_o, d_r, lead, mu, mu_s, drag = 12.7e-3, 9.906e-3, 10e-3, 0.15, 0.20, 0.05
    cos_a = math.cos(math.radians(14.5))
    d_p = (d_o + d_r) / 2  # pitch diameter
    tan_l = lead / (math.pi * d_p)  # tan of the lead angle
    rpm = 60 * v / lead  # 300 rpm
    eta = (cos_a - mu * tan_l) / (cos_a + mu / tan_l)
    eta_s = (cos_a - mu_s * tan_l) / (cos_a + mu_s / tan_l)
    eta_b = (cos_a * tan_l - mu_s) / (tan_l * (cos_a + mu_s * tan_l))
    load_nm = f * lead / (2 * math.pi * eta)  # T = F lead / (2 pi eta)
    alpha = 2 * math.pi * accel / lead  # screw angular acceleration
    screw_nm = 7850 * math.pi * d_p**4 / 32 * length * alpha  # T = J alpha, solid rod at d_p
    mass_nm = mass * accel * lead / (2 * math.pi * eta)  # m a through the thread
    inertia_nm = screw_nm + mass_nm
    # from rest: static friction while the load and m a already act
    breakaway_nm = (f + mass * accel) * lead / (2 * math.pi * eta_s) + screw_nm + drag
    h = (d_o - d_r) / 2  # thread depth
    # PV = n F_peak / (3 h), three threads, MPa m/s, at the peak thrust F + m a = 102 N
    # (the accelerating segment ends at the top speed still carrying m a)
    pv = (rpm / 60) * (f + mass * accel) / (3 * h) / 1e6

    fields = {"accel_mm_s2": 1000.0, "moving_mass_kg": mass}
    c = evaluate(api, {**CUSTOM_SCREW, "drag_torque_nm": drag}, **fields)["candidate"]
    expected = {
        "rpm": rpm,
        "efficiency": eta,
        "backdrive_efficiency": eta_b,
        "torque.load_nm": load_nm,
        "torque.inertia_nm": inertia_nm,
        "torque.drag_nm": drag,
        "torque.total_nm": inertia_nm + drag + load_nm,
        "torque.breakaway_nm": breakaway_nm,
        "pv.value_mpa_m_s": pv,
    }
    for path, value in expected.items():
        got = c
        for part in path.split("."):
            got = got[part]
        assert math.isclose(got, value, rel_tol=1e-9), f"{path}: {got} != {value}"
    assert math.isclose(rpm, 300.0)
    assert c["self_locking"] is (mu_s >= cos_a * tan_l) is False
    # the seed's traverse table is the seed family's rule: a custom screw has none
    assert c["traverse_speed_limit_mm_s"] is None
    assert "traverse_speed" not in {check["name"] for check in c["checks"]}
    assert c["pv"]["limit_mpa_m_s"] is None  # no nut PV limit given, so no PV check
    assert "pv" not in {check["name"] for check in c["checks"]}


def test_catalog_screw_load_torque_by_hand(api: Api, catalog: Catalog) -> None:
    """ZBX8000-L10 at 100 N: T_load = F lead / (2 pi eta), catalog friction and geometry."""
    spec = catalog.by_id[CATALOG_SCREW]
    c = evaluate(api, {"catalog_id": CATALOG_SCREW})["candidate"]
    tan_l = spec.lead_m / (math.pi * (spec.outer_diameter_m + spec.root_diameter_m) / 2)
    cos_a, mu = math.cos(spec.thread_half_angle_rad), spec.friction_dynamic
    eta = (cos_a - mu * tan_l) / (cos_a + mu / tan_l)
    assert math.isclose(c["rpm"], 60 * 0.050 / spec.lead_m, rel_tol=1e-12)
    assert math.isclose(c["torque"]["load_nm"], 100 * spec.lead_m / (2 * math.pi * eta))


# --- bad input: 4xx with {"error", "detail": [{"field", "message"}]} naming the field ---------

NAN, INF = float("nan"), float("inf")

# (id, fields changed (None removes), field named in the error, marks)
BAD_APPLICATION: list[tuple[str, dict[str, Any], str, tuple[Any, ...]]] = [
    ("missing-load", {"load_n": None}, "load_n", ()),
    ("missing-speed", {"speed_mm_s": None}, "speed_mm_s", ()),
    ("missing-length", {"length_mm": None}, "length_mm", ()),
    ("type-load-text", {"load_n": "heavy"}, "load_n", ()),
    ("type-load-list", {"load_n": [100]}, "load_n", ()),
    ("type-load-object", {"load_n": {"value": 100}}, "load_n", ()),
    ("type-load-bool", {"load_n": True}, "load_n", ()),
    ("type-compression-text", {"compression": "maybe"}, "compression", ()),
    ("type-limit-fraction", {"limit": 2.5}, "limit", ()),
    ("type-limit-text", {"limit": "ten"}, "limit", ()),
    ("nan-load", {"load_n": NAN}, "load_n", ()),
    ("nan-speed", {"speed_mm_s": NAN}, "speed_mm_s", ()),
    ("nan-length", {"length_mm": NAN}, "length_mm", ()),
    ("nan-lead", {"lead_mm": NAN}, "lead_mm", ()),
    ("nan-ambient", {"ambient_c": NAN}, "ambient_c", ()),
    ("nan-mass", {"moving_mass_kg": NAN}, "moving_mass_kg", ()),
    ("inf-load", {"load_n": INF}, "load_n", ()),
    ("inf-speed", {"speed_mm_s": INF}, "speed_mm_s", ()),
    ("inf-length", {"length_mm": INF}, "length_mm", ()),
    ("inf-accel", {"accel_mm_s2": INF}, "accel_mm_s2", ()),
    ("minus-inf-ambient", {"ambient_c": -INF}, "ambient_c", ()),
    ("inf-max-torque", {"max_torque_nm": INF}, "max_torque_nm", ()),
    ("negative-load", {"load_n": -100.0}, "load_n", ()),
    ("negative-speed", {"speed_mm_s": -50.0}, "speed_mm_s", ()),
    ("negative-length", {"length_mm": -500.0}, "length_mm", ()),
    ("negative-lead", {"lead_mm": -10.0}, "lead_mm", ()),
    ("negative-accel", {"accel_mm_s2": -1.0}, "accel_mm_s2", ()),
    ("negative-mass", {"moving_mass_kg": -1.0}, "moving_mass_kg", ()),
    ("negative-stroke", {"stroke_mm": -1.0}, "stroke_mm", ()),
    ("negative-cycles", {"cycles_per_day": -1.0}, "cycles_per_day", ()),
    ("below-absolute-zero", {"ambient_c": -300.0}, "ambient_c", ()),
    ("zero-speed", {"speed_mm_s": 0.0}, "speed_mm_s", ()),
    ("zero-length", {"length_mm": 0.0}, "length_mm", ()),
    ("zero-lead", {"lead_mm": 0.0}, "lead_mm", ()),
    ("zero-critical-sf", {"critical_speed_safety_factor": 0.0}, "critical_speed_safety_factor", ()),
    ("zero-buckling-sf", {"buckling_safety_factor": 0.0}, "buckling_safety_factor", ()),
    ("zero-torque-sf", {"torque_safety_factor": 0.0}, "torque_safety_factor", ()),
    ("zero-limit", {"limit": 0}, "limit", ()),
    ("huge-load", {"load_n": 1e300}, "load_n", ()),
    ("huge-speed", {"speed_mm_s": 1e300}, "speed_mm_s", ()),
    ("huge-length", {"length_mm": 1e300}, "length_mm", ()),
    ("huge-lead", {"lead_mm": 1e300}, "lead_mm", ()),
    ("huge-accel", {"accel_mm_s2": 1e300}, "accel_mm_s2", ()),
    ("huge-mass", {"moving_mass_kg": 1e300}, "moving_mass_kg", ()),
    ("huge-ambient", {"ambient_c": 1e300}, "ambient_c", ()),
    ("huge-stroke", {"stroke_mm": 1e300}, "stroke_mm", ()),
    ("huge-cycles", {"cycles_per_day": 1e300}, "cycles_per_day", ()),
    ("huge-max-torque", {"max_torque_nm": 1e300}, "max_torque_nm", ()),
    ("huge-tolerance", {"positioning_tolerance_mm": 1e300}, "positioning_tolerance_mm", ()),
    ("huge-life", {"required_life_years": 1e300}, "required_life_years", ()),
    ("huge-torque-sf", {"torque_safety_factor": 1e300}, "torque_safety_factor", ()),
    (
        "critical-sf-above-1",
        {"critical_speed_safety_factor": 1.5},
        "critical_speed_safety_factor",
        (),
    ),
    ("huge-limit", {"limit": 10**6}, "limit", ()),
    ("enum-end-fixity", {"end_fixity": "pinned"}, "end_fixity", ()),
    ("enum-orientation", {"orientation": "diagonal"}, "orientation", ()),
    ("enum-coating", {"coating": "teflon"}, "coating", ()),
    ("enum-rank-by", {"rank_by": "price"}, "rank_by", ()),
    ("enum-case", {"rank_by": "Torque"}, "rank_by", ()),
    ("extra-field", {"load_kg": 5.0}, "load_kg", ()),
    ("life-without-duty", {"required_life_years": 5.0}, "required_life_years", ()),
]


def _json_text(value: Any) -> str:
    """JSON as Python writes it: NaN and Infinity literals, which httpx's json= refuses."""
    return json.dumps(value, allow_nan=True)


def _query_value(value: Any) -> str | None:
    """A JSON value as a query string value, or None when a query cannot carry it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and math.isnan(value):
        return "nan"
    if isinstance(value, float) and math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if isinstance(value, int | float | str):
        return str(value)
    return None


def _application(changes: dict[str, Any]) -> dict[str, Any]:
    fields = {**BASE, **changes}
    return {k: v for k, v in fields.items() if v is not None}


BAD_APPLICATION_PARAMS = [
    pytest.param(transport, changes, field, marks=marks, id=f"{transport}-{case}")
    for case, changes, field, marks in BAD_APPLICATION
    for transport in ("post-select", "get-select", "evaluate")
    if transport != "get-select"
    or all(v is None or _query_value(v) is not None for v in changes.values())
    if not (transport == "get-select" and marks == ())
]


@pytest.mark.parametrize(("transport", "changes", "field"), BAD_APPLICATION_PARAMS)
def test_bad_application_input_is_422_naming_the_field(
    api: Api, transport: str, changes: dict[str, Any], field: str
) -> None:
    fields = _application(changes)
    if transport == "post-select":
        response = api.post_raw(f"{API}/select", _json_text(fields))
    elif transport == "get-select":
        params = {k: _query_value(v) for k, v in fields.items()}
        response = api.get(f"{API}/select", params=params)
    else:
        body = {"application": fields, "screw": {"catalog_id": CATALOG_SCREW}}
        response = api.post_raw(f"{API}/evaluate", _json_text(body))
        field = f"application.{field}"
    assert_error(response, 422, field)


@pytest.mark.parametrize(
    ("value", "field"),
    [("nan", "load_n"), ("NaN", "load_n"), ("inf", "speed_mm_s"), ("-inf", "length_mm"),
     ("Infinity", "lead_mm"), ("1e300", "load_n"), ("1e999", "load_n"), ("", "lead_mm"),
     ("0x10", "load_n"), ("1,5", "load_n")],
    ids=["nan", "NaN", "inf", "minus-inf", "Infinity", "1e300", "1e999-overflow", "empty",
         "hex", "decimal-comma"],
)  # fmt: skip
def test_bad_query_number_is_422_naming_the_field(api: Api, value: str, field: str) -> None:
    params = {**query(BASE), field: value}
    assert_error(api.get(f"{API}/select", params=params), 422, field)


STEEP = {**CUSTOM_SCREW, "outer_diameter_mm": 10.0, "root_diameter_mm": 8.0}
BAD_SCREW: list[tuple[str, Any, int, str]] = [
    ("unknown-catalog-id", {"catalog_id": "NOPE-L1"}, 404, "screw.catalog_id"),
    ("series-id-not-screw-id", {"catalog_id": "ZBX8000"}, 404, "screw.catalog_id"),
    ("catalog-id-too-long", {"catalog_id": "x" * 101}, 422, "screw.catalog_id"),
    ("catalog-id-number", {"catalog_id": 8000}, 422, "screw.catalog_id"),
    ("catalog-id-with-extra", {"catalog_id": CATALOG_SCREW, "lead_mm": 2.0}, 422, "screw.lead_mm"),
    ("screw-null", None, 422, "screw"),
    ("screw-list", [CATALOG_SCREW], 422, "screw"),
    ("screw-text", CATALOG_SCREW, 422, "screw"),
    ("custom-missing-outer", {**CUSTOM_SCREW, "outer_diameter_mm": None}, 422,
     "screw.outer_diameter_mm"),
    ("custom-missing-friction", {**CUSTOM_SCREW, "friction_static": None}, 422,
     "screw.friction_static"),
    ("root-equals-outer", {**CUSTOM_SCREW, "root_diameter_mm": 12.7}, 422,
     "screw.root_diameter_mm"),
    ("root-above-outer", {**CUSTOM_SCREW, "root_diameter_mm": 20.0}, 422,
     "screw.root_diameter_mm"),
    ("nan-outer", {**CUSTOM_SCREW, "outer_diameter_mm": NAN}, 422, "screw.outer_diameter_mm"),
    ("inf-lead", {**CUSTOM_SCREW, "lead_mm": INF}, 422, "screw.lead_mm"),
    ("negative-root", {**CUSTOM_SCREW, "root_diameter_mm": -1.0}, 422, "screw.root_diameter_mm"),
    ("zero-lead", {**CUSTOM_SCREW, "lead_mm": 0.0}, 422, "screw.lead_mm"),
    ("zero-friction", {**CUSTOM_SCREW, "friction_dynamic": 0.0}, 422, "screw.friction_dynamic"),
    ("friction-above-1", {**CUSTOM_SCREW, "friction_static": 2.0}, 422, "screw.friction_static"),
    ("half-angle-45", {**CUSTOM_SCREW, "thread_half_angle_deg": 45.0}, 422,
     "screw.thread_half_angle_deg"),
    ("huge-outer", {**CUSTOM_SCREW, "outer_diameter_mm": 1e300}, 422, "screw.outer_diameter_mm"),
    ("huge-drag", {**CUSTOM_SCREW, "drag_torque_nm": 1e300}, 422, "screw.drag_torque_nm"),
    ("lead-angle-too-steep-to-drive", {**STEEP, "lead_mm": 200.0}, 422,
     "screw.friction_dynamic"),
    ("unknown-material", {**CUSTOM_SCREW, "material": "brass"}, 422, "screw.material"),
    ("material-number", {**CUSTOM_SCREW, "material": 5}, 422, "screw.material"),
    ("material-negative-modulus",
     {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": -1.0, "density_kg_m3": 7850.0}}, 422,
     "screw.material.youngs_modulus_pa"),
    ("material-nan-density",
     {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": 2e11, "density_kg_m3": NAN}}, 422,
     "screw.material.density_kg_m3"),
    ("material-missing-density", {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": 2e11}}, 422,
     "screw.material.density_kg_m3"),
    ("material-extra-field",
     {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": 2e11, "density_kg_m3": 7850.0,
                                   "poisson": 0.3}}, 422, "screw.material.poisson"),
    ("custom-extra-field", {**CUSTOM_SCREW, "starts": 2}, 422, "screw.starts"),
]  # fmt: skip


@pytest.mark.parametrize(
    ("screw", "status", "field"), [pytest.param(*case[1:], id=case[0]) for case in BAD_SCREW]
)
def test_bad_screw_is_4xx_naming_the_field(api: Api, screw: Any, status: int, field: str) -> None:
    if isinstance(screw, dict):
        screw = {k: v for k, v in screw.items() if v is not None}
    body = {"application": BASE, "screw": screw}
    assert_error(api.post_raw(f"{API}/evaluate", _json_text(body)), status, field)


@pytest.mark.parametrize(
    ("body", "field"),
    [
        ({"screw": {"catalog_id": CATALOG_SCREW}}, "application"),
        ({"application": BASE}, "screw"),
        ({"application": BASE, "screw": {"catalog_id": CATALOG_SCREW}, "units": "in"}, "units"),
    ],
    ids=["missing-application", "missing-screw", "extra-field"],
)
def test_bad_evaluate_body_is_422_naming_the_field(
    api: Api, body: dict[str, Any], field: str
) -> None:
    assert_error(api.post(f"{API}/evaluate", json=body), 422, field)


MALFORMED = {
    "truncated": '{"load_n": 100, "speed_mm_s": ',
    "trailing-garbage": '{"load_n": 100} x',
    "single-quotes": "{'load_n': 100}",
    "trailing-comma": '{"load_n": 100,}',
    "empty": "",
    "null": "null",
    "array": "[]",
    "string": '"load_n"',
    "number": "100",
    "bare-nan": "NaN",
}


@pytest.mark.parametrize("path", ["/select", "/evaluate"])
@pytest.mark.parametrize("name", MALFORMED)
def test_malformed_json_is_422(api: Api, path: str, name: str) -> None:
    response = api.post_raw(API + path, MALFORMED[name])
    assert_error(response, 422, "request")


@pytest.mark.parametrize("path", ["/select", "/evaluate"])
def test_body_that_is_not_utf8_is_422(api: Api, path: str) -> None:
    """Found by schemathesis: FastAPI's own 400 {"detail": ...} for undecodable bytes."""
    response = api.post(
        API + path, content=b"\xff\xfe{", headers={"content-type": "application/json"}
    )
    assert_error(response, 422, "request")


def test_malformed_json_message_says_where(api: Api) -> None:
    detail = assert_error(api.post_raw(f"{API}/select", MALFORMED["truncated"]), 422, "request")
    assert "character 30" in detail[0]["message"]


@pytest.mark.parametrize("content_type", ["text/plain", "application/x-www-form-urlencoded"])
def test_json_sent_with_another_content_type_is_422(api: Api, content_type: str) -> None:
    response = api.post_raw(f"{API}/select", json.dumps(BASE), content_type)
    assert_error(response, 422, "request")


def test_oversized_body_is_413(api: Api) -> None:
    body = json.dumps({**BASE, "padding": "x" * 70_000})
    assert_error(api.post_raw(f"{API}/select", body), 413, "request")


def test_oversized_query_is_414(api: Api) -> None:
    # past the 8192 characters a query may have (app.server.settings)
    params = {**query(BASE), "lead_mm": "1" * 10_000}
    assert_error(api.get(f"{API}/select", params=params), 414, "request")


@pytest.mark.parametrize(
    ("method", "path", "status"),
    [
        ("GET", "/api/v1/nope", 404),
        ("PUT", "/api/v1/evaluate", 405),  # GET evaluate is the api_url of a POST
        ("DELETE", "/api/v1/select", 405),
        ("PUT", "/api/v1/series", 405),
    ],
    ids=["unknown-path", "put-evaluate", "delete-select", "put-series"],
)
def test_routing_errors_use_the_error_shape(api: Api, method: str, path: str, status: int) -> None:
    assert_error(api.request(method, path), status, "request")


# --- valid but extreme input: never a 500, never a non-finite number, schema-valid ----------

MINIMUM_APPLICATION = {
    "load_n": 1e-3,
    "speed_mm_s": 1e-3,
    "length_mm": 1.0,
    "accel_mm_s2": 1e-3,
    "stroke_mm": 0.01,
    "cycles_per_day": 1e-3,
    "required_life_years": 1e-3,
    "positioning_tolerance_mm": 1e-4,
    "max_torque_nm": 1e-6,
    "critical_speed_safety_factor": 0.01,
    "buckling_safety_factor": 0.01,
}
MINIMUM_SCREW = {
    "outer_diameter_mm": 0.1,
    "root_diameter_mm": 0.05,
    "lead_mm": 0.01,
    "friction_dynamic": 1e-3,
    "friction_static": 1e-3,
    "inertia_kg_m2_per_m": 1e-15,
    "pv_limit_mpa_m_s": 1e-6,
    "material": {"youngs_modulus_pa": 1e6, "density_kg_m3": 1.0},
}
EXTREME: list[Any] = [
    pytest.param("select", MINIMUM_APPLICATION, id="select-all-minimum"),
    pytest.param("select", {**MINIMUM_APPLICATION, "load_n": 1e6, "speed_mm_s": 1e5},
                 id="select-minimum-length-maximum-load-speed"),
    pytest.param("evaluate", MINIMUM_SCREW, id="custom-all-minimum"),
    pytest.param("evaluate", {**MINIMUM_SCREW, "outer_diameter_mm": 1000.0,
                              "root_diameter_mm": 999.99, "lead_mm": 1000.0,
                              "material": {"youngs_modulus_pa": 1e13, "density_kg_m3": 1.0}},
                 id="custom-thin-thread-stiff-light-material"),
    pytest.param("select", {**BASE, "load_n": 1e6, "speed_mm_s": 1e5, "length_mm": 1e5,
                            "accel_mm_s2": 1e6, "moving_mass_kg": 1e5, "orientation": "vertical",
                            "ambient_c": 1000.0, "limit": 100}, id="select-all-maximum"),
    pytest.param("select", {**BASE, "ambient_c": -273.15, "vacuum": True}, id="absolute-zero"),
    pytest.param("select", {**BASE, "load_n": 1e-300}, id="select-tiny-load"),
    pytest.param("select", {**BASE, "speed_mm_s": 1e-300}, id="select-tiny-speed"),
    pytest.param("select", {**BASE, "accel_mm_s2": 1e-300}, id="select-tiny-accel"),
    pytest.param("select", {**BASE, "critical_speed_safety_factor": 1e-300,
                            "buckling_safety_factor": 1e-300}, id="select-tiny-safety-factors"),
    pytest.param("select", {**BASE, "positioning_tolerance_mm": 1e-300, "max_torque_nm": 1e-300},
                 id="select-tiny-tolerance-and-torque"),
    pytest.param("select", {**BASE, "stroke_mm": 1e5, "cycles_per_day": 1e7,
                            "required_life_years": 1000.0}, id="select-maximum-duty"),
    pytest.param("select", {**BASE, "length_mm": 1e-300}, id="select-tiny-length"),
    pytest.param("select", {**BASE, "stroke_mm": 1e-300, "cycles_per_day": 1e-300,
                            "required_life_years": 1.0}, id="select-tiny-duty"),
    pytest.param("evaluate", {**CUSTOM_SCREW, "lead_mm": 1e-300}, id="custom-tiny-lead"),
    pytest.param("evaluate", {**CUSTOM_SCREW, "root_diameter_mm": 1e-300}, id="custom-tiny-root"),
    pytest.param("evaluate", {**CUSTOM_SCREW, "outer_diameter_mm": 1e-300,
                              "root_diameter_mm": 5e-301, "lead_mm": 1e-300},
                 id="custom-tiny-geometry"),
    pytest.param("evaluate", {**STEEP, "lead_mm": math.pi * 9 * math.tan(math.radians(50)),
                              "friction_dynamic": 1.0, "friction_static": 1.0},
                 id="custom-50deg-lead-friction-1"),
    pytest.param("evaluate", {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": 1e13,
                                                           "density_kg_m3": 1e-300}},
                 id="custom-tiny-density"),
    pytest.param("evaluate", {**CUSTOM_SCREW, "material": {"youngs_modulus_pa": 1e-300,
                                                           "density_kg_m3": 1e5}},
                 id="custom-tiny-modulus"),
]  # fmt: skip


@pytest.mark.parametrize(("endpoint", "fields"), EXTREME)
def test_extreme_input_answers_finite_or_is_refused(
    api: Api, endpoint: str, fields: dict[str, Any]
) -> None:
    if endpoint == "select":
        response = api.post(f"{API}/select", json=fields, params=FULL)
        model: type[BaseModel] = SelectOut
    else:
        response = api.post(f"{API}/evaluate", json={"application": BASE, "screw": fields})
        model = EvaluateOut
    assert response.status_code in (200, 422), response.text
    if response.status_code == 200:
        body = ok(response, model)
        for candidate in body.get("candidates", []) + body.get("rejected", []):
            assert_candidate(candidate)
        if "candidate" in body:
            assert_candidate(body["candidate"])
    else:
        assert_error(response, 422, response.json()["detail"][0]["field"])


def test_checks_endpoint_lists_the_registry(client: Any) -> None:
    """/api/v1/checks is the registry itself: every check the selection runs, in order."""
    from app.core.checks import REGISTRY

    body = client.get("/api/v1/checks").json()
    assert [c["name"] for c in body["checks"]] == [c.name for c in REGISTRY]
    buckling = next(c for c in body["checks"] if c["name"] == "buckling")
    assert buckling["unit"] == "N" and "pi^2" in buckling["formula"]
    assert buckling["sources"] == ["root_diameter", "youngs_modulus", "yield_strength"]
