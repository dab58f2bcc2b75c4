"""The page of the user's own screw: its geometry, friction, material and nut with the
selector's application inputs, evaluated as POST /api/v1/evaluate evaluates a custom
screw, with the candidate's checks, charts, share link and exports."""

from collections.abc import Mapping
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response

from app.catalog import Catalog
from app.contract.fields import BY_PAGE
from app.contract.form import TYPED_PREFIX, converted_fields, entered_units
from app.contract.outputs import EvaluateOut
from app.contract.params import form_errors, unknown_parameters
from app.contract.screw_link import OWN_MATERIAL, custom_query, screw_values
from app.contract.screws import NUT_FIELD, NUT_LABEL, CustomScrewIn
from app.contract.share_link import summary_rows as input_rows
from app.contract.units import Display, api_value
from app.core import drive, motion
from app.report.present import nut_rows
from app.report.service import run_evaluation
from app.server.deps import CatalogDep
from app.server.errors import AppError
from app.server.headers import is_htmx_fragment
from app.server.responses import ModelJSON
from app.web.export import candidate_csv
from app.web.figures import critical_speed_figure, torque_figure
from app.web.pages import REQUIRED, field_label, form_context, parse_page
from app.web.pressure_figures import pv_figure
from app.web.screw_form import (
    BY_NAME,
    DEFAULT_MATERIAL,
    MATERIAL_FIELDS,
    MATERIAL_LABEL,
    MATERIALS,
    SCREW_FIELDS,
    convert_screw,
    parse_screw,
)
from app.web.templating import templates

router = APIRouter(include_in_schema=False)
#: screw fields that must be filled in before an evaluation runs.
SCREW_REQUIRED = tuple(f.name for f in SCREW_FIELDS if f.required)
#: the names this page reads besides the application's: the screw's, its material's, its nut.
OWN_NAMES = (*(f.name for f in (*SCREW_FIELDS, *MATERIAL_FIELDS)), "material", NUT_FIELD)
#: the application fields this page does not have (they choose among catalog screws).
LEFT_OUT = tuple(
    name for page, f in BY_PAGE.items() if f.catalog_only for name in (page, TYPED_PREFIX + page)
)
EXPORT_NAME = "leadscrew-custom"
#: the PV chart of one screw the catalog does not hold: its PV-limited load against
#: linear speed (``pv_figure``), captioned as such in place of the selector's.
CHART_CAPTIONS = {
    "pv": (
        "PV limit",
        "Largest axial load the nut's PV limit allows against linear speed; the cross is "
        "the thrust the PV check judges (your load with the weight and m a where they act, "
        "at the peak) at the top speed.",
    )
}


def candidate_figures(out: EvaluateOut, units: dict[str, str]) -> dict[str, dict[str, Any]]:
    """The selector's critical-speed, PV and torque charts for one evaluated screw; PV only
    when the nut has a PV limit."""
    c, d = out.candidate, Display(units)
    app = out.inputs.axis()
    length_mm, _ = api_value(app.length_m, "length")
    speed_mm_per_s, _ = api_value(motion.reached_speed(app), "speed")
    figures = {"critical_speed": critical_speed_figure([c], length_mm, d)}
    if c.pv is not None and c.pv.max_load_n is not None:
        figures["pv"] = pv_figure([c], speed_mm_per_s, c.axial_load_n, d)
    figures["torque"] = torque_figure([c], drive.torque_before_factor_nm(app), d)
    return figures


