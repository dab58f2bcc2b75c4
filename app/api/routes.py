"""JSON API under /api/v1: thin over ``app.report.service`` and the core."""

from typing import Annotated, Any, Literal

from fastapi import APIRouter, Query, Request
from fastapi.responses import Response
from starlette.datastructures import QueryParams

from app import __version__
from app.api.query import parse_query, query_parameters
from app.contract.outputs import (
    ChecksOut,
    CompareOut,
    ErrorOut,
    EvaluateOut,
    FormulasOut,
    HealthOut,
    SelectOut,
    SelectQuery,
    SelectSummaryOut,
    SeriesListOut,
    SeriesOut,
)
from app.contract.pairs import MotorsOut, PairRankIn, PairsOut, PairsQuery
from app.contract.schemas import ApplicationIn
from app.contract.screws import EvaluateIn, NutMaterialsOut
from app.report.formulas import CHECKS_OUT
from app.report.pairs import motors_out, run_pairs
from app.report.present import nut_materials_out, series_dict
from app.report.service import (
    FORMULAS_OUT,
    BadIds,
    UnknownScrew,
    compare_ids,
    run_compare,
    run_evaluation,
    run_selection,
    run_selection_summary,
)
from app.server.compute import computed
from app.server.deps import CatalogDep
from app.server.errors import ApiRoute, AppError
from app.server.overload import charge, full_form_units
from app.server.responses import ModelJSON

ERRORS: dict[int | str, dict[str, Any]] = {
    404: {"model": ErrorOut, "description": "Unknown id"},
    413: {"model": ErrorOut, "description": "Request body too large"},
    414: {"model": ErrorOut, "description": "Query string too long or too many parameters"},
    422: {"model": ErrorOut, "description": "Invalid input, by field"},
}
router = APIRouter(prefix="/api/v1", tags=["api"], responses=ERRORS, route_class=ApiRoute)


@router.get("/health", response_model=HealthOut)
async def health(catalog: CatalogDep) -> dict[str, Any]:
    return {
        "status": "ok",
        "version": __version__,
        "catalog_version": catalog.version,
        "candidates": len(catalog.screws),
    }


@router.get("/checks", response_model=ChecksOut)
async def list_checks() -> dict[str, Any]:
    """Every check the selection runs, in order: what it means, its formula and source."""
    return CHECKS_OUT


@router.get("/series", response_model=SeriesListOut)
async def list_series(catalog: CatalogDep) -> dict[str, Any]:
    """Every series with its data and the provenance of each value."""
    return {
        "catalog_version": catalog.version,
        "series": [series_dict(s) for s in catalog.series.values()],
    }


@router.get("/series/{series_id}", response_model=SeriesOut)
async def get_series(series_id: str, catalog: CatalogDep) -> dict[str, Any]:
    series = catalog.series.get(series_id)
    if series is None:
        raise AppError(
            404,
            "unknown series",
            [{"field": "series_id", "message": f"no series '{series_id[:100]}'"}],
        )
    return series_dict(series)


DetailQuery = Annotated[
    Literal["summary", "full"], Query(description=SelectQuery.model_fields["detail"].description)
]


async def _selection(
    request: Request, inputs: ApplicationIn, catalog: CatalogDep, detail: str
) -> Response:
    """The select response in the form asked for; the full form (up to 50 ms for a hundred
    candidates) counted by its validated limit and computed on a compute thread, the
    compact one (a few milliseconds) on the event loop, where handing it to a thread and
    back would cost about as much as it frees (wrk -c32 on distinct compact selects: half
    the throughput)."""
    if detail == "full":
        charge(request.scope, full_form_units(inputs.axis().limit))
        return await computed(_full_selection, inputs, catalog)
    return ModelJSON(run_selection_summary(inputs, catalog))


def _full_selection(inputs: ApplicationIn, catalog: CatalogDep) -> Response:
    return ModelJSON(run_selection(inputs, catalog))


@router.post("/select", response_model=SelectSummaryOut | SelectOut)
async def select_post(
    request: Request, inputs: ApplicationIn, catalog: CatalogDep, detail: DetailQuery = "summary"
) -> Response:
    """Rank every catalog candidate for the application in the JSON body."""
    return await _selection(request, inputs, catalog, detail)


