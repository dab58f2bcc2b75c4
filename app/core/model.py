"""Plain data types of the core: the application, one screw, checks and results (SI);
the cycle in time (profiles, segments) is ``timeline``'s."""

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, fields
from operator import attrgetter
from typing import Any, Literal, Protocol, TypeVar, get_args

from app.core.phrase import Phrase

#: How the screw's ends are held, from the most flexible to the stiffest: the critical
#: speed and the buckling load rise in this order (``formulas.critical_speed``,
#: ``formulas.buckling``).
EndFixity = Literal["fixed-free", "simple-simple", "fixed-simple", "fixed-fixed"]
#: The end fixities in that order.
FIXITY_ORDER: tuple[EndFixity, ...] = get_args(EndFixity)
Orientation = Literal["horizontal", "vertical"]
CoatingChoice = Literal["auto", "tfe", "none"]
#: How the user's load acts: by the orientation (a weight when vertical, against the
#: motion when horizontal), against the motion both ways (friction, cutting), or one way,
#: against the up (out) move (a weight, spring or press).
LoadDirection = Literal["auto", "opposes", "fixed"]
#: What the holding torque given is: a brake's (holds with the power off) or a motor's
#: energised holding torque (a stepper's: holds only while the power is on).
HoldingSource = Literal["brake", "energised"]
#: How the nut is lubricated (its permissible PV's factor, ``formulas.pv_derating``).
Lubrication = Literal["dry", "greased", "oiled"]
RankBy = Literal["torque", "rms", "margin", "life", "size", "motor_margin"]
#: What a failed advice check does: warn (such a screw always ranks after every screw
#: without a warning), or reject the screw.
AdvicePolicy = Literal["warn", "reject"]
#: What kind of screw a candidate is: a sliding leadscrew or a ball screw.
ScrewType = Literal["lead", "ball"]
ProvenanceKind = Literal["seed", "standard", "handbook", "vendor", "derived", "assumed", "user"]

STANDARD_GRAVITY_M_S2 = 9.80665
#: A check passes up to this utilisation: 1 plus rounding, so that an offered remedy
#: (e.g. "reduce the axial load to 369.5 N") passes when applied exactly.
PASS_UTILIZATION = 1.0 + 1e-9
#: A fix proposes values this far inside the limit they are worked out from (a shorter
#: length, a larger size, a lower speed, a stronger motor), so that the fixed design does
#: not sit on the limit: a figure rounded for display would otherwise land at a
#: utilisation just above 1. ``checks.base.MARGIN_NOTE`` says so in the fix.
FIX_MARGIN = 0.05


def holds(margin: Any) -> Any:
    """A hold's margin holds at 1 or more (to the pass rounding, ``PASS_UTILIZATION``);
    NaN (no such hold) does not. A float or an array of margins.

    >>> holds(1.0 - 1e-12), holds(0.99), holds(float("nan"))
    (True, False, False)
    """
    return margin * PASS_UTILIZATION >= 1.0


@dataclass(frozen=True, slots=True)
class Provenance:
    """Where a catalog value comes from: kind and the source or rule behind it."""

    kind: ProvenanceKind
    source: str


#: The provenance of the axis's values that a check's capacity is (``Check.capacity_given``:
#: "motor_curve", "motor_rms_torque", "motor_holding", "motor_detent", "support_static",
#: "support_dynamic"): the user's
#: where typed in, else the library motor's or support unit's; a value missing is the
#: user's.
AxisProvenance = Mapping[str, Provenance]
#: The key of a library motor's continuous rating where its continuous duty zone narrows
#: it above its rated speed: a candidate whose cycle runs there reads it for
#: "motor_rms_torque" (``Candidate.provenance``).
RMS_ZONE = "motor_rms_zone"


