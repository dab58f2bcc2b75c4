"""Core results as the API's typed output models; the same objects feed the templates,
the figures and the CSV export.

A candidate's output (``CandidateOut``) is read from the core's candidate record field by
field, as each field's ``From`` declares (``app.contract.source``), by ``app.report.reader``; a view
(``VIEWS``) reads only its fields, so a compact form never builds the sections it does
not show.
"""

import math
from collections.abc import Mapping
from collections.abc import Mapping as Units
from typing import Any, cast

from app.catalog import Material, Series
from app.contract.fields import FIELDS
from app.contract.outputs import ChangeOut, CountsOut, RemedyOut, SummaryOut
from app.contract.schemas import CandidateOut
from app.contract.screws import CustomScrewIn, MaterialIn
from app.contract.source import Writer
from app.contract.units import DEFAULT_UNITS, api_to_si, render
from app.core.formulas import torque
from app.core.model import Provenance, ScrewSpec
from app.core.record import GEOMETRY_SOURCES, Candidate
from app.core.selection import Selection
from app.report.reader import reader

BY_CORE = {field.core: field for field in FIELDS}


def _prov(p: Provenance) -> dict[str, str]:
    return {"kind": p.kind, "source": p.source}


def candidate_view(c: Candidate, view: str, units: Units[str, str] = DEFAULT_UNITS) -> CandidateOut:
    """One candidate as ``CandidateOut`` holding the fields of ``VIEWS[view]`` alone (in
    API units, sentences in ``units``): what the templates, charts and CSV read."""
    return cast(CandidateOut, reader(CandidateOut, view)(c, c, Writer(units)))


def candidate_json(
    c: Candidate, view: str, units: Units[str, str] = DEFAULT_UNITS
) -> dict[str, Any]:
    """One candidate's ``VIEWS[view]`` as plain JSON values (nested dicts): the compact
    select response, byte for byte what the view's model would serialise."""
    return cast(dict[str, Any], reader(CandidateOut, view, as_dict=True)(c, c, Writer(units)))


def selection_summary(sel: Selection) -> dict[str, Any]:
    """Candidates, rejected, counts and summary in the compact form (``SelectSummaryOut``):
    the passing candidates in the ``summary`` view, the rejected in the ``rejected`` one,
    and the words of each catalog value their verdicts rest on, once."""
    return {
        "candidates": [candidate_json(c, "summary") for c in sel.candidates],
        "rejected": [candidate_json(c, "rejected") for c in sel.rejected],
        "labels": {r.field: r.label for c in sel.candidates for r in c.verdict.rests_on},
        **counts_and_summary(sel, DEFAULT_UNITS),
    }


def selection_out(
    sel: Selection, units: Units[str, str] = DEFAULT_UNITS, view: str = "full"
) -> dict[str, Any]:
    """Candidates, rejected, counts and summary of a selection, the candidates in
    ``VIEWS[view]`` (the rest of SelectOut is the caller's: inputs, links, catalog
    version)."""
    return {
        "candidates": [candidate_view(c, view, units) for c in sel.candidates],
        "rejected": [candidate_view(c, view, units) for c in sel.rejected],
        **counts_and_summary(sel, units),
    }


def counts_and_summary(sel: Selection, units: Units[str, str]) -> dict[str, Any]:
    """The counts and the summary of a selection, shared by the compact and full forms."""
    return {
        "counts": CountsOut.model_construct(
            evaluated=sel.evaluated,
            passed=sel.passed,
            rejected=sel.evaluated - sel.passed,
            failed_by_check=dict(sel.failed_by_check),
        ),
        "summary": SummaryOut.model_construct(
            message=render(sel.summary.message, units),
            most_excluding_check=sel.summary.most_excluding_check,
            best_rejected_id=sel.summary.best_rejected_id,
            input_change=_api_change(sel.summary.input_change),
            changes=[
                ChangeOut.model_construct(inputs=_api_change(c.inputs), admits=c.admits)
                for c in sel.summary.changes
            ],
            remedies=[
                RemedyOut.model_construct(
                    inputs=api_inputs(r.inputs),
                    passing=r.passing,
                    utilization=r.utilization,
                )
                for r in sel.summary.remedies
            ],
            impossible=None
            if sel.summary.impossible is None
            else render(sel.summary.impossible, units),
        ),
    }


def _api_change(change: Mapping[str, float]) -> dict[str, float]:
    """Core input names and SI values as the API's names and units (the field table)."""
    return {BY_CORE[k].api: v / BY_CORE[k].si_factor for k, v in change.items()}


def api_inputs(change: Mapping[str, float | str]) -> dict[str, float | str]:
    """A remedy's inputs as the API's names and units (a word such as a fixity as it is)."""
    return {
        BY_CORE[k].api: v if isinstance(v, str) else v / BY_CORE[k].si_factor
        for k, v in change.items()
    }


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
    rd = api_to_si(data.root_diameter_mm, "length")
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
        outer_diameter_m=api_to_si(data.outer_diameter_mm, "length"),
        root_diameter_m=rd,
        lead_m=api_to_si(data.lead_mm, "length"),
        thread_half_angle_rad=math.radians(data.thread_half_angle_deg),
        friction_static=data.friction_static,
        friction_dynamic=data.friction_dynamic,
        youngs_modulus_pa=e,
        density_kg_m3=rho,
        screw_expansion_per_k=alpha,
        inertia_kg_m2_per_m=inertia,
        drag_torque_min_nm=data.drag_torque_nm,
        drag_torque_max_nm=data.drag_torque_nm,
        pv_limit_pa_m_s=(
            None if data.pv_limit_mpa_m_s is None else api_to_si(data.pv_limit_mpa_m_s, "pv")
        ),
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
