"""HTML pages: the selector (full page or HTMX fragment), a candidate's detail, exports."""

from collections.abc import Mapping
from typing import Any
from urllib.parse import parse_qsl

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.catalog import Catalog
from app.catalog.motors import ANY_MOTOR
from app.contract.exact import PLAIN_MESSAGES
from app.contract.fields import BY_PAGE, FIELDS
from app.contract.form import (
    MOVES,
    TRUE_WORDS,
    UNIT_CHOICES,
    convert_entered,
    converted_fields,
    entered_units,
    form_defaults,
    parse_inputs,
    parse_units,
    typed_exactly,
)
from app.contract.input_field import GROUPS
from app.contract.inputs import SUPPORT
from app.contract.move_table import (
    ADD_MOVE,
    COLUMNS,
    REMOVE_MOVE,
    Row,
    cell,
    cell_errors,
    cell_label,
    converted_rows,
    is_cell,
    moves_of_rows,
    table_rows,
)
from app.contract.params import form_errors, unknown_parameters
from app.contract.reported import columns, row_cells, show, value_of
from app.contract.schemas import ApplicationIn, CandidateOut
from app.contract.screws import CatalogScrewIn
from app.contract.share_link import share_query, summary_rows
from app.contract.units import UNIT_LABELS, Display
from app.report.pairs import run_pairs
from app.report.service import (
    BadIds,
    compare_ids,
    compare_url,
    run_compare,
    run_evaluation,
    run_page_result,
    run_selection,
)
from app.report.versus import KIND_NAMES, kinds_offered, run_versus, versus_url
from app.server.compute import computed
from app.server.deps import CatalogDep
from app.server.errors import AppError
from app.server.headers import is_htmx_fragment
from app.server.overload import charge, full_form_units, page_units
from app.server.responses import ModelJSON
from app.web.advice import check_label, no_pass_advice
from app.web.catalog_view import series_url
from app.web.compare import compare_rows
from app.web.export import results_csv
from app.web.figures import chart_candidates
from app.web.screw_form import catalog_screw_query, nut_carries_over
from app.web.templating import templates
from app.web.versus import versus_rows

router = APIRouter(include_in_schema=False)
#: page fields that must be filled in before a selection runs.
REQUIRED = tuple(field.page for field in FIELDS if field.required)
#: page fields of the first form group, shown outside the Advanced section.
MAIN_FIELDS = tuple(field.page for field in FIELDS if field.group == GROUPS[0])
EXPORT_NAME = "leadscrew-selection"


def form_state(
    params: Mapping[str, str],
) -> tuple[dict[str, str], dict[str, str], list[str], dict[str, str]]:
    """(display units, form values in those units, fields whose units just changed, the
    typed text and unit of each field shown converted)."""
    units = parse_units(params)
    entered = entered_units(params, units)
    values, typed = convert_entered(params, entered, units)
    return units, values, converted_fields(entered, units), typed


def move_rows(params: Mapping[str, str], units: dict[str, str]) -> list[Row]:
    """The table of moves in the display ``units``: as typed (in the units the form was
    in) or from the link's ``moves``, edited by the add and remove buttons."""
    entered = entered_units(params, units)
    return converted_rows(table_rows(params, entered), entered, units)


def focus_row(params: Mapping[str, str], rows: list[Row]) -> int | None:
    """The row whose first cell takes the focus after an edit of the table: the row added,
    or the one now where a row was removed (-1: no row left, the add button); None
    without an edit."""
    if ADD_MOVE in params:
        return len(rows) - 1
    if REMOVE_MOVE in params:
        drop = params[REMOVE_MOVE]
        return min(int(drop), len(rows) - 1) if drop.isdigit() else None
    return None


def parse_page(
    params: Mapping[str, str],
    values: Mapping[str, str],
    rows: list[Row],
    units: dict[str, str],
    catalog: Catalog,
) -> tuple[ApplicationIn | None, dict[str, str]]:
    """The form's inputs with the table's rows as its ``moves`` (a link's ``moves`` text
    as it is when it is no table: the model names its fault), errors at their cells."""
    text, bad, index = moves_of_rows(rows, units)
    data = typed_exactly(values, units)
    if rows or any(is_cell(name) for name in params):
        data[MOVES] = text
    inputs, errors = parse_inputs(data, units, catalog.motors, catalog.supports)
    errors = {**cell_errors(errors, index), **bad}
    return (None, errors) if errors else (inputs, {})


