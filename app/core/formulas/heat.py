"""Heat of a sliding nut: the power its thread's friction and its drag turn into heat,
and the temperature rise at which the screw (as a fin, both ways) and the nut's surface
carry it away [1].

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
def friction_power(
    force_n: float, speed_m_s: float, efficiency: float, loss: float | None = None
) -> float:
    """Power the thread's friction turns into heat [W]: the input F v / eta [W] less the
    useful F v, force [N], mean linear speed [m/s], forward efficiency [-]; ``loss``:
    1 / eta - 1 when already worked out (``friction_loss``: the candidate table's
    column), the same number.

    A 200 kg lift (1962 N) at 12 mm/s on Tr14x3 with an oiled bronze nut (eta = 0.358):

    >>> round(friction_power(1962.0, 0.012, 0.358), 1)
    42.2
    """
    return force_n * speed_m_s * (friction_loss(efficiency) if loss is None else loss)


def friction_loss(efficiency: float) -> float:
    """The power the thread's friction loses per watt of useful power, 1 / eta - 1 [-]
    (``friction_power``).

    >>> friction_loss(0.5)
    1.0
    """
    return 1.0 / efficiency - 1.0


@formula(
    "P_drag = T_drag 2 pi v / lead",
    "power of a torque at the screw's angular speed omega = 2 pi v / lead",
)
def drag_power(
    drag_torque_nm: float, speed_m_s: float, lead_m: float, per_turn_j: float | None = None
) -> float:
    """Power a nut's drag (the preload of an anti-backlash nut) turns into heat [W]: its
    drag torque T_drag [N m] at the screw's angular speed 2 pi v / lead, v the nut's mean
    linear speed [m/s], lead [m]. The drag is friction of the nut's own flanks against the
    screw's, so all its work ends as heat in the nut and the screw; at the cycle's mean
    speed (every move's travel over the cycle's time, dwells included) it is the drag's
    work over one cycle (``energy.shaft_energy`` of the drag) over the cycle's time.
    Valid for a drag torque that does not vary with the speed (the catalog gives one).
    Floats or arrays. ``per_turn_j``: the drag's work per turn T_drag 2 pi when already
    worked out (``drag_work_per_turn``: the candidate table's column), the same number.

    0.03 N m on a 4 mm lead, 0.8 m of travel in an 8.2 s cycle (about 1,257 turns of
    37.7 J), 4.6 W:

    >>> round(drag_power(0.03, 0.8 / 8.2, 0.004), 3)
    4.597
    """
    work_j = drag_work_per_turn(drag_torque_nm) if per_turn_j is None else per_turn_j
    return work_j * speed_m_s / lead_m


def drag_work_per_turn(drag_torque_nm: float) -> float:
    """The work of a drag torque [N m] over one turn of the screw, T_drag 2 pi [J].

    >>> round(drag_work_per_turn(0.03), 4)
    0.1885
    """
    return drag_torque_nm * 2.0 * math.pi


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
    power_w: float,
    fin_w_k: float,
    nut_length_m: float,
    nut_diameter_m: float,
    h_w_m2_k: float,
    conductance_w_k: float | None = None,
) -> float:
    """Steady temperature rise of the nut over the ambient [K]: the heat power [W] (the
    thread's friction and the nut's drag, ``friction_power`` + ``drag_power``) over the
    screw's conductance both ways (two fins, [W/K]) plus the nut surface's convection
    h pi D L (nut length and outside diameter [m], h [W/(m^2 K)]): ``nut_conductance``,
    or ``conductance_w_k`` when already worked out (the candidate table's column at the
    catalog's nut length), the same number.

    >>> round(temperature_rise(10.0, 0.04, 0.028, 0.028, 10.0), 1)
    95.6
    """
    if conductance_w_k is None:
        conductance_w_k = nut_conductance(fin_w_k, nut_length_m, nut_diameter_m, h_w_m2_k)
    return power_w / conductance_w_k


def nut_conductance(
    fin_w_k: float, nut_length_m: float, nut_diameter_m: float, h_w_m2_k: float
) -> float:
    """The nut's conductance to the ambient [W/K] (``temperature_rise``): the screw's
    both ways (two fins, [W/K]) plus the nut surface's convection h pi D L.

    >>> round(nut_conductance(0.04, 0.028, 0.028, 10.0), 4)
    0.1046
    """
    surface_w_k = h_w_m2_k * math.pi * nut_diameter_m * nut_length_m
    return 2.0 * fin_w_k + surface_w_k