@dataclass(frozen=True, slots=True)
class Move:
    """One move of a cycle, in SI: the signed distance [m] (above 0 up or out, below 0
    down or back), the top speed [m/s], the acceleration and deceleration [m/s^2] (0:
    reached at once), the dwell after it [s], the mass it moves [kg], and the external
    load on it [N] with how it acts (``LoadDirection``: ``auto`` a weight on a vertical
    axis and against the motion on a horizontal one, ``opposes`` against the motion,
    ``fixed`` against the up or out move, as a weight, spring or press does)."""

    distance_m: float
    speed_m_s: float
    accel_m_s2: float
    decel_m_s2: float
    dwell_s: float = 0.0
    moving_mass_kg: float = 0.0
    load_n: float = 0.0
    load_direction: LoadDirection = "auto"


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
    #: The friction coefficient of the guides that carry the moving mass's weight on a
    #: horizontal axis [-] (``motion.guide_friction_n``; 0: none counted).
    guide_friction: float = 0.0
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
    #: The duty as hours of running a day, instead of cycles (``motion.cycles_per_day``).
    hours_per_day: float | None = None
    critical_speed_safety_factor: float = 0.8
    buckling_safety_factor: float = 0.5
    torque_safety_factor: float = 1.0
    stepper_torque_margin: float = 1.5
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
    #: ascending (empty: none), continuous (RMS) torque rating, and its continuous duty
    #: zone as (rpm, N m) points (empty: the rating at every speed).
    motor_inertia_kg_m2: float | None = None
    #: The coupling between motor and screw: its rotary inertia [kg m^2], turning with
    #: the screw (the load the motor accelerates besides its rotor; None: none).
    coupling_inertia_kg_m2: float | None = None
    motor_curve: tuple[tuple[float, float], ...] = ()
    motor_rms_torque_nm: float | None = None
    motor_rms_curve: tuple[tuple[float, float], ...] = ()
    #: The stepper's controller: full step angle [deg] (None: no controller checks),
    #: microsteps per full step, and the controller's highest step rate [1/s].
    step_angle_deg: float | None = None
    microsteps: int = 1
    max_step_rate_hz: float | None = None
    #: A library motor's id (its curve and inertia arrive in the fields above), and a
    #: stepper's datasheet values for the pull-out model: drive voltage [V], phase
    #: current [A] (set as RMS or, by default, as the sine's peak), winding resistance
    #: [ohm] and inductance [H], holding torque [N m].
    motor: str | None = None
    motor_supply_v: float | None = None
    motor_phase_current_a: float | None = None
    motor_current_rms: bool = False
    motor_resistance_ohm: float | None = None
    motor_inductance_h: float | None = None
    motor_holding_torque_nm: float | None = None
    load_direction: LoadDirection = "auto"
    #: What ``brake_torque_nm`` is; the motor's detent torque, which holds with the power
    #: off (None: not given); the factor on the holding torque (None: the torque factor,
    #: for a brake at least its service factor, ``holding.BRAKE_SERVICE_FACTOR``).
    holding_source: HoldingSource = "brake"
    detent_torque_nm: float | None = None
    brake_safety_factor: float | None = None
    #: The nut's length, in place of the catalog's (None: the catalog's) [m].
    nut_length_m: float | None = None
    lubrication: Lubrication = "dry"
    #: The thrust bearing (the fixed-side support unit): a library unit's id (its ratings
    #: arrive in the two fields after it unless given), its axial dynamic and static load
    #: ratings [N] (None: not checked), and the static safety factor on the peak thrust.
    support_unit: str | None = None
    support_dynamic_n: float | None = None
    support_static_n: float | None = None
    support_static_safety_factor: float = 2.0
    #: The operating factor f_w on the mean load of a ball nut and of the thrust bearing
    #: for their L10 lives (the axis's vibration and shocks load both) [-], and the
    #: static safety factor f_s on a ball nut's peak thrust against C0a [-].
    ball_load_factor: float = 1.2
    ball_static_safety_factor: float = 2.0
    #: The longest span from the thrust bearing to the nut [m]: the column that buckles
    #: (None: the screw's length).
    bearing_to_nut_m: float | None = None
    #: The load held at rest must stay held with the power off: by the thread
    #: self-locking with the friction margin, a brake, or a stepper's detent torque.
    hold_power_off: bool = True
    #: The cycle as its moves, each with its own distance, speed, ramps, dwell, mass and
    #: load (empty: out and back over the stroke from the scalar inputs above,
    #: ``motion.cycle``).
    moves: tuple[Move, ...] = ()

    @property
    def lubricated(self) -> bool:
        """The nut is greased or oiled."""
        return self.lubrication != "dry"

    @property
    def lubrication_counted(self) -> Lubrication:
        """The lubrication a rating may count on: the nut's, but none in a vacuum, where
        oil and grease evaporate (the vacuum advice warns of them)."""
        return "dry" if self.vacuum else self.lubrication

    @property
    def oil_reaches_nut(self) -> bool:
        """Oil or grease meets the screw and nut: oil is present around the axis, or the
        nut is lubricated."""
        return self.oil_present or self.lubricated


