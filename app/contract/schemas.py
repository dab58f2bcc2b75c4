"""The candidate's output model, ``CandidateOut``, with its parts (checks, torque, life,
verdict, ...: ``app.contract.sections``) and its views (row, summary, rejected, csv, full),
shared by the API, pages, figures and CSV (pydantic v2). The screw inputs are in
``app.contract.screws``, the responses around the candidates (selection, compare, catalog,
errors) in ``app.contract.outputs``; the application input ``ApplicationIn`` is generated
from the field table in ``app.contract.inputs`` and re-exported here.
"""

import operator
from collections.abc import Mapping
from functools import reduce
from types import GenericAlias, UnionType
from typing import TYPE_CHECKING, Annotated, Any, Literal, Union, get_args, get_origin

from pydantic import BaseModel, Field, create_model
from pydantic.fields import FieldInfo

from app.contract.inputs import ApplicationIn as ApplicationIn  # re-exported for the API and pages
from app.contract.reported import added_fields, merged, view_of
from app.contract.sections import (
    AccuracyOut,
    BucklingOut,
    CheckOut,
    CriticalSpeedOut,
    FailedCheckOut,
    HoldingTorqueOut,
    LifeOut,
    OutgassingOut,
    ProfileOut,
    ProvenanceOut,
    PVOut,
    SegmentOut,
    TorqueOut,
    VerdictOut,
)
from app.contract.source import From, degrees, joined
from app.core.model import ProvenanceKind


