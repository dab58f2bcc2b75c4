"""Input and output models of the API, shared with the pages (pydantic v2).

Field names carry their units. Inputs are validated here (finite, in range, known enum
values); the application input ``ApplicationIn`` is generated from the field table in
``app.inputs`` and converts itself to the SI ``Application`` of the core (``to_core``).
"""

import math
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    Tag,
    ValidationInfo,
    field_validator,
)

from app.core.model import ProvenanceKind
from app.inputs import ApplicationIn as ApplicationIn  # re-exported for the API and pages
from app.inputs import NotBool, bounded_number


class MaterialIn(BaseModel):
    model_config = ConfigDict(extra="forbid")

    youngs_modulus_pa: Annotated[float, bounded_number(1e6, 1e13, "Young's modulus [Pa]."), NotBool]
    density_kg_m3: Annotated[float, bounded_number(1.0, 1e5, "Density [kg/m^3]."), NotBool]
    yield_strength_pa: (
        Annotated[
            float,
            bounded_number(1e6, 1e10, "Yield strength [Pa]; without it, Euler buckling only."),
            NotBool,
        ]
        | None
    ) = None


class CatalogScrewIn(BaseModel):
    model_config = ConfigDict(extra="forbid")

    catalog_id: str = Field(max_length=100, description="A screw id from /api/v1/select.")


class CustomScrewIn(BaseModel):
    """A screw that is not in the catalog. Diameters and lead in mm."""

    model_config = ConfigDict(extra="forbid")

    outer_diameter_mm: Annotated[
        float, bounded_number(0.1, 1000.0, "Outer diameter [mm]."), NotBool
    ]
    root_diameter_mm: Annotated[
        float, bounded_number(0.05, 1000.0, "Root (minor) diameter [mm], below the outer."), NotBool
    ]
    lead_mm: Annotated[float, bounded_number(0.01, 1000.0, "Lead [mm]."), NotBool]
    thread_half_angle_deg: Annotated[
        float,
        bounded_number(0.0, 30.0, "Flank half-angle [deg]: 14.5 Acme, 15 trapezoidal."),
        NotBool,
    ] = 14.5
    friction_dynamic: Annotated[
        float, bounded_number(1e-3, 1.0, "Running friction coefficient."), NotBool
    ]
    friction_static: Annotated[
        float, bounded_number(1e-3, 1.0, "Static friction coefficient."), NotBool
    ]
    material: Literal["steel", "stainless-303"] | MaterialIn = "steel"
    drag_torque_nm: Annotated[
        float, bounded_number(0.0, 1e4, "Nut drag torque [N m]."), NotBool
    ] = 0.0
    inertia_kg_m2_per_m: (
        Annotated[
            float,
            bounded_number(
                1e-15, 1e3, "Inertia per length [kg m^2/m]; default: solid rod at the root."
            ),
            NotBool,
        ]
        | None
    ) = None
    pv_limit_mpa_m_s: (
        Annotated[float, bounded_number(1e-6, 1e3, "Nut PV limit [MPa m/s]."), NotBool] | None
    ) = None

    @field_validator("root_diameter_mm")
    @classmethod
    def _root_below_outer(cls, value: float, info: ValidationInfo) -> float:
        outer = info.data.get("outer_diameter_mm")
        if outer is not None and value >= outer:
            raise ValueError("must be smaller than outer_diameter_mm")
        return value

    @field_validator("friction_dynamic", "friction_static")
    @classmethod
    def _thread_drivable(cls, value: float, info: ValidationInfo) -> float:
        """A sliding thread can be driven only while mu tan(lambda) < cos(a_n) (Shigley)."""
        names = ("outer_diameter_mm", "root_diameter_mm", "lead_mm", "thread_half_angle_deg")
        if any(info.data.get(name) is None for name in names):
            return value  # an earlier field is invalid and already reported
        outer, root, lead, half_angle = (float(info.data[name]) for name in names)
        tan_lead = lead / (math.pi * (outer + root) / 2)
        limit = 0.99 * math.cos(math.radians(half_angle)) / tan_lead
        if value >= limit:
            raise ValueError(
                f"with this lead ({math.degrees(math.atan(tan_lead)):.1f} deg lead angle) the "
                f"thread cannot be driven at friction {value:g}: it must be below {limit:.3g}"
            )
        return value


def _screw_kind(data: Any) -> str:
    has_id = isinstance(data, dict) and "catalog_id" in data
    return "catalog" if has_id or isinstance(data, CatalogScrewIn) else "custom"


ScrewIn = Annotated[
    Annotated[CatalogScrewIn, Tag("catalog")] | Annotated[CustomScrewIn, Tag("custom")],
    Discriminator(_screw_kind),
]


