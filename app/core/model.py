"""Plain data types of the core: the application, one screw, checks and results (SI)."""

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Generic, Literal, Protocol, TypeVar

from app.core.phrase import Phrase, Quantity

EndFixity = Literal["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"]
Orientation = Literal["horizontal", "vertical"]
CoatingChoice = Literal["auto", "tfe", "none"]
#: How the user's load acts: by the orientation (a weight when vertical, against the
#: motion when horizontal), against the motion both ways (friction, cutting), or one way,
#: against the up (out) move (a weight, spring or press).
LoadDirection = Literal["auto", "opposes", "fixed"]
#: What the holding torque given is: a brake's (holds with the power off) or a motor's
#: energised holding torque (a stepper's: holds only while the power is on).
HoldingSource = Literal["brake", "energised"]
RankBy = Literal["torque", "margin", "life", "size", "motor_margin"]
#: What a failed advice check does: a warning only, rank the candidate lower, or reject.
AdvicePolicy = Literal["warn", "rank", "reject"]
ProvenanceKind = Literal["seed", "standard", "handbook", "vendor", "derived", "assumed", "user"]

STANDARD_GRAVITY_M_S2 = 9.80665
#: A check passes up to this utilisation: 1 plus rounding, so that an offered remedy
#: (e.g. "reduce the load to 369.5 N") passes when applied exactly.
PASS_UTILIZATION = 1.0 + 1e-9


@dataclass(frozen=True, slots=True)
class Provenance:
    """Where a catalog value comes from: kind and the source or rule behind it."""

    kind: ProvenanceKind
    source: str


@dataclass(frozen=True, slots=True)
class Application:
    """What the axis must do, in SI. Optional fields switch on optional checks."""

    load_n: float
    speed_m_s: float
    length_m: float
    lead_m: float | None = None
    accel_m_s2: float = 1.0
    moving_mass_kg: float = 0.0
    end_fixity: EndFixity = "fixed-simple"
    orientation: Orientation = "horizontal"
    #: True: a nut force up (out) pushes the screw onto its thrust bearing (the bearing at
    #: the end the nut leaves on the up or out move); False: it pulls the screw.
    compression: bool = True
    require_anti_backlash: bool = False
    coating: CoatingChoice = "auto"
    oil_present: bool = False
    vacuum: bool = False
    ambient_c: float = 20.0
    stroke_m: float | None = None
    cycles_per_day: float | None = None
    critical_speed_safety_factor: float = 0.8
    buckling_safety_factor: float = 0.5
    torque_safety_factor: float = 1.0
    max_torque_nm: float | None = None
    brake_torque_nm: float | None = None
    self_locking_friction_factor: float = 0.5
    advice: AdvicePolicy = "warn"
    required_life_years: float | None = None
    positioning_tolerance_m: float | None = None
    rank_by: RankBy = "torque"
    limit: int = 10
    #: Family ids to select from (empty: every family); a nut material (None: any).
    families: tuple[str, ...] = ()
    nut_material: str | None = None
    #: The move: deceleration (None: the acceleration) and the dwell after each move [s].
    decel_m_s2: float | None = None
    dwell_s: float = 0.0
    #: The motor: rotor inertia, torque-speed curve as (rpm, N m) points with rpm
    #: ascending (empty: none), and continuous (RMS) torque rating.
    motor_inertia_kg_m2: float | None = None
    motor_curve: tuple[tuple[float, float], ...] = ()
    motor_rms_torque_nm: float | None = None
    load_direction: LoadDirection = "auto"
    #: What ``brake_torque_nm`` is; the motor's detent torque, which holds with the power
    #: off (None: not given); the factor on the holding torque (None: the torque factor).
    holding_source: HoldingSource = "brake"
    detent_torque_nm: float | None = None
    brake_safety_factor: float | None = None
    #: The nut's length, in place of the catalog's (None: the catalog's) [m].
    nut_length_m: float | None = None


