"""The candidate's output model, ``CandidateOut``, with its parts (checks, torque, life,
verdict, ...) and its views (row, summary, rejected, csv, full), shared by the API, pages,
figures and CSV (pydantic v2). The screw inputs are in ``app.contract.screws``, the
responses around the candidates (selection, compare, catalog, errors) in
``app.contract.outputs``; the application input ``ApplicationIn`` is generated from the
field table in ``app.contract.inputs`` and re-exported here.
"""

import operator
from collections.abc import Mapping
from functools import reduce
from types import GenericAlias, UnionType
from typing import TYPE_CHECKING, Annotated, Any, Literal, Union, get_args, get_origin

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    create_model,
)

from app.contract.inputs import ApplicationIn as ApplicationIn  # re-exported for the API and pages
from app.contract.reported import added_fields, merged, view_of
from app.contract.source import (
    From,
    check_limit,
    check_unit,
    check_value,
    degrees,
    joined,
    km,
    million_cm,
)
from app.contract.source import (
    text as phrase_text,
)
from app.contract.source import (
    texts as phrase_texts,
)
from app.core.model import ProvenanceKind

TORQUE_NOTE = (
    "Torque of the screw assembly alone; bearings, motor shaft, moving parts and "
    "misalignment are extra (seed). The torque safety factor covers them: 1.0 by default, "
    "1.3 to 2 is common at the planning stage."
)


class CheckOut(BaseModel):
    name: Annotated[str, From("name")]
    label: Annotated[str, From("label")]
    kind: Annotated[Literal["limit", "advice"], From("kind")] = Field(
        description="A limit rejects a candidate; advice is reported beside it."
    )
    passed: Annotated[bool, From("passed")]
    value: Annotated[float | None, From(via=check_value)] = Field(
        description="Demand, in ``unit``; null for yes/no checks."
    )
    limit: Annotated[float | None, From(via=check_limit)] = Field(
        description="Capacity, in ``unit``; null for yes/no checks."
    )
    unit: Annotated[str, From(via=check_unit)]
    utilization: Annotated[float | None, From("utilization")] = Field(
        description="value / limit; above 1 fails. Null for yes/no checks, and where a "
        "demand meets a limit of 0 (no capacity at all: unbounded, it fails)."
    )
    message: Annotated[str, From("message")]
    formula: Annotated[str, From("formula")]
    sources: Annotated[list[str], From("sources")]
    fix: Annotated[str | None, From("fix")]


class FailedCheckOut(BaseModel):
    name: Annotated[str, From("name")]
    kind: Annotated[Literal["limit", "advice"], From("kind")]
    utilization: Annotated[float | None, From("utilization")] = Field(
        description="value / limit; above 1 fails."
    )
    fix: Annotated[str | None, From("fix")]


class ProvenanceOut(BaseModel):
    model_config = ConfigDict(frozen=True)

    kind: Annotated[ProvenanceKind, From("kind")]
    source: Annotated[str, From("source")]


class TorqueOut(BaseModel):
    inertia_nm: Annotated[float, From("inertia_nm", "torque")]
    inertia_screw_nm: Annotated[float, From("inertia_screw_nm", "torque")]
    inertia_mass_nm: Annotated[float, From("inertia_mass_nm", "torque")] = Field(
        description="m a lead / (2 pi eta): the accelerating force through the thread."
    )
    inertia_motor_nm: Annotated[float, From("inertia_motor_nm", "torque")] = Field(
        description="J_motor alpha: accelerating the motor's rotor (0 without its inertia)."
    )
    drag_nm: Annotated[float, From("drag_nm", "torque")]
    drag_range_nm: Annotated[list[float], From(("drag_min_nm", "drag_max_nm"), "torque")]
    load_nm: Annotated[float, From("load_nm", "torque")]
    total_nm: Annotated[float, From("total_nm", "torque")]
    breakaway_nm: Annotated[float, From("breakaway_nm", "torque")] = Field(
        description="Starting from rest: (F + m a) lead / (2 pi eta_static) + J alpha + drag."
    )
    safety_factor: Annotated[float, From("safety_factor")]
    required_nm: Annotated[float, From("required_nm", "torque")]
    note: str = TORQUE_NOTE
    peak_nm: Annotated[float | None, From("/quantities.motor_peak_nm", "torque")] = Field(
        default=None, description="Largest motor torque of the move's segments; null: no stroke."
    )
    rms_nm: Annotated[float | None, From("/quantities.motor_rms_nm", "torque")] = Field(
        default=None, description="RMS motor torque over the cycle; null: no stroke."
    )
    peak_motor_nm: Annotated[float, From("/quantities.peak_torque_nm", "torque")] = Field(
        description="The largest motor torque of any moving segment of either move or of "
        "starting from rest, rotor included, before the torque safety factor: what the "
        "drive must give at its peak (the results table's torque when a move is given).",
    )
    peak_segment: Annotated[str, From("peak_segment")] = Field(
        description="Where the peak motor torque occurs: 'starting from rest' (the "
        "break-away) or a moving segment of either move ('decelerating down').",
    )