class EvaluateIn(BaseModel):
    """One application and one screw: ``{"catalog_id": ...}`` or a custom geometry."""

    model_config = ConfigDict(extra="forbid")

    application: ApplicationIn
    screw: ScrewIn


class CheckOut(BaseModel):
    name: str
    label: str
    kind: Literal["limit", "advice"] = Field(
        description="A limit rejects a candidate; advice is reported beside it."
    )
    passed: bool
    value: float | None = Field(description="Demand, in ``unit``; null for yes/no checks.")
    limit: float | None = Field(description="Capacity, in ``unit``; null for yes/no checks.")
    unit: str
    utilization: float | None = Field(description="value / limit; above 1 fails.")
    message: str
    formula: str
    sources: list[str]
    fix: str | None


class ProvenanceOut(BaseModel):
    kind: ProvenanceKind
    source: str


class TorqueOut(BaseModel):
    inertia_nm: float
    inertia_screw_nm: float
    inertia_mass_nm: float = Field(
        description="m a lead / (2 pi eta): the accelerating force through the thread."
    )
    drag_nm: float
    drag_range_nm: list[float]
    load_nm: float
    total_nm: float
    breakaway_nm: float = Field(
        description="Starting from rest: (F + m a) lead / (2 pi eta_static) + J alpha + drag."
    )
    safety_factor: float
    required_nm: float
    note: str
    peak_nm: float | None = Field(
        default=None, description="Largest motor torque of the move's segments; null: no stroke."
    )
    rms_nm: float | None = Field(
        default=None, description="RMS motor torque over the cycle; null: no stroke."
    )


class ProfileOut(BaseModel):
    kind: Literal["trapezoid", "triangle"] = Field(
        description="A triangle when the stroke is too short to reach the top speed."
    )
    accel_time_s: float
    constant_time_s: float
    decel_time_s: float
    move_time_s: float
    cycle_time_s: float = Field(description="Out and back (up and down), each with its dwell.")
    peak_speed_mm_s: float = Field(description="The top speed, or the triangle's peak.")


class SegmentOut(BaseModel):
    name: Literal["accelerate", "constant", "decelerate", "dwell"]
    direction: Literal["up", "down", "out", "back"]
    duration_s: float
    rpm: float = Field(description="The screw's top speed in the segment.")
    thrust_n: float = Field(description="Against the motion; negative: the load drives.")
    torque_nm: float = Field(description="Motor torque; negative: the motor brakes.")


class CriticalSpeedOut(BaseModel):
    theoretical_rpm: float
    allowed_rpm: float
    margin: float = Field(description="allowed_rpm / rpm: how many times the speed fits.")
    safety_factor: float
    end_fixity: str


class BucklingOut(BaseModel):
    applies: bool
    critical_load_n: float = Field(description="Euler, or Johnson below the transition.")
    allowed_load_n: float
    safety_factor: float
    slenderness: float = Field(description="(L / sqrt(k)) / (d_r / 4).")
    transition_slenderness: float | None = Field(
        description="sqrt(2 pi^2 E / S_y): Johnson below it; null without a yield strength."
    )
    mode: Literal["euler", "johnson"]
    root_stress_mpa: float = Field(description="Peak thrust over the root area.")
    yield_strength_mpa: float | None


class PVOut(BaseModel):
    value_mpa_m_s: float
    limit_mpa_m_s: float | None
    pressure_mpa: float
    surface_speed_m_s: float
    max_load_n: float | None
    max_speed_mm_s: float | None


class HoldingTorqueOut(BaseModel):
    seed_method_nm: float = Field(description="Seed: F lead eta / 2 pi, forward eta.")
    physics_nm: float = Field(description="F lead eta_b / 2 pi, back-drive eta, static mu.")
    brake_nm: float = Field(
        description="Holding torque needed: the larger of the two; 0 when self-locking with "
        "margin (before the torque safety factor)."
    )
    available_nm: float | None = Field(description="The brake or holding torque given.")


class LifeOut(BaseModel):
    travel_million_cm: list[float]
    years: list[float] | None
    note: str


class AccuracyOut(BaseModel):
    lead_error_mm: float | None
    repeatability_mm: float | None
    backlash_mm: list[float]
    thermal_growth_mm: float | None


class OutgassingOut(BaseModel):
    hours: float
    weight_loss_percent: float


