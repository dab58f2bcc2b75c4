"""Energy of one cycle: the motor's work at its shaft, where it goes (the load, the
thread's friction, the nut's drag), what braking gives back, and the winding's copper
loss [1, 2].

Each segment of a move runs at a constant motor torque T over a turn angle
theta = 2 pi x / lead (x the nut's travel in it), so the shaft work of a segment is
T theta [1]. Over a move that starts and ends at rest the rotary kinetic energy the ramps
put in and take out cancels, and the shaft work of the cycle is the work done on the load
(its weight and the external load; the kinetic energy of the moving mass cancels too)
plus the thread's friction and the nut's drag: a balance the tests hold the sums to.

References
----------
1. Shigley's Mechanical Engineering Design, 9th ed., sec. 8-2: the raising torque
   passes F lead / (2 pi eta) (the work F x / eta per travel x), the lowering torque
   F lead eta_b / (2 pi), so the thread turns F x (1 / eta - 1) into heat while the
   motor drives and F x (1 - eta_b) while the load drives.
2. Joule's first law, P = I^2 R: the heat of a current I [A, RMS] in a resistance R
   [ohm]. A microstepping drive sets sine and cosine phase currents of peak I_p, whose
   squares sum to I_p^2 at every step (sin^2 + cos^2 = 1), so the two phases of a
   two-phase stepper dissipate I_p^2 R = 2 I_rms^2 R together at every position, moving
   or holding.
"""

import math

from app.core.formulas.declare import formula


@formula("E = T 2 pi x / lead", "work of a constant torque over the turns (Shigley sec. 8-2)")
def shaft_energy(torque_nm: float, travel_m: float, lead_m: float) -> float:
    """Work of the motor at its shaft over a segment [J]: torque [N m] times the turn
    angle 2 pi x / lead, x the nut's travel [m], lead [m]; below 0 when the motor brakes
    (the energy braking gives back). Floats or arrays.

    0.2 N m over 10 mm of a 2 mm lead, five turns:

    >>> round(shaft_energy(0.2, 0.01, 0.002), 4)
    6.2832
    """
    return torque_nm * 2.0 * math.pi * travel_m / lead_m


@formula(
    "E_thread = F x (1/eta - 1) if F >= 0 else |F| x (1 - eta_b)",
    "Shigley sec. 8-2 (raising and lowering torque)",
)
def thread_loss(
    thrust_n: float, travel_m: float, efficiency: float, backdrive_efficiency: float
) -> float:
    """Energy the thread's friction turns into heat over a segment [J]: thrust against the
    motion F [N] over the travel x [m], the motor driving (F >= 0) at the forward
    efficiency eta, else the load driving at the signed back-drive efficiency eta_b
    (below 0 when the thread self-locks: the motor then drives the load down and the
    thread takes both works). Floats or arrays.

    100 N over 0.1 m at eta = 0.4: 10 J of work and 15 J lost; the same driven back at
    eta_b = 0.25: 7.5 J lost.

    >>> thread_loss(100.0, 0.1, 0.4, 0.25), thread_loss(-100.0, 0.1, 0.4, 0.25)
    (15.0, 7.5)
    """
    driving = thrust_n * travel_m * (1.0 / efficiency - 1.0)
    driven = -thrust_n * travel_m * (1.0 - backdrive_efficiency)
    return driving * (thrust_n >= 0.0) + driven * (thrust_n < 0.0)


@formula(
    "E_cu = 2 I_rms^2 R t",
    "Joule's first law P = I^2 R, both phases of a two-phase stepper energised",
)
def stepper_copper_loss(current_rms_a: float, resistance_ohm: float, time_s: float) -> float:
    """Copper loss of a two-phase stepper over ``time_s`` [J]: both windings carry the
    phase current, 2 I_rms^2 R per second (I_rms [A] the RMS phase current, R [ohm] the
    winding resistance of one phase); a drive that sets the sine's peak I_p gives
    I_rms = I_p / sqrt 2, so I_p^2 R. Valid while the drive holds the full current, at
    speed and at rest (a drive that reduces it at standstill loses less).

    2 A RMS, 1.4 ohm, over 1 s:

    >>> round(stepper_copper_loss(2.0, 1.4, 1.0), 6)
    11.2
    """
    return 2.0 * current_rms_a**2 * resistance_ohm * time_s


@formula("P = T omega = T 2 pi n / 60", "power of a torque at a shaft's angular speed")
def shaft_power(torque_nm: float, speed_rpm: float) -> float:
    """Mechanical power at the motor shaft [W]: torque [N m] times the angular speed
    omega = 2 pi n / 60 [rad/s], n the speed [rpm]; below 0 when the motor brakes. Valid
    for any finite torque and speed. Floats or arrays.

    1 N m at 60 rpm (one turn a second) is 2 pi W:

    >>> round(shaft_power(1.0, 60.0), 4)
    6.2832
    """
    return torque_nm * 2.0 * math.pi * speed_rpm / 60.0
