"""Core results as the API's typed output models; the same objects feed the templates,
the figures and the CSV export."""

import math
from collections.abc import Mapping
from collections.abc import Mapping as Units
from functools import lru_cache
from typing import Any

from app.catalog import Material, Series
from app.construct import construct
from app.core.brief import Brief
from app.core.formulas import torque
from app.core.model import CheckResult, Evaluation, Provenance, ScrewSpec, failed_advice
from app.core.selection import Selection, short_forms
from app.fields import FIELDS
from app.schemas import (
    AccuracyOut,
    BucklingOut,
    CandidateOut,
    CandidateRowOut,
    ChangeOut,
    CheckOut,
    CountsOut,
    CriticalSpeedOut,
    CustomScrewIn,
    FailedCheckOut,
    HoldingTorqueOut,
    LifeOut,
    MaterialIn,
    OutgassingOut,
    ProfileOut,
    ProvenanceOut,
    PVOut,
    RejectedSummaryOut,
    SegmentOut,
    SummaryOut,
    TorqueOut,
)
from app.units import DEFAULT_UNITS, api_value, render

BY_CORE = {field.core: field for field in FIELDS}
#: Catalog fields behind the geometry, efficiency and torque of every candidate.
GEOMETRY_SOURCES = (
    "outer_diameter",
    "root_diameter",
    "lead",
    "friction_dynamic",
    "friction_static",
    "thread_half_angle",
    "inertia_per_length",
    "drag_torque",
)
TORQUE_NOTE = (
    "Torque of the screw assembly alone; bearings, motor shaft, moving parts and "
    "misalignment are extra (seed). The torque safety factor covers them: 1.0 by default, "
    "1.3 to 2 is common at the planning stage."
)
LIFE_NOTE = (
    "Life varies with load, environment and duty cycle; longer leads generally last longer (seed)."
)


def _mm(x_m: float) -> float:
    return x_m * 1e3


def _prov(p: Provenance) -> dict[str, str]:
    return {"kind": p.kind, "source": p.source}


def check_out(check: CheckResult, units: Units[str, str] = DEFAULT_UNITS) -> CheckOut:
    """A check in API units; its sentences in ``units`` (the API's by default)."""
    _, unit = api_value(0.0, check.quantity)
    return construct(
        CheckOut,
        name=check.name,
        label=check.label,
        kind=check.kind,
        passed=check.passed,
        value=None if check.value is None else api_value(check.value, check.quantity)[0],
        limit=None if check.limit is None else api_value(check.limit, check.quantity)[0],
        unit=unit,
        utilization=check.utilization,
        message=render(check.message, units),
        formula=check.formula,
        sources=list(check.sources),
        fix=None if check.fix is None else render(check.fix, units),
    )


def _torque(ev: Evaluation) -> TorqueOut:
    t = ev.torque
    return construct(
        TorqueOut,
        inertia_nm=t.inertia_nm,
        inertia_screw_nm=t.inertia_screw_nm,
        inertia_mass_nm=t.inertia_mass_nm,
        drag_nm=t.drag_nm,
        drag_range_nm=[t.drag_min_nm, t.drag_max_nm],
        load_nm=t.load_nm,
        total_nm=t.total_nm,
        breakaway_nm=t.breakaway_nm,
        safety_factor=t.safety_factor,
        required_nm=t.required_nm,
        note=TORQUE_NOTE,
        peak_nm=None if ev.motion is None else ev.motion.peak_nm,
        rms_nm=None if ev.motion is None else ev.motion.rms_nm,
    )


def _motion(ev: Evaluation) -> dict[str, Any]:
    """The move's profile and segments (null without a stroke)."""
    if ev.motion is None:
        return {"profile": None, "segments": None}
    p = ev.motion.profile
    return {
        "profile": construct(
            ProfileOut,
            kind=p.kind,
            accel_time_s=p.accel_time_s,
            constant_time_s=p.constant_time_s,
            decel_time_s=p.decel_time_s,
            move_time_s=p.move_time_s,
            cycle_time_s=p.cycle_time_s,
            peak_speed_mm_s=_mm(p.peak_speed_m_s),
        ),
        "segments": [
            construct(
                SegmentOut,
                name=g.name,
                direction=g.direction,
                duration_s=g.duration_s,
                rpm=g.rpm,
                thrust_n=g.thrust_n,
                torque_nm=g.torque_nm,
            )
            for g in ev.motion.segments
        ],
    }


