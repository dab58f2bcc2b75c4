"""The formula behind each reported quantity: text, the core function, and the source.

Served with every result (``formulas`` in the API, the detail view on the page), so each
number can be traced to its formula and from there to the catalog values and provenance.
Each entry names the core function that computes the number; the text and source are the
ones declared on that function (``app.core.formulas.declare``), or given here where one
function computes several numbers (the operating point, the move) or a variant of its
formula (the running back-drive efficiency, a margin).
"""

from collections.abc import Callable
from typing import Any, TypedDict

from app.contract.units import api_value
from app.core import motion, quantities
from app.core.checks import REGISTRY
from app.core.formulas import (
    accuracy,
    buckling,
    critical_speed,
    efficiency,
    geometry,
    life,
    limits,
    profile,
    pv,
    torque,
)
from app.core.formulas.declare import SEED, SHIGLEY, formula_of


class Formula(TypedDict):
    formula: str
    function: str
    source: str


def _entry(
    function: Callable[..., Any], text: str | None = None, source: str | None = None
) -> Formula:
    """The function's declared formula and source, or the ``text`` and ``source`` given."""
    if text is None or source is None:
        declared = formula_of(function)
        text, source = text or declared.text, source or declared.source
    return {
        "formula": text,
        "function": f"{function.__module__}.{function.__qualname__}",
        "source": source,
    }


