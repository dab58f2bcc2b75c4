"""JSON API under /api/v1: thin over ``app.report.service`` and the core."""

from collections.abc import Sequence
from typing import Annotated, Any, Literal

from fastapi import APIRouter, Body, Query, Request
from fastapi.responses import Response
from starlette.datastructures import QueryParams

from app import __version__
from app.api.examples import (
    APPLICATION_EXAMPLES,
    EVALUATE_EXAMPLES,
    PICK_AND_PLACE_SCREW,
    Z_SCREW,
    example_query,
)
from app.api.hints import HintedRoute
from app.api.query import parse_query, query_parameters
from app.contract.fields import BY_PAGE
from app.contract.machine import MachineIn, MachineOut
from app.contract.outputs import (
    ChecksOut,
    CompareOut,
    ErrorOut,
    EvaluateOut,
    EvaluateQuery,
    FormulasOut,
    HealthOut,
    SelectOut,
    SelectQuery,
    SelectSummaryOut,
    SeriesListOut,
    SeriesOut,
    VersusOut,
)
from app.contract.pairs import MotorsOut, PairRankIn, PairsOut, PairsQuery
from app.contract.schemas import ApplicationIn
from app.contract.screws import CatalogScrewIn, CustomScrewIn, EvaluateIn, NutMaterialsOut
from app.report.formulas import CHECKS_OUT
from app.report.machine import AxisInputError, UnknownChoice, run_machine
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
from app.report.versus import run_versus
from app.server.compute import computed
from app.server.deps import CatalogDep
from app.server.errors import AppError
from app.server.overload import charge, full_form_units
from app.server.responses import ModelJSON

ERRORS: dict[int | str, dict[str, Any]] = {
    404: {"model": ErrorOut, "description": "Unknown id"},
    413: {"model": ErrorOut, "description": "Request body too large"},
    414: {"model": ErrorOut, "description": "Query string too long or too many parameters"},
    422: {"model": ErrorOut, "description": "Invalid input, by field"},
}
router = APIRouter(prefix="/api/v1", tags=["api"], responses=ERRORS, route_class=HintedRoute)
#: A body of the application, with the worked examples /docs offers.
ApplicationBody = Annotated[ApplicationIn, Body(openapi_examples=APPLICATION_EXAMPLES)]
#: What every GET of an application says of its query.
QUERY_NAMES = (
    f" The query carries the API's names and units (`{BY_PAGE['load'].api}`, "
    f"`{BY_PAGE['speed'].api}`); a share link's page names (`load`, `speed`) are "
    "refused, each 422 naming the API's. Every response's `api_url` is its query in this "
    "form, beside `share_url`, the page's."
)


def _get_doc(text: str, route: str, extra: Sequence[tuple[str, str]] = ()) -> str:
    """A GET's description: what it does, its query's names, and the worked example."""
    url = example_query(route, extra)
    return f"{text}{QUERY_NAMES}\n\nExample, the Z axis of a 3D printer: [{url}]({url})"


@router.get("/health", response_model=HealthOut, summary="Health and catalog version")
async def health(catalog: CatalogDep) -> dict[str, Any]:
    """The app's version, the catalog's version (a digest of its files) and how many
    candidates it holds."""
    return {
        "status": "ok",
        "version": __version__,
        "catalog_version": catalog.version,
        "candidates": len(catalog.screws),
    }


@router.get("/checks", response_model=ChecksOut, summary="List the checks")
async def list_checks() -> dict[str, Any]:
    """Every check the selection runs, in order: what it means, its formula and source."""
    return CHECKS_OUT


@router.get("/series", response_model=SeriesListOut, summary="List the catalog series")
async def list_series(catalog: CatalogDep) -> dict[str, Any]:
    """Every series with its data and the provenance of each value."""
    return {
        "catalog_version": catalog.version,
        "series": [series_dict(s) for s in catalog.series.values()],
    }


@router.get("/series/{series_id}", response_model=SeriesOut, summary="One catalog series")
async def get_series(series_id: str, catalog: CatalogDep) -> dict[str, Any]:
    """One series' data with the provenance of each value; 404 for an unknown id."""
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


