"""Published worked examples against the calculation core: the /validation page's table.

Each example names its source, its inputs and the published value, and computes the app's
value live by calling the core's formula functions, so the page always shows what the
running code gives. ``tests/web/test_validation.py`` iterates this same list and holds every
ratio within ``TOLERANCE``: the page and the test cannot drift apart.
"""

import math
from collections.abc import Callable
from dataclasses import dataclass

from app.contract.units import from_si, to_si
from app.core.formulas import (
    ballscrew,
    buckling,
    column_rules,
    efficiency,
    geometry,
    heat,
    profile,
    pv,
    servo,
    stepper,
    torque,
    wear,
)
from app.core.formulas import critical_speed as cs
from app.report import maker_examples as maker
from app.report import thk_example as thk
from app.report import thread_examples as threads
from app.report import trapezoid_table as tr

#: largest relative difference from a published value the app may show.
TOLERANCE = 0.01
#: one inch [m] and one pound-force [N], for the examples printed in inches and pounds.
IN = to_si(1.0, "in")
LBF = to_si(1.0, "lbf")
STEEL_E, STEEL_RHO = 206e9, 7850.0
#: one hour [s] (SKF's lives are in operating hours).
HOUR_S = 3600.0


@dataclass(frozen=True, slots=True)
class Example:
    """One published result: where it is printed, what goes in, what comes out."""

    topic: str
    source: str
    inputs: str
    published: float
    unit: str
    compute: Callable[[], float]
    #: how the example's inputs were mapped onto the app's, where that needs saying
    note: str = ""

    @property
    def value(self) -> float:
        """The app's value, computed now by the core."""
        return self.compute()

    @property
    def ratio(self) -> float:
        """App value over published value: 1 is exact agreement."""
        return self.value / self.published


def _bnb_pv() -> float:
    """bnb-industries bushing PV in psi ft/min, through the core's pressure and speed."""
    d, length = 0.625 * IN, (1 + 1 / 32) * IN
    p = pv.contact_pressure(35 * LBF, d * length)
    v = pv.surface_speed(120.0, geometry.helix_travel(0.0, d))
    return from_si(p * v, "psi ft/min")


def _skf_composite_life_h() -> float:
    """SKF's PTFE composite bushing life G_h = c KM / (p v) (n = 1) as Archard's law in
    time: the wear depth allowed over the wear rate is h / k = c KM, in Pa m."""
    n_mm2 = to_si(1.0, "MPa")  # SKF's p is in N/mm^2
    h_over_k = 1.3 * 1 * 1 * 0.6 * 1.5 * 480 * n_mm2 * HOUR_S
    depth_m, speed_m_s = 1e-4, 0.01
    sliding = wear.wear_life_sliding(depth_m, depth_m / h_over_k, 0.025 * n_mm2 / speed_m_s)
    return sliding / speed_m_s / HOUR_S


def _euler(e_pa: float, d_or_i: float, length_m: float, fixity: str, round_d: bool) -> float:
    i_m4 = buckling.second_moment_round(d_or_i) if round_d else d_or_i
    return buckling.euler_critical_load(e_pa, i_m4, length_m, fixity)


#: Makishinko's printed allowed axial load of its JA050 jack screw [N].
MAKISHINKO_N = 6135.0


def _makishinko(e_pa: float) -> float:
    """Makishinko's JA050 jack screw: a 31.5 mm root over 1000 mm, fixed-free, a quarter
    of Euler's load [N] with the modulus ``e_pa``."""
    return float(
        buckling.allowed_buckling_load(_euler(e_pa, 0.0315, 1.0, "fixed-free", True), 0.25)
    )