def form_context(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """What every page with the application form renders before any result: the typed
    values and units, the field table and its groups, the choices a text field suggests
    (the library's motors), the message of a required field left empty (the page shows it
    as the field is left, before any answer), the table of moves, no result yet."""
    units, values, converted, typed = form_state(params)
    rows = move_rows(params, units)
    edited = ADD_MOVE in params or REMOVE_MOVE in params
    return {
        "move_rows": rows,
        "move_columns": COLUMNS,
        "move_cells": [cell(i, c.key) for i in range(len(rows)) for c in COLUMNS],
        "moves_redrawn": edited or bool(converted),
        "focus_row": focus_row(params, rows),
        "suggestions": {
            "motor": motor_suggestions(catalog),
            SUPPORT.page: [(uid, unit.name) for uid, unit in catalog.supports.items()],
        },
        "typed": typed,
        "units": units,
        "values": values,
        "errors": {},
        "result": None,
        "share_url": None,
        "query": "",
        "figures": {},
        "charted": False,
        "charting_passed": True,
        "converted": converted,
        "d": Display(units),
        "defaults": form_defaults(units),
        "fields": BY_PAGE,
        "groups": GROUPS,
        "input_rows": summary_rows,
        "true_words": TRUE_WORDS,
        "set_groups": set_groups,
        "unit_choices": UNIT_CHOICES,
        "unit_labels": UNIT_LABELS,
        "missing_message": PLAIN_MESSAGES["missing"],
    }


def motor_suggestions(catalog: Catalog) -> list[tuple[str, str]]:
    """The motor field's suggestions: each library motor's id with its name, then "any"."""
    motors = [(motor_id, motor.name) for motor_id, motor in catalog.motors.items()]
    return [*motors, ("any", "every library motor: rank the screw + motor pairs")]


def selector_context(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """Parse the page query, run the selection when the form was filled in."""
    context, inputs = page_inputs(params, catalog)
    if inputs is not None:
        page_results(context, inputs, catalog)
    return context


def page_inputs(
    params: Mapping[str, str], catalog: Catalog
) -> tuple[dict[str, Any], ApplicationIn | None]:
    """The page's form context and its validated inputs (None until the form is filled in,
    or when it has errors, which the context carries)."""
    context = form_context(params, catalog)
    context.update(
        check_label=check_label,
        columns=columns,
        row_cells=row_cells,
        show=show,
        value_of=value_of,
        rank_text="",
        ranked_by="",
    )
    units, values = context["units"], context["values"]
    unknown = unknown_parameters(params)
    if unknown:
        context["errors"] = form_errors(unknown.values())
        return context, None
    if not any(values.get(name, "").strip() for name in REQUIRED):
        return context, None
    inputs, context["errors"] = parse_page(params, values, context["move_rows"], units, catalog)
    return context, inputs


def page_results(context: dict[str, Any], inputs: ApplicationIn, catalog: Catalog) -> None:
    """Run the selection of valid ``inputs`` into the page's ``context``."""
    units = context["units"]
    result, context["rejected_count"] = run_page_result(inputs, catalog, units)
    context["result"] = result
    context["query"] = share_query(inputs, units, typed=context["typed"])
    context["share_url"] = "/?" + context["query"]
    context["compare_fields"] = parse_qsl(context["query"])
    offered = kinds_offered(inputs, catalog)
    context["versus_url"] = versus_url(context["query"]) if offered else None
    charted, context["charting_passed"] = chart_candidates(result)
    context["charted"] = bool(charted)
    given = inputs.model_dump()
    rank_by = str(given["rank_by"])
    text = BY_PAGE["rank_by"].choice_text(rank_by)
    context["rank_text"] = text[:1].lower() + text[1:]
    context["ranked_by"] = rank_by
    if not result.candidates:
        context["advice"] = no_pass_advice(result, units)
    if given["motor"] == ANY_MOTOR:
        context["pairs"] = run_pairs(inputs, catalog)


def rejected_groups(rejected: list[CandidateOut]) -> list[dict[str, Any]]:
    """Rejected candidates grouped by governing (failing) check, nearest group first."""
    groups: dict[str, dict[str, Any]] = {}
    for c in rejected:
        name = c.governing_check or "other"
        groups.setdefault(name, {"name": name, "label": check_label(name), "candidates": []})
        groups[name]["candidates"].append(c)
    return list(groups.values())


def set_groups(
    values: Mapping[str, str], errors: Mapping[str, str], defaults: Mapping[str, str]
) -> set[str]:
    """The form groups under Advanced that hold an error or a value other than its default:
    each of them, and Advanced itself, is drawn open, the rest shut."""
    groups = set()
    for name, field in BY_PAGE.items():
        text = values.get(name, "").strip().lower()
        if name not in MAIN_FIELDS and (name in errors or text not in ("", defaults.get(name))):
            groups.add(field.group)
    return groups


def _push_url(context: dict[str, Any]) -> str:
    """The URL for the address bar: the result's share link; unchanged while input is bad."""
    if context["share_url"]:
        return str(context["share_url"])
    return "false" if context["errors"] else "/"


def _is_fragment(request: Request) -> bool:
    """An HTMX swap (not a history restore, which needs the whole page), read the way the
    response cache reads it."""
    return is_htmx_fragment(request.headers)


@router.api_route("/", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def selector(request: Request, catalog: CatalogDep) -> Response:
    """The selector; an HTMX request gets the results fragment and out-of-band field errors.
    Validated here, counted by its limit (``page_units``), computed and rendered on a
    compute thread."""
    context, inputs = page_inputs(request.query_params, catalog)
    if inputs is not None:
        charge(request.scope, page_units(inputs.axis().limit))
    return await computed(_selector_page, request, context, inputs, catalog)


def _selector_page(
    request: Request, context: dict[str, Any], inputs: ApplicationIn | None, catalog: Catalog
) -> Response:
    if inputs is not None:
        page_results(context, inputs, catalog)
    fragment = _is_fragment(request)
    context["fragment"] = fragment
    response = templates.TemplateResponse(
        request, "partials/htmx_response.html" if fragment else "index.html", context
    )
    response.headers["Vary"] = "HX-Request"
    if fragment:
        response.headers["HX-Push-Url"] = _push_url(context)
    return response


def link_inputs(
    params: Mapping[str, str], catalog: Catalog, own: tuple[str, ...] = ()
) -> tuple[ApplicationIn, dict[str, str]]:
    """Validated inputs and display units of an export or detail link; a 422 page if
    invalid, or if it carries a parameter that neither the form nor the route (its
    ``own`` names: a candidate's ``id``) reads."""
    unknown = unknown_parameters(params, own)
    if unknown:
        detail = [{"field": name, "message": message} for name, message in unknown.items()]
        raise AppError(422, "invalid input", detail)
    units, values, _, _ = form_state(params)
    inputs, errors = parse_page(params, values, move_rows(params, units), units, catalog)
    if inputs is None:
        detail = [{"field": field_label(name), "message": v} for name, v in errors.items()]
        raise AppError(422, "invalid input", detail)
    return inputs, units


def field_label(page: str) -> str:
    """The form label of a page field or a cell of the moves; other keys ('form') as
    they are."""
    return BY_PAGE[page].label if page in BY_PAGE else cell_label(page) or page


def _attachment(extension: str) -> dict[str, str]:
    return {"Content-Disposition": f'attachment; filename="{EXPORT_NAME}.{extension}"'}


def page_candidate(
    inputs: ApplicationIn, cid: str, catalog: Catalog, units: Mapping[str, str]
) -> CandidateOut:
    """Catalog screw ``cid`` evaluated for these inputs (the same dict the result lists
    carry); a 404 page if there is no such screw."""
    if cid not in catalog.by_id:
        message = f"no candidate {cid!r} in this result" if cid else "no candidate id given"
        raise AppError(404, "candidate not found", [{"field": "id", "message": message}])
    return run_evaluation(inputs, CatalogScrewIn(catalog_id=cid), catalog, units).candidate


@router.api_route("/detail", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def detail(request: Request, catalog: CatalogDep) -> Response:
    """One candidate's checks, formulas and provenance: the fragment a result row loads
    when its detail is opened, or (without HTMX) a page of its own linking back."""
    return await computed(_detail_page, request, catalog)


def _detail_page(request: Request, catalog: Catalog) -> Response:
    inputs, units = link_inputs(request.query_params, catalog, ("id",))
    c = page_candidate(inputs, request.query_params.get("id", ""), catalog, units)
    query = share_query(inputs, units)
    spec = catalog.by_id[c.id]
    # the page of one's own screw judges a sliding nut: a ball nut is not one it offers
    try_url = None
    if spec.screw_type == "lead":
        try_query = catalog_screw_query(spec, units, catalog.nut_materials)
        try_url = f"/custom?{try_query}&{share_query(inputs, units, catalog=False)}"
    context = {
        "c": c,
        "d": Display(units),
        "query": query,
        "report_query": query,
        "try_url": try_url,
        "try_keeps_nut": nut_carries_over(spec, catalog.nut_materials),
        "series_url": series_url(spec.series_id),
    }
    template = "partials/detail.html" if _is_fragment(request) else "detail.html"
    response = templates.TemplateResponse(request, template, context)
    response.headers["Vary"] = "HX-Request"
    return response


@router.api_route("/compare", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def compare(request: Request, catalog: CatalogDep) -> Response:
    """2 to 4 candidates side by side (the ids ticked in the results table, or a shared
    link's ``ids=A,B``); a bad id list is said inline, with status 422."""
    return await computed(_compare_page, request, catalog)


def _compare_page(request: Request, catalog: Catalog) -> Response:
    inputs, units = link_inputs(request.query_params, catalog, ("ids",))
    query = share_query(inputs, units)
    context: dict[str, Any] = {"d": Display(units), "query": query, "candidates": []}
    try:
        ids = compare_ids(request.query_params.getlist("ids"), catalog.index.positions)
    except BadIds as exc:
        context["error"] = f"Candidates to compare: {exc}."
        return templates.TemplateResponse(request, "compare.html", context, status_code=422)
    candidates = run_compare(inputs, ids, catalog, units).candidates
    context.update(
        candidates=candidates,
        rows=compare_rows(candidates, context["d"]),
        share_url=compare_url(inputs, ids, units),
    )
    return templates.TemplateResponse(request, "compare.html", context)


@router.api_route("/versus", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def versus(request: Request, catalog: CatalogDep) -> Response:
    """The best leadscrew against the best ball screw for the link's inputs."""
    return await computed(_versus_page, request, catalog)


def _versus_page(request: Request, catalog: Catalog) -> Response:
    inputs, units = link_inputs(request.query_params, catalog)
    out = run_versus(inputs, catalog, units)
    shown = [s for s in out.sides if s.candidate is not None]
    candidates = [s.candidate for s in shown if s.candidate is not None]
    d = Display(units)
    context: dict[str, Any] = {
        "d": d,
        "query": share_query(inputs, units),
        "out": out,
        "shown": shown,
        "kind_names": KIND_NAMES,
        "rows": versus_rows(candidates, d),
        "compare_url": compare_url(inputs, [c.id for c in candidates], units)
        if len(candidates) == 2
        else None,
    }
    return templates.TemplateResponse(request, "versus.html", context)


@router.get("/export.csv")
async def export_csv(request: Request, catalog: CatalogDep) -> Response:
    """The result table as CSV in the link's display units."""
    inputs, units = _export_inputs(request, catalog)
    return await computed(_export_csv, inputs, units, catalog)


def _export_inputs(request: Request, catalog: Catalog) -> tuple[ApplicationIn, dict[str, str]]:
    """An export link's inputs, its full form counted by their limit (app.server.overload)."""
    inputs, units = link_inputs(request.query_params, catalog)
    charge(request.scope, full_form_units(inputs.axis().limit))
    return inputs, units


def _export_csv(inputs: ApplicationIn, units: dict[str, str], catalog: Catalog) -> Response:
    body = results_csv(run_selection(inputs, catalog, units, view="csv"), units)
    return Response(body, media_type="text/csv; charset=utf-8", headers=_attachment("csv"))


@router.get("/export.json")
async def export_json(request: Request, catalog: CatalogDep) -> Response:
    """The API's select response (API units) for the link's inputs; its share link opens
    the page in the link's units."""
    inputs, units = _export_inputs(request, catalog)
    return await computed(_export_json, inputs, units, catalog)


def _export_json(inputs: ApplicationIn, units: dict[str, str], catalog: Catalog) -> Response:
    out = run_selection(inputs, catalog)
    out = out.model_copy(update={"share_url": "/?" + share_query(inputs, units)})
    return ModelJSON(out, headers=_attachment("json"))