@dataclass(frozen=True, slots=True)
class ScrewSpec:
    """One screw-and-nut candidate (series x size x lead x coating), SI units.

    Optional limits (None, or an empty table) are not checked: a custom screw may have no
    design load. A family's own rules arrive as data: ``traverse_bands`` is its table of
    recommended linear speed by lead, (lead from [m], lead to [m], speed [m/s]), and
    ``max_length_m``, ``oil_compatible`` and the temperature range are per variant.
    ``variant`` names the nut or coating option of the family (e.g. "tfe", "bronze").
    ``provenance`` maps each catalog field name to where its value comes from.
    """

    id: str
    series_id: str
    series_name: str
    anti_backlash: bool
    coated: bool
    outer_diameter_m: float
    root_diameter_m: float
    lead_m: float
    thread_half_angle_rad: float
    friction_static: float
    friction_dynamic: float
    youngs_modulus_pa: float
    density_kg_m3: float
    screw_expansion_per_k: float
    inertia_kg_m2_per_m: float
    drag_torque_min_nm: float = 0.0
    drag_torque_max_nm: float = 0.0
    pv_limit_pa_m_s: float | None = None
    design_load_n: float | None = None
    max_length_m: float | None = None
    backlash_min_m: float = 0.0
    backlash_max_m: float = 0.0
    life_min_m: float | None = None
    life_max_m: float | None = None
    lead_accuracy_m_per_m: float | None = None
    repeatability_m: float | None = None
    temperature_min_c: float | None = None
    temperature_max_c: float | None = None
    oil_compatible: bool = True
    outgassing: tuple[tuple[float, float], ...] = ()
    material_name: str = ""
    nut_material: str = ""
    family_id: str = ""
    variant: str = ""
    traverse_bands: tuple[tuple[float, float, float], ...] = ()
    provenance: Mapping[str, Provenance] = field(default_factory=dict)
    yield_strength_pa: float | None = None
    #: Thread pitch P, the standard's pitch diameter d2 and engaged flank height H1 [m],
    #: and the nut length whose engaged turns carry the load (None: not given).
    pitch_m: float | None = None
    flank_pitch_diameter_m: float | None = None
    flank_height_m: float | None = None
    nut_length_m: float | None = None
    #: The nut material's allowable contact pressure by sliding speed, rows of
    #: (sliding speed [m/s], pressure [Pa]) interpolated; its maximum pressure [Pa], its PV
    #: limit over the engaged flank area [Pa m/s] and its maximum sliding speed [m/s].
    bearing_pressure_table: tuple[tuple[float, float], ...] = ()
    max_pressure_pa: float | None = None
    nut_pv_limit_pa_m_s: float | None = None
    max_sliding_speed_m_s: float | None = None
    #: For each catalog value given with a range: the ScrewSpec fields at its low and at
    #: its high end (derived values recomputed), for re-screening at either end.
    assumption_ends: Mapping[str, tuple[Mapping[str, float], Mapping[str, float]]] = field(
        default_factory=dict
    )


class Judged(Protocol):
    """What reading a check's verdict needs of its result (full or brief)."""

    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> Literal["limit", "advice"]: ...
    @property
    def passed(self) -> bool: ...
    @property
    def utilization(self) -> float | None: ...


J = TypeVar("J", bound=Judged)


def failed_advice(checks: Iterable[J]) -> list[J]:
    """The advice checks that fail: reported beside the result, not rejecting it."""
    return [c for c in checks if c.kind == "advice" and not c.passed]


@dataclass(frozen=True, slots=True)
class CheckResult:
    """One check of one candidate: demand against capacity, with the message and the fix.

    ``value`` (demand) and ``limit`` (capacity) are SI in ``quantity``; None for yes/no
    checks. ``utilization`` = value / limit. ``sources`` names the catalog fields the check
    uses. The message, the fix and ``input_limits`` (application inputs any one of which,
    set to the given SI value, would make the check pass, e.g. {"load_n": 120.0}) are
    written when read: most results are ranked or counted, not read.
    """

    name: str
    label: str
    kind: Literal["limit", "advice"]
    passed: bool
    value: float | None
    limit: float | None
    quantity: Quantity | None
    utilization: float | None
    formula: str
    sources: tuple[str, ...]
    explanation: Callable[[], Phrase] = field(repr=False, compare=False)
    remedy: Callable[[], "Phrase | None"] = field(repr=False, compare=False)
    remedy_inputs: Callable[[], "Mapping[str, float] | None"] = field(repr=False, compare=False)

    @property
    def message(self) -> Phrase:
        return self.explanation()

    @property
    def fix(self) -> Phrase | None:
        return None if self.passed else self.remedy()

    @property
    def input_limits(self) -> Mapping[str, float] | None:
        if self.passed:
            return None
        limits = self.remedy_inputs()
        return dict(limits) if limits else None


@dataclass(frozen=True, slots=True)
class Torque:
    """Drive torque breakdown [N m] (seed: inertia + static drag + load)."""

    inertia_screw_nm: float
    inertia_mass_nm: float
    inertia_nm: float
    drag_nm: float
    drag_min_nm: float
    drag_max_nm: float
    load_nm: float
    total_nm: float
    breakaway_nm: float
    safety_factor: float
    required_nm: float
    angular_accel_rad_s2: float
    inertia_kg_m2: float


@dataclass(frozen=True, slots=True)
class CriticalSpeed:
    theoretical_rpm: float
    allowed_rpm: float
    margin: float
    safety_factor: float
    end_fixity: str


