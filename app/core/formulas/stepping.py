"""A stepper drive's controller view of the screw: steps per metre, step rate, resolution.

A stepper turns one full step (its step angle, 1.8 deg for a 200-step motor) per step
pulse, or one microstep with a microstepping driver; the screw moves one lead per turn.

References
----------
1. Prusa Research, "Prusa calculators" (steps per mm for a leadscrew): steps/mm =
   (360 / step angle) x microsteps / lead; e.g. 0.9 deg motor, 16 microsteps, 12 mm
   lead: 533.33 steps/mm.
"""

from app.core.formulas.declare import formula

DEGREES_PER_TURN = 360.0
SECONDS_PER_MINUTE = 60.0


@formula("N_rev = 360 / step_angle x microsteps", "Prusa calculators (steps per mm)")
def steps_per_rev(step_angle_deg: float, microsteps: float) -> float:
    """Step pulses per motor turn [1/rev]: full steps per turn times the microsteps per
    full step. step_angle_deg [deg] is the motor's full step.

    >>> steps_per_rev(1.8, 16), steps_per_rev(0.9, 16)
    (3200.0, 6400.0)
    """
    return DEGREES_PER_TURN / step_angle_deg * microsteps


@formula("N_m = N_rev / lead", "Prusa calculators (steps per mm)")
def steps_per_metre(steps_per_rev_1: float, lead_m: float) -> float:
    """Step pulses per metre of travel [1/m]: the pulses of one turn over the lead [m].
    Its inverse is the travel of one pulse, the finest increment the axis can be told
    to move (a microstep's real position error is larger: detent and load torque shift
    it).

    Prusa's calculator: 0.9 deg, 16 microsteps, 12 mm lead gives 533.33 steps/mm:

    >>> round(steps_per_metre(steps_per_rev(0.9, 16), 0.012) / 1000, 2)
    533.33
    """
    return steps_per_rev_1 / lead_m


@formula("f_step = n / 60 x N_rev", "kinematics")
def step_rate(rpm: float, steps_per_rev_1: float) -> float:
    """Step pulse rate [1/s] at a screw speed ``rpm`` [rev/min] (motor on the screw).

    A Tr8x8 Z axis at 12 mm/s (90 rpm), 1.8 deg and 16 microsteps: 4800 steps/s.

    >>> step_rate(90.0, steps_per_rev(1.8, 16))
    4800.0
    """
    return rpm / SECONDS_PER_MINUTE * steps_per_rev_1
