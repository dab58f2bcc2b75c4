"""THK's whole ball-screw selection example, "High-speed Transfer Equipment (Horizontal
Use)", through the app's own core: axial loads per phase, the mean load, the rated life,
the buckling load, the critical speed and the motor torques.

THK Ball Screw General Catalog, "Examples of Selecting a Ball Screw", printed pp. A-744 to
A-747 (a distributor's copy: https://bondy.dk/wp-content/uploads/THK-spindler.pdf). The
figures are those pages' as transcribed in a public repository's reference tests; the PDF
itself was not at hand. The printed selection conditions: table 60 kg and work 20 kg,
stroke 1000 mm, top speed 1 m/s, acceleration and deceleration times 0.15 s, direct
drive, motor rotor inertia 1e-3 kg m^2, a stop of 2.6 s after each move; the chosen
screw WTF2040-2 (shaft 20 mm, root d1 17.5 mm, lead 40 mm, 1200 mm long, Ca 5.4 kN,
C0a 13.6 kN, shaft inertia 1.23e-3 kg cm^2/mm, efficiency 0.9).
"""

import numpy as np

from app.core import motion, segments
from app.core.formulas import ballscrew, buckling, efficiency, geometry, torque
from app.core.formulas import critical_speed as cs
from app.core.model import Application, Move, ScrewSpec
from app.core.quantities import Quantities, operating_point
from app.core.table import CandidateTable
from app.core.units import to_si

SOURCE = (
    "THK Ball Screw General Catalog, 'Examples of Selecting a Ball Screw', High-speed "
    "Transfer Equipment (Horizontal Use), pp. A-744 to A-747"
)
MASS_KG = 60.0 + 20.0
STROKE_M, SPEED_M_S, RAMP_S, STOP_S = 1.0, 1.0, 0.15, 2.6
#: THK's printed axial load during uniform motion Fa2: the guide's resistance (17 N).
GUIDE_N = 17.0
LEAD_M, SHAFT_D_M, ROOT_D_M, LENGTH_M = 0.040, 0.020, 0.0175, 1.2
CA_N, FW, ETA = 5400.0, 1.5, 0.9
#: THK's shaft inertia 1.23e-3 kg cm^2 (1.23 g cm^2) per mm, in kg m^2 per m.
INERTIA_KG_M2_PER_M = to_si(1.23, "g cm²") / to_si(1.0, "mm")
J_MOTOR = 1e-3
#: THK's buckling check: distance between the mounting points 1100 mm, fixed-fixed
#: (eta_2 = 20), safety 0.5; critical speed: 1100 mm, fixed-supported (lambda_2 = 15.1),
#: 0.8 of the whirling speed. Young's modulus 206 GPa, steel 7850 kg/m^3.
SPAN_M, STEEL_E, STEEL_RHO = 1.1, 206e9, 7850.0
INPUTS = (
    "80 kg, 1 m/s, 1000 mm, ramps 0.15 s, stop 2.6 s; WTF2040-2: 20 mm, d1 17.5 mm, "
    "lead 40 mm, 1200 mm, Ca 5.4 kN, η 0.9; rotor 1e-3 kg m²"
)
NOTE = (
    "Through the selection's own cycle (out and back, each move and its 2.6 s stop); the "
    "guide's resistance is THK's printed uniform-motion load 17 N. For the torques, as "
    "THK does, the 80 kg enters as the inertia m (lead / 2π)² at the motor, outside the "
    "screw's efficiency; THK rounds α = 1047 rad/s² to 1050, so the app's torques are "
    "0.3 % lower."
)
MEAN_NOTE = (
    "THK takes each load direction alone (the other direction's loads as 0), as it "
    "loads the other flank of the ball track; the app's own check, all six phases on "
    "one flank, gives 283.5 N and so half THK's life (2.1e9 rev): it errs safe."
)


def square_thread(
    screw_id: str, shaft_d_m: float, lead_m: float, inertia_kg_m2_per_m: float
) -> ScrewSpec:
    """A THK ball screw as a screw of the app's, for the torques: a square thread on its
    shaft diameter [m] whose friction gives THK's efficiency 0.9 at its lead [m], with
    THK's shaft inertia [kg m^2/m]."""
    tan_l = geometry.tan_lead_angle(lead_m, shaft_d_m)
    mu = efficiency.friction_for_efficiency(tan_l, ETA, 1.0)
    return ScrewSpec(
        id=screw_id, series_id="example", series_name="example", anti_backlash=False,
        coated=False, outer_diameter_m=shaft_d_m, root_diameter_m=shaft_d_m, lead_m=lead_m,
        thread_half_angle_rad=0.0, friction_static=mu, friction_dynamic=mu,
        youngs_modulus_pa=STEEL_E, density_kg_m3=STEEL_RHO, screw_expansion_per_k=1.2e-5,
        inertia_kg_m2_per_m=inertia_kg_m2_per_m,
    )  # fmt: skip