class CandidateFields(BaseModel):
    """One candidate: every number, every check with its message, formula and fix, and
    the provenance of the catalog values it uses. Each field says where it comes from in
    the core's candidate record (``From``); the forms of a candidate (``VIEWS``: the
    results table's row, the compact select's summary, a rejected candidate in the
    compact select, the CSV's row) are sets of these fields, and ``full`` is all of
    them. A number of the output table (``app.contract.reported``) that gives its own
    source is added as a field of its own: ``CandidateOut`` is this model with them."""

    id: Annotated[str, From("screw.id")]
    series: Annotated[str, From("screw.series_id")]
    series_name: Annotated[str, From("screw.series_name")]
    anti_backlash: Annotated[bool, From("screw.anti_backlash")]
    outer_diameter_mm: Annotated[float, From("screw.outer_diameter_m", "length")]
    root_diameter_mm: Annotated[float, From("screw.root_diameter_m", "length")]
    pitch_diameter_mm: Annotated[float, From("pitch_diameter_m", "length")]
    lead_mm: Annotated[float, From("screw.lead_m", "length")]
    lead_angle_deg: Annotated[float, From("lead_angle_rad", via=degrees)]
    coated: Annotated[bool, From("screw.coated")]
    nut_material: Annotated[str, From("screw.nut_material")] = Field(
        description="The nut's material, as the catalog names it; empty for a custom screw."
    )
    axial_load_n: Annotated[float, From("axial_load_n", "force")] = Field(
        description="Running thrust at constant speed (PV uses it)."
    )
    peak_axial_load_n: Annotated[float, From("peak_axial_load_n", "force")] = Field(
        description="Peak thrust, accelerating or braking the moving mass: F + m a. "
        "Buckling, root stress and the design load are judged on it."
    )
    rpm: Annotated[float, From("rpm")]
    efficiency: Annotated[float, From("efficiency")] = Field(
        description="Forward efficiency, Shigley's Acme form, dynamic friction (0-1)."
    )
    efficiency_square_thread: Annotated[float, From("efficiency_square_thread")] = Field(
        description="The manufacturer's square-thread form, for comparison (0-1)."
    )
    backdrive_efficiency: Annotated[float, From("backdrive_efficiency")] = Field(
        description="The load driving the screw from rest: static friction; 0 = locks. With "
        "static friction below running friction (uncoated) it can exceed the forward value."
    )
    backdrive_efficiency_running: Annotated[float, From("backdrive_efficiency_running")] = Field(
        description="The load driving the screw while it runs: dynamic friction."
    )
    self_locking: Annotated[bool, From("self_locking")] = Field(
        description="mu_static >= cos(a_n) tan(lambda): self-locking at the full static "
        "friction (a hold counts on self_locking_with_margin)."
    )
    self_locking_with_margin: Annotated[bool, From("self_locking_with_margin")] = Field(
        description="Self-locking with static friction reduced by the self-locking factor."
    )
    seed_rule_no_backdrive: Annotated[bool, From("seed_rule_no_backdrive")] = Field(
        description="The seed's rule of thumb: lead < OD / 8."
    )
    max_self_locking_lead_mm: Annotated[float, From("max_self_locking_lead_m", "length")] = Field(
        description="Longest lead that still self-locks."
    )
    max_self_locking_lead_with_margin_mm: Annotated[
        float, From("max_self_locking_lead_with_margin_m", "length")
    ]
    holds_power_off: Annotated[bool | None, From("holds_power_off")] = Field(
        default=None,
        description="The answer to 'must hold with the power off' where a load is held at "
        "rest: yes when the thread self-locks with the friction margin, or the brake or "
        "detent torque holds it; null: not required, or no load held.",
    )
    hold_margin: Annotated[float | None, From("hold_margin")] = Field(
        default=None,
        description="Its margin, holding at 1 or more: the thread's (the longest lead that "
        "self-locks at f mu_s over the lead) where the thread holds, else the brake's or "
        "detent torque's over the torque needed where one is given, else the thread's; "
        "null as above.",
    )
    holds_by: Annotated[Literal["thread", "brake", "detent"] | None, From("holds_by")] = Field(
        default=None, description="What gives that margin; null as above."
    )
    holding_rule: Annotated[str | None, From("holding_rule")] = Field(
        default=None,
        description="Where the catalog's rule of thumb (lead < OD / 8) and the physics "
        "(self-locking at the friction margin) disagree: which governs and why.",
    )
    holding_torque: Annotated[HoldingTorqueOut, From()]
    torque: Annotated[TorqueOut, From("torque")]
    critical_speed: Annotated[CriticalSpeedOut, From("critical_speed")]
    buckling: Annotated[BucklingOut, From("buckling")]
    pv: Annotated[PVOut | None, From("pv")] = Field(
        description="The nut's PV by the seed's method (three threads in contact); null "
        "for a ball nut and for a standard thread's nut without a seed PV rating, whose "
        "engaged flanks the nut contact pressure check judges."
    )
    traverse_speed_limit_mm_s: Annotated[float | None, From("traverse_speed_limit_m_s", "speed")]
    traverse_extrapolated: Annotated[bool, From("traverse_extrapolated")]
    life: Annotated[LifeOut | None, From("life")]
    accuracy: Annotated[AccuracyOut, From("accuracy")]
    outgassing: Annotated[list[OutgassingOut] | None, From("outgassing")]
    profile: Annotated[ProfileOut | None, From("profile")] = Field(
        default=None, description="The move over the stroke; null without a stroke."
    )
    segments: Annotated[list[SegmentOut] | None, From("segments")] = Field(
        default=None, description="Each segment of the cycle; null without a stroke."
    )
    checks: Annotated[list[CheckOut], From("checks")]
    utilization: Annotated[dict[str, float | None], From("utilization")] = Field(
        description="Check -> demand / capacity, for every check that applies (null for a "
        "yes/no check)."
    )
    governing_check: Annotated[str | None, From("governing_check")] = Field(
        description="The check with the highest utilization (or a failed yes/no check)."
    )
    governing_limit_provenance: Annotated[
        ProvenanceKind | None, From("governing_limit_provenance")
    ] = Field(
        description="How certain the governing check's limit is: the least certain "
        "provenance of the values it rests on ('user' for a limit typed in; a library "
        "motor's curve or rating and a library support unit's rating carry the entry's "
        "provenance, a curve the motor model draws 'derived' or, from an assumed value, "
        "'assumed')."
    )
    motor_use: Annotated[float | None, From("motor_use")] = Field(
        default=None,
        description="The largest share of the motor used over its checks (drive torque, "
        "torque curve, RMS torque, speed): 1 - motor margin; null: no motor given.",
    )
    passed: Annotated[bool, From("passed")] = Field(
        description="True when every limit passes (advice only warns)."
    )
    robust: Annotated[bool | None, From("robust")] = Field(
        description="A pass that holds at both ends of every ranged (assumed) catalog value "
        "it rests on; false: marginal; null: not a pass."
    )
    hinges_on: Annotated[list[str], From("hinges_on")] = Field(
        description="The ranged catalog values at one end of whose range the pass fails."
    )
    warnings: Annotated[list[CheckOut], From("warnings")] = Field(
        description="Failed advice: reported, not rejected."
    )
    warned: Annotated[list[str], From("warned")] = Field(
        description="The names of the advice checks it fails: reported, not rejected."
    )
    failed: Annotated[list[FailedCheckOut], From("failed")] = Field(
        description="Every failed check (limits and advice), in check order."
    )
    fix: Annotated[str | None, From("fixes", via=joined)] = Field(
        description="For a rejected candidate, what would make it pass."
    )
    provenance: Annotated[dict[str, ProvenanceOut], From("provenance")] = Field(
        description="Catalog field -> provenance, for the fields this candidate's numbers "
        "use; then the axis's values a check's limit is: the motor's torque-speed curve "
        "and rated torque, the support unit's ratings (typed in: 'user')."
    )
    verdict: Annotated[VerdictOut, From("verdict")] = Field(
        description="Why this screw, in short: governs, margin, rests on, watch."
    )


