"""The catalog's pages. /catalog lists every family and its series (sizes, leads, design
load, materials and nut variants side by side, each with its provenance); each series
opens on demand. /catalog/{series_id} gives every value of one series with its provenance
and source: a page of its own, or (to an HTMX request) the fragment the list's
``<details>`` loads when first opened.

The list depends on the catalog alone and is rendered once at start-up; a series page
takes about 2 ms to render and is kept by the response cache, one entry per
series and kind (page or fragment) for any query (``app.main``)."""

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.catalog import Catalog
from app.server.deps import CatalogDep
from app.server.errors import AppError
from app.server.headers import is_htmx_fragment
from app.web.catalog_view import KEY_FIELDS, family_sections, series_view
from app.web.templating import templates

router = APIRouter(include_in_schema=False)


@router.api_route("/catalog", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def catalog_page(request: Request) -> Response:
    """Every family, its sizes side by side, and a link to each series' values: rendered
    once at start-up (``catalog_html``), as it depends on the catalog alone."""
    return HTMLResponse(request.app.state.catalog_html)


def catalog_html(catalog: Catalog) -> str:
    """The catalog page of ``catalog``: the families' comparison tables and one closed
    ``<details>`` per series (about 120 kB; its series' values are pages of their own)."""
    context = {
        "version": catalog.version,
        "families": family_sections(catalog),
        "key_fields": KEY_FIELDS,
    }
    return templates.get_template("catalog.html").render(context)


@router.api_route("/catalog/{series_id}", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def series_page(request: Request, series_id: str, catalog: CatalogDep) -> Response:
    """Every value of one series with its provenance: the fragment for an HTMX request
    (the list's ``<details>`` opened), else the page; a 404 page for an unknown id."""
    series = catalog.series.get(series_id)
    if series is None:
        message = f"no series '{series_id[:100]}' in the catalog"
        raise AppError(404, "unknown series", [{"field": "series_id", "message": message}])
    fragment = is_htmx_fragment(request.headers)
    template = "partials/catalog_series.html" if fragment else "catalog_series.html"
    context = {"version": catalog.version, "s": series_view(series)}
    response = templates.TemplateResponse(request, template, context)
    response.headers["Vary"] = "HX-Request"
    return response