@dataclass(frozen=True, slots=True)
class Buckling:
    """The screw as a column under the peak thrust: Euler when slender, Johnson when short."""

    applies: bool
    critical_load_n: float
    allowed_load_n: float
    safety_factor: float
    slenderness: float
    transition_slenderness: float | None
    mode: Literal["euler", "johnson"]
    root_stress_pa: float
    yield_strength_pa: float | None


@dataclass(frozen=True, slots=True)
class PV:
    value_pa_m_s: float
    limit_pa_m_s: float | None
    pressure_pa: float
    surface_speed_m_s: float
    contact_area_m2: float
    max_load_n: float | None
    max_speed_m_s: float | None


@dataclass(frozen=True, slots=True)
class Life:
    travel_min_m: float
    travel_max_m: float
    years_min: float | None
    years_max: float | None


@dataclass(frozen=True, slots=True)
class Accuracy:
    lead_error_m: float | None
    repeatability_m: float | None
    backlash_min_m: float
    backlash_max_m: float
    thermal_growth_m: float | None


V = TypeVar("V")
SegmentName = Literal["accelerate", "constant", "decelerate", "dwell"]
Direction = Literal["up", "down", "out", "back"]


@dataclass(frozen=True, slots=True)
class Profile:
    """One move of the stroke: a trapezoid, or a triangle when the stroke is too short to
    reach the top speed; times [s] and the peak speed reached [m/s]. The cycle is the move
    out (up) and back (down), each followed by the dwell."""

    kind: Literal["trapezoid", "triangle"]
    accel_time_s: float
    constant_time_s: float
    decel_time_s: float
    move_time_s: float
    cycle_time_s: float
    peak_speed_m_s: float


@dataclass(frozen=True, slots=True)
class Segment(Generic[V]):
    """One segment of the cycle: its duration [s], the screw's top speed in it [rpm], the
    thrust against the motion [N] and the motor torque [N m] (negative: the motor brakes).
    ``V`` is an array (one element per candidate) or a float."""

    name: SegmentName
    direction: Direction
    duration_s: float
    rpm: V
    thrust_n: V
    torque_nm: V


@dataclass(frozen=True, slots=True)
class Motion:
    """The move and the motor torque over the cycle: its segments, the largest torque in
    magnitude and the RMS torque [N m]."""

    profile: Profile
    segments: tuple[Segment[float], ...]
    peak_nm: float
    rms_nm: float


@dataclass(frozen=True, slots=True)
class Evaluation:
    """Everything computed for one screw against one application."""

    screw: ScrewSpec
    axial_load_n: float
    peak_axial_load_n: float
    rpm: float
    pitch_diameter_m: float
    lead_angle_rad: float
    efficiency: float
    efficiency_square_thread: float
    backdrive_efficiency: float
    backdrive_efficiency_running: float
    self_locking: bool
    self_locking_with_margin: bool
    seed_rule_no_backdrive: bool
    max_self_locking_lead_m: float
    max_self_locking_lead_with_margin_m: float
    holding_torque_seed_nm: float
    holding_torque_physics_nm: float
    brake_torque_nm: float
    torque: Torque
    critical_speed: CriticalSpeed
    buckling: Buckling
    pv: PV
    traverse_speed_limit_m_s: float | None
    traverse_extrapolated: bool
    life: Life | None
    accuracy: Accuracy
    checks: tuple[CheckResult, ...]
    passed: bool
    governing_check: str | None
    governing_limit_provenance: ProvenanceKind | None
    max_utilization: float
    #: for a passing candidate: still passes at both ends of every ranged catalog value,
    #: and the values at one end of whose range it fails (None: not assessed)
    robust: bool | None = None
    hinges_on: tuple[str, ...] = ()
    #: the move profile and the torque of each segment (None: no stroke given)
    motion: Motion | None = None

    @property
    def failed_checks(self) -> tuple[CheckResult, ...]:
        """The failed limits: what rejects the candidate."""
        return tuple(c for c in self.checks if not c.passed and c.kind == "limit")

    @property
    def warnings(self) -> tuple[CheckResult, ...]:
        """Failed advice: reported beside the candidate, not a rejection."""
        return tuple(failed_advice(self.checks))


@dataclass(frozen=True, slots=True)
class Change:
    """Application inputs (core names, SI) that, changed together, admit a candidate."""

    inputs: Mapping[str, float]
    admits: str


@dataclass(frozen=True, slots=True)
class Summary:
    """Why nothing (or little) passes, and the input changes that would admit the nearest."""

    most_excluding_check: str | None
    most_excluding_count: int
    best_rejected_id: str | None
    input_change: Mapping[str, float]
    message: Phrase
    changes: tuple[Change, ...] = ()
