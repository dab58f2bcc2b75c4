"""GET /api/v1/select reads its query model with ``app.api.query.parse_query``: the same
values, the same errors and the same OpenAPI parameters as FastAPI's own reading of
``Annotated[SelectQuery, Query()]``."""

from typing import Annotated, Any

import pytest
from fastapi import FastAPI, Query, Request
from fastapi.exceptions import RequestValidationError
from fastapi.testclient import TestClient
from pydantic import BaseModel

from app.api.query import parse_query, query_parameters
from app.contract.inputs import ApplicationIn
from app.contract.outputs import EvaluateQuery, SelectQuery
from app.contract.pairs import PairsQuery
from app.web.errors import validation_error_handler

BASE = "load_n=100&speed_mm_s=50&length_mm=500"
QUERIES = [
    BASE,
    BASE + "&lead_mm=10",
    BASE + "&lead_mm=any",
    BASE + "&lead_mm=",
    BASE + "&load_n=120",  # repeated: the last one counts
    BASE + "&family=B&family=ZBX",
    BASE + "&family=B,ZBX",
    BASE + "&motor_curve=0:0.5,600:0.45,1500:0.3",
    BASE + "&motor_curve=0:0.5",  # one point: refused, naming the field
    BASE + "&motor_curve=0:0.5,600:-1",
    BASE + "&detail=full",
    BASE + "&detail=everything",
    BASE + "&orientation=vertical&moving_mass_kg=2",
    BASE + "&orientation=sideways",
    BASE + "&unknown=1",
    BASE + "&speed_mm_s=nan",
    BASE + "&speed_mm_s=1e400",
    BASE + "&speed_mm_s=",
    BASE + "&end_fixity=fixed-fixed&compression=false&rank_by=margin",
    BASE + "&compression=perhaps",
    "speed_mm_s=50&length_mm=500",  # a required field missing
    "load_n=%EF%BC%91%EF%BC%90%EF%BC%90&speed_mm_s=50&length_mm=500",  # fullwidth digits
]


def _app() -> FastAPI:
    app = FastAPI()
    app.add_exception_handler(RequestValidationError, validation_error_handler)

    @app.get("/api/fastapi")
    def by_fastapi(q: Annotated[SelectQuery, Query()]) -> dict[str, Any]:
        return q.model_dump(mode="json")

    @app.get("/api/ours")
    def by_parse_query(request: Request) -> dict[str, Any]:
        return parse_query(SelectQuery, request.query_params).model_dump(mode="json")

    return app


@pytest.fixture(scope="module")
def probe() -> TestClient:
    return TestClient(_app())


@pytest.mark.parametrize("query", QUERIES)
def test_same_values_and_errors_as_fastapi(probe: TestClient, query: str) -> None:
    theirs, ours = probe.get("/api/fastapi?" + query), probe.get("/api/ours?" + query)
    assert ours.status_code == theirs.status_code, query
    assert ours.json() == theirs.json(), query


def test_an_empty_query_names_each_required_field(probe: TestClient) -> None:
    """Where FastAPI reports the whole query missing, ours names each required field."""
    response = probe.get("/api/ours")
    assert response.status_code == 422
    fields = {d["field"] for d in response.json()["detail"]}
    required = {n for n, f in SelectQuery.model_fields.items() if f.is_required()}
    assert required <= fields


def _fastapis_parameters(model: type[BaseModel]) -> list[dict[str, Any]]:
    """The OpenAPI parameters FastAPI itself writes for ``Annotated[model, Query()]``."""
    probe = FastAPI()

    @probe.get("/")
    def read(q: Annotated[model, Query()]) -> None:  # type: ignore[valid-type]
        """Never called: declares the query model for its documentation."""

    parameters: list[dict[str, Any]] = probe.openapi()["paths"]["/"]["get"]["parameters"]
    return parameters


@pytest.mark.parametrize("model", [SelectQuery, EvaluateQuery, ApplicationIn, PairsQuery])
def test_each_query_model_is_documented_as_fastapi_documents_it(model: type[BaseModel]) -> None:
    assert query_parameters(model) == _fastapis_parameters(model)


def test_the_select_route_documents_every_field_as_fastapi_would(client: TestClient) -> None:
    spec = client.get("/openapi.json").json()
    parameters = spec["paths"]["/api/v1/select"]["get"]["parameters"]
    assert parameters == _fastapis_parameters(SelectQuery)
    assert [p["name"] for p in parameters] == list(SelectQuery.model_fields)
    required = {p["name"] for p in parameters if p["required"]}
    assert required == {n for n, f in SelectQuery.model_fields.items() if f.is_required()}
