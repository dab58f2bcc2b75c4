"""HTML pages: the selector (full page or HTMX fragment) and the catalog."""

from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from pydantic import ValidationError

from app.deps import CatalogDep
from app.errors import validation_details
from app.schemas import ApplicationIn
from app.service import run_selection
from app.share import API_TO_PAGE, page_to_api, parse_units, share_query
from app.templating import templates

router = APIRouter(include_in_schema=False)
REQUIRED = ("load", "speed", "length")


def selector_context(params: dict[str, str], catalog: Any) -> dict[str, Any]:
    """Parse the page query, run the selection when the form was filled in."""
    units = parse_units(params)
    context: dict[str, Any] = {
        "units": units,
        "values": params,
        "errors": {},
        "result": None,
        "share_url": None,
    }
    if not any(params.get(name) for name in REQUIRED):
        return context
    data, errors = page_to_api(params, units)
    if not errors:
        try:
            inputs = ApplicationIn.model_validate(data)
        except ValidationError as exc:
            for item in validation_details(exc.errors()):
                errors.setdefault(API_TO_PAGE.get(item["field"], "form"), item["message"])
        else:
            context["result"] = run_selection(inputs, catalog)
            context["share_url"] = "/?" + share_query(inputs, units)
    context["errors"] = errors
    return context


@router.get("/", response_class=HTMLResponse)
async def selector(request: Request, catalog: CatalogDep) -> Response:
    """The selector; an HTMX request gets only the results fragment."""
    context = selector_context(dict(request.query_params), catalog)
    fragment = request.headers.get("HX-Request") == "true"
    return templates.TemplateResponse(
        request, "partials/results.html" if fragment else "index.html", context
    )


@router.get("/catalog", response_class=HTMLResponse)
async def catalog_page(request: Request, catalog: CatalogDep) -> Response:
    return templates.TemplateResponse(request, "catalog.html", {"catalog": catalog})
