"""The motor's view of the axis for many candidates at once: the torque breakdown of the
move that starts hardest, each segment's torque against the motor's curve, the RMS torque,
the acceleration that fits the curve and the stepper controller's step rate.
"""

from typing import Any

import numpy as np

from app.core import cycle_energy, motion, segments
from app.core.formulas import (
    geometry,
    profile,
    stepping,
    torque,
)
from app.core.model import FIX_MARGIN, Application, Move
from app.core.table import Array, CandidateTable, filled
from app.core.timeline import Segment


def torques(
    app: Application,
    t: CandidateTable,
    force_n: float,
    moving: list[segments.Moving],
    c: motion.Cycle,
    j_screw: Array,
) -> dict[str, Any]:
    """Motor torque: the screw's (with its coupling's) and the rotor's inertia J alpha, and
    every force that passes through the sliding thread (the load and the force m a that
    accelerates the moving mass) at the thread's efficiency, plus the nut's drag. Starting
    from rest the thread is at static friction while the load and m a already act. The
    required torque is the larger of break-away and the peak of the moving segments of both
    moves (``moving``, the rows of ``segments.moving_torques``: decelerating a descending
    load may need more). The breakdown is that of the move of the cycle ``c``
    (``motion.cycle_of``) that starts hardest (``c.lead``, ``motion.lead_move``: out and
    back, the scalar inputs); break-away the largest of every move's start
    (``breakaway``): a move with less thrust may need more torque to start, its
    acceleration higher. The load's inertia at the motor is the screw's and the
    coupling's (``j_screw``, ``segments.screw_side_inertia``) and the heaviest mass any
    move carries (``motion.heaviest_mass``), reflected: a lighter lead move does not lighten
    the heaviest."""
    move = c.lead
    alpha = torque.angular_acceleration(move.accel_m_s2, t.lead_m)
    j_heaviest = torque.reflected_mass_inertia(
        motion.heaviest_mass(app, c.moves), t.lead_m, t.reflected_inertia_per_kg_m2
    )
    inertial_force_n = move.moving_mass_kg * move.accel_m_s2
    t_screw = torque.inertia_torque(j_screw, alpha)
    t_motor = torque.inertia_torque(app.motor_inertia_kg_m2 or 0.0, alpha)
    t_mass = torque.load_torque(inertial_force_n, t.lead_m, t.efficiency, t.efficient_turn_rad)
    t_load = torque.load_torque(force_n, t.lead_m, t.efficiency, t.efficient_turn_rad)
    t_spin = t_screw + t_motor
    t_inertia = t_spin + t_mass
    t_total = torque.total_torque(t_inertia, t.drag_max_nm, t_load)
    # each move's start; the lead move's inertia torques are those of the breakdown
    starts = [breakaway(t, force_n + inertial_force_n, t_spin)]
    for other in app.moves:
        if other is not move:
            start_n = motion.running_thrust(app, other) + other.moving_mass_kg * other.accel_m_s2
            starts.append(breakaway(t, start_n, spin_torque(app, t, other, j_screw)))
    t_start = starts[0] if len(starts) == 1 else np.maximum.reduce(starts)
    magnitude = np.abs(np.array([m[3] for m in moving]))
    largest = np.maximum.reduce(magnitude, axis=0)
    peak = np.maximum(largest, t_start)
    # the segment's index as a float, as every number of ``Quantities`` is
    segment = np.where(largest > t_start, magnitude.argmax(axis=0), -1.0)
    return {
        "angular_accel_rad_s2": alpha,
        "inertia_kg_m2": j_screw + j_heaviest,
        "inertia_screw_nm": t_screw,
        "inertia_mass_nm": t_mass,
        "inertia_motor_nm": t_motor,
        "inertia_nm": t_inertia,
        "drag_nm": t.drag_max_nm,
        "load_nm": t_load,
        "total_nm": t_total,
        "breakaway_nm": t_start,
        "peak_torque_nm": peak,
        "peak_torque_segment": segment,
        "required_nm": peak * app.torque_safety_factor,
    }


def torque_before_factor_nm(app: Application) -> float | None:
    """The most a torque before the torque safety factor may reach [N m]: the drive's
    maximum torque over that factor (the torque check holds the torque times the factor
    to the maximum); None without a maximum."""
    if app.max_torque_nm is None:
        return None
    return app.max_torque_nm / app.torque_safety_factor


