"""Evaluate one screw, or one screened candidate: every number, every check, every fix."""

import math
from collections.abc import Sequence
from functools import partial
from typing import Any

import numpy as np

from app.core import motion
from app.core.brief import (
    CheckRow,
    check_rows,
    governing,
    limit_provenance,
    number,
    positions_array,
)
from app.core.checks import BY_NAME
from app.core.checks.base import Check, Reach
from app.core.formulas import critical_speed
from app.core.model import (
    PV,
    Accuracy,
    Application,
    Buckling,
    CheckResult,
    CriticalSpeed,
    Evaluation,
    Life,
    Motion,
    ScrewSpec,
    Segment,
    Torque,
)
from app.core.quantities import Quantities, axial_load
from app.core.robustness import Robustness
from app.core.screening import Screening, screen_table
from app.core.table import CandidateTable

__all__ = ["axial_load", "evaluate", "evaluations"]


def _result(
    check: Check,
    row: CheckRow,
    app: Application,
    s: ScrewSpec,
    r: Quantities[float],
    reach: Reach,
) -> CheckResult:
    """One check of one candidate; its explanation and fix are written when read."""
    _, demand, capacity, utilization, failed = row
    value, limit = number(demand), number(capacity)
    numeric = value is not None and limit is not None
    return CheckResult(
        name=check.name,
        label=check.label,
        kind=check.kind,
        passed=not failed,
        value=value if numeric else None,
        limit=limit if numeric else None,
        quantity=check.quantity if numeric else None,
        utilization=utilization,
        formula=check.formula,
        sources=check.sources,
        explanation=partial(check.explain, app, s, r, not failed),
        remedy=partial(check.fix, app, s, r, reach),
        remedy_inputs=partial(check.input_limits, app, s, r),
    )


def _torque(app: Application, s: ScrewSpec, r: Quantities[float]) -> Torque:
    return Torque(
        inertia_screw_nm=r.inertia_screw_nm,
        inertia_mass_nm=r.inertia_mass_nm,
        inertia_nm=r.inertia_nm,
        drag_nm=r.drag_nm,
        drag_min_nm=s.drag_torque_min_nm,
        drag_max_nm=s.drag_torque_max_nm,
        load_nm=r.load_nm,
        total_nm=r.total_nm,
        breakaway_nm=r.breakaway_nm,
        safety_factor=app.torque_safety_factor,
        required_nm=r.required_nm,
        angular_accel_rad_s2=r.angular_accel_rad_s2,
        inertia_kg_m2=r.inertia_kg_m2,
    )


def _pv(s: ScrewSpec, r: Quantities[float]) -> PV:
    given = s.pv_limit_pa_m_s is not None
    return PV(
        value_pa_m_s=r.pv_pa_m_s,
        limit_pa_m_s=s.pv_limit_pa_m_s,
        pressure_pa=r.pressure_pa,
        surface_speed_m_s=r.surface_speed_m_s,
        contact_area_m2=r.contact_area_m2,
        max_load_n=r.pv_max_load_n if given else None,
        max_speed_m_s=r.pv_max_speed_m_s if given else None,
    )


def _life(s: ScrewSpec, r: Quantities[float]) -> Life | None:
    if s.life_min_m is None or s.life_max_m is None:
        return None
    return Life(s.life_min_m, s.life_max_m, number(r.life_years_min), number(r.life_years_max))


def _accuracy(s: ScrewSpec, r: Quantities[float]) -> Accuracy:
    return Accuracy(
        lead_error_m=number(r.lead_error_m),
        repeatability_m=s.repeatability_m,
        backlash_min_m=s.backlash_min_m,
        backlash_max_m=s.backlash_max_m,
        thermal_growth_m=r.thermal_growth_m,
    )


#: Axis-independent numbers of the thread that every evaluation reports.
THREAD_COLUMNS = (
    "pitch_diameter_m",
    "lead_angle_rad",
    "efficiency",
    "efficiency_square_thread",
    "backdrive_efficiency",
    "self_locking",
    "seed_rule_no_backdrive",
    "max_self_locking_lead_m",
    "traverse_limit_m_s",
    "traverse_extrapolated",
    "backdrive_efficiency_running",
)


def evaluations(
    app: Application,
    sc: Screening,
    positions: Sequence[int],
    judged: Sequence[Robustness] | None = None,
) -> list[Evaluation]:
    """The candidates at ``positions`` of a screening (in ``sc.table``) with every check;
    ``judged`` gives each one's robustness when it is known.

    Reads the screening's arrays once for the whole batch; computes nothing again.
    """
    index = [int(i) for i in positions]
    if not index:
        return []
    at = positions_array(index)
    rows = sc.quantities.rows(at)
    thread = {name: getattr(sc.table, name)[at].tolist() for name in THREAD_COLUMNS}
    checks = {name: check_rows(sc, name, at) for name in sc.measures}
    worst = sc.max_utilization[at].tolist()
    moves = _motions(app, sc, index, rows)
    passed = sc.passed[at].tolist()
    results = [
        tuple(
            _result(BY_NAME[name], column[k], app, sc.table.screws[i], rows[k], sc.reach)
            for name, column in checks.items()
            if column[k][0]
        )
        for k, i in enumerate(index)
    ]
    return [
        _evaluation(
            app,
            sc.table.screws[i],
            rows[k],
            {name: column[k] for name, column in thread.items()},
            results[k],
            (passed[k], worst[k]),
            moves[k],
            None if judged is None else judged[k],
        )
        for k, i in enumerate(index)
    ]