def _base_context(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """The form's state before any evaluation: the selector's form context without the
    catalog-only inputs, plus the screw's own fields."""
    context = form_context(params, catalog)
    entered = entered_units(params, context["units"])
    context["values"].update(convert_screw(context["values"], entered, context["units"]))
    fields = {page: f for page, f in BY_PAGE.items() if not f.catalog_only}
    own = [f.row for f in (*SCREW_FIELDS, *MATERIAL_FIELDS)]
    return {
        **context,
        "fields": fields,
        # the fields a change of units redraws: this page's (it has no lead to convert)
        "converted": [name for name in context["converted"] if name in fields],
        "converted_screw": converted_fields(entered, context["units"], own),
        "screw_fields": SCREW_FIELDS,
        "material_fields": MATERIAL_FIELDS,
        "materials": MATERIALS,
        "own_material": OWN_MATERIAL,
        "default_material": DEFAULT_MATERIAL,
        "material_label": MATERIAL_LABEL,
        "input_rows": input_rows,
        "screw_label": _label,
    }


def _started(values: Mapping[str, str]) -> bool:
    """Whether any required screw or application field was filled in."""
    return any(values.get(name, "").strip() for name in (*SCREW_REQUIRED, *REQUIRED))


def custom_context(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """Parse the page query; evaluate the screw once the form is filled in and valid."""
    context = _base_context(params, catalog)
    values = context["values"]
    nuts = catalog.nut_materials
    chosen = values.get(NUT_FIELD, "").strip()
    context.update(nut_materials=nuts, nut_label=NUT_LABEL, nut=nuts.get(chosen))
    context["nut_rows"] = nut_rows(nuts[chosen]) if chosen in nuts else []
    unknown = unknown_parameters(params, OWN_NAMES, LEFT_OUT)
    if unknown:
        context["errors"] = form_errors(unknown.values())
        return context
    if not _started(values):
        return context
    rows, units = context["move_rows"], context["units"]
    inputs, app_errors = parse_page(params, values, rows, units, catalog)
    screw, screw_errors = parse_screw(values, context["units"])
    if chosen and chosen not in nuts:
        screw_errors[NUT_FIELD] = f"Choose one of: {', '.join(nuts)}, or none."
        screw = None
    context["errors"] = {**app_errors, **screw_errors}
    if inputs is None or screw is None:
        return context
    result = run_evaluation(inputs, screw, catalog, context["units"])
    query = custom_query(inputs, screw, context["units"])
    context.update(result=result, query=query, share_url="/custom?" + query)
    context["figures"] = candidate_figures(result, context["units"])
    context["chart_captions"] = CHART_CAPTIONS
    context.update(screw=screw, screw_rows=screw_rows(screw, context["units"]))
    return context


def screw_rows(screw: CustomScrewIn, units: Mapping[str, str]) -> list[list[str]]:
    """(name, value, unit) of each given screw value in the display ``units``, for the
    summary and the CSV."""
    rows = []
    for name, value in screw_values(screw, units).items():
        field = BY_NAME.get(name)
        rows.append([name, value, field.display_unit(units) if field is not None else ""])
    return rows


@router.api_route("/custom", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def custom_page(request: Request, catalog: CatalogDep) -> Response:
    """The custom screw's page; an HTMX request gets the results and out-of-band errors."""
    context = custom_context(request.query_params, catalog)
    fragment = is_htmx_fragment(request.headers)
    template = "partials/custom_response.html" if fragment else "custom.html"
    response = templates.TemplateResponse(request, template, context)
    response.headers["Vary"] = "HX-Request"
    if fragment:
        push = context["share_url"] or ("false" if context["errors"] else "/custom")
        response.headers["HX-Push-Url"] = push
    return response


def _evaluated(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """The evaluated context of an export link; a 422 page naming each bad field."""
    context = custom_context(params, catalog)
    if context["result"] is None:
        errors = context["errors"] or {"form": "Enter the screw and the application."}
        detail = [{"field": _label(name), "message": m} for name, m in errors.items()]
        raise AppError(422, "invalid input", detail)
    return context


def _label(name: str) -> str:
    """The form label of a screw or application field; other keys as they are."""
    if name == "material":
        return MATERIAL_LABEL
    if name == NUT_FIELD:
        return NUT_LABEL
    if name in BY_NAME:
        return BY_NAME[name].label
    return field_label(name)


def _attachment(extension: str) -> dict[str, str]:
    return {"Content-Disposition": f'attachment; filename="{EXPORT_NAME}.{extension}"'}


@router.get("/custom/export.csv")
async def custom_csv(request: Request, catalog: CatalogDep) -> Response:
    """The inputs, the screw and its evaluation as CSV in the link's display units."""
    context = _evaluated(request.query_params, catalog)
    result: EvaluateOut = context["result"]
    body = candidate_csv(
        result.inputs.model_dump(), context["screw_rows"], result.candidate, context["units"]
    )
    return Response(body, media_type="text/csv; charset=utf-8", headers=_attachment("csv"))


@router.get("/custom/export.json")
async def custom_json(request: Request, catalog: CatalogDep) -> Response:
    """The API's evaluate response (API units) for the link's screw and application."""
    context = _evaluated(request.query_params, catalog)
    result = run_evaluation(context["result"].inputs, context["screw"], catalog)
    return ModelJSON(result, headers=_attachment("json"))
