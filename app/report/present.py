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
from app.contract.figures import sig
from app.contract.outputs import ChangeOut, CountsOut, RemedyOut, SummaryOut
from app.contract.schemas import CandidateOut
from app.contract.screw_fields import HALF_ANGLE, SCREW_FIELDS
from app.contract.screws import (
    NUT_API,
    CustomScrewIn,
    NutMaterialOut,
    NutMaterialsOut,
    NutValueOut,
)
from app.contract.sections import ProvenanceOut
from app.contract.source import Writer
from app.contract.units import DEFAULT_UNITS, from_si, render
from app.core.model import Provenance, ScrewSpec
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
    select response, byte for byte what the view's model would serialise of the fields it
    gives (a compact view's numbers to 6 significant figures, its null values left out:
    ``app.contract.schemas.COMPACT_VIEWS``)."""
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


def custom_screw(
    data: CustomScrewIn,
    materials: Mapping[str, Material],
    nuts: Mapping[str, NutMaterial] | None = None,
) -> ScrewSpec:
    """A ScrewSpec from a validated ``CustomScrewIn`` (``app.catalog.own``): named screw
    materials from the catalog, the user's own with the thermal expansion of steel, and
    the catalog's nut material by name (``nuts``; UnknownNutMaterial for a name it lacks)."""
    values = data.model_dump()
    own = values.pop("material")
    if isinstance(own, dict):
        material = user_material(
            own["youngs_modulus_pa"], own["density_kg_m3"], own["yield_strength_pa"],
            materials["steel"], own["expansion_per_k"],
        )  # fmt: skip
        material_name = "custom"
    else:
        material, material_name = materials[own], own
    nut = None
    name = values.pop(NUT_API)
    if name is not None:
        nut = (nuts or {}).get(name)
        if nut is None:
            known = ", ".join(nuts or {}) or "none"
            raise UnknownNutMaterial(f"unknown nut material '{name}' (known: {known})")
    return own_screw(own_geometry(values), material, material_name, nut)


def own_geometry(values: Mapping[str, float | None]) -> OwnGeometry:
    """The screw of ``SCREW_FIELDS``' ``values`` (API units, by API name) in SI: each
    number times its row's factor, the flank half-angle from degrees to radians."""
    si = {f.core: f.to_si(values[f.api]) for f in SCREW_FIELDS}
    si[HALF_ANGLE.core] = math.radians(values[HALF_ANGLE.api] or 0.0)
    return OwnGeometry(**si)


#: A nut material's values as the page lists them: (key of its provenance, label).
NUT_ROWS = (
    ("bearing_pressure", "Allowed contact pressure by sliding speed"),
    ("max_pressure", "Maximum contact pressure"),
    ("bearing_pv_limit", "PV limit over the engaged flanks"),
    ("max_sliding_speed", "Maximum sliding speed"),
    ("dynamic_thrust", "Allowable dynamic thrust by size"),
    ("wear_rate", "Specific wear rate"),
    ("allowed_wear", "Allowed wear depth, share of the flank height"),
    ("temperature_range", "Temperature range"),
    ("oil_compatible", "Oil and lubricants"),
    ("friction_dynamic", "Running friction the catalog takes (yours is used, except run dry)"),
)


def _nut_text(nut: NutMaterial, key: str) -> str | None:
    """One value of a nut material as text in SI-derived units (MPa, m/s, mm³/(N m))."""
    limits = nut.limits
    if key == "bearing_pressure":
        table = limits["bearing_pressure_table"]
        rows = [f"{sig(v)} m/s: {sig(from_si(p, 'MPa'))} MPa" for v, p in table]  # type: ignore[attr-defined]
        return "; ".join(rows) or None
    if key == "dynamic_thrust":
        if nut.thrust_table is None:
            return None
        rows = nut.thrust_table.value
        sizes = [
            f"Tr{sig(from_si(d, 'mm'))}x{sig(from_si(p, 'mm'))} {sig(n)} N" for d, p, n in rows
        ]
        return ", ".join(sizes)
    if key == "temperature_range":
        t = nut.temperature_c
        return None if t is None else f"{sig(t[0])} to {sig(t[1])} °C"
    if key == "oil_compatible":
        return "suits oil" if nut.oil_compatible else "no oil"
    if key == "friction_dynamic":
        return f"{sig(nut.friction_dynamic)} (static {sig(nut.friction_static)})"
    spec_name, unit = NUT_UNITS[key]
    value = limits.get(spec_name)
    return None if value is None else f"{sig(from_si(float(value), unit))} {unit}".strip()  # type: ignore[arg-type]


#: The ScrewSpec value and the unit each plain nut value is shown in.
NUT_UNITS = {
    "max_pressure": ("max_pressure_pa", "MPa"),
    "bearing_pv_limit": ("nut_pv_limit_pa_m_s", "MPa m/s"),
    "max_sliding_speed": ("max_sliding_speed_m_s", "m/s"),
    "wear_rate": ("wear_rate_m2_n", "mm³/(N m)"),
    "allowed_wear": ("allowed_wear_fraction", ""),
}


def nut_rows(nut: NutMaterial) -> list[tuple[str, str, Provenance | None]]:
    """(label, value, provenance) of each value a catalog nut material gives."""
    rows = []
    for key, row_label in NUT_ROWS:
        text = _nut_text(nut, key)
        if text is not None:
            rows.append((row_label, text, nut.provenance.get(key)))
    return rows


def _provenance_out(p: Provenance | None) -> ProvenanceOut | None:
    return None if p is None else ProvenanceOut.model_validate({"kind": p.kind, "source": p.source})


def nut_materials_out(nuts: Mapping[str, NutMaterial], version: str) -> NutMaterialsOut:
    """The catalog's nut materials with each value's text and provenance."""
    return NutMaterialsOut(
        catalog_version=version,
        nut_materials=[
            NutMaterialOut(
                key=key,
                name=nut.name,
                family=nut.family,
                values=[
                    NutValueOut(
                        label=label,
                        value=text,
                        provenance=_provenance_out(p),
                    )
                    for label, text, p in nut_rows(nut)
                ],
            )
            for key, nut in nuts.items()
        ],
    )
