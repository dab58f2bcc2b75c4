"""The move over time and the motor that drives it, for many candidates at once.

``move_profile(app)`` is the application's trapezoid (or triangle); ``segments`` gives,
for every candidate, the thrust and motor torque of each segment of the cycle: accelerate,
constant, decelerate and dwell, up and down on a vertical axis, out and back on a
horizontal one. The torque of a moving segment is the thrust through the thread (by the
direction the power flows, ``profile.thread_torque``), the nut's drag, and the rotary
inertia of the screw and the motor's rotor times the angular acceleration; the moving
mass enters through the thrust as m a (against the motion when accelerating, with it
when decelerating). In a dwell the motor holds the load: the holding torque on a vertical
axis that does not self-lock, else nothing. The load acts against the motion both ways
on a horizontal axis and downwards, with the weight, on a vertical one.
"""

from typing import Any

import numpy as np

from app.core.formulas import geometry, profile, torque
from app.core.model import (
    STANDARD_GRAVITY_M_S2,
    Application,
    Direction,
    Profile,
    Segment,
    SegmentName,
)
from app.core.table import Array, CandidateTable

#: The moving segments and the sign of their acceleration along the motion.
RAMPS: tuple[tuple[SegmentName, float], ...] = (
    ("accelerate", 1.0),
    ("constant", 0.0),
    ("decelerate", -1.0),
)
#: The segments of one move, in order.
ORDER: tuple[SegmentName, ...] = ("accelerate", "constant", "decelerate", "dwell")


def decel(app: Application) -> float:
    """The deceleration [m/s^2]: as given, else the acceleration."""
    return app.accel_m_s2 if app.decel_m_s2 is None else app.decel_m_s2


def move_profile(app: Application) -> Profile | None:
    """The move over the stroke (None without a stroke, or a stroke of 0)."""
    if not app.stroke_m:
        return None
    a, d = app.accel_m_s2, decel(app)
    v = profile.peak_speed(app.stroke_m, app.speed_m_s, a, d)
    t_a, t_d = profile.ramp_time(v, a), profile.ramp_time(v, d)
    t_c = profile.constant_time(app.stroke_m, v, a, d)
    move = t_a + t_c + t_d
    return Profile(
        kind="triangle" if v < app.speed_m_s else "trapezoid",
        accel_time_s=t_a,
        constant_time_s=t_c,
        decel_time_s=t_d,
        move_time_s=move,
        cycle_time_s=2.0 * (move + app.dwell_s),
        peak_speed_m_s=v,
    )


def directions(app: Application) -> tuple[tuple[Direction, float], tuple[Direction, float]]:
    """The two moves of the cycle and the sign of the steady load against each: up against
    the weight and down with it, or out and back against the load both ways."""
    if app.orientation == "vertical":
        return (("up", 1.0), ("down", -1.0))
    return (("out", 1.0), ("back", 1.0))


def steady_load(app: Application) -> float:
    """The load the axis carries at rest or at constant speed [N]: plus m g if vertical."""
    if app.orientation == "vertical":
        return app.load_n + app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return app.load_n


def _move(
    app: Application, p: Profile, t: CandidateTable, direction: tuple[Direction, float]
) -> list[Segment[Array]]:
    """The three moving segments of one move, for every candidate."""
    rpm = geometry.screw_speed_rpm(p.peak_speed_m_s, t.lead_m)
    inertia = torque.screw_inertia(t.inertia_kg_m2_per_m, app.length_m)
    inertia = inertia + (app.motor_inertia_kg_m2 or 0.0)
    rates = {"accelerate": app.accel_m_s2, "constant": 0.0, "decelerate": decel(app)}
    times = {"accelerate": p.accel_time_s, "constant": p.constant_time_s}
    out: list[Segment[Array]] = []
    for name, sign in RAMPS:
        accel = sign * rates[name]
        thrust = direction[1] * steady_load(app) + app.moving_mass_kg * accel
        thread = profile.thread_torque(
            thrust, t.lead_m, t.efficiency, t.backdrive_efficiency_signed
        )
        spin = torque.inertia_torque(inertia, torque.angular_acceleration(accel, t.lead_m))
        out.append(
            Segment(
                name=name,
                direction=direction[0],
                duration_s=times.get(name, p.decel_time_s),
                rpm=rpm,
                thrust_n=np.full(len(t), thrust),
                torque_nm=thread + t.drag_max_nm + spin,
            )
        )
    return out


def _dwell(app: Application, direction: Direction, hold_nm: Array) -> Segment[Array]:
    """The dwell after a move: at rest, holding the load on a vertical axis."""
    vertical = app.orientation == "vertical"
    return Segment(
        name="dwell",
        direction=direction,
        duration_s=app.dwell_s,
        rpm=np.zeros(len(hold_nm)),
        thrust_n=np.full(len(hold_nm), steady_load(app) if vertical else 0.0),
        torque_nm=hold_nm if vertical else np.zeros(len(hold_nm)),
    )


def segments(
    app: Application, p: Profile, t: CandidateTable, hold_nm: Array
) -> list[Segment[Array]]:
    """Every segment of the cycle, for every candidate of ``t``; ``hold_nm`` is the
    holding torque of each (0 where the thread self-locks with margin)."""
    out: list[Segment[Array]] = []
    for direction in directions(app):
        out += _move(app, p, t, direction)
        out.append(_dwell(app, direction[0], hold_nm))
    return out


def rms(parts: list[Segment[Array]]) -> Array:
    """RMS motor torque over the cycle, per candidate [N m]."""
    torques: list[Any] = [s.torque_nm for s in parts]
    value = profile.rms_torque(torques, [s.duration_s for s in parts])
    return np.asarray(value, dtype=np.float64)


def curve_torque(app: Application, rpm: Array) -> Array:
    """The motor's torque at ``rpm``, linear between its points [N m]. Below the first
    point it is the first point's torque; past the last point the motor cannot run (the
    speed check rejects it), and the torque is read at the last point."""
    speeds = [point[0] for point in app.motor_curve]
    torques = [point[1] for point in app.motor_curve]
    return np.interp(np.minimum(rpm, speeds[-1]), speeds, torques)