@router.post(
    "/select", response_model=SelectSummaryOut | SelectOut, summary="Select screws for an axis"
)
async def select_post(
    request: Request,
    inputs: ApplicationBody,
    catalog: CatalogDep,
    detail: DetailQuery = "summary",
) -> Response:
    """Rank every catalog candidate for the application in the JSON body: the passing
    screws, best first by the ranking asked for, and the rejected ones with their failed checks and
    fixes; `detail=full` gives every number, check, formula and provenance. The compact
    form gives numbers to 6 significant figures and leaves out values not worked out for
    this query; `detail=full` gives every field at full precision. Inputs are in the API's
    units, the unit in each name (a speed in mm/s); `share_url` is the page of the same
    inputs, `api_url` the GET of the same query."""
    return await _selection(request, inputs, catalog, detail)


@router.get(
    "/select",
    response_model=SelectSummaryOut | SelectOut,
    openapi_extra={"parameters": query_parameters(SelectQuery)},
    summary="Select screws for an axis (query)",
    description=_get_doc(
        "The same as POST, with the fields (and `detail`) as query parameters. The compact "
        "form gives numbers to 6 significant figures and leaves out values not worked out "
        "for this query; `detail=full` gives every field at full precision.",
        "select",
    ),
)
async def select_get(request: Request, catalog: CatalogDep) -> Response:
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
    summary="Compare 2 to 4 screws",
    description=_get_doc(
        "2 to 4 catalog screws side by side for the application in the query: each one's "
        "full record (as `detail=full` gives it) with its verdict. Unknown ids, fewer "
        "than 2 or more than 4: 422 on `ids`.",
        "compare",
        [("ids", f"{Z_SCREW},{PICK_AND_PLACE_SCREW}")],
    ),
)
async def compare_get(request: Request, catalog: CatalogDep) -> Response:
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


@router.get(
    "/versus",
    response_model=VersusOut,
    openapi_extra={"parameters": query_parameters(ApplicationIn)},
    summary="Leadscrew against ball screw for an axis",
    description=_get_doc(
        "The selection run once per kind of screw (the catalog's leadscrew families, then "
        "its ball-screw families, within `family` when given): each kind's first-ranked "
        "passing screw in full (as `detail=full` gives it), else its nearest rejected one "
        "with `excluded_by`, the limits it fails; `candidate` is null when the catalog "
        "offers no screw of that kind for the query. Each side carries cited notes on its "
        "kind's noise and play; `price_note` says why no price is shown.",
        "versus",
    ),
)
async def versus_get(request: Request, catalog: CatalogDep) -> Response:
    inputs = parse_query(ApplicationIn, request.query_params)
    charge(request.scope, 2 * full_form_units(1))
    return await computed(_versus, inputs, catalog)


def _versus(inputs: ApplicationIn, catalog: CatalogDep) -> Response:
    return ModelJSON(run_versus(inputs, catalog))


@router.get("/nut-materials", response_model=NutMaterialsOut, summary="List the nut materials")
async def list_nut_materials(catalog: CatalogDep) -> NutMaterialsOut:
    """The catalog's nut materials a custom screw's ``nut_material`` may name: each one's
    limits (pressure by sliding speed, maximum pressure, PV, sliding speed, the maker's
    dynamic thrust, wear) with their provenance."""
    return nut_materials_out(catalog.nut_materials, catalog.version)


@router.get("/motors", response_model=MotorsOut, summary="List the library motors")
async def list_motors(catalog: CatalogDep) -> MotorsOut:
    """The motor library: each motor's datasheet values with their provenance, and the
    curve (and a servo's continuous torque) the motor checks use."""
    return motors_out(catalog)


PairRankQuery = Annotated[
    PairRankIn | None, Query(description=PairsQuery.model_fields["pair_rank"].description)
]


