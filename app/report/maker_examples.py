"""Makers' worked examples run through the core, for the /validation page and their
tests: Rockford Ball Screw's ball screw sizing, Omron's servo sizing sample and Weihong's
motor selection for a ball screw system.

Rockford Ball Screw, "How To Size A Ball Screw" (update 2018,
rockfordballscrew.com/download/RBS_HowToSizeaBallScrew_Update2018.pdf): a screw with a
0.84 in root, lead 0.250 in, 41.347 in between bearings, fixed-supported; step 6, the
critical speed with the end fixity factor 1.47 and a factor of safety 0.8, as a travel
rate, 687 in/min; step 9, the column load with the factor 2.00 and 0.8, 6,537 lb.

Omron, "Technical Guide for Servo Motor Selection" (CSM_Servo Selection_TG_E_3_1), sample
calculation, printed pp. 12-13: a ball screw driven directly, table and work 5 kg,
friction 0.1, lead 10 mm, screw 20 mm across and 3 kg, efficiency 1; 300 mm/s over a
360 mm stroke with 0.2 s ramps and a 0.2 s stop; rotor 1.23e-5 kg m^2. Printed: J_B
1.5e-4, J_L 1.63e-4 kg m^2, T_L 7.8e-3, T_A 0.165, T_1 0.173, T_rms 0.0828 N m.
"""

import math
from dataclasses import replace

import numpy as np

from app.core.formulas import (
    buckling,
    column_rules,
    critical_speed,
    efficiency,
    geometry,
    profile,
    torque,
)
from app.core.model import Application, Move, ScrewSpec
from app.core.quantities import Quantities, operating_point
from app.core.table import CandidateTable
from app.core.units import from_si, to_si
from app.report import thread_examples as threads

ROCKFORD = "Rockford Ball Screw, How To Size A Ball Screw (2018)"
ROCKFORD_INPUTS = "root 0.84 in, lead 0.250 in, 41.347 in, fixed–supported, factor 0.8"
ROCKFORD_NOTE = (
    "A ball screw whose family names no maker's rule: held to the lowest published rule, "
    "Rockford's own (C_s 1.47; 14.03e6 C d^4 / L^2). A HIWIN screw, rated by HIWIN's "
    "rule, would be allowed 725.5 in/min."
)
ROOT_M, LEAD_M, SPAN_M = to_si(0.84, "in"), to_si(0.250, "in"), to_si(41.347, "in")
#: Rockford's factor of safety on the critical speed and the column load
FACTOR = 0.8
#: carbon steel as the app's handbook values give it (engineering.md, section 4), and the
#: yield of the catalog's C45 (Shigley table A-20, AISI 1045 hot rolled)
STEEL_E, STEEL_RHO = 206e9, 7850.0
C45_YIELD = to_si(310.0, "MPa")

OMRON = "Omron, Technical Guide for Servo Motor Selection, pp. 12–13"
OMRON_INPUTS = "5 kg, μ 0.1, lead 10 mm, screw 20 mm and 3 kg, 300 mm/s, 0.2 s ramps"
OMRON_NOTE = (
    "Omron gives the screw's mass, not its length: a 1 m rod of the density that makes it "
    "3 kg has Omron's J_B = M D^2 / 8. Efficiency 1 (no reducer), g 9.8 as Omron takes it."
)
MASS_KG, MU, G = 5.0, 0.1, 9.8
OMRON_LEAD_M, SCREW_D_M, SCREW_KG, SCREW_L_M = 0.010, 0.020, 3.0, 1.0
J_MOTOR = 1.23e-5
SPEED, RAMP_S, STROKE_M, STOP_S = 0.300, 0.2, 0.360, 0.2
OMRON_RHO = SCREW_KG / (math.pi * SCREW_D_M**2 / 4.0 * SCREW_L_M)


def in_per_min(rpm: float) -> float:
    """A screw speed [rpm] as Rockford's travel rate on its 0.250 in lead [in/min]."""
    return float(from_si(geometry.linear_speed(rpm, LEAD_M), "in/s")) * 60.0


