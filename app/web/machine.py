"""The machine page: stacked axes sized together (``app.report.machine``).

Each axis is given by its results link from the selector (the application as the page
reads it), the mass of its frame and motor that ride on the axis below, and the screw
chosen for it. The form is a plain GET, so a machine is a link too, and choosing another
screw for an upper axis and sizing again updates the axes below it.
"""

from collections.abc import Mapping
from typing import Any
from urllib.parse import parse_qsl

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse, Response
from pydantic import ValidationError

from app.catalog import Catalog
from app.contract.form import parse_inputs
from app.contract.inputs import ApplicationIn
from app.contract.machine import MAX_AXES, AxisIn, MachineIn
from app.contract.params import form_errors, unknown_message, unknown_parameters
from app.contract.share_link import encode_query
from app.report.machine import UnknownChoice, run_machine
from app.server.compute import computed
from app.server.deps import CatalogDep
from app.server.overload import charge
from app.web.pages import form_state
from app.web.templating import templates

router = APIRouter(include_in_schema=False)
#: The query's parameters of axis i (1 to MAX_AXES): its name, results link, frame and
#: motor mass [kg] and chosen screw.
AXIS_PARAMS = ("name", "link", "frame", "motor", "choice")
#: Every parameter the page reads.
MACHINE_NAMES = frozenset(f"{p}{i}" for p in AXIS_PARAMS for i in range(1, MAX_AXES + 1))


def link_query(link: str) -> dict[str, str]:
    """The query of a selector link: a whole URL, a path with its query, or the query.

    >>> link_query("http://host/?load=5&speed=10"), link_query("load=5")
    ({'load': '5', 'speed': '10'}, {'load': '5'})
    """
    _, mark, query = link.strip().partition("?")
    return dict(parse_qsl(query if mark else link.strip(), keep_blank_values=True))


def _axis_inputs(link: str, catalog: Catalog) -> tuple[ApplicationIn | None, str]:
    """The axis's application from its link, or the link's errors in one sentence."""
    params = link_query(link)
    unknown = unknown_parameters(params, ())
    if unknown:
        return None, "; ".join(f"{k}: {m}" for k, m in unknown.items())
    units, values, _, _ = form_state(params)
    inputs, errors = parse_inputs(values, units, catalog.motors, catalog.supports)
    return inputs, "; ".join(f"{k}: {m}" for k, m in errors.items())


def _axis(i: int, params: Mapping[str, str], catalog: Catalog, errors: dict[str, str]) -> Any:
    """Axis ``i`` of the query as ``AxisIn``; None when its link is empty or invalid
    (the errors go into ``errors`` under the query's names)."""
    get = {p: params.get(f"{p}{i}", "").strip() for p in AXIS_PARAMS}
    if not get["link"]:
        return None
    inputs, problem = _axis_inputs(get["link"], catalog)
    if inputs is None:
        errors[f"link{i}"] = problem or "Not a selector link."
        return None
    try:
        return AxisIn(
            name=get["name"] or f"Axis {i}",
            inputs=inputs,
            frame_kg=get["frame"] or 0.0,
            motor_kg=get["motor"] or None,
            choice=get["choice"] or None,
        )
    except ValidationError as exc:
        for error in exc.errors():
            name = {"frame_kg": "frame", "motor_kg": "motor"}.get(str(error["loc"][0]), "name")
            errors[f"{name}{i}"] = error["msg"]
        return None


def machine_query(params: Mapping[str, str], axes: list[Any], machine: Mapping[str, Any]) -> str:
    """The machine's link: its axes' values as given, each with the screw chosen (the
    first-ranked made explicit, so the link keeps the answer)."""
    chosen = iter(machine["axes"])
    pairs: list[tuple[str, str]] = []
    for i, axis in enumerate(axes, start=1):
        if axis is None:
            continue
        pairs += [(f"{p}{i}", params.get(f"{p}{i}", "")) for p in AXIS_PARAMS[:-1]]
        c = next(chosen)["chosen"]
        pairs.append((f"choice{i}", "" if c is None else c["id"]))
    return encode_query([(k, v) for k, v in pairs if v])


def machine_context(params: Mapping[str, str], catalog: Catalog) -> dict[str, Any]:
    """The page's form values, errors by query name, and the machine sized when every
    given axis is valid."""
    unknown = [unknown_message(name, MACHINE_NAMES) for name in params if name not in MACHINE_NAMES]
    errors = form_errors(unknown)
    axes = [_axis(i, params, catalog, errors) for i in range(1, MAX_AXES + 1)]
    given = [a for a in axes if a is not None]
    context: dict[str, Any] = {"values": dict(params), "errors": errors, "n": MAX_AXES}
    if given and not errors:
        try:
            body = MachineIn(axes=given)
        except ValidationError as exc:  # two axes of one name
            errors["form"] = "; ".join(
                str(e["msg"]).removeprefix("Value error, ") for e in exc.errors()
            )
            return context
        try:
            machine = run_machine(body, catalog)
            context.update(machine=machine, query=machine_query(params, axes, machine))
        except UnknownChoice as exc:
            at, choice = exc.args
            errors[f"choice{axes.index(given[at]) + 1}"] = f"No catalog screw {choice[:100]!r}."
    return context


@router.api_route("/machine", methods=["GET", "HEAD"], response_class=HTMLResponse)
async def machine_page(request: Request, catalog: CatalogDep) -> Response:
    """Stacked axes sized together; the empty form without axes."""
    params = dict(request.query_params)
    charge(request.scope, max(1, sum(1 for k in params if k.startswith("link"))))
    context = await computed(machine_context, params, catalog)
    status = 422 if context["errors"] else 200
    return templates.TemplateResponse(request, "machine.html", context, status_code=status)