def _makishinko_note() -> str:
    """What the selector rates the same steel jack screw at: with the leadscrew makers'
    modulus for steel (``column_rules.leadscrew_column_modulus``), below Makishinko's."""
    makers_e = float(column_rules.leadscrew_column_modulus(STEEL_E))
    rated = _makishinko(makers_e)
    own_gpa, makers_gpa = from_si(STEEL_E, "GPa"), from_si(makers_e, "GPa")
    return (
        f"Euler's load at Makishinko's E = {own_gpa:g} GPa. The selector rates a steel lead "
        f"screw by Thomson's and Nook's rule for steel (E = {makers_gpa:.1f} GPa): "
        f"{rated:.0f} N, {(1 - rated / MAKISHINKO_N) * 100:.1f} % below the published value."
    )


KGF_CM = to_si(1.0, "kgf") * to_si(10.0, "mm")
FANUC_ALPHA = (
    "FANUC AC Servo Motor α series Descriptions, B-65142E/04, 4. Selecting a Motor, "
    "inertia examples, printed p. 31 "
    "(http://cncmanuals.com/fanuc/319/ac-servo-motor-alpha-series-descriptions/page/47)"
)
FANUC_ALPHA_I_TORQUE = (
    "FANUC AC Servo Motor αiS/αi series Descriptions, B-65262EN/03, 3.2.1 Calculating the "
    "Load Torque, example for condition 1, printed p. 46 "
    "(http://cncmanuals.com/fanuc/41/ac-servo-motor-alpha-i-is-series-descriptions/page/64)"
)
FANUC_ALPHA_I_RMS = (
    "FANUC AC Servo Motor αiS/αi series Descriptions, B-65262EN/03, example of calculation "
    "for condition 5, root-mean-square value of the torques, printed p. 59 "
    "(http://cncmanuals.com/fanuc/41/ac-servo-motor-alpha-i-is-series-descriptions/page/77)"
)
THK_KR = (
    "THK LM Guide Actuator KR catalog, Evaluating the Rated Life Span of the Ball Screw, "
    "buckling load, p. 12 (http://pdf.directindustry.com/pdf/thk/lm-guide-actuator-kr/"
    "328-6416-_13.html)"
)
#: FANUC αi's horizontal table: weight W 11760 N (1200 kg), gib force F_g 490 N, sliding
#: friction 0.05, lead 20 mm, efficiency 0.9 and the nut's and bearings' friction torque
#: T_f 0.8 N m at the motor (direct drive, Z1/Z2 = 1).
FANUC_AI_W_N, FANUC_AI_GIB_N, FANUC_AI_MU = 11760.0, 490.0, 0.05
FANUC_AI_LEAD_M, FANUC_AI_ETA, FANUC_AI_TF_NM = 0.020, 0.9, 0.8


def _fanuc_constant_load_torque_kgf_cm() -> float:
    """FANUC αi's constant load torque T_m = F l / (2 pi eta) + T_f with F = mu (W + F_g):
    the thread's torque through the core's ``load_torque`` and the nut's and bearings'
    friction torque added as the core adds a nut's drag (``total_torque``), in kgf cm."""
    force_n = FANUC_AI_MU * (FANUC_AI_W_N + FANUC_AI_GIB_N)
    thread_nm = torque.load_torque(force_n, FANUC_AI_LEAD_M, FANUC_AI_ETA)
    return torque.total_torque(0.0, FANUC_AI_TF_NM, thread_nm) / KGF_CM


def _fanuc_rms_torque_nm() -> float:
    """FANUC αi's RMS torque of the α30/4000iS cycle through the core's ``rms_torque``:
    acceleration T_a + T_m for t1, running T_m for t2, deceleration T_a - T_m for t1 (the
    friction helps the motor stop), then the stop at T_o for t3."""
    accel_nm, running_nm, stopped_nm = 83.2, 3.0, 3.0
    ramp_s, run_s, stop_s = 0.08, 2.0, 3.0
    torques = [accel_nm + running_nm, running_nm, accel_nm - running_nm, stopped_nm]
    return profile.rms_torque(torques, [ramp_s, run_s, ramp_s, stop_s])