def _pv(ev: Evaluation) -> PVOut:
    pv = ev.pv
    return construct(
        PVOut,
        value_mpa_m_s=pv.value_pa_m_s / 1e6,
        limit_mpa_m_s=None if pv.limit_pa_m_s is None else pv.limit_pa_m_s / 1e6,
        pressure_mpa=pv.pressure_pa / 1e6,
        surface_speed_m_s=pv.surface_speed_m_s,
        max_load_n=pv.max_load_n,
        max_speed_mm_s=None if pv.max_speed_m_s is None else _mm(pv.max_speed_m_s),
    )


def _life(ev: Evaluation) -> LifeOut | None:
    life = ev.life
    if life is None:
        return None
    low, high = life.years_min, life.years_max
    return construct(
        LifeOut,
        travel_million_cm=[life.travel_min_m / 1e4, life.travel_max_m / 1e4],
        years=[low, high] if low is not None and high is not None else None,
        note=LIFE_NOTE,
    )


def _accuracy(ev: Evaluation) -> AccuracyOut:
    acc = ev.accuracy

    def mm(x: float | None) -> float | None:
        return None if x is None else _mm(x)

    return construct(
        AccuracyOut,
        lead_error_mm=mm(acc.lead_error_m),
        repeatability_mm=mm(acc.repeatability_m),
        backlash_mm=[_mm(acc.backlash_min_m), _mm(acc.backlash_max_m)],
        thermal_growth_mm=mm(acc.thermal_growth_m),
    )


def _critical_speed(ev: Evaluation) -> CriticalSpeedOut:
    c = ev.critical_speed
    return construct(
        CriticalSpeedOut,
        theoretical_rpm=c.theoretical_rpm,
        allowed_rpm=c.allowed_rpm,
        margin=c.margin,
        safety_factor=c.safety_factor,
        end_fixity=c.end_fixity,
    )


def _buckling(ev: Evaluation) -> BucklingOut:
    b = ev.buckling
    return construct(
        BucklingOut,
        applies=b.applies,
        critical_load_n=b.critical_load_n,
        allowed_load_n=b.allowed_load_n,
        safety_factor=b.safety_factor,
        slenderness=b.slenderness,
        transition_slenderness=b.transition_slenderness,
        mode=b.mode,
        root_stress_mpa=b.root_stress_pa / 1e6,
        yield_strength_mpa=None if b.yield_strength_pa is None else b.yield_strength_pa / 1e6,
    )


def _shown(ev: Evaluation, available_nm: float | None) -> dict[str, Any]:
    """What every form of a candidate shows (``CandidateBaseOut``), API units."""
    s = ev.screw
    return {
        "id": s.id,
        "series": s.series_id,
        "series_name": s.series_name,
        "anti_backlash": s.anti_backlash,
        "outer_diameter_mm": _mm(s.outer_diameter_m),
        "lead_mm": _mm(s.lead_m),
        "coated": s.coated,
        "axial_load_n": ev.axial_load_n,
        "rpm": ev.rpm,
        "efficiency": ev.efficiency,
        "self_locking": ev.self_locking,
        "seed_rule_no_backdrive": ev.seed_rule_no_backdrive,
        "max_self_locking_lead_with_margin_mm": _mm(ev.max_self_locking_lead_with_margin_m),
        "holding_torque": construct(
            HoldingTorqueOut,
            seed_method_nm=ev.holding_torque_seed_nm,
            physics_nm=ev.holding_torque_physics_nm,
            brake_nm=ev.brake_torque_nm,
            available_nm=available_nm,
        ),
        "torque": _torque(ev),
        "critical_speed": _critical_speed(ev),
        "pv": _pv(ev),
        "life": _life(ev),
        "governing_check": ev.governing_check,
        "governing_limit_provenance": ev.governing_limit_provenance,
        "passed": ev.passed,
        "robust": ev.robust,
        "hinges_on": list(ev.hinges_on),
        **_motion(ev),
    }


@lru_cache(maxsize=8192)
def provenance_out(p: Provenance) -> ProvenanceOut:
    """A catalog value's provenance as its output model: the same few hundred for every
    response, so built once each (output models are never changed once built)."""
    return construct(ProvenanceOut, kind=p.kind, source=p.source)


