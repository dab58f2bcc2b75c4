"""The report an engineer files: one candidate of a result on a print-ready page.

``/report?<share-link query>&id=<candidate id>`` shows the inputs with their units, the
chosen candidate (the top-ranked one without an id) and the runners-up, the cycle's moves
and its energy per cycle, its torque
breakdown, every check with its value, limit, utilization, formula and the provenance of
each catalog value, the charts (critical speed, PV, torque, motor), the date and the
catalog's version. The browser makes the PDF ("Save as PDF" prints the page), so the app
needs no PDF library; the print stylesheet sizes every chart to the page.
"""

from collections.abc import Mapping
from datetime import UTC, datetime
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.catalog import Catalog
from app.contract.move_table import COLUMNS, shown_moves
from app.contract.reported import REPORTED, show, value_of
from app.contract.share_link import encode_query, share_query, summary_rows
from app.contract.units import Display
from app.report.service import run_page_result
from app.server.deps import CatalogDep
from app.server.errors import AppError
from app.web.catalog_view import series_url
from app.web.figures import result_figures
from app.web.pages import link_inputs, page_candidate
from app.web.templating import templates

router = APIRouter(include_in_schema=False)
#: passing candidates listed after the chosen one.
RUNNERS_UP = 4


def report_context(
    params: Mapping[str, str], catalog: Catalog, base_url: str = "/"
) -> dict[str, Any]:
    """The report of candidate ``id`` (else the top-ranked) for the link's inputs, its
    link absolute under ``base_url`` (the address the report was served from, ending in
    '/'); when nothing passes and no id is given, the nearest rejected candidate; a 422
    page for bad inputs, a 404 page for an unknown id or when no screw is eligible."""
    inputs, units = link_inputs(params, catalog, ("id",))
    result, _ = run_page_result(inputs, catalog, units)
    # without an id: the top-ranked screw, or, when none passes, the nearest rejected one
    nearest = result.summary.best_rejected_id or ""
    top = result.candidates[0].id if result.candidates else nearest
    cid = params.get("id", "") or top
    if not cid:  # no screw is eligible: say why, as the page does
        detail = [{"field": "form", "message": result.summary.message}]
        raise AppError(404, "no screw to report", detail)
    chosen = page_candidate(inputs, cid, catalog, units)
    ranks = {c.id: rank for rank, c in enumerate(result.candidates, start=1)}
    query = share_query(inputs, units)
    return {
        "c": chosen,
        "rank": ranks.get(chosen.id),
        "runners_up": [c for c in result.candidates if c.id != chosen.id][:RUNNERS_UP],
        "result": result,
        "units": units,
        "d": Display(units),
        "input_rows": summary_rows,
        "move_columns": COLUMNS,
        "moves": shown_moves(result.inputs.model_dump().get("moves") or [], units),
        "energy": [
            (row, show(row, value_of(chosen, row.key), Display(units)))
            for row in REPORTED
            if row.quantity == "energy"
        ],
        "figures": result_figures(result, units, catalog, chosen),
        "chart_subject": f"{chosen.id}'s",
        "charting_passed": bool(result.candidates),
        "query": query,
        "share_url": "/?" + query,
        "report_link": f"{base_url.rstrip('/')}/report?{query}&{encode_query({'id': chosen.id})}",
        "date": datetime.now(UTC).date().isoformat(),
        "catalog_version": catalog.version,
        "series_url": series_url(catalog.by_id[chosen.id].series_id),
    }


@router.api_route("/report", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def report(request: Request, catalog: CatalogDep) -> Response:
    """The print-ready report of one candidate."""
    context = report_context(request.query_params, catalog, str(request.base_url))
    return templates.TemplateResponse(request, "report.html", context)
