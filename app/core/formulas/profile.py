"""The move profile (trapezoid or triangle) and the motor torque of each of its segments.

A point-to-point move accelerates at ``a`` to the top speed, runs at it, and decelerates
at ``d`` to rest. When the stroke is too short to reach the top speed, the move is a
triangle that peaks below it. An acceleration of 0 means "reach the speed at once" (the
segment takes no time). Kinematics of uniform acceleration: v = a t, s = v^2 / (2 a).

Sign convention for the torque of a segment: the thrust ``F`` is the force the nut must
push against in the direction of motion (positive: the motor drives; negative: the load
drives, e.g. a descending weight or a decelerating mass). Power flows from the motor when
F > 0 and the thread works at its forward efficiency; it flows from the load when F < 0,
and the back-drive efficiency at running friction applies (Shigley [2] sec. 8-2,
lowering torque). The motor torque is then negative (the motor brakes) unless the thread
is self-locking, where the signed back-drive efficiency is negative and the motor must
drive the load down.
"""

import math

from app.core.formulas import torque
from app.core.formulas.declare import SEED, SHIGLEY, formula

#: Accelerations above 0 count as at least this [m/s^2], so that every time stays finite.
MIN_ACCEL_M_S2 = 1e-9


def inverse(accel_m_s2: float) -> float:
    """1 / a, and 0 for a = 0 (reached at once) [s^2/m]; a above 0 counts as at least
    ``MIN_ACCEL_M_S2``.

    >>> inverse(2.0), inverse(0.0), inverse(5e-324)
    (0.5, 0.0, 999999999.9999999)
    """
    return 1.0 / max(accel_m_s2, MIN_ACCEL_M_S2) if accel_m_s2 > 0.0 else 0.0


@formula("v_peak = min(v, sqrt(2 s / (1/a + 1/d)))", "kinematics")
def peak_speed(
    stroke_m: float, top_speed_m_s: float, accel_m_s2: float, decel_m_s2: float
) -> float:
    """Highest speed of the move [m/s]: the top speed, or the triangle's peak
    v_p = sqrt(2 s / (1/a + 1/d)) when the stroke is shorter than v^2/2a + v^2/2d.

    Source: uniform acceleration, s = v^2 / (2 a) for each ramp (any dynamics text).

    >>> peak_speed(0.1, 0.2, 1.0, 1.0)
    0.2
    >>> round(peak_speed(0.01, 0.2, 1.0, 1.0), 6)
    0.1
    """
    ramps = inverse(accel_m_s2) + inverse(decel_m_s2)
    if ramps == 0.0:
        return top_speed_m_s
    return min(top_speed_m_s, math.sqrt(2.0 * stroke_m / ramps))


@formula("t_a = v_peak / a", "kinematics")
def ramp_time(speed_m_s: float, accel_m_s2: float) -> float:
    """Time to reach ``speed_m_s`` from rest, t = v / a (0 when a = 0) [s].

    >>> ramp_time(0.2, 1.0)
    0.2
    """
    return speed_m_s * inverse(accel_m_s2)


def ramp_distance(speed_m_s: float, accel_m_s2: float) -> float:
    """Travel while reaching ``speed_m_s`` from rest, s = v^2 / (2 a) (0 when a = 0) [m].

    >>> round(ramp_distance(0.2, 1.0), 6)
    0.02
    """
    return speed_m_s**2 * 0.5 * inverse(accel_m_s2)


@formula("t_c = (s - v_peak^2 / 2a - v_peak^2 / 2d) / v_peak", "kinematics")
def constant_time(
    stroke_m: float, peak_speed_m_s: float, accel_m_s2: float, decel_m_s2: float
) -> float:
    """Time at the peak speed: the stroke left after both ramps, over the speed [s];
    0 for a triangle (rounding below 0 is clipped).

    >>> round(constant_time(0.1, 0.2, 1.0, 1.0), 6)
    0.3
    """
    ramps = ramp_distance(peak_speed_m_s, accel_m_s2) + ramp_distance(peak_speed_m_s, decel_m_s2)
    return max(0.0, (stroke_m - ramps) / peak_speed_m_s)


