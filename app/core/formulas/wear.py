"""Wear life of a sliding nut: Archard's law over the engaged flanks [1, 2].

Steady sliding wear removes a volume proportional to the load and the sliding distance,
V = k F s, with k the specific wear rate of the pair [m^3/(N m) = m^2/N]. Spread over the
loaded flank area A, the depth worn is h = k p s with p = F / A: the "depth per unit time
= K P V" of dry rubbing bearings [1] (the PV form of the same law). A nut is worn out
when h reaches the wear it may lose, a fraction of its flank height: a nut has lived its
full life when its thread is worn halfway through, a quarter of the pitch [4]. Wear rates of
one material pair scatter 2-3:1 [1, 2] and so do life tests of power screws [3], so a life
is a band, not a number. The same law, in the same variables, sizes a lead screw nut in
[5]; wear stays proportional to P V above the PV limit, but with a far larger factor [6],
so the mild-wear rate holds only while the PV check passes. A maker's life equation for
PTFE composite bushings, G_h = c KM / (p v) (exponent n = 1) [7], is this law in time:
its worked example (22,500 h) follows from ``wear_life_sliding`` with h / k = c KM.

References
----------
1. M. J. Neale (ed.), The Tribology Handbook, 2nd ed., section A5 "Dry rubbing
   bearings": steady-state wear depth rate = K P V; order-of-magnitude wear rates of dry
   bearing material groups against smooth mild steel.
2. RTP Company, "Wear factor and friction data" (ASTM D3702 thrust-washer test): wear
   volume W = K F V T, K given in 1e-10 in^3 min/(ft lbf h) and in 1e-8 mm^3/(N m).
3. Roton, "Wear life" (roton.com, application engineering): "Test life cycle variations
   of two or three to one are not uncommon."
4. Helix Linear, "Identifying wear with follower nut assemblies" (helixlinear.com,
   engineering tools): the full life of the nut is when the thread is halfway through its
   tooth thickness, or a quarter of the pitch of the screw.
5. tribology-abc.com, calculator "Lead screw" (e3_7): total sliding distance s = h / (k p),
   sliding per move pi d2 L_stroke / P, number of moves s / s1, the wear depth given as a
   ratio of H1 = 0.5 P.
6. "Predicting Bearing Performance of Filled Teflon", J. Eng. Ind. 89(1), 182 (ASME):
   wear rates directly proportional to pressure and velocity in the mild and the severe
   regime, the severe regime's factors much higher; the transition coincides with (but is
   not adequately described by) the PV limit.
7. SKF, plain bearings, bushings, thrust washers and strips, "Calculation example"
   (skf.com): PTFE composite bushings PCM 202325 E in a tramway door linkage, G_h =
   c1 c2 c3 c4 c5 KM / (p v)^n with n = 1, KM = 480, p v = 0.025 applied (p v is 0.0164):
   1.3 x 1 x 1 x 0.6 x 1.5 x 480 / 0.025 = 22 500 operating hours.
8. Steinmeyer, "The duty cycle and its equivalent load" (drive.steinmeyer.com, service
   life calculations): a varying duty is divided into steps, each with its thrust and
   its revolutions, and turned into the one mean load with the same effect on life,
   F_m = (sum F_i^3 n_i q_i / sum n_i q_i)^(1/3) for a ball screw's fatigue (life ~
   F^-3); the revolutions of each step may stand for n_i q_i.
"""

from collections.abc import Sequence

from app.core.formulas.declare import formula


@formula("s_per_travel = sqrt(lead^2 + (pi d_2)^2) / lead", "helix geometry")
def sliding_per_travel(helix_travel_m: float, lead_m: float) -> float:
    """Flank sliding distance per metre of nut travel [m/m]: one turn of the screw slides
    the flanks one helix turn, sqrt(lead^2 + (pi d2)^2), and moves the nut one lead.

    For a one-start screw (lead = P) this is pi d2 / P per metre, near enough: a
    Tr8x8(P2) four-start screw slides a quarter as far per metre as a Tr8x2.

    >>> round(sliding_per_travel(0.0226, 0.002), 2)
    11.3
    """
    return helix_travel_m / lead_m