YASKAWA = (
    "Yaskawa Σ-V-MD series user manual (listed as E-V-MD), 2.2.2 Selection Calculations, "
    "p. 2-5 (https://manualshive.com/en/manual/yaskawa/e-v-md-series/3588034?page=30)"
)
YASKAWA_INPUTS = (
    "250 kg, μ 0.2, η 0.9; ball screw 20 mm × 1.0 m, lead 10 mm, 7.87 t/m³; gear 1/2; "
    "gear and coupling 0.40e-4 kg m²"
)
YASKAWA_NOTE = (
    "The core has no gearbox: the motor turns twice per turn of the screw, so the load "
    "moves 5 mm per motor turn (the lead the core is given), and the screw's own inertia "
    "is reflected by the maker's 1 / R² with R = 2. The friction force is the maker's "
    "μ m g = 0.2 × 250 × 9.8 N."
)
#: Yaskawa's example: linear mass, friction, efficiency, screw, gear ratio R (the motor
#: turns R times per screw turn) and the gear's and coupling's inertia at the motor.
YASKAWA_MASS_KG, YASKAWA_MU, YASKAWA_G, YASKAWA_ETA = 250.0, 0.2, 9.8, 0.9
YASKAWA_SCREW_D_M, YASKAWA_SCREW_L_M, YASKAWA_LEAD_M = 0.02, 1.0, 0.01
YASKAWA_RHO, YASKAWA_RATIO, YASKAWA_J_GEAR = 7870.0, 2.0, 0.40e-4


def _yaskawa_screw_inertia_at_motor() -> float:
    """Yaskawa's ball screw inertia at the motor: the core's solid rod, over R²."""
    per_m = torque.solid_rod_inertia_per_length(YASKAWA_RHO, YASKAWA_SCREW_D_M)
    return torque.screw_inertia(per_m, YASKAWA_SCREW_L_M) / YASKAWA_RATIO**2


def _yaskawa_load_torque_nm() -> float:
    """Yaskawa's load torque at the motor, mu m g through the thread at its efficiency,
    the lead being the load's travel per motor turn (lead / R)."""
    force_n = YASKAWA_MU * YASKAWA_MASS_KG * YASKAWA_G
    return torque.load_torque(force_n, YASKAWA_LEAD_M / YASKAWA_RATIO, YASKAWA_ETA)


def _yaskawa_load_inertia() -> float:
    """Yaskawa's load inertia at the motor: the mass reflected through 5 mm a motor turn,
    the screw over R² and the gear and coupling."""
    mass = torque.reflected_mass_inertia(YASKAWA_MASS_KG, YASKAWA_LEAD_M / YASKAWA_RATIO)
    return mass + _yaskawa_screw_inertia_at_motor() + YASKAWA_J_GEAR


MITSUBISHI = (
    "Mitsubishi MELDAS MDS-B-SVJ2 series manual, 11 Selection, 11-5 Example of servo "
    "selection, Z axis, p. 11-15 "
    "(https://www.easymanua.ls/mitsubishi-electric/meldas-mds-b-svj2-series/manual?p=275)"
)
#: one kg cm² [kg m²] (the Mitsubishi manual's inertia unit).
KG_CM2 = to_si(1.0, "kg cm²")
THK_CHANGE_NUT = (
    "THK General Catalog, Change Nut, Point of Selection, Efficiency, Thrust and Torque, "
    "p. B17-9 (https://www.scribd.com/document/652982319/en-b17-009)"
)
#: THK's DCMB20T change nut: lead 60 mm, efficiency 0.67 (THK's Table 2 at mu 0.2).
THK_CHANGE_NUT_LEAD_M, THK_CHANGE_NUT_ETA = 0.060, 0.67


TR_NOTE = (
    "The table's efficiencies leave out the 15° flank: they are the square-thread form "
    "tan λ / tan(λ + atan f) (the core's square_thread_efficiency) on the basic pitch "
    "diameter d - P/2. The flank form the app's selection uses gives 1 to 3.5 % less over "
    "the table's sizes, so the app asks for more torque than the table."
)


