"""Vectorised screening: every check's utilisation and pass/fail for many candidates.

The formula functions of the core are plain arithmetic, so the same functions that
``evaluate`` calls on floats run here on NumPy arrays, one element per candidate.
``select`` screens the whole catalog here, then builds full evaluations (messages,
fixes) only for the candidates it returns; tests hold both paths in agreement.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from app.core import (
    accuracy,
    buckling,
    critical_speed,
    efficiency,
    geometry,
    life,
    limits,
    pv,
    torque,
)
from app.core.evaluate import axial_load
from app.core.model import PASS_UTILIZATION, Application, ScrewSpec

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]


def _column(values: Sequence[float | None]) -> Array:
    """Float column; None (no such limit) becomes NaN."""
    return np.array([np.nan if v is None else v for v in values], dtype=np.float64)


@dataclass(frozen=True, slots=True)
class CandidateTable:
    """Catalog candidates as columns, with the application-independent constants."""

    screws: tuple[ScrewSpec, ...]
    lead_m: Array
    outer_diameter_m: Array
    root_diameter_m: Array
    thread_depth_m: Array
    helix_travel_m: Array
    youngs_modulus_pa: Array
    density_kg_m3: Array
    inertia_kg_m2_per_m: Array
    drag_max_nm: Array
    pv_limit_pa_m_s: Array
    design_load_n: Array
    max_length_m: Array
    life_min_m: Array
    lead_accuracy: Array
    backlash_max_m: Array
    repeatability_m: Array
    temperature_min_c: Array
    temperature_max_c: Array
    coated: Mask
    anti_backlash: Mask
    efficiency: Array
    efficiency_static: Array
    max_self_locking_lead_m: Array
    traverse_limit_m_s: Array

    @classmethod
    def build(cls, screws: Sequence[ScrewSpec]) -> "CandidateTable":
        """Columns from screws; computed once per catalog (at start-up for ours)."""
        screws = tuple(screws)

        def col(name: str) -> Array:
            return _column([getattr(s, name) for s in screws])

        od, rd, lead = col("outer_diameter_m"), col("root_diameter_m"), col("lead_m")
        d_p = geometry.pitch_diameter(od, rd)
        tan_l = geometry.tan_lead_angle(lead, d_p)
        cos_a = np.cos(col("thread_half_angle_rad"))
        mu_s, mu_d = col("friction_static"), col("friction_dynamic")
        return cls(
            screws=screws,
            lead_m=lead,
            outer_diameter_m=od,
            root_diameter_m=rd,
            thread_depth_m=geometry.thread_depth(od, rd),
            helix_travel_m=geometry.helix_travel(lead, d_p),
            youngs_modulus_pa=col("youngs_modulus_pa"),
            density_kg_m3=col("density_kg_m3"),
            inertia_kg_m2_per_m=col("inertia_kg_m2_per_m"),
            drag_max_nm=col("drag_torque_max_nm"),
            pv_limit_pa_m_s=col("pv_limit_pa_m_s"),
            design_load_n=col("design_load_n"),
            max_length_m=col("max_length_m"),
            life_min_m=col("life_min_m"),
            lead_accuracy=col("lead_accuracy_m_per_m"),
            backlash_max_m=col("backlash_max_m"),
            repeatability_m=np.nan_to_num(col("repeatability_m")),
            temperature_min_c=col("temperature_min_c"),
            temperature_max_c=col("temperature_max_c"),
            coated=np.array([s.coated for s in screws], dtype=bool),
            anti_backlash=np.array([s.anti_backlash for s in screws], dtype=bool),
            efficiency=efficiency.forward_efficiency(tan_l, mu_d, cos_a),
            efficiency_static=efficiency.forward_efficiency(tan_l, mu_s, cos_a),
            max_self_locking_lead_m=efficiency.max_self_locking_lead(d_p, mu_s, cos_a),
            traverse_limit_m_s=_column(
                [
                    limits.band_speed_m_s(s.lead_m, s.traverse_bands) if s.traverse_bands else None
                    for s in screws
                ]
            ),
        )

    def __len__(self) -> int:
        return len(self.screws)


@dataclass(frozen=True, slots=True)
class Screening:
    """Per eligible candidate (``index`` into the table): pass, worst utilisation, torque."""

    index: NDArray[np.intp]
    passed: Mask
    max_utilization: Array
    total_torque_nm: Array
    failed_by_check: dict[str, Mask]


def eligible_mask(app: Application, table: CandidateTable) -> Mask:
    """Candidates with the asked lead (0.5 %) and coating choice."""
    mask = np.ones(len(table), dtype=bool)
    if app.lead_m is not None:
        mask &= np.abs(table.lead_m - app.lead_m) <= 0.005 * app.lead_m
    if app.coating != "auto":
        mask &= table.coated == (app.coating == "tfe")
    return mask


def screen(app: Application, table: CandidateTable) -> Screening:
    """Every check of ``app.core.checks`` for every eligible candidate, as arrays."""
    idx = np.flatnonzero(eligible_mask(app, table))
    t = table
    lead, rd = t.lead_m[idx], t.root_diameter_m[idx]
    e_mod, rho = t.youngs_modulus_pa[idx], t.density_kg_m3[idx]
    force = axial_load(app)
    rpm = geometry.screw_speed_rpm(app.speed_m_s, lead)

    alpha = torque.angular_acceleration(app.accel_m_s2, lead)
    j_screw = torque.screw_inertia(t.inertia_kg_m2_per_m[idx], app.length_m)
    j_mass = torque.reflected_mass_inertia(app.moving_mass_kg, lead)
    t_inertia = torque.inertia_torque(j_screw, alpha) + torque.inertia_torque(j_mass, alpha)
    drag = t.drag_max_nm[idx]
    total = torque.total_torque(t_inertia, drag, torque.load_torque(force, lead, t.efficiency[idx]))
    breakaway = torque.load_torque(force, lead, t.efficiency_static[idx]) + drag

    util: dict[str, Array] = {}
    flags: dict[str, Mask] = {}
    if app.max_torque_nm is not None:
        required = np.maximum(total, breakaway) * app.torque_safety_factor
        util["torque"] = required / app.max_torque_nm
    n_c = critical_speed.critical_speed_rpm(rd, app.length_m, e_mod, rho, app.end_fixity)
    util["critical_speed"] = rpm / critical_speed.allowed_speed_rpm(
        n_c, app.critical_speed_safety_factor
    )
    if app.compression:
        f_cr = buckling.euler_critical_load(
            e_mod, buckling.second_moment_round(rd), app.length_m, app.end_fixity
        )
        util["buckling"] = force / buckling.allowed_buckling_load(f_cr, app.buckling_safety_factor)
    pv_value = pv.pv_value(force, rpm, t.helix_travel_m[idx], t.thread_depth_m[idx])
    util["pv"] = pv_value / t.pv_limit_pa_m_s[idx]
    util["traverse_speed"] = app.speed_m_s / t.traverse_limit_m_s[idx]
    util["design_load"] = force / t.design_load_n[idx]
    util["length"] = app.length_m / t.max_length_m[idx]
    if app.oil_present:
        flags["coating_environment"] = t.coated[idx]
    t_min, t_max = t.temperature_min_c[idx], t.temperature_max_c[idx]
    flags["temperature"] = ~np.isnan(t_min) & ~((t_min <= app.ambient_c) & (app.ambient_c <= t_max))
    if app.orientation == "vertical":
        util["back_driving"] = lead / t.max_self_locking_lead_m[idx]
    if app.require_anti_backlash:
        flags["anti_backlash"] = ~t.anti_backlash[idx]
    if app.required_life_years is not None and app.stroke_m and app.cycles_per_day:
        life_min = t.life_min_m[idx]
        years = life.life_years(life_min, app.stroke_m, app.cycles_per_day)
        util["life"] = app.required_life_years / years
        flags["life"] = np.isnan(life_min)
    if app.positioning_tolerance_m is not None:
        stroke = app.stroke_m if app.stroke_m is not None else app.length_m
        error = (
            accuracy.cumulative_lead_error(t.lead_accuracy[idx], stroke)
            + t.backlash_max_m[idx]
            + t.repeatability_m[idx]
        )
        util["accuracy"] = error / app.positioning_tolerance_m

    failed = {name: u > PASS_UTILIZATION for name, u in util.items()}
    for name, flag in flags.items():
        failed[name] = failed[name] | flag if name in failed else flag
    any_failed = np.zeros(len(idx), dtype=bool)
    n_failed = np.zeros(len(idx))
    for mask in failed.values():
        any_failed |= mask
        n_failed += mask
    max_u = np.zeros(len(idx))
    for u in util.values():
        max_u = np.fmax(max_u, u)
    # a failed yes/no check ranks behind every numeric near-miss (as in evaluate)
    max_u = np.where(
        any_failed & (max_u <= PASS_UTILIZATION), np.maximum(max_u, 1.0 + n_failed), max_u
    )
    return Screening(idx, ~any_failed, max_u, total, failed)