def screw() -> ScrewSpec:
    """WTF2040-2 on its 20 mm shaft (``square_thread``)."""
    return square_thread("WTF2040-2", SHAFT_D_M, LEAD_M, INERTIA_KG_M2_PER_M)


def application(mass_as_inertia: bool) -> Application:
    """The example's cycle: 1 m out and back at 1 m/s with 0.15 s ramps, each move
    followed by the 2.6 s stop. ``mass_as_inertia``: the 80 kg joins the rotor's inertia
    as m (lead / 2 pi)^2 (THK's torques), else the app's own model carries m a through
    the thread (the axial loads)."""
    mass = 0.0 if mass_as_inertia else MASS_KG
    reflected = torque.reflected_mass_inertia(MASS_KG - mass, LEAD_M)
    ramp = SPEED_M_S / RAMP_S
    out = Move(STROKE_M, SPEED_M_S, ramp, ramp, STOP_S, mass, GUIDE_N, "opposes")
    back = Move(-STROKE_M, SPEED_M_S, ramp, ramp, STOP_S, mass, GUIDE_N, "opposes")
    # the three required fields in their order: steady load, speed, screw length
    return Application(
        GUIDE_N,
        SPEED_M_S,
        LENGTH_M,
        moves=(out, back),
        motor_inertia_kg_m2=J_MOTOR + reflected,
    )


def cycle(mass_as_inertia: bool = True) -> Quantities[np.ndarray]:
    """The example's operating point by the selection's own path."""
    return operating_point(application(mass_as_inertia), CandidateTable.build([screw()]))


def phases() -> list[tuple[float, float]]:
    """Each moving phase's axial load on the nut in a fixed frame [N] (above 0: the
    outward direction) and its travel [m], from the app's own segments with the mass
    carried through the thread: THK's Fa1 to Fa6 and l1 to l6."""
    app = application(mass_as_inertia=False)
    parts = segments.segments(app, CandidateTable.build([screw()]), np.zeros(1))
    moving = [s for s in parts if s.name != "dwell"]
    every = motion.profiles(app) or []
    travels = [x for p in every for x in motion.segment_travels(p)]
    senses = [motion.sense(m) for m in motion.cycle(app) for _ in range(3)]
    return [(float(s.thrust_n[0]) * v, d) for s, v, d in zip(moving, senses, travels, strict=True)]


def axial_load(k: int) -> float:
    """THK's Fa_k (k from 1), in its fixed frame, as printed."""
    return phases()[k - 1][0]


def mean_load_one_direction() -> float:
    """THK's F_m1: the cubic mean over the whole cycle of the outward loads alone."""
    loads = phases()
    return float(ballscrew.cubic_mean_load([max(f, 0.0) for f, _ in loads], [d for _, d in loads]))


def mean_load_both_flanks() -> float:
    """The app's own cubic mean load: every phase's load on the one flank."""
    loads = phases()
    return float(ballscrew.cubic_mean_load([f for f, _ in loads], [d for _, d in loads]))


def life_revolutions() -> float:
    """THK's rated life L = (Ca / (f_w F_m))^3 x 10^6 with f_w = 1.5."""
    return ballscrew.rated_life_revolutions(CA_N, FW, mean_load_one_direction())


def buckling_load_n() -> float:
    """THK's permissible buckling load P1 (fixed-fixed, 0.5 of Euler's)."""
    i_m4 = buckling.second_moment_round(ROOT_D_M)
    euler = buckling.euler_critical_load(STEEL_E, i_m4, SPAN_M, "fixed-fixed")
    return buckling.allowed_buckling_load(euler, 0.5)


def critical_speed_rpm() -> float:
    """THK's permissible rotational speed N1 (fixed-supported, 0.8 of the whirling)."""
    whirl = cs.critical_speed_rpm(ROOT_D_M, SPAN_M, STEEL_E, STEEL_RHO, "fixed-simple")
    return cs.allowed_speed_rpm(whirl, 0.8)


def load_inertia_kg_m2() -> float:
    """THK's J: the shaft and the moving mass at the screw (without the rotor)."""
    app = application(mass_as_inertia=True)
    shaft = torque.screw_inertia(INERTIA_KG_M2_PER_M, LENGTH_M)
    return shaft + (app.motor_inertia_kg_m2 or 0.0) - J_MOTOR


def segment_torque_nm(name: str) -> float:
    """The motor torque of the out move's ``name`` segment (THK's Tk, Tt, Tg)."""
    app = application(mass_as_inertia=True)
    parts = segments.segments(app, CandidateTable.build([screw()]), np.zeros(1))
    return float(next(s for s in parts if s.name == name).torque_nm[0])