def candidate_out(
    ev: Evaluation,
    vacuum: bool = False,
    units: Units[str, str] = DEFAULT_UNITS,
    brake_nm: float | None = None,
) -> CandidateOut:
    """One evaluated screw in API units (mm, mm/s, N, N m, MPa m/s); sentences in ``units``."""
    s = ev.screw
    checks = [check_out(c, units) for c in ev.checks]
    fixes = [c.fix for c in checks if c.fix]
    used = {src for c in ev.checks for src in c.sources} | set(GEOMETRY_SOURCES)
    outgassing = [construct(OutgassingOut, hours=h, weight_loss_percent=w) for h, w in s.outgassing]
    traverse = ev.traverse_speed_limit_m_s
    return construct(
        CandidateOut,
        **_shown(ev, brake_nm),
        root_diameter_mm=_mm(s.root_diameter_m),
        pitch_diameter_mm=_mm(ev.pitch_diameter_m),
        lead_angle_deg=math.degrees(ev.lead_angle_rad),
        peak_axial_load_n=ev.peak_axial_load_n,
        efficiency_square_thread=ev.efficiency_square_thread,
        backdrive_efficiency=ev.backdrive_efficiency,
        backdrive_efficiency_running=ev.backdrive_efficiency_running,
        self_locking_with_margin=ev.self_locking_with_margin,
        max_self_locking_lead_mm=_mm(ev.max_self_locking_lead_m),
        buckling=_buckling(ev),
        traverse_speed_limit_mm_s=None if traverse is None else _mm(traverse),
        traverse_extrapolated=ev.traverse_extrapolated,
        accuracy=_accuracy(ev),
        outgassing=outgassing if vacuum else None,
        checks=checks,
        warnings=failed_advice(checks),
        fix=" ".join(fixes) if fixes else None,
        provenance={k: provenance_out(p) for k, p in s.provenance.items() if k in used},
    )


def candidate_row(ev: Evaluation, brake_nm: float | None = None) -> CandidateRowOut:
    """One evaluated screw as a row of the results table (``CandidateRowOut``): what every
    form shows, and each check's utilisation instead of its sentences."""
    return construct(
        CandidateRowOut,
        **_shown(ev, brake_nm),
        utilization={c.name: c.utilization for c in ev.checks},
        warned=[c.name for c in ev.warnings],
    )


def candidate_summary(b: Brief) -> dict[str, Any]:
    """A passing candidate in the compact form (``CandidateSummaryOut``), API units."""
    s = b.screw
    return {
        "id": s.id,
        "series": s.series_id,
        "series_name": s.series_name,
        "anti_backlash": s.anti_backlash,
        "coated": s.coated,
        "outer_diameter_mm": _mm(s.outer_diameter_m),
        "lead_mm": _mm(s.lead_m),
        "rpm": b.rpm,
        "total_torque_nm": b.total_torque_nm,
        "efficiency": b.efficiency,
        "self_locking": b.self_locking,
        "critical_speed_margin": b.critical_speed_margin,
        "life_years": None if b.life_years is None else list(b.life_years),
        "utilization": {c.name: c.utilization for c in b.checks},
        "governing_check": b.governing_check,
        "governing_limit_provenance": b.governing_limit_provenance,
        "passed": b.passed,
        "robust": b.robust,
        "hinges_on": list(b.hinges_on),
        "warnings": [c.name for c in failed_advice(b.checks)],
    }


def rejected_summary(b: Brief, units: Units[str, str] = DEFAULT_UNITS) -> dict[str, Any]:
    """A rejected candidate in the compact form (``RejectedSummaryOut``): its failed
    checks with their utilisation and fix, and the fixes joined as in the full form."""
    failed, fixes = [], []
    for c in b.checks:
        if not c.passed:
            fix = c.fix
            text = None if fix is None else render(fix, units)
            failed.append(
                {"name": c.name, "kind": c.kind, "utilization": c.utilization, "fix": text}
            )
            fixes += [text] if text else []
    return {
        "id": b.screw.id,
        "governing_check": b.governing_check,
        "failed": failed,
        "fix": " ".join(fixes) if fixes else None,
    }


def rejected_out(b: Brief, units: Units[str, str] = DEFAULT_UNITS) -> RejectedSummaryOut:
    """``rejected_summary`` as its output model (for templates, which read attributes)."""
    row = rejected_summary(b, units)
    failed = [construct(FailedCheckOut, **f) for f in row.pop("failed")]
    return construct(RejectedSummaryOut, **row, failed=failed)


def selection_summary(sel: Selection, units: Units[str, str] = DEFAULT_UNITS) -> dict[str, Any]:
    """Candidates, rejected, counts and summary in the compact form (``SelectSummaryOut``)."""
    passing, rejected = short_forms(sel)
    return {
        "candidates": [candidate_summary(b) for b in passing],
        "rejected": [rejected_summary(b, units) for b in rejected],
        **counts_and_summary(sel, units),
    }