def breakaway(t: CandidateTable, start_n: float, spin_nm: Array) -> Array:
    """The torque that starts a move from rest [N m]: its thrust ``start_n`` (the running
    thrust and the force m a that accelerates its mass) through the thread at static
    friction (``profile.thread_torque``: where the load drives the move, at the signed
    back-driven efficiency, so that a thread self-locking at static friction needs the
    motor to start lowering), the screw's and the rotor's inertia torque ``spin_nm`` and
    the nut's drag."""
    thread: Array = profile.thread_torque(
        start_n,
        t.lead_m,
        t.efficiency_static,
        t.start_backdrive_efficiency_signed,
        t.start_efficient_turn_rad,
    )
    return thread + spin_nm + t.drag_max_nm


def spin_torque(app: Application, t: CandidateTable, move: Move, j_screw: Array) -> Array:
    """The screw's (``j_screw``) and the rotor's inertia times the angular acceleration
    of ``move`` [N m]."""
    alpha = torque.angular_acceleration(move.accel_m_s2, t.lead_m)
    screw: Array = torque.inertia_torque(j_screw, alpha)
    return screw + torque.inertia_torque(app.motor_inertia_kg_m2 or 0.0, alpha)


def controller(app: Application, t: CandidateTable, peak_rpm: Array) -> dict[str, Any]:
    """The step rate the peak speed needs and the travel of one step pulse."""
    if app.step_angle_deg is None:
        nan = filled(len(t), np.nan)
        return {"step_rate_hz": nan, "step_resolution_m": nan}
    per_rev = stepping.steps_per_rev(app.step_angle_deg, app.microsteps)
    return {
        "step_rate_hz": stepping.step_rate(peak_rpm, per_rev),
        "step_resolution_m": 1.0 / stepping.steps_per_metre(per_rev, t.lead_m),
    }


def motor_point(
    app: Application,
    t: CandidateTable,
    rpm: Array,
    hold_nm: Array,
    torques: dict[str, Any],
    moving: list[segments.Moving],
    c: motion.Cycle,
) -> dict[str, Any]:
    """The motor's view of the move of the cycle ``c`` (``motion.cycle_of``): every
    segment's torque against the curve (the moving ones' ``moving``, from
    ``segments.moving_torques``), and the break-away that starts each move from rest
    (``torques["breakaway_nm"]``: the thread at static friction) against the curve at
    standstill (``worst_point``); the acceleration and top speed that would fit the
    curve (``curve_fits``). Without a stroke there is no profile to time the segments:
    each moving segment of both moves is judged at the top speed ``rpm``
    (``segments.at_top_speed``: a ramp over the speeds up to it), beside the break-away,
    and the top speed that fits is the one at which all of them do (``slower_fit``); no
    acceleration to fit (NaN)."""
    p = c.fastest
    peak_rpm = worst_rpm = rpm
    nan = filled(len(t), np.nan)
    fits = (nan,) * 4
    parts: list[Segment[Array]] = []
    if p is None:
        peak, rms, referred = nan, nan, nan
        # without a curve the worst point is the largest torque: the peak of the moving
        # segments and the start (``torques``), the same rows ``worst_point`` reads
        index, worst_nm = torques["peak_torque_segment"], torques["peak_torque_nm"]
        worst_rpm = np.where(index < 0, 0.0, rpm)
        if app.motor_curve:
            at_top = segments.at_top_speed(t, moving, rpm)
            index, worst_nm, worst_rpm, starting, at_rest = worst_point(app, t, at_top, torques)
            fit_speed = slower_fit(app, starting, at_rest, c.reached_m_s)
            fix_speed = slower_fit(app, starting, at_rest, c.reached_m_s, 1.0 + FIX_MARGIN)
            fits = (nan, fit_speed, nan, fix_speed)
    else:
        peak_rpm = geometry.screw_speed_rpm(p.peak_speed_m_s, t.lead_m)
        parts = segments.segments(app, t, hold_nm, moving, c)
        index, worst_nm, worst_rpm, starting, at_rest = worst_point(app, t, parts, torques)
        peak = np.maximum.reduce(np.abs(np.array([s.torque_nm for s in parts])), axis=0)
        rms = segments.rms(parts)
        referred = segments.referred_rms(app, parts) if app.motor_rms_curve else rms
        if app.motor_curve and not app.moves:
            worst = (index, worst_rpm, starting, at_rest)
            fits = curve_fits(app, t, parts, torques, worst, p.peak_speed_m_s)
    fitting, fitting_speed, fix_accel, fix_speed = fits
    curve = segments.curve_torque(app, worst_rpm) if app.motor_curve else nan
    return {
        "peak_rpm": peak_rpm,
        "motor_peak_nm": peak,
        "motor_rms_nm": rms,
        "motor_rms_zone_nm": referred,
        "motor_rms_needed_nm": referred * app.torque_safety_factor,
        "motor_worst_segment": np.asarray(index, dtype=np.float64),
        "motor_worst_nm": worst_nm,
        "motor_worst_needed_nm": worst_nm * app.torque_safety_factor,
        "motor_worst_rpm": worst_rpm,
        "motor_curve_nm": curve,
        "motor_fitting_accel_m_s2": fitting,
        "motor_fitting_speed_m_s": fitting_speed,
        "motor_fix_accel_m_s2": fix_accel,
        "motor_fix_speed_m_s": fix_speed,
        **cycle_energy.cycle_energy(app, t, parts, c.profiles),
    }