@router.post("/pairs", response_model=PairsOut, summary="Pair screws with library motors")
async def pairs_post(
    inputs: ApplicationBody, catalog: CatalogDep, pair_rank: PairRankQuery = None
) -> Response:
    """Every catalog screw with every library motor for the axis in the JSON body (its
    own motor set aside): the passing pairs, ranked as the page ranks them (by what the
    application's own ranking means) unless `pair_rank` says otherwise. `share_url` is the
    page of the same axis with the motor "any", `api_url` the GET of the same query."""
    return await computed(_pairs, inputs, catalog, pair_rank)


@router.get(
    "/pairs",
    response_model=PairsOut,
    openapi_extra={"parameters": query_parameters(PairsQuery)},
    summary="Pair screws with library motors (query)",
    description=_get_doc(
        "The same as POST, with the fields (and `pair_rank`) as query parameters.", "pairs"
    ),
)
async def pairs_get(request: Request, catalog: CatalogDep) -> Response:
    query = parse_query(PairsQuery, request.query_params)
    return await computed(_pairs, query.application(), catalog, query.pair_rank)


def _pairs(inputs: ApplicationIn, catalog: CatalogDep, rank: PairRankIn | None) -> Response:
    return ModelJSON(run_pairs(inputs, catalog, rank))


@router.get("/formulas", response_model=FormulasOut, summary="List the formulas")
async def list_formulas() -> dict[str, Any]:
    """Every reported quantity's formula, core function and source: the same for every
    selection, so the compact select response links here instead of repeating it."""
    return {"formulas": FORMULAS_OUT}


@router.post("/evaluate", response_model=EvaluateOut, summary="Evaluate one screw")
async def evaluate_post(
    body: Annotated[EvaluateIn, Body(openapi_examples=EVALUATE_EXAMPLES)], catalog: CatalogDep
) -> Response:
    """One catalog screw (`catalog_id`) or a custom geometry against one application:
    every check, number, formula and provenance, and its robustness. A catalog screw's
    `share_url` is its report page, its `api_url` the GET of the same query; a custom
    screw's `share_url` is the page of one's own screw with the same geometry and inputs."""
    return _evaluation(body.application, body.screw, catalog, "screw.catalog_id")


@router.get(
    "/evaluate",
    response_model=EvaluateOut,
    openapi_extra={"parameters": query_parameters(EvaluateQuery)},
    summary="Evaluate one catalog screw (query)",
    description=_get_doc(
        "One catalog screw (`catalog_id`) against the application in the query: the same "
        "as POST with a catalog screw.",
        "evaluate",
        [("catalog_id", Z_SCREW)],
    ),
)
async def evaluate_get(request: Request, catalog: CatalogDep) -> Response:
    query = parse_query(EvaluateQuery, request.query_params)
    screw = CatalogScrewIn(catalog_id=query.catalog_id)
    return _evaluation(query.application(), screw, catalog, "catalog_id")


def _evaluation(
    inputs: ApplicationIn, screw: CatalogScrewIn | CustomScrewIn, catalog: CatalogDep, id_field: str
) -> Response:
    try:
        return ModelJSON(run_evaluation(inputs, screw, catalog))
    except UnknownScrew as exc:
        raise AppError(
            404,
            "unknown screw",
            [{"field": id_field, "message": f"no catalog screw '{str(exc)[:100]}'"}],
        ) from exc


@router.post("/machine", response_model=MachineOut, summary="Size stacked axes together")
async def machine_post(request: Request, body: MachineIn, catalog: CatalogDep) -> Response:
    """Stacked axes sized together, the top axis first: each axis's moving mass takes the
    axes above it (their moving mass, frame, motor and chosen screw), so each gets its own
    ranked screws and the machine the axis that governs. Costs one selection per axis."""
    charge(request.scope, len(body.axes))
    return await computed(_machine, body, catalog)


def _machine(body: MachineIn, catalog: CatalogDep) -> Response:
    try:
        return ModelJSON(run_machine(body, catalog))
    except AxisInputError as exc:
        field, message = exc.args
        raise AppError(422, "invalid input", [{"field": field, "message": message}]) from exc
    except UnknownChoice as exc:
        i, choice = exc.args
        raise AppError(
            422,
            "unknown screw",
            [{"field": f"axes.{i}.choice", "message": f"no catalog screw '{choice[:100]}'"}],
        ) from exc