class CandidateBaseOut(BaseModel):
    """What every form of a candidate shows: its numbers as the results table and the
    charts read them, and its verdict."""

    id: str
    series: str
    series_name: str
    anti_backlash: bool
    outer_diameter_mm: float
    lead_mm: float
    coated: bool
    axial_load_n: float = Field(description="Running thrust at constant speed (PV uses it).")
    rpm: float
    efficiency: float = Field(
        description="Forward efficiency, Shigley's Acme form, dynamic friction (0-1)."
    )
    self_locking: bool = Field(description="mu_static >= cos(a_n) tan(lambda).")
    seed_rule_no_backdrive: bool = Field(description="The seed's rule of thumb: lead < OD / 8.")
    max_self_locking_lead_with_margin_mm: float
    holding_torque: HoldingTorqueOut
    torque: TorqueOut
    critical_speed: CriticalSpeedOut
    pv: PVOut
    life: LifeOut | None
    governing_check: str | None = Field(
        description="The check with the highest utilisation (or a failed yes/no check)."
    )
    governing_limit_provenance: ProvenanceKind | None = Field(
        description="How certain the governing check's limit is: the least certain "
        "provenance of the values it rests on ('user' for the user's own limit)."
    )
    passed: bool = Field(description="True when every limit passes (advice only warns).")
    robust: bool | None = Field(
        description="A pass that holds at both ends of every ranged (assumed) catalog value "
        "it rests on; false: marginal; null: not a pass."
    )
    hinges_on: list[str] = Field(
        description="The ranged catalog values at one end of whose range the pass fails."
    )
    profile: ProfileOut | None = Field(
        default=None, description="The move over the stroke; null without a stroke."
    )
    segments: list[SegmentOut] | None = Field(
        default=None, description="Each segment of the cycle; null without a stroke."
    )


class CandidateOut(CandidateBaseOut):
    """A candidate in full: every number, every check with its message, formula and fix,
    and the provenance of the catalog values it uses."""

    root_diameter_mm: float
    pitch_diameter_mm: float
    lead_angle_deg: float
    peak_axial_load_n: float = Field(
        description="Peak thrust, accelerating or braking the moving mass: F + m a. "
        "Buckling, root stress and the design load are judged on it."
    )
    efficiency_square_thread: float = Field(
        description="The manufacturer's square-thread form, for comparison (0-1)."
    )
    backdrive_efficiency: float = Field(
        description="The load driving the screw from rest: static friction; 0 = locks. With "
        "static friction below running friction (uncoated) it can exceed the forward value."
    )
    backdrive_efficiency_running: float = Field(
        description="The load driving the screw while it runs: dynamic friction."
    )
    self_locking_with_margin: bool = Field(
        description="Self-locking with static friction reduced by the self-locking factor."
    )
    max_self_locking_lead_mm: float = Field(description="Longest lead that still self-locks.")
    buckling: BucklingOut
    traverse_speed_limit_mm_s: float | None
    traverse_extrapolated: bool
    accuracy: AccuracyOut
    outgassing: list[OutgassingOut] | None
    checks: list[CheckOut]
    warnings: list[CheckOut] = Field(description="Failed advice: reported, not rejected.")
    fix: str | None = Field(description="For a rejected candidate, what would make it pass.")
    provenance: dict[str, ProvenanceOut] = Field(
        description="Catalog field -> provenance, for the fields this candidate's numbers use."
    )


class CandidateRowOut(CandidateBaseOut):
    """A candidate as a row of the results table (and a curve of its charts): each
    check's utilisation, not its message; the row's detail loads when opened."""

    utilization: dict[str, float | None] = Field(
        description="Check -> demand / capacity (null for a yes/no check)."
    )
    warned: list[str] = Field(description="The advice checks it fails: reported, not rejected.")


class CountsOut(BaseModel):
    evaluated: int
    passed: int
    rejected: int
    failed_by_check: dict[str, int]


class ChangeOut(BaseModel):
    inputs: dict[str, float] = Field(description="API input -> value that admits the screw.")
    admits: str = Field(description="The candidate the change admits.")


class SummaryOut(BaseModel):
    message: str
    most_excluding_check: str | None
    best_rejected_id: str | None
    input_change: dict[str, float]
    changes: list[ChangeOut] = Field(
        description="Feasible input changes, each admitting a near candidate (one click)."
    )


class FormulaOut(BaseModel):
    formula: str
    function: str
    source: str


class SelectionBaseOut(BaseModel):
    """What every form of a selection gives besides its candidates."""

    inputs: ApplicationIn
    counts: CountsOut
    summary: SummaryOut
    catalog_version: str
    share_url: str


class SelectOut(SelectionBaseOut):
    candidates: list[CandidateOut]
    rejected: list[CandidateOut]
    formulas: dict[str, FormulaOut] = Field(
        description="Quantity (dotted path in a candidate) -> formula, core function, source."
    )