def worst_point(
    app: Application, t: CandidateTable, parts: list[Segment[Array]], torques: dict[str, Any]
) -> tuple[Array, Array, Array, Array, Array]:
    """Each candidate's point nearest the motor's curve (the largest torque without a
    curve): the segments of ``parts``, each against the curve over the speeds it runs
    through (``segments.segment_curve``: a ramp, the lowest from standstill to its top
    speed), and the break-away (``torques["breakaway_nm"]``) at standstill, one more row.
    Returns the worst row's index (-1: the break-away), its torque [N m] and the speed
    the curve is read at [rpm], and the rows' torques [N m] and top speeds [rpm]."""
    magnitude = np.abs(np.array([s.torque_nm for s in parts]))
    speeds = np.array([s.rpm for s in parts])
    start_nm = np.broadcast_to(np.abs(torques["breakaway_nm"]), speeds[0].shape)
    starting = np.vstack([magnitude, start_nm])
    at_rest = np.vstack([speeds, np.zeros_like(speeds[0])])
    read_rpm = at_rest
    load = starting
    if app.motor_curve:
        read = [segments.segment_curve(app, s.name, s.rpm) for s in parts]
        usable = np.vstack([*(u for u, _ in read), segments.curve_torque(app, at_rest[-1])])
        read_rpm = np.vstack([*(r for _, r in read), at_rest[-1]])
        load = starting / usable
    index = load.argmax(axis=0)
    columns = np.arange(len(t))
    worst_nm, worst_rpm = starting[index, columns], read_rpm[index, columns]
    return np.where(index == len(parts), -1, index), worst_nm, worst_rpm, starting, at_rest


def curve_fits(
    app: Application,
    t: CandidateTable,
    parts: list[Segment[Array]],
    torques: dict[str, Any],
    worst: tuple[Array, Array, Array, Array],
    peak_speed: float,
) -> tuple[Array, Array, Array, Array]:
    """The acceleration [m/s^2] and top speed [m/s] at which each candidate fits its
    motor's curve, bare and with the fix's margin (``FIX_MARGIN``): (fitting accel,
    fitting speed, fix accel, fix speed). ``worst``: ``worst_point``'s index, speed,
    torques and speeds; ``peak_speed`` the move's top speed [m/s]. The acceleration is
    also bounded by the start from rest (``starting_accel``); NaN without one."""
    index, worst_rpm, starting, at_rest = worst
    nan = filled(len(t), np.nan)
    fitting = fix_accel = nan
    if app.accel_m_s2 > 0.0:
        signed = np.array([s.torque_nm for s in parts])
        margin = 1.0 + FIX_MARGIN
        fitting = np.minimum(
            fitting_accel(app, parts, signed, index, worst_rpm), starting_accel(app, t, torques)
        )
        fix_accel = np.minimum(
            fitting_accel(app, parts, signed, index, worst_rpm, margin),
            starting_accel(app, t, torques, margin),
        )
    fitting_speed = slower_fit(app, starting, at_rest, peak_speed)
    fix_speed = slower_fit(app, starting, at_rest, peak_speed, 1.0 + FIX_MARGIN)
    return fitting, fitting_speed, fix_accel, fix_speed


