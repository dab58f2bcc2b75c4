"""Every number of one axis for many candidates at once: the operating point of each.

``operating_point(app, table)`` computes, over the table's columns, the speeds, loads,
torques, limits and margins that the checks and the reports read. The same arithmetic
serves one screw (a table of one) or the whole catalog; ``at(i)`` gives one
candidate's numbers as plain floats.

The numbers come in parts, each by what it describes and computed by its own module:
the axis's thrusts (``q.axis``), the torque breakdown (``q.torque``), the screw as a
shaft and a column (``q.column``), the nut under load (``q.nut``), its life
(``q.life``), its heat (``q.heat``), the travel's accuracy (``q.accuracy``), holding
with the power off (``q.holding``), the move against the motor (``q.motor``), the
thrust bearing (``q.support``) and the cycle's energy (``q.energy``). Each number's
name is unique across the parts, so a name alone finds it (``quantity``, ``PART_OF``).
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields
from operator import itemgetter
from typing import Any, Generic, TypeVar, cast, get_origin

import numpy as np

from app.core import column, drive, duty, holding, motion, nut, segments
from app.core.formulas import (
    geometry,
)
from app.core.formulas.declare import formula
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Move
from app.core.table import Array, CandidateTable, filled

V = TypeVar("V")


@formula(
    "F = load (+ m g when vertical, + mu_g m g when horizontal), the running thrust", "statics"
)
def axial_load(app: Application, lead: Move | None = None) -> float:
    """Running thrust on the nut at constant speed [N]: the load, plus m g when vertical
    (on the up move, or on the move against a load of fixed direction) or the guides'
    friction when horizontal (``motion.guide_friction_n``, on the out move); in a cycle
    of the user's own moves, the top-speed thrust of the move that starts hardest
    (``motion.lead_move``; ``lead``: that move when already worked out)."""
    if app.moves:
        return motion.running_thrust(app, motion.lead_move(app) if lead is None else lead)
    if app.orientation == "vertical":
        return app.load_n + app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return app.load_n + motion.guide_friction_n(app, app.moving_mass_kg)


@formula("F_peak = max |F_nut| over the segments of both moves and at rest", "Newton's second law")
def peak_axial_load(app: Application, forces: Sequence[float] = ()) -> float:
    """Peak thrust on the nut [N]: the largest force the nut exerts on the moving mass in
    any segment of either move or at rest (``motion.nut_force_forms``), so the running
    thrust plus m a accelerating against the load, or plus m d braking a mass that moves
    with it, whichever is larger (Newton's second law). ``forces``: those forces [N]
    when already worked out (``motion.nut_forces``).

    >>> peak_axial_load(Application(load_n=5.0, speed_m_s=0.1, length_m=0.5,
    ...                             moving_mass_kg=50.0, accel_m_s2=5.0))
    255.0
    >>> round(peak_axial_load(Application(load_n=0.0, speed_m_s=0.1, length_m=0.5,
    ...     moving_mass_kg=20.0, accel_m_s2=1.0, decel_m_s2=2.0, orientation="vertical")), 2)
    236.13
    """
    return max(abs(f) for f in forces or motion.nut_forces(app))


def move_points(app: Application, c: motion.Cycle, peak_n: float) -> list[tuple[float, float]]:
    """The thrust [N] and speed [m/s] a nut's rating is judged at, per move: the peak
    thrust ``peak_n`` at the top speed (an accelerating segment reaches the top speed
    still carrying m a); in a cycle of the user's own moves, which differ in thrust and
    speed, each move's largest thrust at its own top speed."""
    if not app.moves or c.profiles is None:
        return [(peak_n, c.reached_m_s)]
    return [
        (max(abs(f) for f in c.moving_n[3 * k : 3 * k + 3]), p.peak_speed_m_s)
        for k, p in enumerate(c.profiles)
    ]


def pv_point(app: Application, c: motion.Cycle, peak_n: float) -> tuple[float, float]:
    """The thrust [N] and speed [m/s] the nut's PV is judged at: of ``move_points``, the
    move where their product (to which a nut's PV is proportional) is largest.

    >>> from app.core.model import Move
    >>> moves = (Move(0.3, 0.15, 1.5, 1.5, 0.3, 4.0, 15.0, "opposes"),
    ...          Move(-0.3, 0.25, 2.5, 2.0, 0.7, 1.5, 5.0, "opposes"))
    >>> app = Application(load_n=0.0, speed_m_s=0.25, length_m=0.5, moves=moves)
    >>> pv_point(app, motion.cycle_of(app), 21.0)
    (21.0, 0.15)
    """
    return max(move_points(app, c, peak_n), key=lambda point: point[0] * point[1])


def compression_sign(app: Application) -> float:
    """+1 when a nut force up (out) pushes the screw onto its thrust bearing (compression),
    -1 when it pulls the screw away from it (tension)."""
    return 1.0 if app.compression else -1.0


@formula("F_c = max(0, c F_nut) over the segments of both moves and at rest", "statics")
def compressive_axial_load(app: Application, forces: Sequence[float] = ()) -> float:
    """The largest thrust that pushes the screw onto its thrust bearing [N], in any segment
    of either move or at rest: c F_nut with c = +1 when an up (out) force compresses the
    screw (``app.compression``), else -1; 0 when the screw is only ever pulled. A
    horizontal axis whose load opposes the motion compresses the screw on one of the two
    moves whichever end holds the bearing. ``forces`` as for ``peak_axial_load``.

    >>> compressive_axial_load(Application(load_n=5.0, speed_m_s=0.1, length_m=0.5,
    ...                                    moving_mass_kg=50.0, accel_m_s2=5.0,
    ...                                    compression=False))
    255.0
    """
    c = compression_sign(app)
    return max(0.0, *(c * f for f in forces or motion.nut_forces(app)))


# Not frozen: a frozen dataclass sets each of its fields through object.__setattr__,
# which cost tens of microseconds per select (a dozen parts of ten numbers each).
# Nothing assigns to one.
@dataclass(slots=True)
class AxisLoad(Generic[V]):
    """The axis on each screw: the thrusts on the nut [N] and the screw's speed [rpm]."""

    #: the running thrust (``axial_load``) and the peak thrust (``peak_axial_load``)
    force_n: V
    peak_force_n: V
    #: The largest thrust that compresses the screw (0: only ever pulled) [N]
    compressive_force_n: V
    #: the load held at rest (``motion.steady_load``: weight and loads of fixed direction;
    #: friction holds nothing) [N]
    holding_force_n: V
    #: the screw speed at the top speed
    rpm: V


@dataclass(slots=True)
class Torques(Generic[V]):
    """The drive torque and its parts [N m] (``drive.torques``)."""

    angular_accel_rad_s2: V
    #: the load's inertia at the motor: the screw's and the heaviest moving mass of the
    #: cycle's moves reflected (``motion.heaviest_mass``) [kg m^2]
    inertia_kg_m2: V
    inertia_screw_nm: V
    inertia_mass_nm: V
    #: the rotor's inertia torque J_motor alpha (inside ``inertia_nm`` and ``total_nm``)
    inertia_motor_nm: V
    inertia_nm: V
    drag_nm: V
    load_nm: V
    total_nm: V
    breakaway_nm: V
    #: the largest motor torque of any moving segment of either move, rotor included,
    #: without the safety factor (what the drive must give at its peak), and where it
    #: occurs: the index of its segment in ``segments.moving_torques`` (-1: starting from
    #: rest, the break-away)
    peak_torque_nm: V
    peak_torque_segment: V
    required_nm: V


@dataclass(slots=True)
class ColumnLimits(Generic[V]):
    """The screw as a shaft and a column (``column.column_limits``)."""

    critical_rpm: V
    allowed_rpm: V
    critical_load_n: V
    allowed_load_n: V
    slenderness: V
    transition_slenderness: V
    #: The column that buckles: the span from the thrust bearing to the nut when given,
    #: else the screw's length [m]
    column_length_m: V
    #: The root section under the peak thrust and the torque it carries with it
    #: (``column.root_torque``): the von Mises stress of the two, and each alone [Pa]
    root_stress_pa: V
    root_torque_nm: V
    root_axial_stress_pa: V
    root_shear_stress_pa: V


@dataclass(slots=True)
class NutLoad(Generic[V]):
    """The nut under load: the seed's PV, the engaged flanks and the ratings they give
    (``nut.pv_limit``, ``nut.seed_pv``, ``nut.flanks``)."""

    #: The thrust [N] and screw speed [rpm] the PV is judged at (``pv_point``)
    pv_force_n: V
    pv_rpm: V
    pv_pa_m_s: V
    pressure_pa: V
    surface_speed_m_s: V
    contact_area_m2: V
    pv_max_load_n: V
    #: The nut's permissible PV [Pa m/s]: the rating times the temperature (at the
    #: ambient) and lubrication factors (``formulas.pv_derating``)
    pv_temperature_factor: V
    pv_lubrication_factor: V
    pv_limit_pa_m_s: V
    pv_max_speed_m_s: V
    #: The nut's engaged flanks: their area (L / P) pi d2 H1 (NaN without a thread pitch),
    #: their sliding speed (the helix at d2; NaN without d2), the contact pressure the nut
    #: material allows there and the load that pressure carries over the engaged flank
    #: area (NaN: the nut gives no rating), and the nut material's permissible PV there,
    #: derated as ``pv_limit_pa_m_s`` (NaN: none given).
    flank_area_m2: V
    sliding_speed_m_s: V
    #: the thrust [N] and the flanks' sliding speed [m/s] the contact pressure is judged
    #: at: of the move each nut carries worst (``nut.flanks``), where the pressure allowed
    #: and its load are taken
    bearing_force_n: V
    bearing_sliding_speed_m_s: V
    nut_allowed_pressure_pa: V
    nut_allowed_load_n: V
    nut_pv_limit_pa_m_s: V
    #: The axial load the nut is rated to carry in motion: the size's design load where
    #: the catalog gives one, else a polymer nut's dynamic flank pressure over the engaged
    #: flank area (NaN: neither).
    rated_load_n: V
    #: the nut length whose engaged turns carry the load: the user's, else the catalog's
    #: (NaN without a thread pitch) [m]
    nut_length_m: V


@dataclass(slots=True)
class NutLife(Generic[V]):
    """How long the nut lasts (``nut.wear_life``, ``duty.duty``)."""

    #: The seed's rated travel, low end, at most the nut's wear travel at the cycle's wear
    #: thrust where its material has a wear rate (NaN: no rating) [m]; the rated band in
    #: years of the duty, each end so capped (NaN: no rating or no duty).
    life_travel_min_m: V
    life_years_min: V
    life_years_max: V
    #: Nut wear (Archard): the steady thrust that wears the nut as the whole cycle does
    #: (``motion.wear_thrust``: every moving segment of both moves, m a on the ramps) [N],
    #: nut travel until the allowed wear depth [m] and that travel in years of the duty
    #: (NaN: no wear rating, no thrust, or no duty)
    wear_force_n: V
    wear_travel_m: V
    wear_life_years: V
    #: The load a ball nut's ball track carries (``duty.ball_track_load``: the cycle's
    #: cubic mean with the preload, else the running thrust with it) [N]
    ball_load_n: V


@dataclass(slots=True)
class NutHeat(Generic[V]):
    """The nut's heat balance (``duty.heat_balance``): the cycle's mean speed [m/s] (the
    top speed without a stroke), the thread's friction power at it, at the cycle's wear
    thrust (``NutLife.wear_force_n``) [W], the nut's drag power at it [W], and the nut's
    steady rise over the ambient from both [K] (NaN: no heat balance)."""

    heat_speed_m_s: V
    friction_power_w: V
    drag_power_w: V
    nut_temperature_rise_k: V


@dataclass(slots=True)
class TravelError(Generic[V]):
    """The travel's positioning error [m] (``duty.duty``): the lead error accumulated
    over the stroke and the screw's thermal growth over it at the ambient; and its growth
    from the nut's friction heat between the thrust bearing and the nut
    (``duty.heat_growth``, worked out with ``duty.heat_balance``; NaN where not counted:
    no duty, a ball nut, a screw without the values its heat balance reads)."""

    lead_error_m: V
    thermal_growth_m: V
    heat_growth_m: V


@dataclass(slots=True)
class PowerOffHold(Generic[V]):
    """Holding the load with the power off (``holding.holding``)."""

    holding_seed_nm: V
    holding_physics_nm: V
    #: the physical holding torque at the distrusted static friction f mu_s, the friction
    #: the self-locking margin trusts (what the brake is sized on, beside the seed's)
    holding_distrusted_nm: V
    brake_nm: V
    #: the holding torque the given brake or motor must hold: ``brake_nm`` times its
    #: safety factor (``brake_factor``)
    brake_needed_nm: V
    #: the brake torque to fit: ``brake_nm`` times a brake's safety factor (at least its
    #: service factor, whatever holds the load now: a brake the fixes ask for)
    brake_to_fit_nm: V
    locks_with_margin: V
    max_self_locking_lead_with_margin_m: V
    #: Where it is required and a load is held (NaN otherwise): the thread's margin, the
    #: longest lead that self-locks at f mu_s over the lead; the hold's, the margin of the
    #: means that holds or would (``holding.hold_margins``): the thread's where it holds or
    #: nothing else is given, else the unpowered torque (a brake's or the detent) over the
    #: torque needed (``brake_needed_nm`` as if it did not lock); and whether that means
    #: is the thread (1) or not (0). Each margin holds at 1 or more.
    hold_thread_margin: V
    hold_margin: V
    hold_by_thread: V


@dataclass(slots=True)
class MotorPoint(Generic[V]):
    """The move against the motor (``drive.motor_point``, ``drive.controller``)."""

    #: The peak rpm (the top speed's without a stroke); the largest torque in magnitude
    #: and the RMS torque over the cycle (NaN without a stroke); the segment that uses the
    #: most of the motor curve (index in ``segments.segments``, -1 without a stroke), its
    #: torque magnitude and rpm, the curve's torque there (NaN: no curve). The RMS torque
    #: held to the continuous duty zone (``segments.referred_rms``: the RMS torque where
    #: the motor has no zone). The ``_needed``
    #: torques are the motor's to give: times the torque safety factor.
    peak_rpm: V
    motor_peak_nm: V
    motor_rms_nm: V
    motor_rms_zone_nm: V
    motor_rms_needed_nm: V
    motor_worst_segment: V
    motor_worst_nm: V
    motor_worst_needed_nm: V
    motor_worst_rpm: V
    motor_curve_nm: V
    #: the acceleration at which the worst segment fits the curve when that segment is an
    #: acceleration (NaN otherwise, or when no acceleration fits)
    motor_fitting_accel_m_s2: V
    #: the top speed at which every segment fits the curve (NaN: none, or a cycle of
    #: moves, whose speeds are the moves')
    motor_fitting_speed_m_s: V
    #: the same two with the torque ``FIX_MARGIN`` inside the curve: the figures a fix
    #: proposes, which keep the check's margin when applied
    motor_fix_accel_m_s2: V
    motor_fix_speed_m_s: V
    #: The stepper's controller: step pulses per second at the peak rpm and the travel
    #: of one pulse [m] (NaN without a step angle).
    step_rate_hz: V
    step_resolution_m: V


@dataclass(slots=True)
class SupportBearing(Generic[V]):
    """The thrust bearing (``duty.support_bearing``): its allowed static thrust C0a / fs,
    the cycle's cube-mean thrust on it [N] and its L10 life in years of the duty (NaN:
    not given)."""

    support_allowed_n: V
    support_mean_load_n: V
    support_life_years: V


@dataclass(slots=True)
class CycleEnergy(Generic[V]):
    """The energy of one cycle [J] (``cycle_energy.cycle_energy``; NaN without a move): the
    motor's work at its shaft where it drives, the energy braking gives back, the work
    done on the load, the thread's friction and the nut's drag losses, and a stepper's
    copper loss (NaN without its phase current and resistance)."""

    cycle_motor_work_j: V
    cycle_regen_j: V
    cycle_load_work_j: V
    cycle_thread_loss_j: V
    cycle_drag_loss_j: V
    cycle_copper_loss_j: V


@dataclass(slots=True)
class Quantities(Generic[V]):
    """One axis's numbers, SI, by what they describe; ``V`` is an array (one element per
    candidate) or a float. Each number's name is unique across the parts (``NAMES``,
    ``quantity``)."""

    axis: AxisLoad[V]
    torque: Torques[V]
    column: ColumnLimits[V]
    nut: NutLoad[V]
    life: NutLife[V]
    heat: NutHeat[V]
    accuracy: TravelError[V]
    holding: PowerOffHold[V]
    motor: MotorPoint[V]
    support: SupportBearing[V]
    energy: CycleEnergy[V]

    def at(self, i: int) -> "Quantities[float]":
        """The numbers of the candidate at ``i``, each read as a float when it is read:
        what a check's sentence or fix reads (a handful of its hundred numbers)."""
        return cast("Quantities[float]", _At(self, i))


class _At:
    """One candidate's numbers (or those of one part) read from the arrays of
    ``Quantities`` one at a time."""

    __slots__ = ("_i", "_q")

    def __init__(self, q: Any, i: int) -> None:
        self._q, self._i = q, i

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._q, name)
        return _At(value, self._i) if name in PARTS else float(value[self._i])


