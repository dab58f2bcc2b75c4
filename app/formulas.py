"""The formula behind each reported quantity: text, the core function, and the source.

Served with every result (``formulas`` in the API, the detail view on the page), so each
number can be traced to its formula and from there to the catalog values and provenance.
"""

from typing import TypedDict

from app.core.checks import REGISTRY


class Formula(TypedDict):
    formula: str
    function: str
    source: str


SEED = "seed catalog, Leadscrew Assemblies: Design and Engineering Data"
SHIGLEY = "Shigley's Mechanical Engineering Design, 10th ed., sec. 8-2"


#: Modules of the core outside ``app.core.formulas``.
CORE_MODULES = ("quantities", "evaluate", "selection", "motion")


def _f(formula: str, function: str, source: str) -> Formula:
    package = "app.core" if function.split(".")[0] in CORE_MODULES else "app.core.formulas"
    return {"formula": formula, "function": f"{package}.{function}", "source": source}


FORMULAS: dict[str, Formula] = {
    "pitch_diameter_mm": _f(
        "d_p = d2 of a standard thread (ISO 2904: d - 0.5 P), else (OD + RD) / 2",
        "geometry.pitch_diameter",
        SEED + "; ISO 2904",
    ),
    "lead_angle_deg": _f("lambda = atan(lead / (pi d_p))", "geometry.lead_angle", SHIGLEY),
    "rpm": _f("n = 60 v / lead", "geometry.screw_speed_rpm", SEED + " (RS = speed / lead)"),
    "axial_load_n": _f(
        "F = load (+ m g when vertical), the running thrust", "quantities.axial_load", "statics"
    ),
    "peak_axial_load_n": _f(
        "F_peak = F + m a", "quantities.peak_axial_load", "Newton's second law"
    ),
    "efficiency": _f(
        "eta = (cos a_n - mu tan l) / (cos a_n + mu / tan l), mu dynamic",
        "efficiency.forward_efficiency",
        SHIGLEY + " (Acme form)",
    ),
    "efficiency_square_thread": _f(
        "eta = tan l / tan(l + atan mu)",
        "efficiency.square_thread_efficiency",
        SHIGLEY + " (square thread, manufacturer's form)",
    ),
    "backdrive_efficiency": _f(
        "eta_b = (cos a_n tan l - mu_s) / (tan l (cos a_n + mu_s tan l)), 0 if negative",
        "efficiency.backdrive_efficiency",
        SHIGLEY,
    ),
    "self_locking": _f("mu_s >= cos a_n tan l", "efficiency.is_self_locking", SHIGLEY),
    "seed_rule_no_backdrive": _f(
        "lead < OD / 8", "efficiency.seed_backdrive_rule", SEED + " (Back Driving)"
    ),
    "backdrive_efficiency_running": _f(
        "eta_b at the running (dynamic) friction",
        "efficiency.backdrive_efficiency",
        SHIGLEY,
    ),
    "self_locking_with_margin": _f(
        "f mu_s >= cos a_n tan l (f: the self-locking friction factor)",
        "efficiency.self_locking_limit_friction",
        SHIGLEY + "; margin as the seed's d/8 rule",
    ),
    "max_self_locking_lead_with_margin_mm": _f(
        "lead = pi d_p f mu_s / cos a_n", "efficiency.max_self_locking_lead", SHIGLEY
    ),
    "max_self_locking_lead_mm": _f(
        "lead = pi d_p mu_s / cos a_n", "efficiency.max_self_locking_lead", SHIGLEY
    ),
    "holding_torque.seed_method_nm": _f(
        "T_b = F lead eta / (2 pi), forward eta",
        "efficiency.holding_torque",
        SEED + " (Back Driving)",
    ),
    "holding_torque.physics_nm": _f(
        "T_b = F lead eta_b / (2 pi), back-drive eta", "efficiency.holding_torque", SHIGLEY
    ),
    "holding_torque.brake_nm": _f(
        "T = max(seed method, physics); 0 when self-locking with the friction margin",
        "quantities.operating_point",
        "safe side of both",
    ),
    "torque.inertia_screw_nm": _f(
        "T = (J/L x L) x 2 pi a / lead",
        "torque.inertia_torque",
        SEED + " (Inertia Torque T = I alpha)",
    ),
    "torque.inertia_mass_nm": _f(
        "T = m a lead / (2 pi eta): the accelerating force through the thread",
        "torque.load_torque",
        SEED + " (Torque To Move Load) with the force m a",
    ),
    "torque.inertia_nm": _f(
        "T = T_inertia_screw + T_inertia_mass", "quantities.operating_point", SEED
    ),
    "torque.peak_nm": _f("T = max |T_segment| over the cycle", "motion.segments", "move profile"),
    "torque.rms_nm": _f(
        "T_rms = sqrt(sum T_i^2 t_i / sum t_i)",
        "profile.rms_torque",
        "root mean square over the cycle (motor vendors' continuous-duty rule)",
    ),
    "profile.peak_speed_mm_s": _f(
        "v_peak = min(v, sqrt(2 s / (1/a + 1/d)))", "profile.peak_speed", "kinematics"
    ),
    "profile.accel_time_s": _f("t_a = v_peak / a", "profile.ramp_time", "kinematics"),
    "profile.decel_time_s": _f("t_d = v_peak / d", "profile.ramp_time", "kinematics"),
    "profile.constant_time_s": _f(
        "t_c = (s - v_peak^2 / 2a - v_peak^2 / 2d) / v_peak", "profile.constant_time", "kinematics"
    ),
    "profile.move_time_s": _f("t = t_a + t_c + t_d", "motion.move_profile", "kinematics"),
    "profile.cycle_time_s": _f(
        "t = 2 (move + dwell), out and back", "motion.move_profile", "kinematics"
    ),
    "segments.duration_s": _f(
        "t_a, t_c, t_d of the profile for the moving segments; the dwell as given",
        "motion.move_profile",
        "kinematics",
    ),
    "segments.rpm": _f(
        "n = 60 v_peak / lead while moving (its top speed); 0 in a dwell",
        "geometry.screw_speed_rpm",
        SEED + " (RS = speed / lead)",
    ),
    "segments.thrust_n": _f(
        "F = s F_steady + m a, a = +a, 0, -d along the motion; F_steady = load (+ m g "
        "when vertical), s = +1 out, back and up, -1 down; in a dwell F_steady when vertical",
        "motion.segments",
        "statics and Newton's second law",
    ),
    "segments.torque_nm": _f(
        "T = F lead / (2 pi eta) if F >= 0 else F lead eta_b / (2 pi), + T_drag "
        "+ (J_screw + J_rotor) alpha; in a dwell the holding torque when vertical, else 0",
        "profile.thread_torque",
        SHIGLEY + " (raising and lowering torque); " + SEED + " (Back Driving)",
    ),
    "torque.drag_nm": _f(
        "top of the series' static drag range",
        "quantities.operating_point",
        SEED + " (Static Frictional Torque)",
    ),
    "torque.load_nm": _f(
        "T = F lead / (2 pi eta)", "torque.load_torque", SEED + " (Torque To Move Load)"
    ),
    "torque.total_nm": _f(
        "T = T_inertia + T_drag + T_load",
        "torque.total_torque",
        SEED + " (Torque: sum of three components)",
    ),
    "torque.breakaway_nm": _f(
        "T = (F + m a) lead / (2 pi eta_static) + J_screw alpha + T_drag, starting from rest",
        "torque.load_torque",
        SEED + " with static friction",
    ),
    "torque.required_nm": _f(
        "T = SF x max(T_total, T_breakaway)", "quantities.operating_point", "user torque margin"
    ),
    "critical_speed.theoretical_rpm": _f(
        "n_c = 60 / (2 pi) (beta / L)^2 sqrt(E / rho) d_r / 4",
        "critical_speed.critical_speed_rpm",
        "Blevins, Formulas for Natural Frequency, table 8-1; Thomson n_c = 4.76e6 d_r / L^2",
    ),
    "critical_speed.margin": _f(
        "margin = n_allowed / n",
        "critical_speed.speed_margin",
        "inverse of the critical-speed utilisation",
    ),
    "critical_speed.allowed_rpm": _f(
        "n = SF x n_c", "critical_speed.allowed_speed_rpm", "Thomson (80 % of critical)"
    ),
    "buckling.critical_load_n": _f(
        "F_cr = pi^2 E A / s^2 (Euler) for s >= s_1, else A (S_y - (S_y s / 2 pi)^2 / E)",
        "buckling.column_critical_load",
        "Euler (Timoshenko & Gere); Johnson, Shigley sec. 4-13",
    ),
    "buckling.slenderness": _f(
        "s = (L / sqrt(k)) / (d_r / 4)", "buckling.slenderness", "Shigley sec. 4-11"
    ),
    "buckling.transition_slenderness": _f(
        "s_1 = sqrt(2 pi^2 E / S_y)", "buckling.transition_slenderness", "Shigley sec. 4-12"
    ),
    "buckling.root_stress_mpa": _f(
        "sigma = F_peak / (pi d_r^2 / 4)", "buckling.root_stress", "axial stress"
    ),
    "buckling.allowed_load_n": _f(
        "F = SF x F_cr", "buckling.allowed_buckling_load", "lead-screw practice (0.5)"
    ),
    "pv.value_mpa_m_s": _f(
        "PV = F / (3 H.T. h) x n H.T.",
        "pv.pv_value",
        SEED + " (PV Calculation, 3 threads in contact)",
    ),
    "pv.pressure_mpa": _f("P = F / (3 H.T. h)", "pv.contact_pressure", SEED),
    "pv.surface_speed_m_s": _f(
        "V = n H.T., H.T. = sqrt(lead^2 + (pi d_p)^2)", "pv.surface_speed", SEED
    ),
    "pv.max_load_n": _f("F = PV_lim 3 h / n", "pv.max_load_for_pv", SEED + " (inverted)"),
    "pv.max_speed_mm_s": _f("v = lead x PV_lim 3 h / F", "pv.max_rpm_for_pv", SEED + " (inverted)"),
    "traverse_speed_limit_mm_s": _f(
        "band table by lead (family data)", "limits.band_limit", SEED + " (Traverse Speed)"
    ),
    "life.years": _f(
        "years = rated travel / (2 stroke x cycles/day x 365)",
        "life.life_years",
        SEED + " (Anti-Backlash Life)",
    ),
    "accuracy.lead_error_mm": _f(
        "e = lead accuracy x stroke", "accuracy.cumulative_lead_error", SEED + " (Screw Accuracy)"
    ),
    "accuracy.thermal_growth_mm": _f(
        "dL = alpha stroke (T - 20 C)",
        "accuracy.thermal_growth",
        "303 stainless 17.3e-6 /K (ASM Handbook)",
    ),
}

#: Each check's own formula, from the registry: ``checks.<name>``.
FORMULAS.update(
    {
        f"checks.{c.name}": {
            "formula": c.formula,
            "function": f"{type(c).__module__}.{type(c).__name__}.measure",
            "source": c.source,
        }
        for c in REGISTRY
    }
)