@formula("h = k p s", "Archard's law; Neale, Tribology Handbook A5 (depth rate = K P V)")
def wear_depth(wear_rate_m2_n: float, pressure_pa: float, sliding_m: float) -> float:
    """Depth worn off the loaded flanks [m] = k [m^2/N] x p [Pa] x s [m].

    Valid in steady mild wear, below the material's PV limit (above it wear turns severe
    and the rate jumps); running-in wear is not included.
    Source: Archard's law V = k F s over the contact area; Neale [1] A5.

    RTP's ASTM D3702 test in its metric unit: K = 26e-8 mm^3/(N m) (unfilled POM) at
    0.90 MPa for 1000 h at 0.25 m/s wears

    >>> round(wear_depth(26e-8 * 1e-9, 0.90e6, 0.25 * 3600 * 1000) * 1e3, 3)
    0.211

    millimetres.
    """
    return wear_rate_m2_n * pressure_pa * sliding_m


@formula("s_life = f_w H / (k p)", "Archard's law solved for the sliding distance")
def wear_life_sliding(allowed_depth_m: float, wear_rate_m2_n: float, pressure_pa: float) -> float:
    """Sliding distance [m] until the flanks have lost ``allowed_depth_m`` [m]: the
    inverse of ``wear_depth``, s = h / (k p) with k [m^2/N] and p [Pa].

    Unbounded (inf) without pressure; the caller decides what that means.

    >>> round(wear_life_sliding(0.25 * 1e-3, 1e-15, 1e6) / 1e3, 1)
    250.0

    The depth a nut may lose [4]: its thread worn a quarter of the pitch thinner, measured
    along the axis, is a depth P/4 cos(beta) normal to a flank at beta to the radial plane
    (both flanks together where the load reverses: the same total); for an ISO
    trapezoidal thread (beta = 15 deg, flank height H1 = P/2) that is 0.483 H1, the
    catalog's ``allowed_wear_to_flank_height``:

    >>> from math import cos, radians
    >>> round((1 / 4) * cos(radians(15.0)) / (1 / 2), 3)
    0.483
    """
    return allowed_depth_m / (wear_rate_m2_n * pressure_pa)


@formula("L_wear = s_life / s_per_travel", "helix geometry")
def wear_life_travel(sliding_life_m: float, sliding_per_travel_m_m: float) -> float:
    """Nut travel [m] in a sliding life [m]: divided by the sliding per metre of travel.

    >>> wear_life_travel(250e3, 10.0)
    25000.0
    """
    return sliding_life_m / sliding_per_travel_m_m


@formula(
    "F_w = sum |F_i| x_i / sum x_i over the moving segments of both moves",
    "Archard's law summed over the cycle's segments (the load-spectrum mean [8] with the "
    "wear law's exponent 1)",
)
def cycle_wear_thrust(thrusts_n: Sequence[float], travels_m: Sequence[float]) -> float:
    """The steady thrust [N] that wears the nut as much per cycle as the cycle itself.

    thrusts_n: the thrust the nut carries in each segment [N], either sign (the flank it
    loads; the allowed wear is the thread's total thinning, both flanks together);
    travels_m: the nut travel in each segment [m]. Archard's wear volume of a cycle is
    sum k |F_i| s_i, and the flanks slide s_i = x_i x helix / lead in every segment, so
    the cycle wears as the travel-weighted mean thrust would over the whole travel: the
    load-spectrum mean of [8] with the exponent of a life ~ F^-1. A segment at rest (a
    dwell) slides nothing and wears nothing. Valid where the wear is mild throughout
    (the PV check); 0 without travel.

    A pick-and-place move of 1.5 kg at 10 m/s^2 to 0.3 m/s over 0.4 m, no load: each
    ramp takes 0.03 s and 4.5 mm at 15 N, the cruise 391 mm at 0 N, both ways:

    >>> round(cycle_wear_thrust([15.0, 0.0, 15.0] * 2, [0.0045, 0.391, 0.0045] * 2), 4)
    0.3375
    """
    total_m = sum(travels_m)
    if total_m <= 0.0:
        return 0.0
    return sum(abs(f) * x for f, x in zip(thrusts_n, travels_m, strict=True)) / total_m