def fitting_accel(
    app: Application,
    parts: list[Segment[Array]],
    torque_nm: Array,
    worst: Array,
    rpm: Array,
    margin: float = 1.0,
) -> Array:
    """The acceleration [m/s^2] at which each candidate's worst segment fits the motor
    curve, where that segment accelerates: its torque is affine in the acceleration,
    T(a) = T_run + k a with T_run the constant-speed segment's that follows, so
    a = (T_curve / (SF margin) - T_run) / k, the curve read at the segment's speed
    ``rpm``; ``margin`` above 1 leaves the torque that much below the curve (a fix's). NaN
    where another segment is the worst, or where no acceleration fits (k <= 0, or T_run
    alone over the curve)."""
    columns = np.arange(torque_nm.shape[1])
    accelerating = np.array([s.name == "accelerate" for s in parts])[worst]
    after = np.minimum(worst + 1, len(parts) - 1)
    t_acc, t_run = torque_nm[worst, columns], torque_nm[after, columns]
    slope = (t_acc - t_run) / app.accel_m_s2
    room = segments.curve_torque(app, rpm) / (app.torque_safety_factor * margin) - t_run
    fits = accelerating & (slope > 0.0) & (room > 0.0)
    return np.where(fits, room / np.where(fits, slope, 1.0), np.nan)


def starting_accel(
    app: Application, t: CandidateTable, torques: dict[str, Any], margin: float = 1.0
) -> Array:
    """The highest acceleration [m/s^2] at which the break-away that starts the move
    (``torques["breakaway_nm"]``) still fits the curve at standstill, a bound on
    ``fitting_accel``'s where the accelerate segment governs (a slower ramp that fits it
    may leave the start over the curve, read at 0 rpm). The break-away is affine in the
    acceleration, its part in it the force m a through the thread at static friction and
    the screw's and the rotor's inertia torques: B(a) = B_0 + (B - B_0) a / a_now.
    Infinite where it fits at any acceleration, NaN where it fits at none (B_0 alone
    over the curve)."""
    accel = app.accel_m_s2
    part = (
        torque.load_torque(
            app.moving_mass_kg * accel, t.lead_m, t.efficiency_static, t.start_efficient_turn_rad
        )
        + torques["inertia_screw_nm"]
        + torques["inertia_motor_nm"]
    )
    rest = torques["breakaway_nm"] - part
    room = segments.curve_torque(app, np.zeros(len(t))) / (app.torque_safety_factor * margin)
    room = room - np.abs(rest)
    grows = part > 0.0
    fits = np.divide(room * accel, part, out=np.full(len(t), np.inf), where=grows)
    return np.where(room > 0.0, fits, np.nan)


def slower_fit(
    app: Application, torque_nm: Array, rpm: Array, peak_speed_m_s: float, margin: float = 1.0
) -> Array:
    """The top speed [m/s] at which every segment of the move fits the motor curve, from
    each segment's torque magnitude ``torque_nm`` and speed ``rpm`` (a row per segment, a
    column per candidate). A segment's torque does not depend on the speed (the thread's
    Coulomb friction, the load, the drag, inertia times the acceleration), while its
    speed scales with the top speed: each segment fits up to the highest rpm at which the
    usable curve still gives its torque times the safety factor (``segments.curve_speed``),
    and the top speed ``peak_speed_m_s`` scales by the smallest of those over the
    segment's rpm. NaN where a segment needs more than the curve gives at its lowest
    speed (a dwell's hold, or a torque no slower move lowers). ``margin`` above 1 leaves
    each torque that much below the curve (a fix's)."""
    most = segments.curve_speed(app, torque_nm * app.torque_safety_factor * margin)
    ratio = np.divide(most, rpm, out=np.where(np.isnan(most), np.nan, np.inf), where=rpm > 0.0)
    return np.asarray(peak_speed_m_s * ratio.min(axis=0), dtype=np.float64)
