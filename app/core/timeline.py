"""The cycle in time: each move's profile (its ramps, constant run and dwell), its
segments with the thrust and the motor torque in each, and the motor's view of the
whole cycle (SI)."""

from dataclasses import dataclass
from typing import Any, Generic, Literal, TypeVar

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
    ``V`` is an array (one element per candidate) or a float. A candidate's own segments
    also carry the motor's usable torque the segment is held against [N m] (its curve over
    the stepper margin at the segment's speed, a ramp's lowest from standstill to its top
    speed: ``segments.segment_curve``; None without a curve) and whether the segment
    governs the motor: the one nearest its curve, or the largest torque without a curve
    (``Quantities.motor.motor_worst_segment``). A moving segment the load drives may be
    worked at its braking end (``segments.moving_torques``): where, ``braking_end``, a
    mask of the candidates (None: nowhere, a dwell)."""

    name: SegmentName
    direction: Direction
    duration_s: float
    rpm: V
    thrust_n: V
    torque_nm: V
    curve_nm: float | None = None
    governs: bool = False
    braking_end: Any = None


@dataclass(frozen=True, slots=True)
class Motion:
    """The move and the motor torque over the cycle: its segments, the largest torque in
    magnitude and the RMS torque [N m]."""

    profile: Profile
    segments: tuple[Segment[float], ...]
    peak_nm: float
    rms_nm: float
