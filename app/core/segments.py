"""Each segment of the cycle for many candidates at once: its thrust and motor torque.

``segments`` gives, for every candidate, the thrust and motor torque of each segment of
the cycle (``motion.cycle``): accelerate, constant, decelerate and dwell, up and down on
a vertical axis, out and back on a horizontal one. The torque of a moving segment is the
thrust through the thread (by the direction the power flows, ``profile.thread_torque``),
the nut's drag, and the rotary inertia of the screw and the motor's rotor times the
angular acceleration; the moving mass enters through the thrust as m a. In a dwell the
motor holds the load: the holding torque where the axis holds a load (vertical, or a
load of fixed direction) and does not self-lock, else nothing. ``curve_torque`` reads
the motor's curve at a segment's speed.
"""

from collections.abc import Sequence
from typing import Any

import numpy as np

from app.core.formulas import geometry, profile, torque
from app.core.model import Application, Move
from app.core.motion import (
    RAMPS,
    Cycle,
    cycle,
    cycle_of,
    direction_word,
    load_sense,
    rest_loads,
    sense,
)
from app.core.table import Array, CandidateTable, Mask, filled
from app.core.timeline import Direction, Profile, Segment, SegmentName

#: A moving segment for every candidate: its name and direction, the thrust against the
#: motion [N], the motor torque [N m] and where it is worked at the braking end
#: (``moving_torques``).
Moving = tuple[SegmentName, Direction, float, Array, Mask]


def _move(
    app: Application,
    p: Profile,
    t: CandidateTable,
    rows: list[Moving],
) -> list[Segment[Array]]:
    """The three moving segments of one move (its ``moving_torques`` rows), for every
    candidate."""
    rpm = geometry.screw_speed_rpm(p.peak_speed_m_s, t.lead_m)
    return _timed(t, rows, rpm, (p.accel_time_s, p.constant_time_s, p.decel_time_s))


def at_top_speed(t: CandidateTable, rows: list[Moving], rpm: Array) -> list[Segment[Array]]:
    """The moving segments of every move (``moving_torques`` rows) where no stroke times
    them: each at the top speed ``rpm`` (a ramp runs from standstill to it, which
    ``segment_curve`` reads), its duration unknown (NaN). The motor's curve judges them as
    it judges a timed move's, the decelerate segment and a ramp's sweep through a dip in
    the curve included."""
    return _timed(t, rows, rpm, [float("nan")] * len(rows))


def _timed(
    t: CandidateTable, rows: list[Moving], rpm: Array, durations: Sequence[float]
) -> list[Segment[Array]]:
    """The segments of ``moving_torques`` rows at the top speed ``rpm``, each lasting its
    duration [s] of ``durations``."""
    return [
        Segment(
            name=name,
            direction=direction,
            duration_s=duration,
            rpm=rpm,
            thrust_n=filled(len(t), thrust),
            torque_nm=torque_nm,
            braking_end=braking,
        )
        for (name, direction, thrust, torque_nm, braking), duration in zip(
            rows, durations, strict=True
        )
    ]


def moving_segment_names(app: Application) -> list[tuple[SegmentName, Direction]]:
    """The moving segments of every move of the cycle (``motion.cycle``: out and back, or
    the user's own moves in their order), name and direction, in the order of
    ``moving_torques``."""
    return [(name, direction_word(app, move)) for move in cycle(app) for name, _ in RAMPS]


def screw_side_inertia(app: Application, t: CandidateTable) -> Array:
    """The rotary inertia that turns with the screw [kg m^2]: the screw's over its length
    (``torque.screw_inertia``) and the coupling's (``coupling_inertia_kg_m2``); the
    rotor's apart, the motor's own (Oriental Motor, Motor Sizing Calculations: the
    coupling is part of the load inertia)."""
    screw: Array = torque.screw_inertia(t.inertia_kg_m2_per_m, app.length_m)
    return screw + (app.coupling_inertia_kg_m2 or 0.0)