class PageSelectionOut(SelectionBaseOut):
    """The results page's selection: the passing candidates as table rows; the rejected
    in full only when nothing passes (the charts and the advice are then about them)."""

    candidates: list[CandidateRowOut]
    rejected: list[CandidateOut]


class FormulasOut(BaseModel):
    formulas: dict[str, FormulaOut] = Field(
        description="Quantity (dotted path in a candidate) -> formula, core function, source."
    )


class CandidateSummaryOut(BaseModel):
    """A passing candidate as the compact select response gives it: the numbers the
    results table shows; ``detail=full`` (or POST /api/v1/evaluate) gives everything."""

    id: str
    series: str
    series_name: str
    anti_backlash: bool
    coated: bool
    outer_diameter_mm: float
    lead_mm: float
    rpm: float
    total_torque_nm: float
    efficiency: float
    self_locking: bool
    critical_speed_margin: float
    life_years: list[float] | None
    utilization: dict[str, float | None] = Field(
        description="Check name -> value / limit, for every check that applies."
    )
    governing_check: str | None
    governing_limit_provenance: ProvenanceKind | None
    passed: bool
    robust: bool | None
    hinges_on: list[str]
    warnings: list[str] = Field(description="Names of the failed advice checks.")


class SelectQuery(ApplicationIn):
    """The GET select's query: the application's fields and the response's form."""

    detail: Literal["summary", "full"] = Field(
        "summary",
        description="summary (default): passing candidates as the results table shows "
        "them, rejected ones as their failed checks with utilisation and fix, formulas at "
        "/api/v1/formulas (SelectSummaryOut); full: every number, check message, formula "
        "and provenance of every candidate, and the formulas table (SelectOut).",
    )

    @field_validator("*")
    @classmethod
    def _needs(cls, value: Any, info: ValidationInfo) -> Any:
        """The application's fields as ``ApplicationIn`` checks them; ``detail`` as it is."""
        if info.field_name == "detail":
            return value
        return super()._needs(value, info)

    def application(self) -> ApplicationIn:
        """The application's fields alone, as the body of a POST would give them."""
        values = {name: getattr(self, name) for name in ApplicationIn.model_fields}
        return ApplicationIn.model_construct(self.model_fields_set - {"detail"}, **values)


class FailedCheckOut(BaseModel):
    name: str
    kind: Literal["limit", "advice"]
    utilization: float | None = Field(description="value / limit; above 1 fails.")
    fix: str | None


class RejectedSummaryOut(BaseModel):
    """A rejected candidate as the compact select response gives it."""

    id: str
    governing_check: str | None = Field(
        description="The failed limit with the highest utilisation (or the first failed "
        "yes/no check): what rejects it most."
    )
    failed: list[FailedCheckOut] = Field(description="Every failed check, in check order.")
    fix: str | None = Field(description="What would make it pass.")


class SelectSummaryOut(BaseModel):
    """The default select response; ``detail=full`` gives ``SelectOut``."""

    detail: Literal["summary"]
    inputs: ApplicationIn
    candidates: list[CandidateSummaryOut]
    rejected: list[RejectedSummaryOut]
    counts: CountsOut
    summary: SummaryOut
    catalog_version: str
    share_url: str
    formulas_url: str = Field(description="The formulas table (GET), the same for every query.")


class EvaluateOut(BaseModel):
    inputs: ApplicationIn
    candidate: CandidateOut
    catalog_version: str
    formulas: dict[str, FormulaOut]


class SourcedOut(BaseModel):
    value: Any
    unit: str
    provenance: ProvenanceOut


class SeriesOut(BaseModel):
    id: str
    name: str
    family: str
    family_name: str
    type: str
    file: str
    fields: dict[str, SourcedOut]
    candidate_ids: list[str]


class SeriesListOut(BaseModel):
    catalog_version: str
    series: list[SeriesOut]


class CheckInfoOut(BaseModel):
    name: str
    label: str
    kind: Literal["limit", "advice"]
    description: str
    formula: str = Field(description="demand = ...; capacity = ... (or: passes when ...).")
    source: str
    sources: list[str] = Field(description="Catalog fields the check reads.")
    unit: str = Field(description="API unit of the check's value and limit.")


class ChecksOut(BaseModel):
    checks: list[CheckInfoOut]


class HealthOut(BaseModel):
    status: Literal["ok"]
    version: str
    catalog_version: str
    candidates: int


class ErrorDetail(BaseModel):
    field: str
    message: str


class ErrorOut(BaseModel):
    error: str
    detail: list[ErrorDetail]