def rockford_critical_speed(hiwin_rated: bool = False) -> float:
    """The allowed travel rate [in/min] of Rockford's screw rated as a ball screw: at 0.8
    of the lowest published rule (``hiwin_rated``: of HIWIN's)."""
    rated = critical_speed.rated_critical_speed_rpm(
        ROOT_M, SPAN_M, STEEL_E, STEEL_RHO, "fixed-simple", True, hiwin_rated=hiwin_rated
    )
    return in_per_min(critical_speed.allowed_speed_rpm(float(rated), FACTOR))


def rockford_column_lbf() -> float:
    """Rockford's column at 0.8 [lbf], rated as a ball screw of a family that names no
    rule: the core's column (carbon steel) held to Rockford's and Thomson's Euler load."""
    own = buckling.column_critical_load(STEEL_E, ROOT_M, SPAN_M, "fixed-simple", C45_YIELD)
    lowest = column_rules.makers_column_modulus(STEEL_E, True, False)
    i = buckling.second_moment_round(ROOT_M)
    rated = column_rules.rated_column_load(own, i, SPAN_M, "fixed-simple", lowest)
    return float(from_si(FACTOR * float(rated), "lbf"))


def omron_screw_inertia() -> float:
    """Omron's J_B through the core's solid rod [kg m^2]."""
    per_m = torque.solid_rod_inertia_per_length(OMRON_RHO, SCREW_D_M)
    return float(torque.screw_inertia(per_m, SCREW_L_M))


def omron_load_inertia() -> float:
    """Omron's J_L: the screw and the table's mass through the lead [kg m^2]."""
    return omron_screw_inertia() + torque.reflected_mass_inertia(MASS_KG, OMRON_LEAD_M)


def omron_load_torque() -> float:
    """Omron's T_L: mu m g through the lead at efficiency 1 [N m]."""
    return float(torque.load_torque(MU * MASS_KG * G, OMRON_LEAD_M, 1.0))


def omron_acceleration_torque() -> float:
    """Omron's T_A: rotor and load inertia at the ramp's angular acceleration [N m]."""
    alpha = torque.angular_acceleration(SPEED / RAMP_S, OMRON_LEAD_M)
    return float(torque.inertia_torque(J_MOTOR + omron_load_inertia(), alpha))


def omron_peak_torque() -> float:
    """Omron's T_1 = T_A + T_L: the ramp up's torque [N m]."""
    return omron_acceleration_torque() + omron_load_torque()


def omron_rms_torque() -> float:
    """Omron's T_rms over one move and its stop: T_1 over the 0.2 s ramp up, T_L at speed,
    T_A - T_L over the ramp down and nothing in the 0.2 s stop (``profile.rms_torque``)
    [N m]; the way back is alike."""
    t_a, t_l = omron_acceleration_torque(), omron_load_torque()
    run_s = STROKE_M / SPEED - RAMP_S
    return float(
        profile.rms_torque([t_a + t_l, t_l, t_a - t_l, 0.0], [RAMP_S, run_s, RAMP_S, STOP_S])
    )


WEIHONG = (
    "Weihong, WISE servo (WSDV) user manual, 3.5.2.1 Example of Motor Selection for Ball "
    "Screw System, pp. 25–27 (https://www.easymanua.ls/weihong/wise-wsdv-6r820psb/manual?p=31, "
    "https://manualshive.com/ru/manual/weihong/wise-wsdv-11020psb/952565?page=32, "
    "https://www.easymanua.ls/weihong/wise-wsdv-2r820psb/manual?p=33)"
)
WEIHONG_INPUTS = (
    "10 kg, μ 0.1; ball screw 20 mm, lead 20 mm, 0.5 m, η 0.9; 0.3 m in 0.1 / 0.8 / 0.1 s, "
    "cycle 2 s; rotor 0.14e-4, coupling 10e-6 kg m²"
)
WEIHONG_NOTE = (
    "Through the selection's own cycle (out and back, each move and its 1 s stop). As the "
    "maker does, the table's 10 kg enters as the inertia m (lead / 2π)² at the motor, "
    "outside the screw's efficiency; the app's own model, m a through the thread at 0.9, "
    "gives about 2 % more RMS and 5 % more peak. The guide friction is the maker's "
    "μ W g = 0.1 × 9.8 × 10 N; the screw's efficiency 0.9 is the maker's, given to a "
    "square thread by its friction (μ 0.032); the screw's inertia a solid 20 mm rod at "
    "the maker's 7.9 t/m³."
)