def moving_torques(
    app: Application, t: CandidateTable, c: Cycle | None = None, j_screw: Array | None = None
) -> list[Moving]:
    """Each moving segment of every move, for every candidate: its name and direction,
    the thrust against the motion v F_nut [N] and the motor torque [N m]: the thrust
    through the thread and the nut's drag (``running_torque``, worked out once per
    thrust), and the spin (``plus_spin``), whether the segment has a stroke to last or not.
    Segments of the same thrust and acceleration (the out and the back move of a
    horizontal axis) share one torque array. ``c``: the cycle and ``j_screw``: the
    screw's side's inertia (``screw_side_inertia``) when already worked out
    (``motion.cycle_of``)."""
    c = c or cycle_of(app)
    inertia = screw_side_inertia(app, t) if j_screw is None else j_screw
    if app.motor_inertia_kg_m2:
        inertia = inertia + app.motor_inertia_kg_m2
    forces = iter(c.moving_n)
    out: list[Moving] = []
    running: dict[float, Array] = {}
    worked: dict[tuple[float, float], tuple[Array, Mask]] = {}
    for move in c.moves:
        v, word = sense(move), direction_word(app, move)
        rates = {"accelerate": move.accel_m_s2, "constant": 0.0, "decelerate": move.decel_m_s2}
        for name, sign in RAMPS:
            thrust, accel = v * next(forces), sign * rates[name]
            if thrust not in running:
                running[thrust] = running_torque(t, thrust)
            if (thrust, accel) not in worked:
                worked[thrust, accel] = _worse_end(t, thrust, running, accel, inertia)
            out.append((name, word, thrust, *worked[thrust, accel]))
    return out


def _worse_end(
    t: CandidateTable, thrust_n: float, running: dict[float, Array], accel: float, j: Array
) -> tuple[Array, Mask]:
    """A segment's motor torque at its worse end, and where that is the braking end: where
    the load drives the screw (``thrust_n`` below 0), the larger in size of the torque at
    the running friction and top drag and the torque at the braking end
    (``CandidateTable.braking_backdrive_efficiency_signed``: a ball screw's low
    equivalent friction, a sliding nut's running one; the bottom of the drag range),
    where the load drives the motor hardest (a self-locking thread needs the most torque
    at the first); else at the running friction and top drag."""
    torque_nm = plus_spin(t, running[thrust_n], accel, j)
    if thrust_n >= 0.0:
        return torque_nm, np.zeros(len(t), dtype=bool)
    low = plus_spin(t, running_torque(t, thrust_n, braking=True), accel, j)
    braking = np.abs(low) > np.abs(torque_nm)
    return np.where(braking, low, torque_nm), braking


def running_torque(t: CandidateTable, thrust_n: float, braking: bool = False) -> Array:
    """The motor torque that passes the thrust ``thrust_n`` through the thread
    (``profile.thread_torque``) against the nut's drag, for every candidate [N m]: at the
    running friction and the top of the drag range, or (``braking``) at the braking end
    (``_worse_end``)."""
    eta_b, drag_nm = worked_end(t, braking)
    thread = profile.thread_torque(thrust_n, t.lead_m, t.efficiency, eta_b, t.efficient_turn_rad)
    torque_nm: Array = thread + drag_nm
    return torque_nm


def worked_end(t: CandidateTable, braking: Mask | bool) -> tuple[Array, Array]:
    """The signed back-driven efficiency and the drag torque [N m] a segment is worked at:
    the braking end's (``CandidateTable.braking_backdrive_efficiency_signed``, the bottom
    of the drag range) where ``braking`` (a mask of the candidates, or one for all), else
    the running friction's and the top of the drag range."""
    eta_b = np.where(braking, t.braking_backdrive_efficiency_signed, t.backdrive_efficiency_signed)
    return eta_b, np.where(braking, t.drag_min_nm, t.drag_max_nm)


def plus_spin(
    t: CandidateTable, torque_nm: Array, accel_m_s2: float, inertia_kg_m2: Array
) -> Array:
    """``torque_nm`` [N m] with the screw's and the rotor's inertia ``inertia_kg_m2`` times
    the angular acceleration of ``accel_m_s2``: a moving segment's motor torque (none
    added at no acceleration, the constant segment)."""
    if not accel_m_s2:
        return torque_nm
    alpha = torque.angular_acceleration(accel_m_s2, t.lead_m)
    with_spin: Array = torque_nm + torque.inertia_torque(inertia_kg_m2, alpha)
    return with_spin


def _dwell(
    app: Application, move: Move, rest_n: float, hold_nm: Array, steady_n: float
) -> Segment[Array]:
    """The dwell after ``move``: at rest, holding its load ``rest_n`` where there is one
    to hold (``hold_nm`` holds ``steady_n``, the largest; the holding torque is linear in
    the load held)."""
    held = app.orientation == "vertical" or load_sense(app, move)[0] > 0.0
    hold = hold_nm if rest_n == steady_n else hold_nm * (rest_n / steady_n)
    return Segment(
        name="dwell",
        direction=direction_word(app, move),
        duration_s=move.dwell_s,
        rpm=np.zeros(len(hold_nm)),
        thrust_n=filled(len(hold_nm), rest_n),
        torque_nm=hold if held else np.zeros(len(hold_nm)),
    )


