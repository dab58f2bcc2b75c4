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
from app.catalog.own import (
    NutMaterial,
    OwnGeometry,
    UnknownNutMaterial,
    own_screw,
    user_material,
)
from app.contract.fields import FIELDS
from app.contract.outputs import ChangeOut, CountsOut, RemedyOut, SummaryOut
from app.contract.schemas import CandidateOut
from app.contract.screws import CustomScrewIn, MaterialIn
from app.contract.source import Writer
from app.contract.units import DEFAULT_UNITS, api_to_si, render
from app.core.model import Provenance, ScrewSpec
from app.core.phrase import Quantity
from app.core.record import Candidate
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
    the passing candidates in the ``summary`` view, the rejected in the ``rejected`` one."""
    return {
        "candidates": [candidate_json(c, "summary") for c in sel.candidates],
        "rejected": [candidate_json(c, "rejected") for c in sel.rejected],
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


def custom_screw(
    data: CustomScrewIn,
    materials: Mapping[str, Material],
    nuts: Mapping[str, NutMaterial] | None = None,
) -> ScrewSpec:
    """A ScrewSpec from a validated ``CustomScrewIn`` (``app.catalog.own``): named screw
    materials from the catalog, the user's own with the thermal expansion of steel, and
    the catalog's nut material by name (``nuts``; UnknownNutMaterial for a name it lacks)."""
    if isinstance(data.material, MaterialIn):
        own = data.material
        material = user_material(
            own.youngs_modulus_pa, own.density_kg_m3, own.yield_strength_pa, materials["steel"]
        )
        material_name = "custom"
    else:
        material, material_name = materials[data.material], data.material
    nut = None
    if data.nut_material is not None:
        nut = (nuts or {}).get(data.nut_material)
        if nut is None:
            known = ", ".join(nuts or {}) or "none"
            raise UnknownNutMaterial(f"unknown nut material '{data.nut_material}' (known: {known})")
    geometry = OwnGeometry(
        outer_diameter_m=api_to_si(data.outer_diameter_mm, "length"),
        root_diameter_m=api_to_si(data.root_diameter_mm, "length"),
        lead_m=api_to_si(data.lead_mm, "length"),
        thread_half_angle_rad=math.radians(data.thread_half_angle_deg),
        friction_static=data.friction_static,
        friction_dynamic=data.friction_dynamic,
        drag_torque_nm=data.drag_torque_nm,
        pv_limit_pa_m_s=_si_or_none(data.pv_limit_mpa_m_s, "pv"),
        inertia_kg_m2_per_m=data.inertia_kg_m2_per_m,
        pitch_m=_si_or_none(data.pitch_mm, "length"),
    )
    return own_screw(geometry, material, material_name, nut)


def _si_or_none(value: float | None, quantity: Quantity) -> float | None:
    return None if value is None else api_to_si(value, quantity)