def _motions(
    app: Application, sc: Screening, index: list[int], rows: list[Quantities[float]]
) -> list[Motion | None]:
    """The move and its segments' torques for the candidates at ``index`` (None each
    without a stroke)."""
    p = motion.move_profile(app)
    if p is None:
        return [None] * len(index)
    hold = np.array([r.brake_nm for r in rows])
    parts = motion.segments(app, p, sc.table.take(np.array(index)), hold)
    columns = [(s, s.rpm.tolist(), s.thrust_n.tolist(), s.torque_nm.tolist()) for s in parts]
    return [
        Motion(
            profile=p,
            segments=tuple(
                Segment(s.name, s.direction, s.duration_s, rpm[k], thrust[k], torque[k])
                for s, rpm, thrust, torque in columns
            ),
            peak_nm=r.motor_peak_nm,
            rms_nm=r.motor_rms_nm,
        )
        for k, r in enumerate(rows)
    ]


def _evaluation(
    app: Application,
    s: ScrewSpec,
    r: Quantities[float],
    thread: dict[str, Any],
    checks: tuple[CheckResult, ...],
    verdict: tuple[bool, float],
    move: Motion | None = None,
    judged: Robustness | None = None,
) -> Evaluation:
    """One candidate's report; ``verdict`` is (passed, worst utilisation) from screening,
    ``judged`` its robustness when known."""
    traverse = number(thread["traverse_limit_m_s"])
    top = governing(app, checks)
    return Evaluation(
        screw=s,
        axial_load_n=r.force_n,
        peak_axial_load_n=r.peak_force_n,
        rpm=r.rpm,
        pitch_diameter_m=thread["pitch_diameter_m"],
        lead_angle_rad=thread["lead_angle_rad"],
        efficiency=thread["efficiency"],
        efficiency_square_thread=thread["efficiency_square_thread"],
        backdrive_efficiency=thread["backdrive_efficiency"],
        backdrive_efficiency_running=thread["backdrive_efficiency_running"],
        self_locking=thread["self_locking"],
        self_locking_with_margin=bool(r.locks_with_margin),
        seed_rule_no_backdrive=thread["seed_rule_no_backdrive"],
        max_self_locking_lead_m=thread["max_self_locking_lead_m"],
        max_self_locking_lead_with_margin_m=r.max_lock_lead_m,
        holding_torque_seed_nm=r.holding_seed_nm,
        holding_torque_physics_nm=r.holding_physics_nm,
        brake_torque_nm=r.brake_nm,
        torque=_torque(app, s, r),
        critical_speed=CriticalSpeed(
            r.critical_rpm,
            r.allowed_rpm,
            critical_speed.speed_margin(r.allowed_rpm, r.rpm),
            app.critical_speed_safety_factor,
            app.end_fixity,
        ),
        buckling=_buckling(app, s, r),
        pv=_pv(s, r),
        traverse_speed_limit_m_s=traverse,
        traverse_extrapolated=traverse is not None and thread["traverse_extrapolated"],
        life=_life(s, r),
        accuracy=_accuracy(s, r),
        checks=checks,
        passed=verdict[0],
        governing_check=None if top is None else top.name,
        governing_limit_provenance=limit_provenance(top, s),
        max_utilization=verdict[1],
        motion=move,
        robust=None if judged is None else judged.robust,
        hinges_on=() if judged is None else judged.hinges_on,
    )


def _buckling(app: Application, s: ScrewSpec, r: Quantities[float]) -> Buckling:
    transition = number(r.transition_slenderness)
    short = transition is not None and r.slenderness < transition
    return Buckling(
        applies=r.compressive_force_n > 0.0,
        critical_load_n=r.critical_load_n,
        allowed_load_n=r.allowed_load_n,
        safety_factor=app.buckling_safety_factor,
        slenderness=r.slenderness,
        transition_slenderness=transition,
        mode="johnson" if short else "euler",
        root_stress_pa=r.root_stress_pa,
        yield_strength_pa=s.yield_strength_pa,
    )


def evaluate(
    app: Application, screw: ScrewSpec | CandidateTable, reach: Reach | None = None
) -> Evaluation:
    """Compute torque, speeds, loads, PV, life, accuracy and all checks for one screw, or
    for the one screw of a table (a catalog's row, ``CatalogIndex.row``); ``reach`` is
    what the catalog offers, for the fixes (unbounded by default)."""
    table = screw if isinstance(screw, CandidateTable) else CandidateTable.build([screw])
    screw = table.screws[0]
    if min(table.efficiency[0], table.efficiency_static[0]) <= 0.0:
        raise ValueError(
            f"{screw.id}: lead angle {math.degrees(table.lead_angle_rad[0]):.1f} deg is too "
            f"steep to drive against friction {screw.friction_dynamic:g}"
        )
    return evaluations(app, screen_table(app, table, np.arange(1), reach), [0])[0]