def selection_out(sel: Selection, units: Units[str, str] = DEFAULT_UNITS) -> dict[str, Any]:
    """Candidates, rejected, counts and summary of a selection in full (the rest of
    SelectOut is the caller's: inputs, links, catalog version)."""
    app = sel.application
    vacuum, brake = app.vacuum, app.brake_torque_nm
    return {
        "candidates": [candidate_out(e, vacuum, units, brake) for e in sel.candidates],
        "rejected": [candidate_out(e, vacuum, units, brake) for e in sel.rejected],
        **counts_and_summary(sel, units),
    }


def counts_and_summary(sel: Selection, units: Units[str, str]) -> dict[str, Any]:
    """The counts and the summary of a selection, shared by the compact and full forms."""
    return {
        "counts": construct(
            CountsOut,
            evaluated=sel.evaluated,
            passed=sel.passed,
            rejected=sel.evaluated - sel.passed,
            failed_by_check=dict(sel.failed_by_check),
        ),
        "summary": construct(
            SummaryOut,
            message=render(sel.summary.message, units),
            most_excluding_check=sel.summary.most_excluding_check,
            best_rejected_id=sel.summary.best_rejected_id,
            input_change=_api_change(sel.summary.input_change),
            changes=[
                construct(ChangeOut, inputs=_api_change(c.inputs), admits=c.admits)
                for c in sel.summary.changes
            ],
        ),
    }


def _api_change(change: Mapping[str, float]) -> dict[str, float]:
    """Core input names and SI values as the API's names and units (the field table)."""
    return {BY_CORE[k].api: v / BY_CORE[k].si_factor for k, v in change.items()}


def _jsonable(value: Any) -> Any:
    if isinstance(value, tuple):
        return [_jsonable(v) for v in value]
    return value


def series_dict(series: Series) -> dict[str, Any]:
    return {
        "id": series.id,
        "name": series.name,
        "family": series.family,
        "family_name": series.family_name,
        "type": series.type,
        "file": series.file,
        "fields": {
            k: {"value": _jsonable(v.value), "unit": v.unit, "provenance": _prov(v.provenance)}
            for k, v in series.fields.items()
        },
        "candidate_ids": [s.id for s in series.screws],
    }


def custom_screw(data: CustomScrewIn, materials: Mapping[str, Material]) -> ScrewSpec:
    """A ScrewSpec from a validated ``CustomScrewIn``; named materials from the catalog."""
    user = Provenance("user", "given in the request")
    yield_prov: Provenance | None = user
    if isinstance(data.material, MaterialIn):
        e, rho = data.material.youngs_modulus_pa, data.material.density_kg_m3
        alpha = materials["steel"].expansion_per_k.value
        yield_pa = data.material.yield_strength_pa
        material_name = "custom"
        e_prov = rho_prov = user
    else:
        material = materials[data.material]
        e, rho = material.youngs_modulus_pa.value, material.density_kg_m3.value
        alpha = material.expansion_per_k.value
        strength = material.yield_strength_pa
        yield_pa = None if strength is None else strength.value
        yield_prov = None if strength is None else strength.provenance
        material_name = data.material
        e_prov, rho_prov = material.youngs_modulus_pa.provenance, material.density_kg_m3.provenance
    rd = data.root_diameter_mm * 1e-3
    inertia = data.inertia_kg_m2_per_m
    if inertia is None:
        inertia = torque.solid_rod_inertia_per_length(rho, rd)
        inertia_prov = Provenance("derived", "solid rod at the root diameter: rho pi d_r^4 / 32")
    else:
        inertia_prov = user
    return ScrewSpec(
        id="custom",
        series_id="custom",
        series_name="Custom screw",
        anti_backlash=False,
        coated=False,
        outer_diameter_m=data.outer_diameter_mm * 1e-3,
        root_diameter_m=rd,
        lead_m=data.lead_mm * 1e-3,
        thread_half_angle_rad=math.radians(data.thread_half_angle_deg),
        friction_static=data.friction_static,
        friction_dynamic=data.friction_dynamic,
        youngs_modulus_pa=e,
        density_kg_m3=rho,
        screw_expansion_per_k=alpha,
        inertia_kg_m2_per_m=inertia,
        drag_torque_min_nm=data.drag_torque_nm,
        drag_torque_max_nm=data.drag_torque_nm,
        pv_limit_pa_m_s=None if data.pv_limit_mpa_m_s is None else data.pv_limit_mpa_m_s * 1e6,
        material_name=material_name,
        yield_strength_pa=yield_pa,
        provenance={
            **({"yield_strength": yield_prov} if yield_pa is not None and yield_prov else {}),
            **dict.fromkeys(GEOMETRY_SOURCES, user),
            "pv_limit": user,
            "inertia_per_length": inertia_prov,
            "youngs_modulus": e_prov,
            "density": rho_prov,
        },
    )
