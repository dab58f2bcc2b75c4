"""Every number of one axis for many candidates at once: the operating point of each.

``operating_point(app, table)`` computes, over the table's columns, the speeds, loads,
torques, limits and margins that the checks and the reports read. The same arithmetic
serves one screw (a table of one) or the whole catalog; ``row(i)`` gives one
candidate's numbers as plain floats.
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any, Generic, TypeVar, cast

import numpy as np
from numpy.typing import NDArray

from app.core import motion
from app.core.formulas import (
    accuracy,
    bearing,
    buckling,
    critical_speed,
    efficiency,
    geometry,
    heat,
    life,
    pv,
    pv_derating,
    stepping,
    support,
    torque,
    wear,
)
from app.core.formulas.declare import formula
from app.core.model import STANDARD_GRAVITY_M_S2, Application, Segment
from app.core.table import Array, CandidateTable

V = TypeVar("V")
#: Ambient temperature at which the screw's length is nominal [C].
REFERENCE_TEMPERATURE_C = 20.0


@formula("F = load (+ m g when vertical), the running thrust", "statics")
def axial_load(app: Application) -> float:
    """Running thrust on the nut at constant speed [N]: the load, plus m g when vertical
    (on the up move, or on the move against a load of fixed direction); in a cycle of the
    user's own moves, the top-speed thrust of the move that starts hardest
    (``motion.lead_move``)."""
    if app.moves:
        return motion.running_thrust(app, motion.lead_move(app))
    if app.orientation == "vertical":
        return app.load_n + app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return app.load_n


@formula("F_peak = max |F_nut| over the segments of both moves and at rest", "Newton's second law")
def peak_axial_load(app: Application) -> float:
    """Peak thrust on the nut [N]: the largest force the nut exerts on the moving mass in
    any segment of either move or at rest (``motion.nut_force_forms``), so the running
    thrust plus m a accelerating against the load, or plus m d braking a mass that moves
    with it, whichever is larger (Newton's second law).

    >>> peak_axial_load(Application(load_n=5.0, speed_m_s=0.1, length_m=0.5,
    ...                             moving_mass_kg=50.0, accel_m_s2=5.0))
    255.0
    >>> round(peak_axial_load(Application(load_n=0.0, speed_m_s=0.1, length_m=0.5,
    ...     moving_mass_kg=20.0, accel_m_s2=1.0, decel_m_s2=2.0, orientation="vertical")), 2)
    236.13
    """
    return max(abs(f) for f in motion.nut_forces(app))


def compression_sign(app: Application) -> float:
    """+1 when a nut force up (out) pushes the screw onto its thrust bearing (compression),
    -1 when it pulls the screw away from it (tension)."""
    return 1.0 if app.compression else -1.0


@formula("F_c = max(0, c F_nut) over the segments of both moves and at rest", "statics")
def compressive_axial_load(app: Application) -> float:
    """The largest thrust that pushes the screw onto its thrust bearing [N], in any segment
    of either move or at rest: c F_nut with c = +1 when an up (out) force compresses the
    screw (``app.compression``), else -1; 0 when the screw is only ever pulled. A
    horizontal axis whose load opposes the motion compresses the screw on one of the two
    moves whichever end holds the bearing.

    >>> compressive_axial_load(Application(load_n=5.0, speed_m_s=0.1, length_m=0.5,
    ...                                    moving_mass_kg=50.0, accel_m_s2=5.0,
    ...                                    compression=False))
    255.0
    """
    c = compression_sign(app)
    return max(0.0, *(c * f for f in motion.nut_forces(app)))


@dataclass(frozen=True, slots=True)
class Quantities(Generic[V]):
    """One axis's numbers, SI; ``V`` is an array (one element per candidate) or a float."""

    force_n: V
    peak_force_n: V
    rpm: V
    angular_accel_rad_s2: V
    inertia_kg_m2: V
    inertia_screw_nm: V
    inertia_mass_nm: V
    inertia_nm: V
    drag_nm: V
    load_nm: V
    total_nm: V
    breakaway_nm: V
    required_nm: V
    critical_rpm: V
    allowed_rpm: V
    critical_load_n: V
    allowed_load_n: V
    slenderness: V
    transition_slenderness: V
    #: The root section under the peak thrust and the torque it carries with it
    #: (``_root_torque``): the von Mises stress of the two, and each alone [Pa]
    root_stress_pa: V
    root_torque_nm: V
    root_axial_stress_pa: V
    root_shear_stress_pa: V
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
    nut_allowed_pressure_pa: V
    nut_allowed_load_n: V
    nut_pv_limit_pa_m_s: V
    #: The axial load the nut is rated to carry in motion: the size's design load where
    #: the catalog gives one, else a polymer nut's dynamic flank pressure over the engaged
    #: flank area (NaN: neither).
    rated_load_n: V
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
    #: Heat: the cycle's mean speed [m/s] (the top speed without a stroke), the thread's
    #: friction power at it [W], and the nut's steady rise over the ambient [K] (NaN: no
    #: heat balance)
    heat_speed_m_s: V
    friction_power_w: V
    nut_temperature_rise_k: V
    lead_error_m: V
    thermal_growth_m: V
    holding_seed_nm: V
    holding_physics_nm: V
    brake_nm: V
    #: the brake torque to fit: ``brake_nm`` times the brake safety factor (``brake_factor``)
    brake_needed_nm: V
    locks_with_margin: V
    max_self_locking_lead_with_margin_m: V
    #: The move: the peak rpm (the top speed's without a stroke); the largest torque in
    #: magnitude and the RMS torque over the cycle (NaN without a stroke); the segment
    #: that uses the most of the motor curve (index in ``motion.segments``, -1 without a
    #: stroke), its torque magnitude and rpm, the curve's torque there (NaN: no curve).
    #: The ``_needed`` torques are the motor's to give: times the torque safety factor.
    peak_rpm: V
    motor_peak_nm: V
    motor_rms_nm: V
    motor_rms_needed_nm: V
    motor_worst_segment: V
    motor_worst_nm: V
    motor_worst_needed_nm: V
    motor_worst_rpm: V
    motor_curve_nm: V
    #: the acceleration at which the worst segment fits the curve when that segment is an
    #: acceleration (NaN otherwise, or when no acceleration fits)
    motor_fitting_accel_m_s2: V
    #: The stepper's controller: step pulses per second at the peak rpm and the travel
    #: of one pulse [m] (NaN without a step angle).
    step_rate_hz: V
    step_resolution_m: V
    #: The largest thrust that compresses the screw (0: only ever pulled) [N]; the rotor's
    #: inertia torque J_motor alpha (inside ``inertia_nm`` and ``total_nm``); the largest
    #: motor torque of any moving segment of either move, rotor included, without the
    #: safety factor (what the drive must give at its peak).
    compressive_force_n: V
    inertia_motor_nm: V
    peak_torque_nm: V
    #: where the peak torque occurs: the index of its segment in
    #: ``motion.moving_torques`` (-1: starting from rest, the break-away)
    peak_torque_segment: V
    #: the load held at rest (``motion.steady_load``: weight and loads of fixed direction;
    #: friction holds nothing) [N]
    holding_force_n: V
    #: the physical holding torque at the distrusted static friction f mu_s, the friction
    #: the self-locking margin trusts (what the brake is sized on, beside the seed's)
    holding_distrusted_nm: V
    #: Holding with the power off, where it is required and a load is held (NaN
    #: otherwise): the thread's margin, the longest lead that self-locks at f mu_s over
    #: the lead; and the hold's, the larger of it and the unpowered torque (a brake's or
    #: the detent) over the torque needed (``brake_needed_nm`` as if it did not lock).
    #: Each holds at 1 or more.
    hold_thread_margin: V
    hold_margin: V
    #: the nut length whose engaged turns carry the load: the user's, else the catalog's
    #: (NaN without a thread pitch) [m]
    nut_length_m: V
    #: The column that buckles: the span from the thrust bearing to the nut when given,
    #: else the screw's length [m]; the thrust bearing's allowed static thrust C0a / fs, the
    #: cycle's cube-mean thrust on it and its L10 life in years of the duty (NaN: not given)
    column_length_m: V
    support_allowed_n: V
    support_mean_load_n: V
    support_life_years: V
    #: The energy of one cycle [J] (``motion.cycle_energy``; NaN without a move): the
    #: motor's work at its shaft where it drives, the energy braking gives back, the work
    #: done on the load, the thread's friction and the nut's drag losses, and a stepper's
    #: copper loss (NaN without its phase current and resistance).
    cycle_motor_work_j: V
    cycle_regen_j: V
    cycle_load_work_j: V
    cycle_thread_loss_j: V
    cycle_drag_loss_j: V
    cycle_copper_loss_j: V

    def at(self, i: int) -> "Quantities[float]":
        """The numbers of the candidate at ``i``, each read as a float when it is read:
        what a check's sentence or fix reads (a handful of its hundred numbers)."""
        return cast("Quantities[float]", _At(self, i))

    def rows(self, index: Sequence[int] | NDArray[np.intp]) -> "list[Quantities[float]]":
        """The numbers of the candidates at ``index`` as floats (NaN: no such limit)."""
        at = np.asarray(index, dtype=np.intp)
        columns = [getattr(self, name)[at].tolist() for name in NAMES]
        return [Quantities(*values) for values in zip(*columns, strict=True)]


class _At:
    """One candidate's numbers read from the arrays of ``Quantities`` one at a time."""

    __slots__ = ("_i", "_q")

    def __init__(self, q: Quantities[Array], i: int) -> None:
        self._q, self._i = q, i

    def __getattr__(self, name: str) -> float:
        return float(getattr(self._q, name)[self._i])


#: The fields of ``Quantities``, in declaration order.
NAMES = tuple(f.name for f in fields(Quantities))


def _torques(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Motor torque: the screw's and the rotor's inertia J alpha, and every force that
    passes through the sliding thread (the load and the force m a that accelerates the
    moving mass) at the thread's efficiency, plus the nut's drag. Starting from rest the
    thread is at static friction while the load and m a already act. The required torque
    is the larger of break-away and the peak of the moving segments of both moves
    (``motion.moving_torques``: decelerating a descending load may need more). The
    breakdown and break-away are those of the move that starts hardest
    (``motion.lead_move``: out and back, the scalar inputs)."""
    move = motion.lead_move(app)
    alpha = torque.angular_acceleration(move.accel_m_s2, t.lead_m)
    j_screw = torque.screw_inertia(t.inertia_kg_m2_per_m, app.length_m)
    j_mass = torque.reflected_mass_inertia(move.moving_mass_kg, t.lead_m)
    inertial_force_n = move.moving_mass_kg * move.accel_m_s2
    t_screw = torque.inertia_torque(j_screw, alpha)
    t_motor = torque.inertia_torque(app.motor_inertia_kg_m2 or 0.0, alpha)
    t_mass = torque.load_torque(inertial_force_n, t.lead_m, t.efficiency)
    t_load = torque.load_torque(force_n, t.lead_m, t.efficiency)
    t_total = torque.total_torque(t_screw + t_motor + t_mass, t.drag_max_nm, t_load)
    t_start = (
        torque.load_torque(force_n + inertial_force_n, t.lead_m, t.efficiency_static)
        + t_screw
        + t_motor
        + t.drag_max_nm
    )
    moving = np.stack([np.abs(m[3]) for m in motion.moving_torques(app, t)])
    peak = np.maximum(moving.max(axis=0), t_start)
    segment = np.where(moving.max(axis=0) > t_start, np.argmax(moving, axis=0), -1)
    return {
        "angular_accel_rad_s2": alpha,
        "inertia_kg_m2": j_screw + j_mass,
        "inertia_screw_nm": t_screw,
        "inertia_mass_nm": t_mass,
        "inertia_motor_nm": t_motor,
        "inertia_nm": t_screw + t_motor + t_mass,
        "drag_nm": t.drag_max_nm,
        "load_nm": t_load,
        "total_nm": t_total,
        "breakaway_nm": t_start,
        "peak_torque_nm": peak,
        "peak_torque_segment": segment,
        "required_nm": peak * app.torque_safety_factor,
    }


def _root_torque(t: CandidateTable, peak_n: float, torques: dict[str, Any]) -> Array:
    """``torque.root_torque`` at the peak thrust, at the lower of the running and the
    static efficiency (the thrust of a start from rest passes the thread at static
    friction), with the nut's drag and the whole screw's inertia torque [N m]."""
    eta = np.minimum(t.efficiency, t.efficiency_static)
    return np.asarray(
        torque.root_torque(peak_n, t.lead_m, eta, torques["drag_nm"], torques["inertia_screw_nm"])
    )


def column_length(app: Application) -> float:
    """The length of the screw that buckles [m]: from the thrust bearing to the nut at its
    farthest when that span is given (THK, Ball Screw "Method for Mounting the Ball Screw
    Shaft": the buckling load uses the distance between the mounting surfaces, the
    bearing and the nut), else the whole screw; never longer than the screw.

    >>> column_length(Application(load_n=1.0, speed_m_s=0.1, length_m=1.0, bearing_to_nut_m=0.6))
    0.6
    """
    if app.bearing_to_nut_m is None:
        return app.length_m
    return min(app.bearing_to_nut_m, app.length_m)


def _column_limits(
    app: Application, t: CandidateTable, peak_n: float, torques: dict[str, Any]
) -> dict[str, Any]:
    """Critical speed over the screw's length, and the screw as a column (its span from
    the thrust bearing to the nut) under the peak thrust: Euler when slender, Johnson's
    parabola when short, and the stress at the root under the peak thrust and the torque
    the screw carries with it (von Mises)."""
    n_c = critical_speed.critical_speed_rpm(
        t.root_diameter_m, app.length_m, t.youngs_modulus_pa, t.density_kg_m3, app.end_fixity
    )
    column_m = column_length(app)
    f_cr = buckling.column_critical_load(
        t.youngs_modulus_pa, t.root_diameter_m, column_m, app.end_fixity, t.yield_strength_pa
    )
    with np.errstate(invalid="ignore"):
        transition = buckling.transition_slenderness(t.youngs_modulus_pa, t.yield_strength_pa)
    root_nm = _root_torque(t, peak_n, torques)
    return {
        "critical_rpm": n_c,
        "allowed_rpm": critical_speed.allowed_speed_rpm(n_c, app.critical_speed_safety_factor),
        "critical_load_n": f_cr,
        "allowed_load_n": buckling.allowed_buckling_load(f_cr, app.buckling_safety_factor),
        "slenderness": buckling.slenderness(t.root_diameter_m, column_m, app.end_fixity),
        "column_length_m": np.full(len(t), column_m),
        "transition_slenderness": transition,
        "root_stress_pa": buckling.root_von_mises_stress(peak_n, root_nm, t.root_diameter_m),
        "root_torque_nm": root_nm,
        "root_axial_stress_pa": np.broadcast_to(
            buckling.root_stress(peak_n, t.root_diameter_m), root_nm.shape
        ),
        "root_shear_stress_pa": buckling.root_shear_stress(root_nm, t.root_diameter_m),
    }


def _finite(values: Array) -> Array:
    """NaN where a limit is unbounded (e.g. the PV speed limit with no thrust at all)."""
    return np.where(np.isfinite(values), values, np.nan)


def _pv_limit(app: Application, t: CandidateTable) -> dict[str, Any]:
    """The nut's permissible PV at the ambient and its lubrication: the rating times the
    temperature factor (``pv_derating.temperature_factors`` at the ambient; 1 where the
    material's highest temperature is unknown) times the lubrication factor.

    A PV rating is the PV whose own friction heat brings the nut to its highest
    temperature from the rating's room [pv_derating 1-3]: it already holds the nut's rise,
    so only the ambient above the room derates it (the rise itself is the nut heat
    check's, with the duty)."""
    temperature = pv_derating.temperature_factors(app.ambient_c, t.temperature_max_c)
    lubrication = pv_derating.LUBRICATION_FACTORS[app.lubrication][0]
    return {
        "pv_temperature_factor": temperature,
        "pv_lubrication_factor": np.full(len(t), lubrication),
        "pv_limit_pa_m_s": t.pv_limit_pa_m_s * temperature * lubrication,
    }


def _nut(
    app: Application, t: CandidateTable, force_n: float, rpm: Array, limit: Array
) -> dict[str, Any]:
    """PV of the nut (seed, three threads in contact) and its limits inverted at the
    permissible PV ``limit``, at the peak thrust ``force_n``: an accelerating segment ends
    at the top speed still carrying m a."""
    area = pv.contact_area(t.helix_travel_m, t.thread_depth_m)
    return {
        "pv_pa_m_s": pv.pv_value(force_n, rpm, t.helix_travel_m, t.thread_depth_m),
        "pressure_pa": np.broadcast_to(pv.contact_pressure(force_n, area), rpm.shape),
        "surface_speed_m_s": pv.surface_speed(rpm, t.helix_travel_m),
        "contact_area_m2": area,
        "pv_max_load_n": pv.max_load_for_pv(limit, rpm, t.thread_depth_m),
        "pv_max_speed_m_s": _finite(
            geometry.linear_speed(pv.max_rpm_for_pv(limit, force_n, t.thread_depth_m), t.lead_m)
        ),
    }


def _table_pressures(t: CandidateTable, speed_m_s: Array) -> Array:
    """Each candidate's pressure-speed table value at its sliding speed [Pa] (NaN without
    a table); candidates sharing a table are interpolated together."""
    out = np.full(len(t), np.nan)
    for position, table in enumerate(t.pressure_tables):
        rows = np.flatnonzero(t.pressure_table == position)
        if rows.size:
            out[rows] = bearing.table_pressure(speed_m_s[rows], table)
    return out


def nut_allowed_pressures(t: CandidateTable, pv_limit_pa_m_s: Array, speed_m_s: Array) -> Array:
    """The pressure each nut's material allows at its sliding speed [Pa]: the lowest of
    its table value, p_max and the (derated) ``pv_limit_pa_m_s`` over the speed [m/s]
    (``bearing.allowable_pressure``); NaN for a nut with none of them."""
    allowed: Array = bearing.allowable_pressure(
        _table_pressures(t, speed_m_s), t.max_pressure_pa, pv_limit_pa_m_s, speed_m_s
    )
    return allowed


def _nut_length(app: Application, t: CandidateTable) -> Array:
    """The nut length whose engaged turns carry the load: the user's, else the catalog's
    (NaN where the catalog gives none) [m]."""
    if app.nut_length_m is None:
        return t.nut_length_m
    return np.where(np.isnan(t.nut_length_m), np.nan, app.nut_length_m)


def _flank_area(app: Application, t: CandidateTable) -> Array:
    """The engaged flank area (L / P) pi d2 H1 of a standard thread's nut [m^2] (NaN
    without a thread pitch), with the nut length of ``_nut_length``."""
    area = bearing.engaged_flank_area(
        _nut_length(app, t), t.pitch_m, t.flank_pitch_diameter_m, t.flank_height_m
    )
    return np.asarray(area, dtype=np.float64)


def _flanks(app: Application, t: CandidateTable, rpm: Array, derate: Array) -> dict[str, Any]:
    """The engaged flanks of the nut: sliding speed n / 60 times the helix of one turn at
    d2, the pressure the nut material allows at it (the lowest of its table value, p_max
    and PV_lim / v, the PV limit derated by ``derate``, the temperature and lubrication
    factors of ``_pv_limit``) and that pressure over the engaged flank area."""
    speed = pv.surface_speed(rpm, t.flank_helix_travel_m)
    pv_limit = t.nut_pv_limit_pa_m_s * derate
    allowed = nut_allowed_pressures(t, pv_limit, speed)
    area = _flank_area(app, t)
    return {
        "nut_pv_limit_pa_m_s": pv_limit,
        "flank_area_m2": area,
        "sliding_speed_m_s": speed,
        "nut_allowed_pressure_pa": allowed,
        "nut_allowed_load_n": allowed * area,
        "rated_load_n": np.where(
            np.isnan(t.design_load_n),
            bearing.dynamic_load(t.dynamic_pressure_pa, area),
            t.design_load_n,
        ),
        "nut_length_m": np.where(np.isnan(t.pitch_m), np.nan, _nut_length(app, t)),
    }


def _wear(app: Application, t: CandidateTable, flank_area_m2: Array) -> dict[str, Any]:
    """Nut travel until its flanks have worn the allowed depth (Archard's law at the
    cycle's wear thrust, ``motion.wear_thrust``): over the engaged flanks and flank height
    of a standard thread, else over the seed's three threads and thread depth."""
    force_n = motion.wear_thrust(app)
    flanks = ~np.isnan(flank_area_m2)
    area = np.where(flanks, flank_area_m2, pv.contact_area(t.helix_travel_m, t.thread_depth_m))
    height = np.where(flanks, t.flank_height_m, t.thread_depth_m)
    helix = np.where(flanks, t.flank_helix_travel_m, t.helix_travel_m)
    with np.errstate(over="ignore"):  # a vanishing thrust: an unbounded life, NaN below
        sliding = wear.wear_life_sliding(
            t.allowed_wear_fraction * height, t.wear_rate_m2_n, pv.contact_pressure(force_n, area)
        )
    travel = _finite(wear.wear_life_travel(sliding, wear.sliding_per_travel(helix, t.lead_m)))
    cycles, stroke = motion.cycles_per_day(app), motion.equivalent_stroke(app)
    rated = bool(stroke and cycles)
    years = life.life_years(travel, stroke, cycles) if rated else travel * np.nan
    return {
        "wear_force_n": np.full(len(t), force_n),
        "wear_travel_m": travel,
        "wear_life_years": years,
    }


def _heat(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Friction power at the cycle's mean speed and the nut's steady temperature rise:
    the screw conducts the heat away both ways as a fin, the nut's surface convects it.
    A cycle of the user's own moves heats at its mean friction power: its travel-weighted
    mean thrust (``motion.wear_thrust``) at its mean speed, every segment through the
    forward efficiency (a segment the load drives loses less: the safe side)."""
    p = motion.move_profile(app)
    stroke = motion.equivalent_stroke(app) or 0.0
    mean_speed = app.speed_m_s if p is None else 2.0 * stroke / p.cycle_time_s
    if app.moves:
        force_n = motion.wear_thrust(app)
    power = _finite(heat.friction_power(force_n, mean_speed, t.efficiency))
    h = heat.FREE_CONVECTION_W_M2_K
    fin = heat.fin_conductance(t.root_diameter_m, t.thermal_conductivity_w_m_k, h)
    nut_d = heat.NUT_OUTER_TO_D * t.outer_diameter_m
    rise = heat.temperature_rise(power, fin, _nut_length(app, t), nut_d, h)
    return {
        "heat_speed_m_s": np.full(len(t), mean_speed),
        "friction_power_w": power,
        "nut_temperature_rise_k": rise,
    }


def _duty(app: Application, t: CandidateTable, wear_travel_m: Array) -> dict[str, Any]:
    """Rated life in years for the duty, lead error and thermal growth over the stroke.

    The seed rates its nuts' travel without the load it holds at, and warns that life
    varies with load: the rated travel is taken as at most the wear life of the same nut
    material at this cycle's wear thrust (``wear_travel_m``, NaN where the nut has no
    wear rate), so a rating never promises more at a high load than the wear law."""
    nan = np.full(len(t), np.nan)
    stroke, cycles = motion.equivalent_stroke(app), motion.cycles_per_day(app)
    rated = bool(stroke and cycles)
    travel = app.stroke_m if app.stroke_m is not None else app.length_m
    low_m = np.where(np.isnan(t.life_min_m), np.nan, np.fmin(t.life_min_m, wear_travel_m))
    high_m = np.where(np.isnan(t.life_max_m), np.nan, np.fmin(t.life_max_m, wear_travel_m))
    return {
        "life_travel_min_m": low_m,
        "life_years_min": life.life_years(low_m, stroke, cycles) if rated else nan,
        "life_years_max": life.life_years(high_m, stroke, cycles) if rated else nan,
        "lead_error_m": accuracy.cumulative_lead_error(t.lead_accuracy, travel),
        "thermal_growth_m": accuracy.thermal_growth(
            t.screw_expansion_per_k, travel, app.ambient_c - REFERENCE_TEMPERATURE_C
        ),
    }


def travel_thrusts(app: Application) -> tuple[list[float], list[float]]:
    """The thrust on the nut in each moving segment of every move [N] and the distance
    travelled in it [m] (a ramp covers v t / 2, the constant segment v t,
    ``motion.wear_forms``); none without a stroke."""
    if motion.move_profile(app) is None:
        return [], []
    forms, travels = motion.wear_forms(app)
    return [g + h * app.load_n for g, h in forms], travels


def _support(app: Application, t: CandidateTable) -> dict[str, Any]:
    """The thrust bearing: its allowed static thrust C0a / fs, the cube-mean thrust of the
    cycle and its L10 life in years (revolutions times the lead over the duty's travel)."""
    nan = np.full(len(t), np.nan)
    allowed = nan
    if app.support_static_n is not None:
        allowed = np.full(
            len(t),
            support.static_allowed_load(app.support_static_n, app.support_static_safety_factor),
        )
    forces, distances = travel_thrusts(app)
    mean_n = support.mean_axial_load(forces, distances) if forces else math.nan
    years = nan
    stroke = motion.equivalent_stroke(app)
    duty = stroke and app.cycles_per_day
    if app.support_dynamic_n is not None and duty and mean_n > 0.0:
        revolutions = support.rating_life_revolutions(app.support_dynamic_n, mean_n)
        years = life.life_years(revolutions * t.lead_m, stroke, app.cycles_per_day)
    return {
        "support_allowed_n": allowed,
        "support_mean_load_n": np.full(len(t), mean_n),
        "support_life_years": years,
    }


def _holding(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Holding the load ``force_n`` at standstill (``motion.steady_load``: friction holds
    nothing). The thread counts as self-locking only with static friction reduced by
    ``app.self_locking_friction_factor``; otherwise a brake (or the motor) must hold the
    larger of the seed's value (forward efficiency, running friction) and the physical one
    at that same distrusted friction (back-drive efficiency at f mu_s), times the brake's
    safety factor (the torque safety factor when none is given)."""
    mu_margin = t.friction_static * app.self_locking_friction_factor
    locks = mu_margin >= efficiency.self_locking_limit_friction(
        np.tan(t.lead_angle_rad), t.cos_half_angle
    )
    seed = efficiency.holding_torque(force_n, t.lead_m, t.efficiency)
    physics = efficiency.holding_torque(force_n, t.lead_m, t.backdrive_efficiency)
    distrusted = efficiency.holding_torque(
        force_n,
        t.lead_m,
        efficiency.backdrive_efficiency(np.tan(t.lead_angle_rad), mu_margin, t.cos_half_angle),
    )
    brake = np.where(locks, 0.0, np.maximum(seed, distrusted))
    max_lock = efficiency.max_self_locking_lead(t.pitch_diameter_m, mu_margin, t.cos_half_angle)
    return {
        **_hold_margins(app, t, max_lock, np.maximum(seed, distrusted) * brake_factor(app)),
        "holding_seed_nm": np.where(locks, 0.0, seed),
        "holding_physics_nm": physics,
        "holding_distrusted_nm": distrusted,
        "brake_nm": brake,
        "brake_needed_nm": brake * brake_factor(app),
        "locks_with_margin": locks,
        "max_self_locking_lead_with_margin_m": max_lock,
    }


def unpowered_torque(app: Application) -> float | None:
    """The torque that holds with the power off besides the thread [N m]: a brake's, or
    a stepper's detent torque (its energised holding torque does not count); None: none."""
    if app.holding_source == "brake":
        return app.brake_torque_nm
    return app.detent_torque_nm


def _hold_margins(
    app: Application, t: CandidateTable, max_lock_m: Array, needed_nm: Array
) -> dict[str, Any]:
    """The power-off hold's margins (``efficiency.hold_margin``): the thread's alone, and
    the hold's with the unpowered torque (``unpowered_torque``) over ``needed_nm``; NaN
    where holding with the power off is not required or no load is held."""
    nan = np.full(len(t), np.nan)
    if not (app.hold_power_off and motion.holds_a_load(app)):
        return {"hold_thread_margin": nan, "hold_margin": nan}
    torque_nm = unpowered_torque(app)
    device = nan if torque_nm is None else np.full(len(t), torque_nm)
    needed = np.where(needed_nm > 0.0, needed_nm, np.nan)
    return {
        "hold_thread_margin": efficiency.hold_margin(max_lock_m, t.lead_m, nan, 1.0),
        "hold_margin": efficiency.hold_margin(max_lock_m, t.lead_m, device, needed),
    }


def brake_factor(app: Application) -> float:
    """The safety factor on the holding torque: the brake's, else the torque factor."""
    if app.brake_safety_factor is None:
        return app.torque_safety_factor
    return app.brake_safety_factor


def operating_point(app: Application, t: CandidateTable) -> Quantities[Array]:
    """Every number of ``app`` for every candidate of ``t``, as arrays."""
    force_n, peak_n = axial_load(app), peak_axial_load(app)
    rpm = geometry.screw_speed_rpm(motion.reached_speed(app), t.lead_m)
    # no (or vanishing) thrust: an unbounded PV speed, NaN after ``_finite``
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        values = _values(app, t, force_n, peak_n, rpm)
    return Quantities(**{k: np.asarray(v, dtype=np.float64) for k, v in values.items()})


def _values(
    app: Application, t: CandidateTable, force_n: float, peak_n: float, rpm: Array
) -> dict[str, Any]:
    torques = _torques(app, t, force_n)
    return {
        "force_n": np.full(len(t), force_n),
        "peak_force_n": np.full(len(t), peak_n),
        "compressive_force_n": np.full(len(t), compressive_axial_load(app)),
        "holding_force_n": np.full(len(t), motion.steady_load(app)),
        "rpm": rpm,
        **torques,
        **_column_limits(app, t, peak_n, torques),
        **_heat(app, t, force_n),
        **(limits := _pv_limit(app, t)),
        **_nut(app, t, peak_n, rpm, limits["pv_limit_pa_m_s"]),
        **(
            flanks := _flanks(
                app, t, rpm, limits["pv_temperature_factor"] * limits["pv_lubrication_factor"]
            )
        ),
        **(worn := _wear(app, t, flanks["flank_area_m2"])),
        **_duty(app, t, worn["wear_travel_m"]),
        **_support(app, t),
        **(holding := _holding(app, t, motion.steady_load(app))),
        **(motor := _motor(app, t, rpm, holding["brake_nm"], torques)),
        **_controller(app, t, motor["peak_rpm"]),
    }


def _controller(app: Application, t: CandidateTable, peak_rpm: Array) -> dict[str, Any]:
    """The step rate the peak speed needs and the travel of one step pulse."""
    if app.step_angle_deg is None:
        nan = np.full(len(t), np.nan)
        return {"step_rate_hz": nan, "step_resolution_m": nan}
    per_rev = stepping.steps_per_rev(app.step_angle_deg, app.microsteps)
    return {
        "step_rate_hz": stepping.step_rate(peak_rpm, per_rev),
        "step_resolution_m": 1.0 / stepping.steps_per_metre(per_rev, t.lead_m),
    }


def _motor(
    app: Application, t: CandidateTable, rpm: Array, hold_nm: Array, torques: dict[str, Any]
) -> dict[str, Any]:
    """The motor's view of the move: every segment's torque against the curve. Without a
    stroke there is no profile: the one point is today's torque at the top speed, ``rpm``."""
    p = motion.move_profile(app)
    peak_rpm = worst_rpm = rpm
    nan = np.full(len(t), np.nan)
    fitting = nan
    parts: list[Segment[Array]] = []
    if p is None:
        worst_nm = np.maximum(torques["total_nm"], torques["breakaway_nm"])
        index, peak, rms = np.full(len(t), -1.0), nan, nan
    else:
        peak_rpm = geometry.screw_speed_rpm(p.peak_speed_m_s, t.lead_m)
        parts = motion.segments(app, t, hold_nm)
        signed = np.stack([s.torque_nm for s in parts])
        magnitude = np.abs(signed)
        speeds = np.stack([s.rpm for s in parts])
        load = magnitude / motion.curve_torque(app, speeds) if app.motor_curve else magnitude
        index = np.argmax(load, axis=0)
        columns = np.arange(len(t))
        worst_nm, worst_rpm = magnitude[index, columns], speeds[index, columns]
        peak, rms = magnitude.max(axis=0), motion.rms(parts)
        if app.motor_curve and app.accel_m_s2 > 0.0 and not app.moves:
            fitting = _fitting_accel(app, parts, signed, index, worst_rpm)
    curve = motion.curve_torque(app, worst_rpm) if app.motor_curve else nan
    return {
        "peak_rpm": peak_rpm,
        "motor_peak_nm": peak,
        "motor_rms_nm": rms,
        "motor_rms_needed_nm": rms * app.torque_safety_factor,
        "motor_worst_segment": index,
        "motor_worst_nm": worst_nm,
        "motor_worst_needed_nm": worst_nm * app.torque_safety_factor,
        "motor_worst_rpm": worst_rpm,
        "motor_curve_nm": curve,
        "motor_fitting_accel_m_s2": fitting,
        **motion.cycle_energy(app, t, parts),
    }


def _fitting_accel(
    app: Application, parts: list[Segment[Array]], torque_nm: Array, worst: Array, rpm: Array
) -> Array:
    """The acceleration [m/s^2] at which each candidate's worst segment fits the motor
    curve, where that segment accelerates: its torque is affine in the acceleration,
    T(a) = T_run + k a with T_run the constant-speed segment's that follows, so
    a = (T_curve / SF - T_run) / k, the curve read at the segment's speed ``rpm``. NaN
    where another segment is the worst, or where no acceleration fits (k <= 0, or T_run
    alone over the curve)."""
    columns = np.arange(torque_nm.shape[1])
    accelerating = np.array([s.name == "accelerate" for s in parts])[worst]
    after = np.minimum(worst + 1, len(parts) - 1)
    t_acc, t_run = torque_nm[worst, columns], torque_nm[after, columns]
    slope = (t_acc - t_run) / app.accel_m_s2
    room = motion.curve_torque(app, rpm) / app.torque_safety_factor - t_run
    fits = accelerating & (slope > 0.0) & (room > 0.0)
    return np.where(fits, room / np.where(fits, slope, 1.0), np.nan)
