"""Evaluate one screw against one application: every number, every check, every fix."""

import math
from dataclasses import replace

from app.core import accuracy, buckling, critical_speed, efficiency, geometry, life, limits, pv
from app.core import torque as torque_
from app.core.checks import build_checks
from app.core.model import (
    PASS_UTILIZATION,
    PV,
    STANDARD_GRAVITY_M_S2,
    Accuracy,
    Application,
    Buckling,
    CriticalSpeed,
    Evaluation,
    Life,
    ScrewSpec,
    Torque,
)

REFERENCE_TEMPERATURE_C = 20.0


def axial_load(app: Application) -> float:
    """Axial force on the nut [N]: the given load, plus m g on a vertical axis."""
    if app.orientation == "vertical":
        return app.load_n + app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return app.load_n


def evaluate(app: Application, screw: ScrewSpec) -> Evaluation:
    """Compute torque, speeds, loads, PV, life, accuracy and all checks for one screw."""
    force_n = axial_load(app)
    d_p = geometry.pitch_diameter(screw.outer_diameter_m, screw.root_diameter_m)
    h = geometry.thread_depth(screw.outer_diameter_m, screw.root_diameter_m)
    tan_l = geometry.tan_lead_angle(screw.lead_m, d_p)
    lam = geometry.lead_angle(screw.lead_m, d_p)
    rpm = geometry.screw_speed_rpm(app.speed_m_s, screw.lead_m)
    cos_a = math.cos(screw.thread_half_angle_rad)

    eta = efficiency.forward_efficiency(tan_l, screw.friction_dynamic, cos_a)
    eta_static = efficiency.forward_efficiency(tan_l, screw.friction_static, cos_a)
    eta_b = efficiency.backdrive_efficiency(tan_l, screw.friction_static, cos_a)
    self_locking = efficiency.is_self_locking(tan_l, screw.friction_static, cos_a)
    if min(eta, eta_static) <= 0.0:
        raise ValueError(
            f"{screw.id}: lead angle {math.degrees(lam):.1f} deg is too steep to drive "
            f"against friction {screw.friction_dynamic:g}"
        )

    alpha = torque_.angular_acceleration(app.accel_m_s2, screw.lead_m)
    j_screw = torque_.screw_inertia(screw.inertia_kg_m2_per_m, app.length_m)
    j_mass = torque_.reflected_mass_inertia(app.moving_mass_kg, screw.lead_m)
    t_inertia_screw = torque_.inertia_torque(j_screw, alpha)
    t_inertia_mass = torque_.inertia_torque(j_mass, alpha)
    t_inertia = t_inertia_screw + t_inertia_mass
    t_drag = screw.drag_torque_max_nm
    t_load = torque_.load_torque(force_n, screw.lead_m, eta)
    t_total = torque_.total_torque(t_inertia, t_drag, t_load)
    t_break = torque_.load_torque(force_n, screw.lead_m, eta_static) + t_drag
    torque = Torque(
        inertia_screw_nm=t_inertia_screw,
        inertia_mass_nm=t_inertia_mass,
        inertia_nm=t_inertia,
        drag_nm=t_drag,
        drag_min_nm=screw.drag_torque_min_nm,
        drag_max_nm=screw.drag_torque_max_nm,
        load_nm=t_load,
        total_nm=t_total,
        breakaway_nm=t_break,
        safety_factor=app.torque_safety_factor,
        required_nm=max(t_total, t_break) * app.torque_safety_factor,
        angular_accel_rad_s2=alpha,
        inertia_kg_m2=j_screw + j_mass,
    )

    n_c = critical_speed.critical_speed_rpm(
        screw.root_diameter_m,
        app.length_m,
        screw.youngs_modulus_pa,
        screw.density_kg_m3,
        app.end_fixity,
    )
    allowed_rpm = critical_speed.allowed_speed_rpm(n_c, app.critical_speed_safety_factor)
    crit = CriticalSpeed(
        theoretical_rpm=n_c,
        allowed_rpm=allowed_rpm,
        margin=critical_speed.speed_margin(allowed_rpm, rpm),
        safety_factor=app.critical_speed_safety_factor,
        end_fixity=app.end_fixity,
    )

    f_cr = buckling.euler_critical_load(
        screw.youngs_modulus_pa,
        buckling.second_moment_round(screw.root_diameter_m),
        app.length_m,
        app.end_fixity,
    )
    buck = Buckling(
        applies=app.compression,
        critical_load_n=f_cr,
        allowed_load_n=buckling.allowed_buckling_load(f_cr, app.buckling_safety_factor),
        safety_factor=app.buckling_safety_factor,
    )

    ht = geometry.helix_travel(screw.lead_m, d_p)
    area = pv.contact_area(ht, h)
    pv_limit = screw.pv_limit_pa_m_s
    pv_res = PV(
        value_pa_m_s=pv.pv_value(force_n, rpm, ht, h),
        limit_pa_m_s=pv_limit,
        pressure_pa=pv.contact_pressure(force_n, area),
        surface_speed_m_s=pv.surface_speed(rpm, ht),
        contact_area_m2=area,
        max_load_n=None if pv_limit is None else pv.max_load_for_pv(pv_limit, rpm, h),
        max_speed_m_s=(
            None
            if pv_limit is None
            else pv.max_rpm_for_pv(pv_limit, force_n, h) * screw.lead_m / 60.0
        ),
    )

    traverse = (
        limits.band_limit(screw.lead_m, screw.traverse_bands) if screw.traverse_bands else None
    )

    life_res = None
    if screw.life_min_m is not None and screw.life_max_m is not None:
        stroke_m, cycles = app.stroke_m, app.cycles_per_day
        life_res = Life(
            travel_min_m=screw.life_min_m,
            travel_max_m=screw.life_max_m,
            years_min=(
                life.life_years(screw.life_min_m, stroke_m, cycles) if stroke_m and cycles else None
            ),
            years_max=(
                life.life_years(screw.life_max_m, stroke_m, cycles) if stroke_m and cycles else None
            ),
        )

    stroke = app.stroke_m if app.stroke_m is not None else app.length_m
    acc = Accuracy(
        lead_error_m=(
            None
            if screw.lead_accuracy_m_per_m is None
            else accuracy.cumulative_lead_error(screw.lead_accuracy_m_per_m, stroke)
        ),
        repeatability_m=screw.repeatability_m,
        backlash_min_m=screw.backlash_min_m,
        backlash_max_m=screw.backlash_max_m,
        thermal_growth_m=accuracy.thermal_growth(
            screw.screw_expansion_per_k, stroke, app.ambient_c - REFERENCE_TEMPERATURE_C
        ),
    )

    # The seed's holding torque uses the forward efficiency at running friction; the
    # physical one, the back-drive efficiency at static friction, is larger for uncoated
    # screws (mu_d 0.15 > mu_s 0.08) and steep leads. A brake must hold the larger.
    holding_seed = 0.0 if self_locking else efficiency.holding_torque(force_n, screw.lead_m, eta)
    holding_physics = efficiency.holding_torque(force_n, screw.lead_m, eta_b)
    partial = Evaluation(
        screw=screw,
        axial_load_n=force_n,
        rpm=rpm,
        lead_angle_rad=lam,
        efficiency=eta,
        efficiency_square_thread=efficiency.square_thread_efficiency(tan_l, screw.friction_dynamic),
        backdrive_efficiency=eta_b,
        self_locking=self_locking,
        seed_rule_no_backdrive=efficiency.seed_backdrive_rule(screw.lead_m, screw.outer_diameter_m),
        max_self_locking_lead_m=efficiency.max_self_locking_lead(d_p, screw.friction_static, cos_a),
        holding_torque_seed_nm=holding_seed,
        holding_torque_physics_nm=holding_physics,
        brake_torque_nm=0.0 if self_locking else max(holding_seed, holding_physics),
        torque=torque,
        critical_speed=crit,
        buckling=buck,
        pv=pv_res,
        traverse_speed_limit_m_s=None if traverse is None else traverse.speed_m_s,
        traverse_extrapolated=traverse is not None and traverse.extrapolated,
        life=life_res,
        accuracy=acc,
        checks=(),
        passed=False,
        governing_check=None,
        max_utilization=0.0,
    )
    checks = build_checks(app, partial)
    utilized = [c for c in checks if c.utilization is not None]
    governing = max(utilized, key=lambda c: c.utilization or 0.0) if utilized else None
    failed = [c for c in checks if not c.passed]
    max_u = max((c.utilization or 0.0 for c in utilized), default=0.0)
    if failed and max_u <= PASS_UTILIZATION:
        # a failed yes/no check ranks behind every numeric near-miss
        max_u = max(max_u, 1.0 + len(failed))
    if failed and (governing is None or governing.passed):
        governing_name: str | None = failed[0].name
    else:
        governing_name = governing.name if governing else None
    return replace(
        partial,
        checks=checks,
        passed=not failed,
        governing_check=governing_name,
        max_utilization=max_u,
    )