#: Each part of ``Quantities`` by its name there: its class and the names of its numbers.
PARTS: dict[str, tuple[type[Any], tuple[str, ...]]] = {
    f.name: (cls, tuple(g.name for g in fields(cls)))
    for f in fields(Quantities)
    for cls in [cast(type[Any], get_origin(f.type))]
}
#: Each part's class and the getter of its numbers from a mapping by name, for
#: ``from_names``.
_PARTS = [(cls, itemgetter(*names)) for cls, names in PARTS.values()]
#: Every number's name, part by part in declaration order, and the part that holds it.
PART_OF = {name: part for part, (_, names) in PARTS.items() for name in names}
NAMES = tuple(PART_OF)


def quantity(q: Quantities[V], name: str) -> V:
    """The number ``name`` of ``q``, from the part that holds it (``PART_OF``).

    >>> PART_OF["total_nm"], PART_OF["critical_rpm"]
    ('torque', 'column')
    """
    value: V = getattr(getattr(q, PART_OF[name]), name)
    return value


def from_names(values: Mapping[str, V]) -> Quantities[V]:
    """The ``Quantities`` holding ``values`` (every number, by its name)."""
    return Quantities(*[cls(*take(values)) for cls, take in _PARTS])


def operating_point(app: Application, t: CandidateTable) -> Quantities[Array]:
    """Every number of ``app`` for every candidate of ``t``, as float arrays (each part
    gives its numbers as float arrays of the table's length: a flag as 0 or 1, an index
    as a float)."""
    c = motion.cycle_of(app)
    rpm = geometry.screw_speed_rpm(c.reached_m_s, t.lead_m)
    # no (or vanishing) thrust: an unbounded PV speed, NaN after ``table.finite``
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        return from_names(_values(app, t, rpm, c))