@formula(
    "T = F lead / (2 pi eta) if F >= 0 else F lead eta_b / (2 pi)",
    SHIGLEY + " (raising and lowering torque); " + SEED + " (Back Driving)",
)
def thread_torque(
    thrust_n: float,
    lead_m: float,
    efficiency: float,
    backdrive_efficiency: float,
    turn_rad: float | None = None,
) -> float:
    """Motor torque to pass a thrust through the thread, by where the power flows [N m].

    T = F lead / (2 pi eta) when F >= 0 (the motor drives), and T = F lead eta_b / (2 pi)
    when F < 0 (the load drives; eta_b the signed back-drive efficiency at running
    friction, negative when the thread self-locks). Works on floats and arrays.
    ``turn_rad``: 2 pi eta when already worked out (``torque.efficient_turn``: the
    candidate table's column), the same number.
    Source: Shigley [2] sec. 8-2, raising and lowering torques T_R, T_L; seed [1]
    "Torque To Move Load" and "Back Driving".

    >>> round(thread_torque(100.0, 0.002 * math.pi, 0.5, 0.4), 6)
    0.2
    >>> round(thread_torque(-100.0, 0.002 * math.pi, 0.5, 0.4), 6)
    -0.04
    """
    turn = torque.efficient_turn(efficiency) if turn_rad is None else turn_rad
    if isinstance(thrust_n, float | int):  # one thrust for every candidate: one branch
        if thrust_n >= 0.0:
            return thrust_n * lead_m / turn
        return thrust_n * lead_m * backdrive_efficiency / (2.0 * math.pi)
    driving = thrust_n * lead_m / turn
    driven = thrust_n * lead_m * backdrive_efficiency / (2.0 * math.pi)
    return driving * (thrust_n >= 0.0) + driven * (thrust_n < 0.0)


def signed_backdrive_efficiency(tan_lead: float, friction: float, cos_half_angle: float) -> float:
    """Back-drive efficiency without the clip at 0 [-]: eta_b = (cos a_n tan l - mu) /
    (tan l (cos a_n + mu tan l)); negative when the thread self-locks, so that
    F lead eta_b / (2 pi) is Shigley's lowering torque T_L with its sign.

    Source: Shigley [2] sec. 8-2.

    >>> round(signed_backdrive_efficiency(0.5 / math.pi, 0.09, 1.0), 4)
    0.4284
    >>> signed_backdrive_efficiency(0.05, 0.1, 1.0) < 0
    True
    """
    return (cos_half_angle * tan_lead - friction) / (
        tan_lead * (cos_half_angle + friction * tan_lead)
    )


@formula(
    "T_rms = sqrt(sum T_i^2 t_i / sum t_i)",
    "root mean square over the cycle (motor vendors' continuous-duty rule)",
)
def rms_torque(torques_nm: list[float], durations_s: list[float]) -> float:
    """Root-mean-square torque over a cycle, sqrt(sum T_i^2 t_i / sum t_i) [N m]
    (the motor's heating; compare with its continuous rating). Floats or arrays.

    Source: e.g. Oriental Motor, "Motor Sizing Calculations", effective load torque.

    >>> round(rms_torque([2.0, 1.0, 0.0], [1.0, 2.0, 1.0]), 6)
    1.224745
    """
    heat: float = sum(t * t * d for t, d in zip(torques_nm, durations_s, strict=True))
    mean: float = heat / sum(durations_s)
    root: float = mean**0.5
    return root


@formula(
    "T_eq = T_c0 sqrt(sum (T_i / T_c(n_i))^2 t_i / sum t_i)",
    "RMS torque held to the continuous duty zone at each segment's speed (Yaskawa)",
)
def referred_rms_torque(
    torques_nm: list[float],
    durations_s: list[float],
    continuous_nm: list[float],
    rated_nm: float,
) -> float:
    """The cycle's RMS torque referred to the continuous rating ``rated_nm`` [N m]:
    each segment's torque ``T_i`` [N m] scaled by ``rated_nm`` over the continuous torque
    the motor allows at that segment's speed, ``continuous_nm`` [N m] (its continuous
    duty zone), T_eq = T_c0 sqrt(sum (T_i / T_c(n_i))^2 t_i / sum t_i). Held against
    ``rated_nm``, it asks what Yaskawa's rule asks: the effective torque within the
    continuous duty zone of the torque-speed chart, where that zone narrows above the
    rated speed. Equal to ``rms_torque`` where the zone is flat (every ``T_c`` equal to
    ``rated_nm``). Floats or arrays; every ``T_c`` above zero.

    Source: Yaskawa, Sigma-II Series servomotor manual, sec. 3.2.3 (select "a servomotor
    with effective torque within the continuous duty zone"); Sigma-7 rotary servomotor
    manual, torque-motor speed characteristics (A: continuous duty zone).

    >>> round(referred_rms_torque([2.0, 1.0, 0.0], [1.0, 2.0, 1.0], [2.0] * 3, 2.0), 6)
    1.224745
    >>> round(referred_rms_torque([1.0, 1.0], [1.0, 1.0], [2.0, 1.0], 2.0), 6)
    1.581139
    """
    scaled = [t * rated_nm / c for t, c in zip(torques_nm, continuous_nm, strict=True)]
    return rms_torque(scaled, durations_s)