class ProfileOut(BaseModel):
    kind: Annotated[Literal["trapezoid", "triangle"], From("kind")] = Field(
        description="A triangle when the stroke is too short to reach the top speed."
    )
    accel_time_s: Annotated[float, From("accel_time_s")]
    constant_time_s: Annotated[float, From("constant_time_s")]
    decel_time_s: Annotated[float, From("decel_time_s")]
    move_time_s: Annotated[float, From("move_time_s")]
    cycle_time_s: Annotated[float, From("cycle_time_s")] = Field(
        description="Out and back (up and down), each with its dwell."
    )
    peak_speed_mm_s: Annotated[float, From("peak_speed_m_s", "speed")] = Field(
        description="The top speed, or the triangle's peak."
    )


class SegmentOut(BaseModel):
    name: Annotated[Literal["accelerate", "constant", "decelerate", "dwell"], From("name")]
    direction: Annotated[Literal["up", "down", "out", "back"], From("direction")]
    duration_s: Annotated[float, From("duration_s")]
    rpm: Annotated[float, From("rpm")] = Field(description="The screw's top speed in the segment.")
    thrust_n: Annotated[float, From("thrust_n", "force")] = Field(
        description="Against the motion; negative: the load drives."
    )
    torque_nm: Annotated[float, From("torque_nm", "torque")] = Field(
        description="Motor torque; negative: the motor brakes."
    )
    curve_nm: Annotated[float | None, From("curve_nm", "torque")] = Field(
        default=None,
        description="The motor's usable torque at the segment's top speed (its curve over "
        "the stepper margin), which the torque-speed curve check holds the torque times the "
        "safety factor against; null without a curve.",
    )
    governs: Annotated[bool, From("governs")] = Field(
        default=False,
        description="The segment that governs the motor: nearest its curve, or the largest "
        "torque without one.",
    )


class CriticalSpeedOut(BaseModel):
    theoretical_rpm: Annotated[float, From("theoretical_rpm")]
    allowed_rpm: Annotated[float, From("allowed_rpm")]
    margin: Annotated[float, From("margin")] = Field(
        description="allowed_rpm / rpm: how many times the speed fits."
    )
    safety_factor: Annotated[float, From("safety_factor")]
    end_fixity: Annotated[str, From("end_fixity")]


class BucklingOut(BaseModel):
    applies: Annotated[bool, From("applies")]
    critical_load_n: Annotated[float, From("critical_load_n", "force")] = Field(
        description="Euler, or Johnson below the transition."
    )
    allowed_load_n: Annotated[float, From("allowed_load_n", "force")]
    safety_factor: Annotated[float, From("safety_factor")]
    slenderness: Annotated[float, From("slenderness")] = Field(
        description="(L / sqrt(k)) / (d_r / 4)."
    )
    transition_slenderness: Annotated[float | None, From("transition_slenderness")] = Field(
        description="sqrt(2 pi^2 E / S_y): Johnson below it; null without a yield strength."
    )
    mode: Annotated[Literal["euler", "johnson"], From("mode")]
    root_stress_mpa: Annotated[float, From("root_stress_pa", "pressure")] = Field(
        description="Von Mises stress at the root: the peak thrust over the root area with "
        "the shear of the torque the screw carries with it."
    )
    yield_strength_mpa: Annotated[float | None, From("yield_strength_pa", "pressure")]