def segments(
    app: Application,
    t: CandidateTable,
    hold_nm: Array,
    moving: list[Moving] | None = None,
    c: Cycle | None = None,
) -> list[Segment[Array]]:
    """Every segment of the cycle (a move's accelerate, constant, decelerate and dwell,
    move after move; ``segment_labels`` names them), for every candidate of ``t``;
    ``hold_nm`` is the holding torque of each at ``steady_load`` (0 where the thread
    self-locks with margin); ``moving`` the rows of ``moving_torques`` and ``c`` the
    cycle (``motion.cycle_of``) when already computed. Empty without a profile."""
    c = c or cycle_of(app)
    every = c.profiles
    if every is None:
        return []
    rows = moving_torques(app, t, c) if moving is None else moving
    steady = c.steady_n
    out: list[Segment[Array]] = []
    rests = rest_loads(app, c.moves)
    for k, (move, p, rest) in enumerate(zip(c.moves, every, rests, strict=True)):
        out += _move(app, p, t, rows[3 * k : 3 * k + 3])
        out.append(_dwell(app, move, rest, hold_nm, steady))
    return out


def rms(parts: list[Segment[Array]]) -> Array:
    """RMS motor torque over the cycle, per candidate [N m]."""
    torques: list[Any] = [s.torque_nm for s in parts]
    value = profile.rms_torque(torques, [s.duration_s for s in parts])
    return np.asarray(value, dtype=np.float64)


def continuous_rating(app: Application) -> float | None:
    """The motor's continuous torque rating [N m] the cycle's RMS torque is held to: the
    one given, else the first point of its continuous duty zone; None without either."""
    if app.motor_rms_torque_nm is not None:
        return app.motor_rms_torque_nm
    return app.motor_rms_curve[0][1] if app.motor_rms_curve else None


def continuous_torque(app: Application, rpm: Array) -> Array:
    """The continuous torque the motor allows at ``rpm`` [N m]: its continuous duty zone
    (``motor_rms_curve``, given), read as its torque-speed curve is (``read_curve``) and
    never above the rating (``continuous_rating``)."""
    zone: Array = read_curve(app.motor_rms_curve, rpm)
    return np.minimum(zone, continuous_rating(app) or np.inf)


def referred_rms(app: Application, parts: list[Segment[Array]]) -> Array:
    """The cycle's RMS torque referred to the continuous rating, each segment's torque
    held to the continuous duty zone (``motor_rms_curve``, given) at its speed
    (``profile.referred_rms_torque``) [N m]. Without a zone the rating holds at every
    speed and the plain RMS torque (``rms``) is the one held to it."""
    torques: list[Any] = [s.torque_nm for s in parts]
    allowed: list[Any] = [continuous_torque(app, s.rpm) for s in parts]
    rated = continuous_rating(app) or np.nan
    value = profile.referred_rms_torque(torques, [s.duration_s for s in parts], allowed, rated)
    return np.asarray(value, dtype=np.float64)


def curve_margin(app: Application) -> float:
    """What the motor's curve is divided by before a move is held against it: a
    stepper's (one with a step angle) torque margin on its pull-out torque, 1 for a
    servo, whose curve is already its rated envelope."""
    return app.stepper_torque_margin if app.step_angle_deg is not None else 1.0


def curve_speed(app: Application, torque_nm: Array) -> Array:
    """The highest rpm up to which the motor's usable torque (``curve_torque``) stays at
    least ``torque_nm`` [N m]: where the curve, linear between its points, first falls
    below it; the last point's speed where it never does (the motor runs no faster);
    NaN where it gives less already at its first point.

    >>> app = Application(load_n=0.0, speed_m_s=0.1, length_m=0.5,
    ...                   motor_curve=((0.0, 0.4), (1000.0, 0.2), (2000.0, 0.1)))
    >>> np.round(curve_speed(app, np.array([0.3, 0.1, 0.05, 0.5])), 9).tolist()
    [500.0, 2000.0, 2000.0, nan]
    """
    speeds, usable = _usable_points(app)
    need = np.ravel(torque_nm)
    below = usable[:, None] < need[None, :]
    first = np.where(below.any(axis=0), below.argmax(axis=0), len(speeds))
    before = np.maximum(first - 1, 0)
    after = np.minimum(first, len(speeds) - 1)
    drop = usable[before] - usable[after]
    share = (usable[before] - need) / np.where(drop > 0.0, drop, 1.0)
    crossing = speeds[before] + share * (speeds[after] - speeds[before])
    rpm = np.where(first == len(speeds), speeds[-1], crossing)
    rpm = np.where(first == 0, np.nan, rpm)
    return np.asarray(rpm.reshape(np.shape(torque_nm)), dtype=np.float64)