#: The maker's ball-screw example: 10 kg table, mu 0.1, ball screw 20 mm x lead 20 mm (0.5 m,
#: steel 7.9 t/m^3, efficiency 0.9 as stated), 0.3 m in 0.1 / 0.8 / 0.1 s then stopped, a
#: 2 s cycle; coupling 10e-6 and 0.2 kW motor 0.14e-4 kg m^2 (pp. 25-26 of the manual).
WEIHONG_MASS_KG, WEIHONG_MU, WEIHONG_G = 10.0, 0.1, 9.8
WEIHONG_LEAD_M, WEIHONG_SCREW_D_M, WEIHONG_SCREW_L_M = 0.02, 0.02, 0.5
WEIHONG_J_COUPLING, WEIHONG_J_MOTOR = 10e-6, 0.14e-4


def weihong_screw() -> ScrewSpec:
    """The example's ball screw as a screw of the app's: a square thread on a 20 mm pitch
    diameter, lead 20 mm, whose friction gives the stated efficiency 0.9
    (``efficiency.friction_for_efficiency``), inertia of a solid 20 mm steel rod at the
    maker's density 7.9 t/m^3 (the maker's W_B D^2 / 8)."""
    tan_l = geometry.tan_lead_angle(WEIHONG_LEAD_M, WEIHONG_SCREW_D_M)
    mu = efficiency.friction_for_efficiency(tan_l, 0.9, threads.SQUARE)
    return ScrewSpec(
        id="weihong-ball-screw", series_id="example", series_name="example",
        anti_backlash=False, coated=False, outer_diameter_m=WEIHONG_SCREW_D_M,
        root_diameter_m=WEIHONG_SCREW_D_M, lead_m=WEIHONG_LEAD_M, thread_half_angle_rad=0.0,
        friction_static=mu, friction_dynamic=mu, youngs_modulus_pa=STEEL_E,
        density_kg_m3=7900.0, screw_expansion_per_k=1.2e-5,
        inertia_kg_m2_per_m=torque.solid_rod_inertia_per_length(7900.0, WEIHONG_SCREW_D_M),
    )  # fmt: skip


def weihong_application(mass_as_inertia: bool = True) -> Application:
    """The example's cycle as the app's: 0.3 m out and 0.3 m back, each at 1/3 m/s with
    0.1 s ramps (10/3 m/s^2) and the 1 s stop after it (the maker's 2 s cycle is one move
    and its stop; both halves are alike, so the RMS over the two is the RMS over one). The
    guide friction mu W g = 0.1 x 9.8 x 10 = 9.8 N opposes the motion both ways. The maker
    reflects the table to the motor as W (lead / 2 pi)^2, outside the screw's efficiency:
    ``mass_as_inertia`` does the same (the 10 kg joins the rotor's inertia), else the app's
    own model carries m a through the thread."""
    speed, ramp = 0.3 / 0.9, 0.3 / 0.9 / 0.1
    mass = 0.0 if mass_as_inertia else WEIHONG_MASS_KG
    reflected = torque.reflected_mass_inertia(WEIHONG_MASS_KG - mass, WEIHONG_LEAD_M)
    friction = WEIHONG_MU * WEIHONG_G * WEIHONG_MASS_KG
    out = Move(0.3, speed, ramp, ramp, 1.0, mass, friction, "opposes")
    return Application(
        load_n=friction,
        speed_m_s=speed,
        length_m=WEIHONG_SCREW_L_M,
        moves=(out, replace(out, distance_m=-0.3)),
        motor_inertia_kg_m2=WEIHONG_J_MOTOR + WEIHONG_J_COUPLING + reflected,
    )


def weihong_cycle(mass_as_inertia: bool = True) -> Quantities[np.ndarray]:
    """The example's operating point, by the selection's own path (``operating_point``:
    ``motion.cycle``, ``segments.segments``, ``segments.rms``)."""
    table = CandidateTable.build([weihong_screw()])
    return operating_point(weihong_application(mass_as_inertia), table)


#: one kgf cm [N m]: FANUC prints its torques in N m and in kgf cm.