class PVOut(BaseModel):
    value_mpa_m_s: Annotated[float, From("value_pa_m_s", "pv")]
    limit_mpa_m_s: Annotated[float | None, From("limit_pa_m_s", "pv")]
    pressure_mpa: Annotated[float, From("pressure_pa", "pressure")]
    surface_speed_m_s: Annotated[float, From("surface_speed_m_s")]
    max_load_n: Annotated[float | None, From("max_load_n", "force")]
    max_speed_mm_s: Annotated[float | None, From("max_speed_m_s", "speed")]


class HoldingTorqueOut(BaseModel):
    seed_method_nm: Annotated[float, From("holding_torque_seed_nm", "torque")] = Field(
        description="Seed: F lead eta / 2 pi, forward eta."
    )
    physics_nm: Annotated[float, From("holding_torque_physics_nm", "torque")] = Field(
        description="F lead eta_b / 2 pi, back-drive eta, static mu."
    )
    brake_nm: Annotated[float, From("brake_nm", "torque")] = Field(
        description="Holding torque needed: the larger of the two; 0 when self-locking with "
        "margin (before the torque safety factor)."
    )
    available_nm: Annotated[float | None, From("app.brake_torque_nm", "torque")] = Field(
        description="The brake or holding torque given."
    )


class LifeOut(BaseModel):
    model: Annotated[
        Literal["rated", "wear", "l10"],
        From("model"),
        Field(
            description="rated: the seed's rated travel; wear: the nut's wear by Archard's "
            "law (an ISO or other nut the seed rates none), its band the wear rate's "
            "published 3:1 scatter; l10: a ball nut's L10 fatigue life (ISO 3408-5) at the "
            "cycle's cubic mean load, one value"
        ),
    ]
    travel_million_cm: Annotated[
        list[float], From(("travel_min_m", "travel_max_m"), via=million_cm)
    ]
    travel_km: Annotated[list[float], From(("travel_min_m", "travel_max_m"), via=km)]
    years: Annotated[list[float] | None, From(("years_min", "years_max"))]
    hours: Annotated[
        list[float], From("hours"), Field(description="Hours of running at the top speed")
    ]
    cycles: Annotated[
        list[float] | None,
        From("cycles"),
        Field(description="Cycles out and back over the stroke (with a stroke)"),
    ]
    note: Annotated[str, From("note")]


class AccuracyOut(BaseModel):
    lead_error_mm: Annotated[float | None, From("lead_error_m", "length")]
    repeatability_mm: Annotated[float | None, From("repeatability_m", "length")]
    backlash_mm: Annotated[list[float], From(("backlash_min_m", "backlash_max_m"), "length")]
    thermal_growth_mm: Annotated[float | None, From("thermal_growth_m", "length")]


class OutgassingOut(BaseModel):
    hours: Annotated[float, From("0")]
    weight_loss_percent: Annotated[float, From("1")]


class RestOut(BaseModel):
    field: Annotated[str, From("field")] = Field(description="The catalog key.")
    label: Annotated[str, From("label")] = Field(description="The value in words.")
    kind: Annotated[str, From("kind")] = Field(
        description="Its provenance ('assumed'), or 'assumed range' for a ranged value."
    )
    hinges: Annotated[bool, From("hinges")] = Field(
        description="The pass fails at one end of this value's range."
    )


class SkipOut(BaseModel):
    check: Annotated[str, From("check")] = Field(description="The check's name.")
    label: Annotated[str, From("label")]
    missing: Annotated[list[str], From("missing")] = Field(
        description="The values this screw lacks that the check reads, in words."
    )