def curve_torque(app: Application, rpm: Array) -> Array:
    """The motor's usable torque at ``rpm`` [N m]: its curve (``read_curve``) divided by
    ``curve_margin``."""
    usable: Array = read_curve(app.motor_curve, rpm) / curve_margin(app)
    return usable


#: The segments that run through every speed from standstill to their top speed.
RAMP_NAMES = frozenset(("accelerate", "decelerate"))


def segment_curve(app: Application, name: SegmentName, rpm: Array) -> tuple[Array, Array]:
    """The motor's usable torque a segment named ``name`` at the top speed ``rpm`` is
    held against [N m], and the speed it is read at [rpm]: a ramp (accelerate,
    decelerate) passes through every speed from standstill to ``rpm`` with the same
    torque, so the lowest usable torque over that range (``swept_curve_torque``); the
    constant and dwell segments the usable torque at ``rpm`` (``curve_torque``)."""
    if name in RAMP_NAMES:
        return swept_curve_torque(app, rpm)
    return curve_torque(app, rpm), np.asarray(rpm, dtype=np.float64)


def swept_curve_torque(app: Application, rpm: Array) -> tuple[Array, Array]:
    """The lowest usable torque (``curve_torque``) over the speeds from standstill to
    ``rpm`` [N m], and the speed where it is lowest [rpm] (``rpm`` itself where none is
    lower, as on a curve that only falls). The curve is linear between its points, so
    the lowest value is at ``rpm`` or at one of its points below it: a published curve
    that dips at a resonance (SY42STH47-1684B: 0.28 N m at 270 rpm, 0.29 N m at 360 rpm)
    limits a move that accelerates through the dip.

    >>> app = Application(load_n=0.0, speed_m_s=0.1, length_m=0.5,
    ...                   motor_curve=((0.0, 0.4), (300.0, 0.2), (600.0, 0.3)))
    >>> [np.round(v, 9).tolist() for v in swept_curve_torque(app, np.array([150.0, 600.0]))]
    [[0.3, 0.2], [150.0, 300.0]]
    """
    top = np.asarray(rpm, dtype=np.float64)
    at_top = np.ravel(curve_torque(app, top))
    speeds, usable = _usable_points(app)
    below = speeds[:, None] < np.ravel(top)[None, :]
    masked = np.where(below, usable[:, None], np.inf)
    k = masked.argmin(axis=0)
    lowest = masked[k, np.arange(masked.shape[1])]
    dips = lowest < at_top
    torque = np.where(dips, lowest, at_top).reshape(top.shape)
    where = np.where(dips, speeds[k], np.ravel(top)).reshape(top.shape)
    return np.asarray(torque, dtype=np.float64), np.asarray(where, dtype=np.float64)


def read_curve(curve: tuple[tuple[float, float], ...], rpm: Array) -> Array:
    """A motor's (rpm, N m) curve read at ``rpm`` [N m]: linear between its points, the
    first point's torque below it; past the last point the motor cannot run (the speed
    check rejects it), and the torque is read at the last point.

    >>> read_curve(((0.0, 0.4), (1000.0, 0.2)), np.array([500.0, 2000.0])).tolist()
    [0.30000000000000004, 0.2]
    """
    speeds, torques = _curve_points(curve)
    at: Array = np.interp(np.minimum(rpm, speeds[-1]), speeds, torques)
    return at


def _usable_points(app: Application) -> tuple[Array, Array]:
    """The motor curve's points as the usable torque (``curve_torque``) has them: speeds
    [rpm] and torques over ``curve_margin`` [N m]."""
    speeds, torques = _curve_points(app.motor_curve)
    return speeds, torques / curve_margin(app)


def _curve_points(curve: tuple[tuple[float, float], ...]) -> tuple[Array, Array]:
    """A motor curve's speeds [rpm] and torques [N m], as arrays."""
    points: Array = np.array(curve, dtype=np.float64).reshape(-1, 2)
    speeds: Array = points[:, 0]
    torques: Array = points[:, 1]
    return speeds, torques