@router.get(
    "/select",
    response_model=SelectSummaryOut | SelectOut,
    openapi_extra={"parameters": query_parameters(SelectQuery)},
)
async def select_get(request: Request, catalog: CatalogDep) -> Response:
    """The same as POST, with the fields (and ``detail``) as query parameters (a
    shareable link)."""
    query = parse_query(SelectQuery, request.query_params)
    return await _selection(request, query.application(), catalog, query.detail)


#: The compare's own query parameter, besides the select's.
IDS_PARAMETER = {
    "name": "ids",
    "in": "query",
    "required": True,
    "description": "2 to 4 catalog screw ids, comma-separated (or the parameter repeated).",
    "schema": {"type": "string", "title": "Ids"},
    "example": "Tr12x3-bronze,Tr16x4-bronze",
}


@router.get(
    "/compare",
    response_model=CompareOut,
    openapi_extra={"parameters": [*query_parameters(SelectQuery), IDS_PARAMETER]},
)
async def compare_get(request: Request, catalog: CatalogDep) -> Response:
    """2 to 4 catalog screws side by side for the application in the query: each one's
    full record (as ``detail=full`` gives it) with its verdict. Unknown ids, fewer than 2
    or more than 4: 422 on ``ids``."""
    params = request.query_params
    rest = QueryParams([(k, v) for k, v in params.multi_items() if k != "ids"])
    query = parse_query(SelectQuery, rest)
    try:
        ids = compare_ids(params.getlist("ids"), catalog.index.positions)
    except BadIds as exc:
        raise AppError(422, "invalid input", [{"field": "ids", "message": str(exc)}]) from exc
    return await computed(_compare, query.application(), ids, catalog)


def _compare(inputs: ApplicationIn, ids: list[str], catalog: CatalogDep) -> Response:
    return ModelJSON(run_compare(inputs, ids, catalog))


@router.get("/nut-materials", response_model=NutMaterialsOut)
async def list_nut_materials(catalog: CatalogDep) -> NutMaterialsOut:
    """The catalog's nut materials a custom screw's ``nut_material`` may name: each one's
    limits (pressure by sliding speed, maximum pressure, PV, sliding speed, the maker's
    dynamic thrust, wear) with their provenance."""
    return nut_materials_out(catalog.nut_materials, catalog.version)


@router.get("/motors", response_model=MotorsOut)
async def list_motors(catalog: CatalogDep) -> MotorsOut:
    """The motor library: each motor's datasheet values with their provenance, and the
    curve (and a servo's continuous torque) the motor checks use."""
    return motors_out(catalog)


PairRankQuery = Annotated[
    PairRankIn, Query(description=PairsQuery.model_fields["pair_rank"].description)
]


@router.post("/pairs", response_model=PairsOut)
async def pairs_post(
    inputs: ApplicationIn, catalog: CatalogDep, pair_rank: PairRankQuery = "motor_margin"
) -> Response:
    """Every catalog screw with every library motor for the axis in the JSON body (its
    own motor set aside): the passing pairs, ranked."""
    return await computed(_pairs, inputs, catalog, pair_rank)


@router.get(
    "/pairs",
    response_model=PairsOut,
    openapi_extra={"parameters": query_parameters(PairsQuery)},
)
async def pairs_get(request: Request, catalog: CatalogDep) -> Response:
    """The same as POST, with the fields (and ``pair_rank``) as query parameters."""
    query = parse_query(PairsQuery, request.query_params)
    return await computed(_pairs, query.application(), catalog, query.pair_rank)


def _pairs(inputs: ApplicationIn, catalog: CatalogDep, rank: PairRankIn) -> Response:
    return ModelJSON(run_pairs(inputs, catalog, rank))


@router.get("/formulas", response_model=FormulasOut)
async def list_formulas() -> dict[str, Any]:
    """Every reported quantity's formula, core function and source: the same for every
    selection, so the compact select response links here instead of repeating it."""
    return {"formulas": FORMULAS_OUT}


@router.post("/evaluate", response_model=EvaluateOut)
async def evaluate_post(body: EvaluateIn, catalog: CatalogDep) -> Response:
    """One catalog screw (``catalog_id``) or a custom geometry against one application."""
    try:
        return ModelJSON(run_evaluation(body.application, body.screw, catalog))
    except UnknownScrew as exc:
        raise AppError(
            404,
            "unknown screw",
            [{"field": "screw.catalog_id", "message": f"no catalog screw '{str(exc)[:100]}'"}],
        ) from exc