def _values(app: Application, t: CandidateTable, rpm: Array, c: motion.Cycle) -> dict[str, Any]:
    """The numbers of ``operating_point``; each of the axis's own (its cycle ``c``, its
    thrusts and the moving segments' torques) worked out once and handed to every part
    that reads it."""
    forces = c.forces
    force_n, peak_n = axial_load(app, c.lead), peak_axial_load(app, forces)
    wear_n, steady_n = c.wear_n, c.steady_n
    j_screw = segments.screw_side_inertia(app, t)
    moving = segments.moving_torques(app, t, c, j_screw)
    torques = drive.torques(app, t, force_n, moving, c, j_screw)
    derate = (limits := nut.pv_limit(app, t))["pv_temperature_factor"]
    points = move_points(app, c, peak_n)
    flank = nut.flanks(app, t, rpm, derate * limits["pv_lubrication_factor"], points)
    worn = nut.wear_life(app, t, flank["flank_area_m2"], wear_n, c.cycles_per_day)
    held = holding.holding(app, t, steady_n)
    motor = drive.motor_point(app, t, rpm, held["brake_nm"], torques, moving, c)
    pv_n, pv_m_s = pv_point(app, c, peak_n)
    pv_rpm = rpm if pv_m_s == c.reached_m_s else geometry.screw_speed_rpm(pv_m_s, t.lead_m)
    return {
        "force_n": filled(len(t), force_n),
        "peak_force_n": filled(len(t), peak_n),
        "compressive_force_n": filled(len(t), compressive_axial_load(app, forces)),
        "holding_force_n": filled(len(t), steady_n),
        "rpm": rpm,
        **torques,
        **column.column_limits(app, t, peak_n, torques),
        **duty.heat_balance(app, t, c),
        **limits,
        "pv_force_n": filled(len(t), pv_n),
        "pv_rpm": pv_rpm,
        **nut.seed_pv(app, t, pv_n, pv_rpm, limits["pv_limit_pa_m_s"]),
        **flank,
        **worn,
        "ball_load_n": duty.ball_track_load(app, t, c, force_n),
        **duty.duty(app, t, worn["wear_travel_m"], c.cycles_per_day),
        **duty.support_bearing(app, t, c),
        **held,
        **motor,
        **drive.controller(app, t, motor["peak_rpm"]),
    }
