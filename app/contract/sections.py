"""The sections of a candidate's output model (``app.contract.schemas.CandidateOut``):
its checks, the torque and its parts, the move's profile and segments, critical speed,
buckling, PV, the holding torque, life, accuracy, outgassing and the verdict. Each
field declares where it comes from in the core's record (``app.contract.source``).
"""

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.contract.source import From, check_limit, check_unit, check_value, km, million_cm
from app.contract.source import text as phrase_text
from app.contract.source import texts as phrase_texts
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
    inertia_screw_nm: Annotated[float, From("inertia_screw_nm", "torque")] = Field(
        description="(J_screw + J_coupling) alpha: accelerating the screw and its coupling."
    )
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
        description="Starting from rest: (F + m a) lead / (2 pi eta_static) + J alpha + drag "
        "(a move the load drives: through the back-driven efficiency at static friction), "
        "the largest of every move's start."
    )
    safety_factor: Annotated[float, From("safety_factor")]
    required_nm: Annotated[float, From("required_nm", "torque")]
    note: str = TORQUE_NOTE
    peak_nm: Annotated[float | None, From("/quantities.motor.motor_peak_nm", "torque")] = Field(
        default=None, description="Largest motor torque of the move's segments; null: no stroke."
    )
    rms_nm: Annotated[float | None, From("/quantities.motor.motor_rms_nm", "torque")] = Field(
        default=None, description="RMS motor torque over the cycle; null: no stroke."
    )
    peak_motor_nm: Annotated[float, From("/quantities.torque.peak_torque_nm", "torque")] = Field(
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
        description="The motor's usable torque (its curve over the stepper margin) at the "
        "segment's top speed, for a ramp (accelerate, decelerate) the lowest from standstill "
        "to its top speed, which the torque-speed curve check holds the torque times the "
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
    judged_thrust_n: Annotated[float, From("force_n", "force")] = Field(
        description="The thrust the PV is judged at: the peak thrust at the top speed; in a "
        "cycle of moves, that of the move whose thrust times speed is largest."
    )
    judged_speed_mm_s: Annotated[float, From("speed_m_s", "speed")] = Field(
        description="The linear speed the PV is judged at, with judged_thrust_n."
    )
    value_mpa_m_s: Annotated[float, From("value_pa_m_s", "pv")]
    limit_mpa_m_s: Annotated[float | None, From("limit_pa_m_s", "pv")]
    pressure_mpa: Annotated[float, From("pressure_pa", "pressure")]
    surface_speed_m_s: Annotated[float, From("surface_speed_m_s")]
    max_load_n: Annotated[float | None, From("max_load_n", "force")]
    max_speed_mm_s: Annotated[float | None, From("max_speed_m_s", "speed")]


class HoldingTorqueOut(BaseModel):
    seed_method_nm: Annotated[float, From("holding_torque_seed_nm", "torque")] = Field(
        description="Seed: F lead eta / 2 pi, forward eta, where back-driving is likely; "
        "0 where the thread self-locks with the friction margin."
    )
    physics_nm: Annotated[float, From("holding_torque_physics_nm", "torque")] = Field(
        description="F lead eta_b / 2 pi, back-drive eta, static mu."
    )
    physics_with_margin_nm: Annotated[float, From("holding_torque_with_margin_nm", "torque")] = (
        Field(
            description="F lead eta_b / 2 pi, back-drive eta at the static mu times the "
            "self-locking friction factor: the friction a hold may count on."
        )
    )
    brake_nm: Annotated[float, From("brake_nm", "torque")] = Field(
        description="Holding torque needed: the larger of the seed's and the physics with "
        "margin; 0 when self-locking with margin (before the brake safety factor)."
    )
    brake_to_fit_nm: Annotated[float, From("brake_to_fit_nm", "torque")] = Field(
        description="The brake to fit: brake_nm times a brake's safety factor (the brake "
        "safety factor; when none is given, the torque safety factor and at least 1.5), "
        "the torque the holding check asks of a brake, whatever holds the load now; 0 when "
        "self-locking with margin."
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
    capped_by_wear: Annotated[
        bool,
        From("capped_by_wear"),
        Field(
            description="rated: whether the nut's wear life (Archard's law at the assumed "
            "wear rate) cuts the seed's rated travel at either end of the band"
        ),
    ]
    travel_million_cm: Annotated[
        list[float], From(("travel_min_m", "travel_max_m"), via=million_cm)
    ]
    travel_km: Annotated[list[float], From(("travel_min_m", "travel_max_m"), via=km)]
    years: Annotated[list[float] | None, From(("years_min", "years_max"))]
    hours: Annotated[
        list[float],
        From("hours"),
        Field(
            description="Hours of operation: the cycles times the cycle's time (moves, "
            "ramps and dwells) with a stroke; the travel at the top speed without one"
        ),
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
    backlash_mm: Annotated[
        list[float] | None,
        From(("backlash_min_m", "backlash_max_m"), "length"),
        Field(description="The nut's axial play, least and most (null: not given)"),
    ]
    thermal_growth_mm: Annotated[float | None, From("thermal_growth_m", "length")]
    heat_growth_mm: Annotated[
        float | None,
        From("heat_growth_m", "length"),
        Field(
            description="The screw's growth from its nut's friction heat, between the "
            "thrust bearing and the nut at the far end of the stroke (null: not counted: "
            "no stroke, a ball nut, or a screw without the values its heat balance reads)"
        ),
    ]


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
    partial: Annotated[list[SkipOut], From("partial")] = Field(
        description="Checks that ran without a value this screw lacks: judged on the "
        "terms they have, each with the values whose terms it left out (a positioning "
        "accuracy without the lead error of a screw with no lead accuracy)."
    )
    not_applicable: Annotated[list[str], From("not_applicable")] = Field(
        description="Checks that do not apply to this kind of screw (a leadscrew nut's "
        "PV, pressure, speed, design-load, wear and heat checks on a ball screw): not "
        "counted as skipped."
    )
    summary: Annotated[str, From("summary", via=phrase_text)] = Field(
        description="Passes or fails in one line; never 'passes every check' when a check "
        "could not run or ran without a value the screw lacks, and then which and why."
    )