FORMULAS: dict[str, Formula] = {
    "pitch_diameter_mm": _entry(geometry.pitch_diameter),
    "lead_angle_deg": _entry(geometry.lead_angle),
    "rpm": _entry(geometry.screw_speed_rpm),
    "axial_load_n": _entry(quantities.axial_load),
    "peak_axial_load_n": _entry(quantities.peak_axial_load),
    "efficiency": _entry(efficiency.forward_efficiency),
    "efficiency_square_thread": _entry(efficiency.square_thread_efficiency),
    "backdrive_efficiency": _entry(efficiency.backdrive_efficiency),
    "self_locking": _entry(efficiency.is_self_locking),
    "seed_rule_no_backdrive": _entry(efficiency.seed_backdrive_rule),
    "backdrive_efficiency_running": _entry(
        efficiency.backdrive_efficiency, "eta_b at the running (dynamic) friction"
    ),
    "self_locking_with_margin": _entry(efficiency.self_locking_limit_friction),
    "max_self_locking_lead_with_margin_mm": _entry(
        efficiency.max_self_locking_lead, "lead = pi d_p f mu_s / cos a_n"
    ),
    "max_self_locking_lead_mm": _entry(
        efficiency.max_self_locking_lead, "lead = pi d_p mu_s / cos a_n"
    ),
    "holding_torque.seed_method_nm": _entry(
        efficiency.holding_torque, "T_b = F lead eta / (2 pi), forward eta"
    ),
    "holding_torque.physics_nm": _entry(
        efficiency.holding_torque, "T_b = F lead eta_b / (2 pi), back-drive eta", SHIGLEY
    ),
    "holding_torque.brake_nm": _entry(
        quantities.operating_point,
        "T = max(seed method, physics); 0 when self-locking with the friction margin",
        "safe side of both",
    ),
    "torque.inertia_screw_nm": _entry(torque.inertia_torque),
    "torque.inertia_mass_nm": _entry(
        torque.load_torque,
        "T = m a lead / (2 pi eta): the accelerating force through the thread",
        SEED + " (Torque To Move Load) with the force m a",
    ),
    "torque.inertia_motor_nm": _entry(
        torque.inertia_torque,
        "T = J_motor alpha: the rotor's inertia times the screw's angular acceleration",
        SEED + " (Inertia Torque T = I alpha) with the rotor's I",
    ),
    "torque.inertia_nm": _entry(
        quantities.operating_point,
        "T = T_inertia_screw + T_inertia_mass + T_inertia_motor",
        SEED,
    ),
    "torque.peak_nm": _entry(motion.segments, "T = max |T_segment| over the cycle", "move profile"),
    "torque.peak_motor_nm": _entry(
        quantities.operating_point,
        "T = max(|T_segment| over the moving segments of both moves, T_breakaway)",
        "move profile",
    ),
    "torque.rms_nm": _entry(profile.rms_torque),
    "profile.peak_speed_mm_s": _entry(profile.peak_speed),
    "profile.accel_time_s": _entry(profile.ramp_time),
    "profile.decel_time_s": _entry(profile.ramp_time, "t_d = v_peak / d"),
    "profile.constant_time_s": _entry(profile.constant_time),
    "profile.move_time_s": _entry(motion.move_profile, "t = t_a + t_c + t_d", "kinematics"),
    "profile.cycle_time_s": _entry(
        motion.move_profile, "t = 2 (move + dwell), out and back", "kinematics"
    ),
    "segments.duration_s": _entry(
        motion.move_profile,
        "t_a, t_c, t_d of the profile for the moving segments; the dwell as given",
        "kinematics",
    ),
    "segments.rpm": _entry(
        geometry.screw_speed_rpm, "n = 60 v_peak / lead while moving (its top speed); 0 in a dwell"
    ),
    "segments.thrust_n": _entry(
        motion.segments,
        "F = s F_steady + m a, a = +a, 0, -d along the motion; F_steady = load (+ m g "
        "when vertical), s = +1 out, back and up, -1 down; in a dwell F_steady when vertical",
        "statics and Newton's second law",
    ),
    "segments.torque_nm": _entry(
        profile.thread_torque,
        "T = F lead / (2 pi eta) if F >= 0 else F lead eta_b / (2 pi), + T_drag "
        "+ (J_screw + J_rotor) alpha; in a dwell the holding torque when vertical, else 0",
    ),
    "torque.drag_nm": _entry(
        quantities.operating_point,
        "top of the series' static drag range",
        SEED + " (Static Frictional Torque)",
    ),
    "torque.load_nm": _entry(torque.load_torque),
    "torque.total_nm": _entry(torque.total_torque),
    "torque.breakaway_nm": _entry(
        torque.load_torque,
        "T = (F + m a) lead / (2 pi eta_static) + J_screw alpha + T_drag, starting from rest",
        SEED + " with static friction",
    ),
    "torque.required_nm": _entry(
        quantities.operating_point, "T = SF x max(T_total, T_breakaway)", "user torque margin"
    ),
    "critical_speed.theoretical_rpm": _entry(critical_speed.critical_speed_rpm),
    "critical_speed.margin": _entry(critical_speed.speed_margin),
    "critical_speed.allowed_rpm": _entry(critical_speed.allowed_speed_rpm),
    "buckling.critical_load_n": _entry(buckling.column_critical_load),
    "buckling.slenderness": _entry(buckling.slenderness),
    "buckling.transition_slenderness": _entry(buckling.transition_slenderness),
    "buckling.root_stress_mpa": _entry(buckling.root_von_mises_stress),
    "buckling.allowed_load_n": _entry(buckling.allowed_buckling_load),
    "pv.value_mpa_m_s": _entry(pv.pv_value),
    "pv.pressure_mpa": _entry(pv.contact_pressure),
    "pv.surface_speed_m_s": _entry(pv.surface_speed),
    "pv.max_load_n": _entry(pv.max_load_for_pv),
    "pv.max_speed_mm_s": _entry(pv.max_rpm_for_pv),
    "traverse_speed_limit_mm_s": _entry(limits.band_limit),
    "life.years": _entry(life.life_years),
    "accuracy.lead_error_mm": _entry(accuracy.cumulative_lead_error),
    "accuracy.thermal_growth_mm": _entry(accuracy.thermal_growth),
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


#: Every check the selection runs, in registry order, as the API lists it: what it
#: means, its formula, its source, the catalog values it reads and its API unit.
CHECKS_OUT: dict[str, Any] = {
    "checks": [
        {
            "name": c.name,
            "label": c.label,
            "kind": c.kind,
            "description": c.description,
            "formula": c.formula,
            "source": c.source,
            "sources": list(c.sources),
            "unit": api_value(0.0, c.quantity)[1],
        }
        for c in REGISTRY
    ]
}