class VerdictOut(BaseModel):
    """Why this screw: what governs it, what that rests on, what to watch."""

    governs: Annotated[str | None, From("governs")] = Field(
        description="The governing check: the rejecting check closest to its limit."
    )
    governs_label: Annotated[str, From("governs_label")]
    utilization: Annotated[float | None, From("utilization")] = Field(
        description="The governing check's demand / capacity; null for a yes/no check."
    )
    margin: Annotated[float | None, From("margin")] = Field(
        description="1 - utilization: the share of the governing limit left."
    )
    rests_on: Annotated[list[RestOut], From("rests_on")] = Field(
        description="Assumed catalog values the governing check reads, and the ranged "
        "values the pass hinges on."
    )
    watch: Annotated[list[str], From("watch", via=phrase_texts)] = Field(
        description="Warnings, the next-closest limit, power-off holding, a marginal pass."
    )
    text: Annotated[str, From("text", via=phrase_text)] = Field(
        description="All of it in one or two sentences."
    )
    skipped: Annotated[list[SkipOut], From("skipped")] = Field(
        description="Checks that run for this application but could not for this screw, "
        "each with the values it lacks."
    )
    not_applicable: Annotated[list[str], From("not_applicable")] = Field(
        description="Checks that do not apply to this kind of screw (a leadscrew nut's "
        "PV, pressure, speed, design-load, wear and heat checks on a ball screw): not "
        "counted as skipped."
    )
    summary: Annotated[str, From("summary", via=phrase_text)] = Field(
        description="Passes or fails in one line; never 'passes every check' when a check "
        "could not run, and then which did not and why."
    )


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
        description="mu_static >= cos(a_n) tan(lambda)."
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
        description="Its margin, holding at 1 or more: the larger of the thread's (the "
        "longest lead that self-locks at f mu_s over the lead) and the brake's or detent "
        "torque's over the torque needed; null as above.",
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
    pv: Annotated[PVOut, From("pv")]
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
        "provenance of the values it rests on ('user' for the user's own limit)."
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
        description="Catalog field -> provenance, for the fields this candidate's numbers use."
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
VERDICT = RANKED + " verdict"
#: The verdict in the compact select, without what the candidate already gives or the
#: response names once: the governing check and its utilisation are the candidate's
#: ``governing_check`` and ``utilization``, the margin is 1 - that utilisation, the
#: check's label is at /api/v1/checks, a catalog value's label is in the response's
#: ``labels``, whether the pass hinges on a value is whether ``hinges_on`` names it, and
#: the sentence is these in words.
COMPACT_VERDICT = {"verdict": {"rests_on": {"field": True, "kind": True}, "watch": True}}
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
            VERDICT,
        ),
        view_of("row"),
    ),
    "summary": merged(whole(NAMED, RANKED), COMPACT_VERDICT, view_of("summary")),
    "rejected": merged(whole("id governing_check failed"), view_of("rejected")),
    "csv": view_of("csv"),
    "full": whole(*CandidateOut.model_fields),
}


def view_model(model: type[BaseModel], view: View, name: str) -> type[BaseModel]:
    """The model of one view of ``model``: its fields in the view, in the model's order,
    each with its description and default; a nested model cut to its own view (named
    ``<Model><name>``, e.g. TorqueSummaryOut). For OpenAPI and for validating a view."""
    unknown = set(view) - set(model.model_fields)
    if unknown:
        raise ValueError(f"{model.__name__} has no field {', '.join(sorted(unknown))}")
    fields: dict[str, Any] = {}
    for field_name, info in model.model_fields.items():
        part = view.get(field_name)
        if part is None:
            continue
        annotation = info.annotation if part is True else _cut(info.annotation, part, name)
        fields[field_name] = (annotation, info)
    title = f"{model.__name__.removesuffix('Out')}{name}Out"
    return create_model(title, __doc__=model.__doc__, **fields)


def _cut(annotation: Any, view: View, name: str) -> Any:
    """``annotation`` with its model (alone, optional, or in a list) cut to ``view``."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return view_model(annotation, view, name)
    origin = get_origin(annotation)
    if origin is None:
        return annotation
    args = tuple(_cut(a, view, name) for a in get_args(annotation))
    if origin in (UnionType, Union):
        return reduce(operator.or_, args)
    return GenericAlias(origin, args)


#: The compact select's candidate and rejected candidate, and the page's row, as models.
CandidateSummaryOut = view_model(CandidateOut, VIEWS["summary"], "Summary")
RejectedSummaryOut = view_model(CandidateOut, VIEWS["rejected"], "Rejected")
