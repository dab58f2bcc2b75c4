"""A hybrid stepper's pull-out torque against speed from its datasheet's electrical
values, so a user can enter a motor's numbers instead of its curve [1, 2].

A chopper drive holds the phase current at its set value I while the winding lets it:
each full step reverses the current of one phase, from -I to +I, through the winding's
inductance L, driven by what the supply V leaves over the resistive drop I R. That takes
t = 2 L I / (V - I R) [2]. While a full step lasts longer than t the motor gives its
holding torque; faster, the current (and with it the torque) reaches only the share of
I that the step's time allows, so the torque falls as 1 / speed above the corner speed
(constant power) [1]. The model ignores back-EMF and the mid-band resonance dips of real
curves, so it is an envelope for sizing, to be checked against the maker's curve.

References
----------
1. Farnell, "Stepper motor calculator": max speed = V / (2 L I_max spr) [rev/s], minimum
   time per step = 2 L I_max / V, spr full steps per revolution.
2. D. W. Jones, "Control of Stepping Motors", University of Iowa (1995), current
   limiting: the current in an L-R winding rises at (V - i R) / L.
"""

from app.core.formulas.declare import formula

DEGREES_PER_TURN = 360.0
SECONDS_PER_MINUTE = 60.0


@formula(
    "n_c = 60 (V - I R) / (2 L I x 360 / step_angle)",
    "Farnell, Stepper motor calculator; Jones, Control of Stepping Motors",
)
def corner_speed_rpm(
    supply_v: float,
    current_a: float,
    resistance_ohm: float,
    inductance_h: float,
    step_angle_deg: float,
) -> float:
    """Speed [rpm] up to which the drive reaches the set phase current every full step:
    one full step (360 / step_angle per turn) lasts the current's reversal time
    2 L I / (V - I R) [s]. supply_v [V], current_a [A] (phase current set on the
    driver), resistance_ohm [ohm] and inductance_h [H] per phase, step_angle_deg [deg].

    Valid for a chopper (constant-current) drive with V well above I R; zero when the
    supply cannot drive the set current through the winding at all.

    Farnell's form (R neglected): 24 V, 2 mH, 1.5 A, 200 steps a turn gives
    24 / (2 x 0.002 x 1.5 x 200) = 20 rev/s = 1200 rpm:

    >>> corner_speed_rpm(24.0, 1.5, 0.0, 0.002, 1.8)
    1200.0
    >>> round(corner_speed_rpm(24.0, 2.0, 1.4, 0.003, 1.8))
    530
    """
    drive_v = max(supply_v - current_a * resistance_ohm, 0.0)
    full_steps = DEGREES_PER_TURN / step_angle_deg
    reversals_per_s = drive_v / (2.0 * inductance_h * current_a)
    return SECONDS_PER_MINUTE * reversals_per_s / full_steps


@formula("T(n) = T_h if n <= n_c else T_h n_c / n", "Farnell, Stepper motor calculator")
def pull_out_torque(rpm: float, holding_torque_nm: float, corner_rpm: float) -> float:
    """Pull-out torque [N m] at ``rpm`` [rev/min]: the holding torque [N m] (at the set
    current) up to the corner speed [rpm], then falling as corner / rpm (the current a
    step reaches is in proportion to the step's time: constant power).

    >>> pull_out_torque(500.0, 0.59, 530.0), round(pull_out_torque(1060.0, 0.59, 530.0), 3)
    (0.59, 0.295)
    """
    if rpm <= corner_rpm:
        return holding_torque_nm
    return holding_torque_nm * corner_rpm / rpm


def pull_out_curve(
    holding_torque_nm: float, corner_rpm: float, max_rpm: float, points: int = 12
) -> tuple[tuple[float, float], ...]:
    """The model's curve as (rpm, N m) points from standstill to ``max_rpm`` [rpm]: the
    corner, then points spaced evenly in speed (the 1 / n fall is convex, so straight
    lines between them lie below it: the safe side).

    >>> pull_out_curve(0.59, 530.0, 1060.0, 3)
    ((0.0, 0.59), (530.0, 0.59), (795.0, 0.3933333333333333), (1060.0, 0.295))
    >>> pull_out_curve(0.59, 530.0, 300.0)
    ((0.0, 0.59), (300.0, 0.59))
    """
    if corner_rpm >= max_rpm:
        return ((0.0, holding_torque_nm), (max_rpm, holding_torque_nm))
    step = (max_rpm - corner_rpm) / (points - 1)
    speeds = [0.0, corner_rpm, *(corner_rpm + step * (i + 1) for i in range(points - 1))]
    return tuple((n, pull_out_torque(n, holding_torque_nm, corner_rpm)) for n in speeds)
