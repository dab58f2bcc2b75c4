"""Every number of one axis for many candidates at once: the operating point of each.

``operating_point(app, table)`` computes, over the table's columns, the speeds, loads,
torques, limits and margins that the checks and the reports read. The same arithmetic
serves one screw (a table of one) or the whole catalog; ``row(i)`` gives one
candidate's numbers as plain floats.
"""

from collections.abc import Sequence
from dataclasses import dataclass, fields
from typing import Any, Generic, TypeVar

import numpy as np

from app.core.formulas import (
    accuracy,
    buckling,
    critical_speed,
    efficiency,
    geometry,
    life,
    pv,
    torque,
)
from app.core.model import STANDARD_GRAVITY_M_S2, Application
from app.core.table import Array, CandidateTable

V = TypeVar("V")
#: Ambient temperature at which the screw's length is nominal [C].
REFERENCE_TEMPERATURE_C = 20.0


def axial_load(app: Application) -> float:
    """Axial force on the nut [N]: the given load, plus m g on a vertical axis."""
    if app.orientation == "vertical":
        return app.load_n + app.moving_mass_kg * STANDARD_GRAVITY_M_S2
    return app.load_n


@dataclass(frozen=True, slots=True)
class Quantities(Generic[V]):
    """One axis's numbers, SI; ``V`` is an array (one element per candidate) or a float."""

    force_n: V
    rpm: V
    angular_accel_rad_s2: V
    inertia_kg_m2: V
    inertia_screw_nm: V
    inertia_mass_nm: V
    inertia_nm: V
    drag_nm: V
    load_nm: V
    total_nm: V
    breakaway_nm: V
    required_nm: V
    critical_rpm: V
    allowed_rpm: V
    critical_load_n: V
    allowed_load_n: V
    pv_pa_m_s: V
    pressure_pa: V
    surface_speed_m_s: V
    contact_area_m2: V
    pv_max_load_n: V
    pv_max_speed_m_s: V
    life_years_min: V
    life_years_max: V
    lead_error_m: V
    thermal_growth_m: V
    holding_seed_nm: V
    holding_physics_nm: V
    brake_nm: V

    def rows(self, index: Sequence[int]) -> "list[Quantities[float]]":
        """The numbers of the candidates at ``index`` as floats (NaN: no such limit)."""
        columns = [getattr(self, name)[list(index)].tolist() for name in NAMES]
        return [Quantities(*values) for values in zip(*columns, strict=True)]


#: The fields of ``Quantities``, in declaration order.
NAMES = tuple(f.name for f in fields(Quantities))