@dataclass(frozen=True, slots=True)
class ScrewSpec:
    """One screw-and-nut candidate (series x size x lead x coating), SI units.

    Optional limits (None, or an empty table) are not checked: a custom screw may have no
    design load. The nut's axial play (``backlash_min_m``, ``backlash_max_m``) is None
    where nothing gives it (a screw of one's own without a catalog nut), never 0. A
    family's own rules arrive as data: ``traverse_bands`` is its table of
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
    backlash_min_m: float | None = None
    backlash_max_m: float | None = None
    life_min_m: float | None = None
    life_max_m: float | None = None
    #: a leadscrew's cumulative lead error per length of travel (the seed's lead accuracy)
    lead_accuracy_m_per_m: float | None = None
    repeatability_m: float | None = None
    temperature_min_c: float | None = None
    temperature_max_c: float | None = None
    oil_compatible: bool = True
    #: the nut's friction, pressure and wear ratings are a lubricated nut's (a bronze
    #: nut): run dry it is not rated by them
    lubricated_rating: bool = False
    #: such a nut's running and static friction run dry (None: none given), which the
    #: candidate table takes for an axis that runs it dry (``table.as_run``)
    dry_friction_dynamic: float | None = None
    dry_friction_static: float | None = None
    outgassing: tuple[tuple[float, float], ...] = ()
    material_name: str = ""
    nut_material: str = ""
    family_id: str = ""
    variant: str = ""
    traverse_bands: tuple[tuple[float, float, float], ...] = ()
    provenance: Mapping[str, Provenance] = field(default_factory=dict)
    yield_strength_pa: float | None = None
    #: The screw material's thermal conductivity [W/(m K)] (None: no heat balance).
    thermal_conductivity_w_m_k: float | None = None
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
    #: A sliding nut's flank pressure in motion [Pa] (from its maker's allowable dynamic
    #: thrust): its rating in motion is this pressure over the engaged flank area (None:
    #: rated otherwise).
    dynamic_pressure_pa: float | None = None
    nut_pv_limit_pa_m_s: float | None = None
    max_sliding_speed_m_s: float | None = None
    #: The nut's specific wear rate against the screw [m^2/N = m^3/(N m)] and the wear
    #: depth it may lose, as a fraction of its flank height (None: no wear rating).
    wear_rate_m2_n: float | None = None
    allowed_wear_fraction: float | None = None
    #: For each catalog value given with a range: the ScrewSpec fields at its low and at
    #: its high end (derived values recomputed), for re-screening at either end.
    assumption_ends: Mapping[str, tuple[Mapping[str, float], Mapping[str, float]]] = field(
        default_factory=dict
    )
    #: A ball screw ("ball") or a sliding leadscrew ("lead"). A ball nut's ratings: the
    #: basic dynamic and static axial load ratings Ca and C0a [N], its ball diameter [m],
    #: the maker's DN speed limit [mm rpm] and the lead accuracy grade (None or empty:
    #: not a ball screw, or not published).
    screw_type: ScrewType = "lead"
    dynamic_load_n: float | None = None
    static_load_n: float | None = None
    ball_diameter_m: float | None = None
    #: A ball screw's pitch circle (ball-centre) diameter d0 [m], its nominal diameter
    #: (ISO 3408-1), on which its lead angle is taken (None: not given; the lead angle is
    #: then taken on (OD + RD) / 2).
    pitch_circle_diameter_m: float | None = None
    dn_limit_mm_rpm: float | None = None
    #: The published rule a ball screw's maker rates its critical speed by, as its family
    #: declares it (``critical_speed.MAKER_RULES``); None: not declared, and a ball screw
    #: is rated by the lowest of the published rules (``rated_critical_speed_rpm``).
    critical_speed_rule: str | None = None
    #: The published buckling rule a ball screw's maker rates its column by, as its family
    #: declares it (``column_rules.BUCKLING_RULES``); None: not declared, and a ball screw's
    #: column is rated by the lowest published rule (``column_rules.rated_column_load``).
    buckling_rule: str | None = None
    accuracy_grade: str = ""
    #: a ball nut's axial preload [N] (0: a nut with play; None: not a ball screw)
    preload_n: float | None = None
    #: A ball screw's ISO 3408-3 tolerance class: the travel variation it allows within
    #: any 300 mm, v300p [m], and for a positioning class its maker's table of the limit
    #: deviation e_p by useful travel, rows of (useful travel up to [m], e_p [m]); without
    #: a table the transport rule applies (``accuracy.ball_travel_deviation``). A ball
    #: screw has no lead accuracy per length (``lead_accuracy_m_per_m`` None): v300p is
    #: not a rate.
    travel_variation_300mm_m: float | None = None
    travel_deviation_bands: tuple[tuple[float, float], ...] = ()


class Judged(Protocol):
    """What reading a check's verdict needs of its result."""

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


