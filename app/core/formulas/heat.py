"""Heat of a sliding nut: the power its friction turns into heat, and the temperature
rise at which the screw (as a fin, both ways) and the nut's surface carry it away [1].

References
----------
1. F. P. Incropera, D. P. DeWitt et al., Fundamentals of Heat and Mass Transfer, 6th ed.:
   sec. 3.6 (extended surfaces; the infinitely long fin conducts sqrt(h P k A_c) per
   kelvin at its base), Example 3.9 (5 mm rods of copper, 2024 aluminium and AISI 316
   stainless, h = 100 W/(m^2 K), base 100 C in 25 C air: 8.3, 5.6 and 1.6 W), Table 1.1
   (free convection of gases: h = 2-25 W/(m^2 K)).
"""

import math

from app.core.formulas.declare import formula

#: Free convection from a slowly moving screw and nut [W/(m^2 K)]: assumed, the lower
#: middle of Incropera's Table 1.1 range for gases (2-25).
FREE_CONVECTION_W_M2_K = 10.0
#: A trapezoidal nut's outside diameter over the screw's [1]: assumed, a round nut of
#: about twice the thread (flanged nuts are larger: the safe side).
NUT_OUTER_TO_D = 2.0


@formula("P_f = F v (1 / eta - 1)", "the flow of power through the thread (Shigley sec. 8-2)")
def friction_power(force_n: float, speed_m_s: float, efficiency: float) -> float:
    """Power the thread's friction turns into heat [W]: the input F v / eta [W] less the
    useful F v, force [N], mean linear speed [m/s], forward efficiency [-].

    A 200 kg lift (1962 N) at 12 mm/s on Tr14x3 with an oiled bronze nut (eta = 0.358):

    >>> round(friction_power(1962.0, 0.012, 0.358), 1)
    42.2
    """
    return force_n * speed_m_s * (1.0 / efficiency - 1.0)


@formula("G_fin = sqrt(h pi d k pi d^2 / 4)", "Incropera, sec. 3.6 (infinitely long fin)")
def fin_conductance(diameter_m: float, conductivity_w_m_k: float, h_w_m2_k: float) -> float:
    """Heat an infinitely long round rod conducts away from its base per kelvin [W/K]:
    sqrt(h P k A_c), P = pi d, A_c = pi d^2 / 4; diameter [m], conductivity k [W/(m K)],
    convection h [W/(m^2 K)]. Valid for a rod long against its fin length sqrt(k A / h P).

    Incropera Example 3.9, 5 mm copper (k = 398) at h = 100 and 75 K: 8.3 W.

    >>> round(fin_conductance(0.005, 398.0, 100.0) * 75.0, 1)
    8.3
    """
    perimeter_m = math.pi * diameter_m
    section_m2 = math.pi * diameter_m**2 / 4.0
    conductance: float = (h_w_m2_k * perimeter_m * conductivity_w_m_k * section_m2) ** 0.5
    return conductance


@formula(
    "dT = P / (2 G_fin(d_3) + h pi D_nut L_nut)",
    "Incropera, sec. 3.6 and Newton's law of cooling",
)
def temperature_rise(
    power_w: float, fin_w_k: float, nut_length_m: float, nut_diameter_m: float, h_w_m2_k: float
) -> float:
    """Steady temperature rise of the nut over the ambient [K]: the friction power [W]
    over the screw's conductance both ways (two fins, [W/K]) plus the nut surface's
    convection h pi D L (nut length and outside diameter [m], h [W/(m^2 K)]).

    >>> round(temperature_rise(10.0, 0.04, 0.028, 0.028, 10.0), 1)
    95.6
    """
    surface_w_k = h_w_m2_k * math.pi * nut_diameter_m * nut_length_m
    return power_w / (2.0 * fin_w_k + surface_w_k)
