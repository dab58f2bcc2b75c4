"""Heat of a sliding nut: the power its thread's friction and its drag turn into heat,
and the temperature rise at which the screw (as a fin, both ways) and the nut's surface
carry it away [1].

References
----------
1. F. P. Incropera, D. P. DeWitt et al., Fundamentals of Heat and Mass Transfer, 6th ed.:
   sec. 3.6 (extended surfaces; the infinitely long fin conducts sqrt(h P k A_c) per
   kelvin at its base, one of length L with an adiabatic tip that times tanh(m L),
   m = sqrt(h P / (k A_c)): Table 3.4, case B), Example 3.9 (5 mm rods of copper, 2024
   aluminium and AISI 316 stainless, h = 100 W/(m^2 K), base 100 C in 25 C air: 8.3,
   5.6 and 1.6 W), Table 1.1 (free convection of gases: h = 2-25 W/(m^2 K)).
"""

import math
from typing import Any

import numpy as np

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


@formula("m = sqrt(4 h / (k d))", "Incropera, sec. 3.6 (m = sqrt(h P / (k A_c)), a round rod)")
def fin_parameter(diameter_m: Any, conductivity_w_m_k: Any, h_w_m2_k: float) -> Any:
    """A round rod's fin parameter m [1/m]: sqrt(h P / (k A_c)) = sqrt(4 h / (k d));
    diameter d [m], conductivity k [W/(m K)], convection h [W/(m^2 K)]. Its inverse is
    the length over which the rod's excess temperature falls by e. Numbers or arrays.

    A 10.5 mm C45 root (k 50.7) in still air (h 10): 1 / m = 115 mm.

    >>> round(1.0 / float(fin_parameter(0.0105, 50.7, 10.0)), 4)
    0.1154
    """
    return np.sqrt(4.0 * h_w_m2_k / (np.asarray(conductivity_w_m_k) * diameter_m))


@formula(
    "G_fin(L) = G_fin tanh(m L)",
    "Incropera, sec. 3.6, Table 3.4 case B (a fin with an adiabatic tip)",
)
def fin_share(length_m: Any, m_per_m: Any) -> Any:
    """The part of an infinitely long round rod's conductance (``fin_conductance``) a rod
    of length L [m] conducts with its far end insulated: tanh(m L), m its fin parameter
    [1/m] (``fin_parameter``). Numbers or arrays alike.

    A 10.5 mm C45 root (k 50.7) in still air (h 10): 136 mm of it conducts 0.827 of an
    endless one's heat, a metre all of it:

    >>> m = fin_parameter(0.0105, 50.7, 10.0)
    >>> round(float(fin_share(0.136, m)), 3), round(float(fin_share(1.0, m)), 4)
    (0.827, 1.0)
    """
    return np.tanh(m_per_m * length_m)


def nut_sides_m(screw_length_m: float, span_m: float, nut_length_m: Any) -> tuple[Any, Any]:
    """The screw's length each side of the nut [m] at the end of a stroke ``span_m`` [m]
    centred on the screw: (L - s - L_nut) / 2 to the near end (none where the stroke and
    the nut fill the screw) and the rest to the far one. Along a centred stroke the nut's
    two fins conduct least there (tanh is concave), so its heat balance is taken there.

    >>> [round(float(side), 3) for side in nut_sides_m(0.6, 0.3, 0.028)]
    [0.136, 0.436]
    """
    near = np.maximum(0.0, (screw_length_m - span_m - nut_length_m) / 2.0)
    return near, np.maximum(0.0, screw_length_m - nut_length_m - near)


@formula(
    "dT = P / (G_fin (tanh(m L_1) + tanh(m L_2)) + h pi D_nut L_nut)",
    "Incropera, sec. 3.6 and Newton's law of cooling",
)
def temperature_rise(
    power_w: float,
    fins_w_k: float,
    nut_length_m: float,
    nut_diameter_m: float,
    h_w_m2_k: float,
) -> float:
    """Steady temperature rise of the nut over the ambient [K]: the heat power [W] (the
    thread's friction and the nut's drag, ``friction_power`` + ``drag_power``) over the
    screw's conductance both ways (its two fins together, ``fin_conductance`` times each
    side's ``fin_share``, [W/K]) plus the nut surface's convection h pi D L (nut length
    and outside diameter [m], h [W/(m^2 K)]): ``nut_conductance``.

    >>> round(temperature_rise(10.0, 0.08, 0.028, 0.028, 10.0), 1)
    95.6
    """
    return power_w / nut_conductance(fins_w_k, nut_length_m, nut_diameter_m, h_w_m2_k)


def nut_conductance(
    fins_w_k: float, nut_length_m: float, nut_diameter_m: float, h_w_m2_k: float
) -> float:
    """The nut's conductance to the ambient [W/K] (``temperature_rise``): the screw's
    both ways (its two fins together, [W/K]) plus the nut surface's convection h pi D L.

    >>> round(nut_conductance(0.08, 0.028, 0.028, 10.0), 4)
    0.1046
    """
    surface_w_k = h_w_m2_k * math.pi * nut_diameter_m * nut_length_m
    return fins_w_k + surface_w_k


@formula(
    "dL = alpha dT_nut (tanh(m L_f) / m + L_nut / 2)",
    "Incropera, sec. 3.6, Table 3.4 case B (the adiabatic-tip fin's excess temperature "
    "theta(x) = theta_b cosh(m (L_f - x)) / cosh(m L_f), integrated over the fin); THK "
    "Ball Screw, Point of Selection: Studying the Positioning Accuracy (the screw's "
    "thermal displacement from its heat, dL = alpha times the integral of its rise)",
)
def heated_growth(
    expansion_per_k: Any, rise_k: Any, m_per_m: Any, fin_length_m: Any, nut_length_m: Any
) -> Any:
    """The screw's growth from the nut's friction heat between its axially fixed end and
    the nut's middle [m]: alpha times the integral of its rise over the ambient along that
    span, the fin's profile (``fin_share``: a fin of length L_f [m] from the nut, its far
    end insulated) integrated, theta_b tanh(m L_f) / m, plus the screw under half the nut
    at the nut's rise (``temperature_rise``). alpha the screw's expansion [1/K], dT_nut
    the nut's rise [K], m the fin parameter [1/m] (``fin_parameter``), nut length [m].
    Numbers or arrays alike.

    Valid for the steady heat balance of ``temperature_rise`` (the screw at the nut's
    temperature under it, still air along it); the insulated far end, where a thrust
    bearing in fact draws heat off, errs long.

    The 200 kg lifting table (``temperature_rise``: Tr14x3 of C45, alpha 11.7e-6 /K, a
    10.5 mm root of k 50.7, m = 8.668 /m) resting 2 minutes each way, its nut 77.2 K
    above the ambient, 436 mm of screw from the nut to the far end, a 28 mm nut:
    11.7e-6 x 77.2 x (tanh(8.668 x 0.436) / 8.668 + 0.014) = 0.117 mm.

    >>> m = fin_parameter(0.0105, 50.7, 10.0)
    >>> round(float(heated_growth(11.7e-6, 77.2, m, 0.436, 0.028)) * 1e3, 4)
    0.1167
    """
    excess_m = np.tanh(m_per_m * fin_length_m) / m_per_m + nut_length_m / 2.0
    return expansion_per_k * rise_k * excess_m
