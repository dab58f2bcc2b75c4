"""Published power-screw (thread) examples, through the core's thread formulas: each
example's figure as the core computes it from the example's own inputs, for /validation.

Shigley's Example 8-1 (a square thread with a collar), a two-start ISO trapezoidal screw
that self-locks (torques to raise and to lower, efficiency), Mott's Acme screw and a
square-thread jack.
"""

import math

from app.contract.units import from_si, to_si
from app.core.formulas import efficiency, geometry, profile, torque, trapezoidal

#: cos of a square thread's half angle (0°)
SQUARE = 1.0
SHIGLEY = "Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed., Example 8-1"


def shigley_thread_torque() -> float:
    """Shigley ex. 8-1 raising torque of the thread alone (the core has no collar)."""
    d_m = geometry.pitch_diameter(0.032, 0.028)
    lead = geometry.lead_from_pitch(0.004, 2)
    eta = efficiency.forward_efficiency(geometry.tan_lead_angle(lead, d_m), 0.08, SQUARE)
    return torque.load_torque(6400.0, lead, eta)


def shigley_lowering_torque() -> float:
    """Shigley ex. 8-1 lowering torque of the thread: minus the physical holding torque."""
    lead = 0.008
    eta_b = efficiency.backdrive_efficiency(geometry.tan_lead_angle(lead, 0.030), 0.08, SQUARE)
    return -efficiency.holding_torque(6400.0, lead, eta_b)


def shigley_overall_efficiency() -> float:
    """Shigley ex. 8-1 overall efficiency: the core's thread torque plus the printed collar
    torque F f_c d_c / 2, which the core does not model."""
    collar = 6400.0 * 0.08 * 0.040 / 2
    return 6400.0 * 0.008 / (2 * math.pi * (shigley_thread_torque() + collar))


#: Tr 100 x 12, two-start, ISO trapezoidal (half angle 15°), friction 0.15, 300 kN, no collar.
POWER_SCREWS = (
    "FOSSEE Scilab Textbook Companion 764, ch. 6 Power Screws, example EX6.2, "
    "result6_2.txt (github.com/FOSSEE/Scilab-TBC-Uploads, 764/CH6/EX6.2.b)"
)
POWER_SCREWS_INPUTS = "Tr 100 × 12, two-start, half angle 15°, f 0.15, 300 kN, no collar"
ADAPTIVE = (
    "Adaptive Books, Statics, 5.6.1 Screw threads, problem 2 (https://www.adaptivebooks.org/"
    "statics/friction-the-application-of-statics-to-machine-design/screw-threads)"
)
MOTT = "R. L. Mott, Machine Elements in Mechanical Design, 4th ed., Example Problem 17-1, p. 703"
MOTT_NOTE = (
    "Mott's own figures (cos 14.5° = 0.968, tan λ = 0.0592) give 1814 lb in by his "
    "equation 17-10, the core's form; the printed 1809 is 0.3 % below it."
)


def tr100(thrust_n: float) -> tuple[float, float]:
    """The two-start Tr 100 x 12 of ``POWER_SCREWS``: its forward efficiency and the
    motor torque [N m] to pass ``thrust_n`` through it (``profile.thread_torque``: raising
    when positive; lowering, with the load behind the move, when negative)."""
    lead = geometry.lead_from_pitch(0.012, 2)
    tan_l = geometry.tan_lead_angle(lead, trapezoidal.pitch_diameter(0.100, 0.012))
    cos_a = math.cos(math.radians(15.0))
    eta = efficiency.forward_efficiency(tan_l, 0.15, cos_a)
    eta_b = profile.signed_backdrive_efficiency(tan_l, 0.15, cos_a)
    return eta, profile.thread_torque(thrust_n, lead, eta, eta_b)


def mott_acme_torque_lb_in() -> float:
    """Mott's access-hatch screw in lb in: one of two Acme 1 1/2-4 screws (pitch diameter
    1.3429 in, single start, half angle 14.5°) raising 12,500 lb at friction 0.15."""
    lead = to_si(0.25, "in")
    tan_l = geometry.tan_lead_angle(lead, to_si(1.3429, "in"))
    eta = efficiency.forward_efficiency(tan_l, 0.15, math.cos(math.radians(14.5)))
    return from_si(torque.load_torque(to_si(12_500.0, "lbf"), lead, eta), "lb in")


def adaptive_square_torque_lb_in() -> float:
    """Adaptive Books' square-thread jack in lb in: 10,000 lb on a single-start thread of
    two threads per inch, mean diameter 2 in, friction 0.2."""
    lead = to_si(0.5, "in")
    tan_l = geometry.tan_lead_angle(lead, to_si(2.0, "in"))
    eta = efficiency.forward_efficiency(tan_l, 0.2, SQUARE)
    return from_si(torque.load_torque(to_si(10_000.0, "lbf"), lead, eta), "lb in")