#: A view of a model: field name -> True (the whole field) or the view of a nested model.
View = Mapping[str, Any]


def whole(*groups: str) -> dict[str, Any]:
    """A view taking whole each field named in ``groups`` (names separated by spaces)."""
    return dict.fromkeys((name for group in groups for name in group.split()), True)


#: What names a candidate, and its verdict: in the row and the summary alike.
NAMED = "id series series_name anti_backlash outer_diameter_mm lead_mm coated nut_material"
RANKED = "utilization governing_check governing_limit_provenance passed robust hinges_on warned"
#: The verdict in the compact select, without what the candidate already gives or the
#: response names once: the governing check and its utilisation are the candidate's
#: ``governing_check`` and ``utilization``, the margin is 1 - that utilisation, the
#: check's label is at /api/v1/checks, a catalog value's label is in the response's
#: ``labels``, whether the pass hinges on a value is whether ``hinges_on`` names it, and
#: the sentence is these in words.
COMPACT_VERDICT = {"verdict": {"rests_on": {"field": True, "kind": True}, "watch": True}}
#: The verdict in the results table's row: its sentence, and the governing check's label
#: (the report's runners-up); a row's checks, skips and summary are its detail's, loaded
#: when opened (reading them for every row was a fifth of the row's cost).
ROW_VERDICT = {"verdict": {"text": True, "governs_label": True}}


if TYPE_CHECKING:  # mypy cannot see fields made at run time (see app.contract.inputs)
    CandidateOut = CandidateFields
else:
    CandidateOut = create_model(
        "CandidateOut",
        __base__=CandidateFields,
        __doc__=CandidateFields.__doc__,
        **added_fields(CandidateFields.model_fields),
    )


#: The forms of a candidate, each a set of ``CandidateOut``'s fields (``full``: all); the
#: output table adds its numbers to the views it names (``csv`` is the table's alone).
VIEWS: dict[str, View] = {
    "row": merged(
        whole(
            NAMED,
            "axial_load_n rpm efficiency self_locking seed_rule_no_backdrive "
            "max_self_locking_lead_with_margin_mm holds_power_off hold_margin holds_by "
            "holding_rule holding_torque torque critical_speed pv life "
            "profile segments motor_use",
            RANKED,
        ),
        ROW_VERDICT,
        view_of("row"),
    ),
    "summary": merged(whole(NAMED, RANKED), COMPACT_VERDICT, view_of("summary")),
    "rejected": merged(whole("id governing_check failed"), view_of("rejected")),
    "csv": view_of("csv"),
    "full": whole(*CandidateOut.model_fields),
}
#: The views of the compact select (and /machine), as JSON: each number to
#: ``COMPACT_FIGURES`` significant figures, and a value not worked out for this query
#: (null in the full form, a non-finite number, a check's utilisation where it did not
#: run, a part that may be null none of whose fields in the view is worked out) left out
#: rather than given as null. ``detail=full`` gives every field at full
#: precision. ``app.report.reader`` applies it as it reads such a view; ``view_model``
#: with ``compact`` describes it.
COMPACT_VIEWS = frozenset({"summary", "rejected"})
COMPACT_FIGURES = 6
#: What a compact view model's doc and each of its optional fields add.
COMPACT_DOC = (
    "The compact form: numbers to 6 significant figures; a value not worked out for this "
    "query (null in the full form, or a part none of whose fields shown here is) is "
    "absent, never null."
)
COMPACT_ABSENT = " Absent when not worked out for this query (null in the full form)."
COMPACT_ENTRIES = " An entry not worked out for this query (null in the full form) is absent."


