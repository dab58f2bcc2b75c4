"""The parts of a result loaded after its table: ``/charts?<share-link query>`` and
``/rejected?<share-link query>``.

The results fragment carries no figure: its charts section asks for them as soon as it is
swapped in (htmx, ``hx-trigger="load"``), so the table is shown without waiting for the
figures. The rejected list loads when its section is first opened. Both keep the fragment
small. An HTMX request gets the part alone; any other (the part's plain link, without
JavaScript) a page of its own.
"""

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.catalog import Catalog
from app.contract.schemas import ApplicationIn
from app.contract.share_link import share_query
from app.report.service import run_page_result, run_page_selection
from app.server.compute import computed
from app.server.deps import CatalogDep
from app.server.headers import is_htmx_fragment
from app.server.overload import charge, page_units
from app.web.advice import check_label
from app.web.figures import chart_candidates, result_figures
from app.web.pages import link_inputs, rejected_groups
from app.web.templating import templates

router = APIRouter(include_in_schema=False)


@router.api_route("/charts", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def charts(request: Request, catalog: CatalogDep) -> Response:
    """The charts of the link's result: a section for the results page, or a page."""
    inputs, units = _inputs(request, catalog)
    return await computed(_charts_page, request, inputs, units, catalog)


def _inputs(request: Request, catalog: Catalog) -> tuple[ApplicationIn, dict[str, str]]:
    """The link's inputs and display units (a 422 page if invalid), counted as a page."""
    inputs, units = link_inputs(request.query_params, catalog)
    charge(request.scope, page_units(inputs.axis().limit))
    return inputs, units


def _charts_page(
    request: Request, inputs: ApplicationIn, units: dict[str, str], catalog: Catalog
) -> Response:
    result, _ = run_page_result(inputs, catalog, units)
    query = share_query(inputs, units)
    context: dict[str, Any] = {
        "figures": result_figures(result, units, catalog),
        "charting_passed": chart_candidates(result)[1],
        "query": query,
        "share_url": "/?" + query,
    }
    return _part(request, "partials/charts.html", "charts.html", context)


@router.api_route("/rejected", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def rejected(request: Request, catalog: CatalogDep) -> Response:
    """The link's rejected candidates: the list for the results page, or a page."""
    inputs, units = _inputs(request, catalog)
    return await computed(_rejected_page, request, inputs, units, catalog)


def _rejected_page(
    request: Request, inputs: ApplicationIn, units: dict[str, str], catalog: Catalog
) -> Response:
    _, rejected = run_page_selection(inputs, catalog, units)
    query = share_query(inputs, units)
    context: dict[str, Any] = {
        "rejected_groups": rejected_groups(rejected),
        "check_label": check_label,
        "query": query,
        "share_url": "/?" + query,
    }
    return _part(request, "partials/rejected_list.html", "rejected.html", context)


def _part(request: Request, part: str, page: str, context: dict[str, Any]) -> Response:
    """``part`` for an HTMX request, else ``page`` (which varies on HX-Request)."""
    template = part if is_htmx_fragment(request.headers) else page
    response = templates.TemplateResponse(request, template, context)
    response.headers["Vary"] = "HX-Request"
    return response