def _tr(name: str, friction: float) -> Example:
    """One efficiency of the distributor's trapezoidal table, through the core."""
    row = tr.BY_NAME[name]
    published = row.efficiency_f01 if friction == 0.1 else row.efficiency_f02
    return Example(
        f"Trapezoidal efficiency, {name}",
        tr.SOURCE,
        f"d {from_si(row.nominal_m, 'mm'):g} mm, P {from_si(row.pitch_m, 'mm'):g} mm, lead "
        f"{from_si(row.lead_m, 'mm'):g} mm, f {friction:g}",
        published,
        "",
        lambda: tr.table_efficiency(row, friction),
        TR_NOTE,
    )


MISUMI = "MISUMI Economy Series e-catalog 2025, Selection of Ball Screws 2"
MISUMI_LIFE = "MISUMI Economy Series e-catalog 2025, Selection of Ball Screws 3, p. 1678"
NOOK = "Nook Industries, Acme and lead screw assembly application selection example"
ROTON = "Roton, Application Engineering: Speed (https://www.roton.com/resources/application-engineering/speed/)"

# fmt: off
EXAMPLES: tuple[Example, ...] = (
    Example("Critical speed", "Thomson, Screw critical speed (maximum RPM) calculation",
            "steel, root 1 in, 100 in, simple–simple", 476.0, "rpm",
            lambda: cs.critical_speed_rpm(1 * IN, 100 * IN, STEEL_E, STEEL_RHO, "simple-simple")),
    Example("Allowed speed", f"{MISUMI}, 5-1 Critical Speed, p. 1677",
            "root 12.5 mm, 790 mm, fixed–supported, factor 0.8", 3024.0, "rpm",
            lambda: cs.allowed_speed_rpm(
                cs.critical_speed_rpm(0.0125, 0.790, STEEL_E, 7800.0, "fixed-simple"), 0.8)),
    Example("Euler buckling", "Engineering ToolBox, Euler's Column Formula",
            "aluminium E 69 GPa, I 241 cm⁴, 5 m, fixed–fixed", 263e3, "N",
            lambda: _euler(69e9, 241e-8, 5.0, "fixed-fixed", False)),
    Example("Euler buckling", "engineeringprep.com problem 410, Column",
            "E 10 GPa, I 400 cm⁴, 5 m, fixed–fixed", 63e3, "N",
            lambda: _euler(10e9, 400e-8, 5.0, "fixed-fixed", False)),
    Example("Allowed axial load", f"{MISUMI}, 4. Allowable Axial Load, p. 1676",
            "root 12.5 mm, 820 mm, fixed–supported, factor 0.5", 3630.0, "N",
            lambda: buckling.allowed_buckling_load(
                _euler(STEEL_E, 0.0125, 0.820, "fixed-simple", True), 0.5)),
    Example("Allowed axial load", "Makishinko screw jacks, E-19, example JA050",
            "root 31.5 mm, 1000 mm, fixed–free, factor 0.25", MAKISHINKO_N, "N",
            lambda: _makishinko(STEEL_E), _makishinko_note()),
    Example("Raising torque (thread)", threads.SHIGLEY,
            "square, d 32 mm, p 4 mm, double start, f 0.08, F 6.4 kN", 15.94, "N m",
            threads.shigley_thread_torque),
    Example("Lowering torque (thread)", threads.SHIGLEY,
            "square, d_m 30 mm, lead 8 mm, f 0.08, F 6.4 kN", -0.466, "N m",
            threads.shigley_lowering_torque),
    Example("Overall efficiency", threads.SHIGLEY,
            "as above, with the printed collar torque 10.24 N m", 0.311, "",
            threads.shigley_overall_efficiency),
    Example("Lead angle", threads.SHIGLEY, "lead 8 mm, d_m 30 mm", 4.852, "°",
            lambda: math.degrees(geometry.lead_angle(0.008, 0.030))),
    Example("Raising torque, trapezoidal (thread)", threads.POWER_SCREWS,
            threads.POWER_SCREWS_INPUTS, 3378.16, "N m", lambda: threads.tr100(300e3)[1]),
    Example("Lowering torque, self-locking (thread)", threads.POWER_SCREWS,
            threads.POWER_SCREWS_INPUTS, 1030.69, "N m", lambda: threads.tr100(-300e3)[1],
            "A self-locking thread must be driven to lower its load: the core's motor torque "
            "for a thrust behind the move, through the signed back-drive efficiency."),
    Example("Efficiency, trapezoidal", threads.POWER_SCREWS, threads.POWER_SCREWS_INPUTS,
            0.339213, "", lambda: threads.tr100(300e3)[0]),
    Example("Raising torque, Acme (thread)", threads.MOTT,
            "Acme 1 1/2-4, d_p 1.3429 in, single start, f 0.15, 12,500 lb", 1809.0, "lb in",
            threads.mott_acme_torque_lb_in, threads.MOTT_NOTE),
    Example("Raising torque, square thread", threads.ADAPTIVE,
            "10,000 lb, 2 threads per inch, single start, d_m 2 in, f 0.2", 2840.0, "lb in",
            threads.adaptive_square_torque_lb_in),
    Example("Torque to move a load", "engineeringprep.com problem 516, Power Screw Torque",
            "20 kN, lead 10 mm, efficiency 70 %", 45.5, "N m",
            lambda: torque.load_torque(20_000.0, 0.01, 0.70)),
    Example("Square-thread efficiency", "Square-thread spot value (tan λ = (L/d_p)/π)",
            "L/d_p 0.5, friction 0.09", 0.630, "",
            lambda: efficiency.square_thread_efficiency(0.5 / math.pi, 0.09)),
    Example("Square-thread efficiency", "Square-thread spot value (tan λ = (L/d_p)/π)",
            "L/d_p 1.0, friction 0.15", 0.647, "",
            lambda: efficiency.square_thread_efficiency(1.0 / math.pi, 0.15)),
    Example("PV", "bnb-industries, Bearing Technical Information, Measuring Operating PV",
            "shaft 5/8 in, bearing 1-1/32 in, 35 lb, 120 rpm", 1066.2, "psi ft/min",
            _bnb_pv),
    Example("Average travel rate", f"{NOOK}, steps 2–3",
            "36 in in 10 s = 3.6 in/s, 1 in lead (rpm = in/min)", 216.0, "in/min",
            lambda: geometry.screw_speed_rpm(36 * IN / 10.0, 1 * IN)),
    Example("Peak travel rate", f"{NOOK}, steps 2–3",
            "triangular profile, peak 2 × 3.6 in/s, 1 in lead", 432.0, "in/min",
            lambda: geometry.screw_speed_rpm(2 * 36 * IN / 10.0, 1 * IN)),
    Example("Screw speed", ROTON, "1 1/2 × .500 Hilead, 100 in/min", 200.0, "rpm",
            lambda: geometry.screw_speed_rpm(100 * IN / 60.0, 0.5 * IN)),
    Example("Ball speed limit (DN)", ROTON, "3,000 rpm × in, 3/4 in ball screw", 4000.0, "rpm",
            lambda: ballscrew.dn_speed_limit(3000 * from_si(IN, "mm"), 0.75 * IN)),
    Example("Stepper corner speed", "Farnell, Stepper motor calculator",
            "24 V, 2 mH, 1.5 A, 200 steps a turn (R neglected)", 1200.0, "rpm",
            lambda: stepper.corner_speed_rpm(24.0, 1.5, 0.0, 0.002, 1.8)),
    Example("Stepper back-EMF", "Duet3D, back EMF due to rotation (D. Crocker)",
            "holding 0.55 N m at 1.68 A, 5 rev/s", 7.3, "V",
            lambda: stepper.back_emf_constant(0.55, 1.68) * 2 * math.pi * 5.0),
    Example("Brushed DC motor torque", "Magmotor C21-F-300FX performance sheet (2022)",
            "48 V, stall 342 oz in, no load 3780 rpm, at 3117 rpm", 60.0, "oz in",
            lambda: servo.peak_torque_nm(3117.0, 342.0, 0.0, 3780.0, 0.0)),
    Example("Fin heat", "Incropera & DeWitt, Heat and Mass Transfer, 6th ed., Example 3.9",
            "5 mm copper rod (k 398), h 100 W/(m² K), 75 K", 8.3, "W",
            lambda: heat.fin_conductance(0.005, 398.0, 100.0) * 75.0),
    Example("Ball screw L10 life", f"{MISUMI_LIFE}, 6-1 Life Calculation Example",
            "BSS1520, C 4400 N, mean load 250 N, 2118 rpm, f_w 1.2", 24824.0, "h",
            lambda: ballscrew.rated_life_revolutions(4400.0, 1.2, 250.0) / (60.0 * 2118.0)),
    Example("Sliding wear life", "SKF, composite plain bearings, calculation example",
            "PTFE composite, c 1.17, KM 480, p v 0.025 applied", 22500.0, "h",
            _skf_composite_life_h),
    Example("Peak torque of a cycle", maker.WEIHONG, maker.WEIHONG_INPUTS, 0.231, "N m",
            lambda: float(maker.weihong_cycle().motor.motor_peak_nm[0]), maker.WEIHONG_NOTE),
    Example("RMS torque of a cycle", maker.WEIHONG, maker.WEIHONG_INPUTS, 0.067, "N m",
            lambda: float(maker.weihong_cycle().motor.motor_rms_nm[0]), maker.WEIHONG_NOTE),
    Example("Axial load, acceleration (Fa1)", thk.SOURCE, thk.INPUTS, 550.0, "N",
            lambda: thk.axial_load(1), thk.NOTE),
    Example("Axial load, deceleration (Fa3)", thk.SOURCE, thk.INPUTS, -516.0, "N",
            lambda: thk.axial_load(3), thk.NOTE),
    Example("Axial load, back, acceleration (Fa4)", thk.SOURCE, thk.INPUTS, -550.0, "N",
            lambda: thk.axial_load(4), thk.NOTE),
    Example("Axial load, back, deceleration (Fa6)", thk.SOURCE, thk.INPUTS, 516.0, "N",
            lambda: thk.axial_load(6), thk.NOTE),
    Example("Peak axial load (Fa max)", thk.SOURCE, thk.INPUTS, 550.0, "N",
            lambda: float(thk.cycle(mass_as_inertia=False).axis.peak_force_n[0]), thk.NOTE),
    Example("Cubic mean axial load (Fm1)", thk.SOURCE, thk.INPUTS, 225.0, "N",
            thk.mean_load_one_direction, thk.MEAN_NOTE),
    Example("Ball screw rated life L10", thk.SOURCE, "Ca 5.4 kN, Fm 225 N, f_w 1.5",
            4.1e9, "rev", thk.life_revolutions, thk.MEAN_NOTE),
    Example("Permissible buckling load", thk.SOURCE,
            "d1 17.5 mm, 1100 mm, fixed–fixed, factor 0.5", 15500.0, "N",
            thk.buckling_load_n),
    Example("Permissible rotational speed", thk.SOURCE,
            "d1 17.5 mm, 1100 mm, fixed–supported, factor 0.8", 2180.0, "rpm",
            thk.critical_speed_rpm),
    Example("Load inertia at the screw", thk.SOURCE, thk.INPUTS, 3.39e-3, "kg m²",
            thk.load_inertia_kg_m2, thk.NOTE),
    Example("Friction torque, uniform motion (T1)", thk.SOURCE, thk.INPUTS, 0.120, "N m",
            lambda: thk.segment_torque_nm("constant"), thk.NOTE),
    Example("Acceleration torque (T2)", thk.SOURCE, thk.INPUTS, 4.61, "N m",
            lambda: thk.segment_torque_nm("accelerate") - thk.segment_torque_nm("constant"),
            thk.NOTE),
    Example("Torque during acceleration (Tk)", thk.SOURCE, thk.INPUTS, 4.73, "N m",
            lambda: float(thk.cycle().motor.motor_peak_nm[0]), thk.NOTE),
    Example("Torque during deceleration (Tg)", thk.SOURCE, thk.INPUTS, -4.49, "N m",
            lambda: thk.segment_torque_nm("decelerate"), thk.NOTE),
    Example("RMS torque of a cycle (Trms)", thk.SOURCE, thk.INPUTS, 1.305, "N m",
            lambda: float(thk.cycle().motor.motor_rms_nm[0]), thk.NOTE),
    Example("Ball screw shaft inertia", FANUC_ALPHA,
            "steel 7.8 t/m³, 32 mm, 1 m", 0.0008, "kg m²",
            lambda: torque.screw_inertia(torque.solid_rod_inertia_per_length(7800.0, 0.032),
                                         1.0)),
    Example("Table and work inertia", FANUC_ALPHA, "1000 kg, 8 mm per motor turn",
            0.00162, "kg m²", lambda: torque.reflected_mass_inertia(1000.0, 0.008)),
    Example("Constant load torque (Tm)", FANUC_ALPHA_I_TORQUE,
            "μ 0.05, W 11760 N, gib 490 N, lead 20 mm, η 0.9, T_f 0.8 N m", 30.3, "kgf cm",
            _fanuc_constant_load_torque_kgf_cm,
            "FANUC prints T_m = 3.0 N m = 30.3 kgf cm; the table compares the kgf cm figure, "
            "the one with three digits (the app's 2.966 N m is 1.1 % under the rounded "
            "3.0). T_f, the nut's and bearings' friction torque, is added outside the "
            "efficiency, as the app adds a nut's drag torque."),
    Example("RMS torque of a cycle (Trms)", FANUC_ALPHA_I_RMS,
            "T_a 83.2, T_m = T_o 3.0 N m; t1 0.08, t2 2.0, t3 3.0 s", 15.0, "N m",
            _fanuc_rms_torque_nm,
            "The cycle as FANUC's formula takes it: T_a + T_m over the ramp up (t1), T_m "
            "running (t2), T_a - T_m over the ramp down (t1) and T_o at rest (t3)."),
    Example("Permissible buckling load", THK_KR,
            "d1 17.5 mm, 1300 mm, fixed–fixed (n 4), E 206 GPa, factor 0.5", 11000.0, "N",
            lambda: buckling.allowed_buckling_load(
                _euler(STEEL_E, 0.0175, 1.3, "fixed-fixed", True), 0.5),
            "THK prints 11000 N, rounded; the exact Euler load at n = 4 is 11077 N."),
    Example("Motor shaft speed (nM)", YASKAWA, "15 m/min, lead 10 mm, gear 1/2", 3000.0,
            "rpm", lambda: geometry.screw_speed_rpm(to_si(15.0, "m") / 60.0,
                                                     YASKAWA_LEAD_M / YASKAWA_RATIO),
            YASKAWA_NOTE),
    Example("Load torque at the motor (TL)", YASKAWA, YASKAWA_INPUTS, 0.43, "N m",
            _yaskawa_load_torque_nm, YASKAWA_NOTE),
    Example("Ball screw inertia at the motor (JB)", YASKAWA, YASKAWA_INPUTS, 0.31e-4,
            "kg m²", _yaskawa_screw_inertia_at_motor, YASKAWA_NOTE),
    Example("Load inertia at the motor (JL)", YASKAWA, YASKAWA_INPUTS, 2.29e-4, "kg m²",
            _yaskawa_load_inertia, YASKAWA_NOTE),
    Example("Ball screw inertia (JB)", MITSUBISHI, "steel 7.80e-3 kg/cm³, 40 mm × 1000 mm",
            19.6, "kg cm²",
            lambda: torque.screw_inertia(torque.solid_rod_inertia_per_length(7800.0, 0.040),
                                         1.0) / KG_CM2),
    Example("Thrust from a torque", THK_CHANGE_NUT,
            "DCMB20T, lead 60 mm, η 0.67 (μ 0.2), T 19.6 N m", 1370.0, "N",
            lambda: 19.6 / torque.load_torque(1.0, THK_CHANGE_NUT_LEAD_M, THK_CHANGE_NUT_ETA),
            "The torque to move a load is linear in the load, so the thrust a torque gives "
            "is the torque over the core's torque per newton, lead / (2π η)."),
    Example("Torque from a thrust (back-driving)", THK_CHANGE_NUT,
            "DCMB20T, lead 60 mm, η 0.67 (μ 0.2), Fa 980 N", 6.27, "N m",
            lambda: efficiency.holding_torque(980.0, THK_CHANGE_NUT_LEAD_M,
                                              THK_CHANGE_NUT_ETA),
            "THK takes the forward efficiency 0.67 for the torque a thrust makes, as the "
            "core's holding torque does when given the forward efficiency (the seed's "
            "form); the app's own hold check uses the back-driving efficiency, which needs "
            "the screw's pitch diameter, not on this page."),
    Example("Lead angle, Tr 20 x 20 (P5)", tr.SOURCE,
            "lead 20 mm on d2 = 20 - 5/2 mm; printed 20°00′",
            20.0, "°", lambda: tr.lead_angle_deg(tr.BY_NAME["Tr 20 x 20 (P5)"])),
    Example("Lead angle, Tr 14 x 6 (P3)", tr.SOURCE,
            "lead 6 mm on d2 = 14 - 3/2 mm; printed 8°41′",
            tr.BY_NAME["Tr 14 x 6 (P3)"].published_angle_deg, "°",
            lambda: tr.lead_angle_deg(tr.BY_NAME["Tr 14 x 6 (P3)"])),
    _tr("Tr 20 x 4", 0.1),
    _tr("Tr 20 x 4", 0.2),
    _tr("Tr 14 x 6 (P3)", 0.1),
    _tr("Tr 20 x 20 (P5)", 0.1),
    _tr("Tr 20 x 20 (P5)", 0.2),
    Example("Critical speed, a ball screw", f"{maker.ROCKFORD}, step 6", maker.ROCKFORD_INPUTS,
            687.0, "in/min", maker.rockford_critical_speed, maker.ROCKFORD_NOTE),
    Example("Column load, a ball screw", f"{maker.ROCKFORD}, step 9", maker.ROCKFORD_INPUTS,
            6537.0, "lb", maker.rockford_column_lbf, maker.ROCKFORD_NOTE),
    Example("Ball screw inertia (J_B)", maker.OMRON, maker.OMRON_INPUTS, 1.5e-4, "kg m²",
            maker.omron_screw_inertia, maker.OMRON_NOTE),
    Example("Load inertia (J_L)", maker.OMRON, maker.OMRON_INPUTS, 1.63e-4, "kg m²",
            maker.omron_load_inertia, maker.OMRON_NOTE),
    Example("Load torque (T_L)", maker.OMRON, maker.OMRON_INPUTS, 7.8e-3, "N m",
            maker.omron_load_torque, maker.OMRON_NOTE),
    Example("Acceleration torque (T_A)", maker.OMRON, maker.OMRON_INPUTS, 0.165, "N m",
            maker.omron_acceleration_torque, maker.OMRON_NOTE),
    Example("Peak torque of a cycle (T_1)", maker.OMRON, maker.OMRON_INPUTS, 0.173, "N m",
            maker.omron_peak_torque, maker.OMRON_NOTE),
    Example("RMS torque of a cycle (T_rms)", maker.OMRON, maker.OMRON_INPUTS, 0.0828, "N m",
            maker.omron_rms_torque, maker.OMRON_NOTE),
)
# fmt: on