def view_model(
    model: type[BaseModel], view: View, name: str, compact: bool = False
) -> type[BaseModel]:
    """The model of one view of ``model``: its fields in the view, in the model's order,
    each with its description and default; a nested model cut to its own view (named
    ``<Model><name>``, e.g. TorqueSummaryOut). For OpenAPI and for validating a view.
    ``compact`` (``COMPACT_VIEWS``): a field that can be null is optional and never null
    instead (absent when not worked out), and so are a dict's values; nested models
    (taken whole too) alike."""
    unknown = set(view) - set(model.model_fields)
    if unknown:
        raise ValueError(f"{model.__name__} has no field {', '.join(sorted(unknown))}")
    fields: dict[str, Any] = {}
    for field_name, info in model.model_fields.items():
        part = view.get(field_name)
        if part is None:
            continue
        annotation = (
            info.annotation
            if part is True and not compact
            else _cut(info.annotation, part, name, compact)
        )
        if compact and _nullable(annotation):
            fields[field_name] = (_not_null(annotation), _absent(info))
        elif compact and _null_values(info.annotation):
            fields[field_name] = (annotation, _absent(info, info.default, COMPACT_ENTRIES))
        else:
            fields[field_name] = (annotation, info)
    title = f"{model.__name__.removesuffix('Out')}{name}Out"
    doc = f"{model.__doc__ or ''}\n\n{COMPACT_DOC}".strip() if compact else model.__doc__
    return create_model(title, __doc__=doc, **fields)


def _nullable(annotation: Any) -> bool:
    return get_origin(annotation) in (UnionType, Union) and type(None) in get_args(annotation)


def _null_values(annotation: Any) -> bool:
    """A dict whose values can be null."""
    return get_origin(annotation) is dict and _nullable(get_args(annotation)[1])


def _absent(info: FieldInfo, default: Any = None, absent: str = COMPACT_ABSENT) -> Any:
    """A field that can be null (or a dict with null values), as the compact form gives
    it: optional (its default None is never served), absent when not worked out."""
    return Field(default, description=f"{info.description or ''}{absent}".strip())


def _cut(annotation: Any, view: View | Literal[True], name: str, compact: bool = False) -> Any:
    """``annotation`` with its model (alone, optional, in a list or a dict) cut to ``view``
    (True: whole); in the compact form a dict's values never null."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        whole_model = whole(*annotation.model_fields) if view is True else view
        return view_model(annotation, whole_model, name, compact)
    origin = get_origin(annotation)
    if origin not in (UnionType, Union, list, dict):
        return annotation
    args = tuple(_cut(a, view, name, compact) for a in get_args(annotation))
    if origin in (UnionType, Union):
        return reduce(operator.or_, args)
    if compact and origin is dict:
        args = (args[0], _not_null(args[1]))
    return GenericAlias(origin, args)


def _not_null(annotation: Any) -> Any:
    """``annotation`` without None (the compact form leaves out null values)."""
    if not _nullable(annotation):
        return annotation
    return reduce(operator.or_, [a for a in get_args(annotation) if a is not type(None)])


#: The compact select's candidate and rejected candidate, and the page's row, as models.
CandidateSummaryOut = view_model(CandidateOut, VIEWS["summary"], "Summary", compact=True)
RejectedSummaryOut = view_model(CandidateOut, VIEWS["rejected"], "Rejected", compact=True)
