"""The energy of one cycle for many candidates at once, from its segments.

``cycle_energy`` sums each segment's (``segments.segments``) shaft work, the work on the
load, the thread's friction and the nut's drag over the segment's travel, and adds a
stepper's copper loss over the whole cycle.
"""

import math

import numpy as np

from app.core.formulas import energy
from app.core.model import Application
from app.core.motion import segment_travels
from app.core.segments import worked_end
from app.core.table import Array, CandidateTable, filled
from app.core.timeline import Profile, Segment

#: A net work within this share of the sum of its terms' sizes is rounding, not work: a
#: weight raised and lowered again does none (double precision keeps some 16 digits).
ROUNDING = 1e-12

#: The energy of one cycle, per candidate [J] (``cycle_energy``).
ENERGY = (
    "cycle_motor_work_j",
    "cycle_regen_j",
    "cycle_load_work_j",
    "cycle_thread_loss_j",
    "cycle_drag_loss_j",
    "cycle_copper_loss_j",
)


def copper_current_rms(app: Application) -> float | None:
    """A stepper's RMS phase current [A] where its step angle, current and winding
    resistance are given; None otherwise (a servo's copper loss needs its torque
    constant, which is not an input).

    The current's amplitude is the current typed, or sqrt 2 times it where it is set as
    RMS (``motor_current_rms``). Microstepping (``microsteps`` above 1) drives the phases
    with a sine and a cosine of that amplitude: I_rms = I_amplitude / sqrt 2, so the two
    windings lose I_amplitude^2 R together at every step position. Full steps
    (``microsteps`` 1) drive both phases at the full amplitude all the time (a square
    wave, two phases on): I_rms = I_amplitude, twice the microstepping drive's heat."""
    current = app.motor_phase_current_a
    if app.step_angle_deg is None or current is None or app.motor_resistance_ohm is None:
        return None
    amplitude = current * math.sqrt(2.0) if app.motor_current_rms else current
    return amplitude if app.microsteps == 1 else amplitude / math.sqrt(2.0)


def cycle_energy(
    app: Application, t: CandidateTable, parts: list[Segment[Array]], every: list[Profile] | None
) -> dict[str, Array]:
    """The energy of one cycle over ``parts`` (``segments``) of the moves whose profiles
    are ``every`` (``motion.profiles``), per candidate [J]: the
    motor's work at its shaft where it drives (``energy.shaft_energy`` above 0), the
    energy braking gives back on decelerate and down segments (its work below 0, before
    the drive's own losses), the work done on the load (sum F x: its weight and external
    load; the moving mass's kinetic energy cancels over each move), the thread's friction
    (``energy.thread_loss``) and the nut's drag, each at the end of the friction and drag
    its segment's torque is worked at (``Segment.braking_end``), and a stepper's copper
    loss over the whole cycle (``energy.stepper_copper_loss``, the drive holding its current at rest
    too: NaN without its current and resistance). NaN without a profile. The balance:
    motor work - braking = load work + thread loss + drag loss."""
    nan = filled(len(t), np.nan)
    if every is None or not parts:
        return dict.fromkeys(ENERGY, nan)
    travels = [x for p in every for x in (*segment_travels(p), 0.0)]
    zero = np.zeros(len(t))
    motor, regen, load, thread, drag, size = zero, zero, zero, zero, zero, zero
    for s, x in zip(parts, travels, strict=True):
        shaft = energy.shaft_energy(s.torque_nm, x, t.lead_m)
        motor = motor + np.maximum(shaft, 0.0)
        regen = regen + np.maximum(-shaft, 0.0)
        work = s.thrust_n * x
        load = load + work
        size = size + np.abs(work)
        # at the end of the friction and drag the segment's torque was worked at
        eta_b, drag_nm = worked_end(t, False if s.braking_end is None else s.braking_end)
        thread = thread + energy.thread_loss(s.thrust_n, x, t.efficiency, eta_b)
        drag = drag + np.asarray(energy.shaft_energy(drag_nm, x, t.lead_m), dtype=np.float64)
    current = copper_current_rms(app)
    copper = nan
    if current is not None:
        joules = energy.stepper_copper_loss(
            current, app.motor_resistance_ohm or 0.0, every[0].cycle_time_s
        )
        copper = filled(len(t), joules)
    return {
        "cycle_motor_work_j": motor,
        "cycle_regen_j": regen,
        "cycle_load_work_j": np.where(np.abs(load) <= ROUNDING * size, 0.0, load),
        "cycle_thread_loss_j": thread,
        "cycle_drag_loss_j": drag,
        "cycle_copper_loss_j": copper,
    }