#: ScrewSpec's fields in its constructor's order, read together, and each one's place.
_FIELDS = tuple(f.name for f in fields(ScrewSpec))
_ALL_VALUES = attrgetter(*_FIELDS)
_PLACE = {name: i for i, name in enumerate(_FIELDS)}


def at_values(screw: ScrewSpec, changes: Mapping[str, object]) -> ScrewSpec:
    """``screw`` with some of its values replaced (one end of a range, a friction run
    dry): what ``dataclasses.replace`` gives, built from the values read in one call (the
    catalog's 7,500 variants are built at every start: half the time ``replace`` takes)."""
    values: list[Any] = list(_ALL_VALUES(screw))
    for name, value in changes.items():
        values[_PLACE[name]] = value
    return ScrewSpec(*values)


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
    """The nut's PV at the thrust and linear speed it is judged at
    (``quantities.pv_point``), against its permissible PV."""

    force_n: float
    speed_m_s: float
    value_pa_m_s: float
    limit_pa_m_s: float | None
    pressure_pa: float
    surface_speed_m_s: float
    contact_area_m2: float
    max_load_n: float | None
    max_speed_m_s: float | None


@dataclass(frozen=True, slots=True)
class Accuracy:
    lead_error_m: float | None
    repeatability_m: float | None
    backlash_min_m: float | None
    backlash_max_m: float | None
    thermal_growth_m: float | None
    #: the screw's growth from its nut's friction heat (``duty.heat_growth``; None: not
    #: counted)
    heat_growth_m: float | None


@dataclass(frozen=True, slots=True)
class Change:
    """Application inputs (core names, SI) that, changed together, admit a candidate."""

    inputs: Mapping[str, float]
    admits: str


@dataclass(frozen=True, slots=True)
class Remedy:
    """A change of the application verified by screening again with it made
    (``app.core.remedy``): its inputs (core names, SI; ``end_fixity`` a word), how many
    candidates then pass, and the lowest governing utilisation among them."""

    inputs: Mapping[str, float | str]
    passing: int
    utilization: float


@dataclass(frozen=True, slots=True)
class Summary:
    """Why nothing (or little) passes, and the input changes that would admit the nearest;
    when nothing passes, the verified remedies, or why no screw can do it."""

    most_excluding_check: str | None
    most_excluding_count: int
    best_rejected_id: str | None
    input_change: Mapping[str, float]
    message: Phrase
    changes: tuple[Change, ...] = ()
    remedies: tuple[Remedy, ...] = ()
    impossible: Phrase | None = None