def _torques(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Seed torque method: inertia + static drag + load through the thread's efficiency."""
    alpha = torque.angular_acceleration(app.accel_m_s2, t.lead_m)
    j_screw = torque.screw_inertia(t.inertia_kg_m2_per_m, app.length_m)
    j_mass = torque.reflected_mass_inertia(app.moving_mass_kg, t.lead_m)
    t_screw = torque.inertia_torque(j_screw, alpha)
    t_mass = torque.inertia_torque(j_mass, alpha)
    t_load = torque.load_torque(force_n, t.lead_m, t.efficiency)
    t_total = torque.total_torque(t_screw + t_mass, t.drag_max_nm, t_load)
    t_break = torque.load_torque(force_n, t.lead_m, t.efficiency_static) + t.drag_max_nm
    return {
        "angular_accel_rad_s2": alpha,
        "inertia_kg_m2": j_screw + j_mass,
        "inertia_screw_nm": t_screw,
        "inertia_mass_nm": t_mass,
        "inertia_nm": t_screw + t_mass,
        "drag_nm": t.drag_max_nm,
        "load_nm": t_load,
        "total_nm": t_total,
        "breakaway_nm": t_break,
        "required_nm": np.maximum(t_total, t_break) * app.torque_safety_factor,
    }


def _column_limits(app: Application, t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Critical speed and Euler buckling of the screw as a column between its supports."""
    n_c = critical_speed.critical_speed_rpm(
        t.root_diameter_m, app.length_m, t.youngs_modulus_pa, t.density_kg_m3, app.end_fixity
    )
    f_cr = buckling.euler_critical_load(
        t.youngs_modulus_pa,
        buckling.second_moment_round(t.root_diameter_m),
        app.length_m,
        app.end_fixity,
    )
    return {
        "critical_rpm": n_c,
        "allowed_rpm": critical_speed.allowed_speed_rpm(n_c, app.critical_speed_safety_factor),
        "critical_load_n": f_cr,
        "allowed_load_n": buckling.allowed_buckling_load(f_cr, app.buckling_safety_factor),
    }


def _nut(app: Application, t: CandidateTable, force_n: float, rpm: Array) -> dict[str, Any]:
    """PV of the nut (seed, three threads in contact) and its limits inverted."""
    area = pv.contact_area(t.helix_travel_m, t.thread_depth_m)
    limit = t.pv_limit_pa_m_s
    return {
        "pv_pa_m_s": pv.pv_value(force_n, rpm, t.helix_travel_m, t.thread_depth_m),
        "pressure_pa": np.broadcast_to(pv.contact_pressure(force_n, area), rpm.shape),
        "surface_speed_m_s": pv.surface_speed(rpm, t.helix_travel_m),
        "contact_area_m2": area,
        "pv_max_load_n": pv.max_load_for_pv(limit, rpm, t.thread_depth_m),
        "pv_max_speed_m_s": pv.max_rpm_for_pv(limit, force_n, t.thread_depth_m) * t.lead_m / 60.0,
    }


def _duty(app: Application, t: CandidateTable) -> dict[str, Any]:
    """Rated life in years for the duty, lead error and thermal growth over the stroke."""
    nan = np.full(len(t), np.nan)
    stroke, cycles = app.stroke_m, app.cycles_per_day
    rated = bool(stroke and cycles)
    travel = app.stroke_m if app.stroke_m is not None else app.length_m
    return {
        "life_years_min": life.life_years(t.life_min_m, stroke, cycles) if rated else nan,
        "life_years_max": life.life_years(t.life_max_m, stroke, cycles) if rated else nan,
        "lead_error_m": accuracy.cumulative_lead_error(t.lead_accuracy, travel),
        "thermal_growth_m": accuracy.thermal_growth(
            t.screw_expansion_per_k, travel, app.ambient_c - REFERENCE_TEMPERATURE_C
        ),
    }


def _holding(t: CandidateTable, force_n: float) -> dict[str, Any]:
    """Torque that keeps the load from turning the screw; 0 where the thread self-locks.

    The seed's method uses the forward efficiency at running friction; the physical one,
    the back-drive efficiency at static friction, is larger for uncoated screws
    (mu_d 0.15 > mu_s 0.08) and steep leads. A brake must hold the larger.
    """
    seed = np.where(t.self_locking, 0.0, efficiency.holding_torque(force_n, t.lead_m, t.efficiency))
    physics = efficiency.holding_torque(force_n, t.lead_m, t.backdrive_efficiency)
    return {
        "holding_seed_nm": seed,
        "holding_physics_nm": physics,
        "brake_nm": np.where(t.self_locking, 0.0, np.maximum(seed, physics)),
    }


def operating_point(app: Application, t: CandidateTable) -> Quantities[Array]:
    """Every number of ``app`` for every candidate of ``t``, as arrays."""
    force_n = axial_load(app)
    rpm = geometry.screw_speed_rpm(app.speed_m_s, t.lead_m)
    values = {
        "force_n": np.full(len(t), force_n),
        "rpm": rpm,
        **_torques(app, t, force_n),
        **_column_limits(app, t, force_n),
        **_nut(app, t, force_n, rpm),
        **_duty(app, t),
        **_holding(t, force_n),
    }
    return Quantities(**{k: np.asarray(v, dtype=np.float64) for k, v in values.items()})
