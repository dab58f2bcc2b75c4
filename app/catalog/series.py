"""One series entry: validate it, derive what it leaves out, expand leads x variants.

The derivation rules are catalog/README.md "Rules"; every derived value's provenance
names its rule so a user can trace it.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from app.catalog.entry import Entry
from app.catalog.family import Family, IdVariant
from app.catalog.models import Material, Series, Sourced
from app.core.formulas import geometry, pv
from app.core.model import Provenance, ScrewSpec

MM = 1e-3
INCHES_PER_M = 1 / 0.0254
SERIES_FIELDS = frozenset(
    {
        "name",
        "type",
        "outer_diameter_mm",
        "root_diameter_mm",
        "root_diameter_ratio",
        "inertia_kg_m2_per_in",
        "drag_torque_nm",
        "backlash_mm",
        "screw_material",
        "nut_material",
        "friction_static",
        "nut_variants",
        "variants",
        "leads_mm",
        "max_lead_to_od",
        "design_load_n",
        "design_contact_pressure_mpa",
        "design_load_factor",
        "lead_accuracy_mm_per_mm",
        "repeatability_mm",
        "temperature_range_c",
        "straightness_mm_per_300mm",
        "nut_expansion_per_c",
        "nut_tensile_strength_mpa",
        "outgassing_percent",
    }
)
UNRATED_LIFE = Provenance(
    "derived",
    "no life rating in the catalog for this series (the seed lists N/A for the "
    "free-wheeling B series)",
)


@dataclass(frozen=True, slots=True)
class Variant:
    """One nut variant of one series, its values read and converted to SI."""

    key: str
    id_part: IdVariant
    field_suffix: str
    coated: bool
    fields: Mapping[str, Sourced]


def _diameters(entry: Entry) -> tuple[Sourced, Sourced]:
    """Outer and root diameter; the root from ``root_diameter_ratio`` when not given."""
    od_m = entry.number("outer_diameter_mm") * MM
    if entry.has("root_diameter_mm"):
        rd_name = "root_diameter_mm"
        root = Sourced(entry.number(rd_name) * MM, "m", entry.prov(rd_name))
    else:
        rd_name = "root_diameter_ratio"
        ratio = entry.number(rd_name)
        source = f"{ratio:g} x OD: {entry.prov(rd_name).source}"
        root = Sourced(ratio * od_m, "m", Provenance("assumed", source))
    if root.value >= od_m:
        raise entry.fail(rd_name, "root diameter must be below the outer diameter")
    return Sourced(od_m, "m", entry.prov("outer_diameter_mm")), root


def _design_load(entry: Entry, d_p: float, h: float) -> Sourced:
    """Given, or derived from contact pressure over the seed's three-thread area (rule 4)."""
    if entry.has("design_load_n"):
        return Sourced(entry.number("design_load_n"), "N", entry.prov("design_load_n"))
    pressure = entry.number("design_contact_pressure_mpa") * 1e6
    factor = entry.number("design_load_factor")
    load = factor * pressure * pv.contact_area(math.pi * d_p, h)
    rule = (
        f"{factor:g} x {pressure / 1e6:g} MPa x 3 pi d_p h (seed three-thread area; "
        f"pressure and factor assumed)"
    )
    return Sourced(load, "N", Provenance("derived", rule))


def _leads(entry: Entry, od_m: float) -> tuple[float, ...]:
    """The offered leads up to ``max_lead_to_od`` x OD; a lead listed twice is an error."""
    listed = entry.numbers("leads_mm")
    if len(set(listed)) != len(listed):
        repeated = next(x for x in listed if listed.count(x) > 1)
        raise entry.fail("leads_mm", f"lead {repeated:g} mm is listed twice")
    max_lead_m = entry.number("max_lead_to_od") * od_m
    return tuple(x * MM for x in listed if x * MM <= max_lead_m + 1e-12)


def _material(entry: Entry, materials: Mapping[str, Material]) -> Material:
    name = entry.text("screw_material")
    if name not in materials:
        raise entry.fail("screw_material", f"unknown material '{name}'")
    return materials[name]


def _sourced(entry: Entry, name: str, unit: str, scale: float = 1.0) -> Sourced:
    return Sourced(entry.number(name) * scale, unit, entry.prov(name))


def _geometry_fields(entry: Entry, family: Family, material: Material) -> dict[str, Sourced]:
    """Size, thread, material, drag and load fields: what the core's geometry checks read."""
    od, rd = _diameters(entry)
    d_p = geometry.pitch_diameter(od.value, rd.value)
    inertia = entry.number("inertia_kg_m2_per_in") * INCHES_PER_M
    low, high = entry.range("backlash_mm")
    return {
        "type": Sourced(entry.text("type", family.anti_backlash_by_type), "", entry.prov("type")),
        "outer_diameter": od,
        "root_diameter": rd,
        "pitch_diameter": Sourced(d_p, "m", Provenance("derived", "(OD + RD) / 2 (seed P_o)")),
        "inertia_per_length": Sourced(inertia, "kg m2/m", entry.prov("inertia_kg_m2_per_in")),
        "youngs_modulus": material.youngs_modulus_pa,
        "density": material.density_kg_m3,
        "screw_expansion": material.expansion_per_k,
        "thread_half_angle": family.half_angle_deg,
        "thread_form": family.thread_form,
        "friction_static": _sourced(entry, "friction_static", ""),
        "drag_torque": Sourced(entry.range("drag_torque_nm"), "N m", entry.prov("drag_torque_nm")),
        "backlash": Sourced((low * MM, high * MM), "m", entry.prov("backlash_mm")),
        "design_load": _design_load(entry, d_p, geometry.thread_depth(od.value, rd.value)),
        "leads": Sourced(_leads(entry, od.value), "m", entry.prov("leads_mm")),
        **({"yield_strength": material.yield_strength_pa} if material.yield_strength_pa else {}),
    }


#: Values a family may leave out (a vendor-neutral family has no vacuum or accuracy data):
#: field name -> (catalog key, SI unit, factor from the catalog unit), in display order.
ACCURACY_VALUES = {
    "lead_accuracy": ("lead_accuracy_mm_per_mm", "m/m", 1.0),
    "repeatability": ("repeatability_mm", "m", MM),
}
NUT_VALUES = {
    "straightness": ("straightness_mm_per_300mm", "m/m", MM / 0.3),
    "nut_expansion": ("nut_expansion_per_c", "1/K", 1.0),
    "nut_tensile_strength": ("nut_tensile_strength_mpa", "Pa", 1e6),
}


def _optional(entry: Entry, values: Mapping[str, tuple[str, str, float]]) -> dict[str, Sourced]:
    return {
        name: _sourced(entry, key, unit, scale)
        for name, (key, unit, scale) in values.items()
        if entry.has(key)
    }


def _other_fields(entry: Entry) -> dict[str, Sourced]:
    """Accuracy, material names, nut and environment fields: shown, some checked; the
    optional ones only when the data gives them, so nothing unknown is shown as known."""
    fields = {
        **_optional(entry, ACCURACY_VALUES),
        "nut_material": Sourced(entry.text("nut_material"), "", entry.prov("nut_material")),
        "screw_material": Sourced(entry.text("screw_material"), "", entry.prov("screw_material")),
        **_optional(entry, NUT_VALUES),
    }
    if entry.has("outgassing_percent"):
        rows = entry.rows("outgassing_percent", 2)
        fields["outgassing"] = Sourced(rows, "h, %", entry.prov("outgassing_percent"))
    if entry.has("temperature_range_c"):
        t_range = entry.range("temperature_range_c", positive=False)
        fields["temperature_range"] = Sourced(t_range, "C", entry.prov("temperature_range_c"))
    return fields


def _value_or_none(fields: Mapping[str, Sourced], name: str) -> Any:
    return fields[name].value if name in fields else None


def _variant(entry: Entry, key: str, family_data: Mapping[str, Any]) -> Variant:
    """One variant's values: the family's declaration under the series' own overrides."""
    own = entry.data.get("variants", {}).get(key, {})
    v = Entry(entry.file, f"{entry.entry}.variants.{key}", {**family_data, **own})
    fields = {
        "friction_dynamic": _sourced(v, "friction_dynamic", ""),
        "pv_limit": _sourced(v, "pv_limit_mpa_m_s", "Pa m/s", 1e6),
        "oil_compatible": Sourced(v.flag("oil_compatible"), "", v.prov("oil_compatible")),
    }
    if v.has("max_length_mm"):
        fields["max_length"] = _sourced(v, "max_length_mm", "m", MM)
    if v.has("life_million_cm"):
        low, high = v.range("life_million_cm")
        fields["life"] = Sourced((low * 1e4, high * 1e4), "m", v.prov("life_million_cm"))
    id_part = IdVariant(key, v.plain_text("suffix", ""))
    return Variant(key, id_part, v.plain_text("field_suffix", key), v.plain_flag("coated"), fields)


def _variants(entry: Entry, family: Family) -> list[Variant]:
    """The variants this series offers (``nut_variants``), in the order listed."""
    offered = entry.texts("nut_variants")
    own = entry.data.get("variants", {})
    if not isinstance(own, dict) or not all(isinstance(t, dict) for t in own.values()):
        raise entry.fail("variants", "must be a table of variant tables, e.g. variants.tfe.X")
    for name, keys in (("nut_variants", offered), ("variants", list(own))):
        unknown = [key for key in keys if key not in family.variants]
        if unknown:
            raise entry.fail(name, f"no variant '{unknown[0]}' declared by the family")
    if len(set(offered)) != len(offered):
        raise entry.fail("nut_variants", "a variant is listed twice")
    return [_variant(entry, key, family.variants[key]) for key in offered]


def _screw(
    family: Family, series: Series, variant: Variant, lead_m: float, offered: Provenance
) -> ScrewSpec:
    """One candidate: the series' fields with one variant's values at one lead."""
    fields = series.fields
    prov = {k: s.provenance for k, s in fields.items()}
    prov.update({k: s.provenance for k, s in variant.fields.items()})
    prov.setdefault("life", UNRATED_LIFE)
    prov["lead"] = fields["leads"].provenance
    prov["coating"] = offered
    life = variant.fields.get("life")
    max_length = variant.fields.get("max_length")
    t_min, t_max = _value_or_none(fields, "temperature_range") or (None, None)
    od, rd = fields["outer_diameter"].value, fields["root_diameter"].value
    return ScrewSpec(
        id=family.screw_id(series.id, lead_m, od, variant.id_part),
        series_id=series.id,
        series_name=series.name,
        anti_backlash=family.anti_backlash_by_type[series.type],
        coated=variant.coated,
        outer_diameter_m=od,
        root_diameter_m=rd,
        lead_m=lead_m,
        thread_half_angle_rad=math.radians(family.half_angle_deg.value),
        friction_static=fields["friction_static"].value,
        friction_dynamic=variant.fields["friction_dynamic"].value,
        youngs_modulus_pa=fields["youngs_modulus"].value,
        density_kg_m3=fields["density"].value,
        screw_expansion_per_k=fields["screw_expansion"].value,
        inertia_kg_m2_per_m=fields["inertia_per_length"].value,
        drag_torque_min_nm=fields["drag_torque"].value[0],
        drag_torque_max_nm=fields["drag_torque"].value[1],
        pv_limit_pa_m_s=variant.fields["pv_limit"].value,
        design_load_n=fields["design_load"].value,
        max_length_m=None if max_length is None else max_length.value,
        backlash_min_m=fields["backlash"].value[0],
        backlash_max_m=fields["backlash"].value[1],
        life_min_m=None if life is None else life.value[0],
        life_max_m=None if life is None else life.value[1],
        lead_accuracy_m_per_m=_value_or_none(fields, "lead_accuracy"),
        repeatability_m=_value_or_none(fields, "repeatability"),
        temperature_min_c=t_min,
        temperature_max_c=t_max,
        oil_compatible=variant.fields["oil_compatible"].value,
        yield_strength_pa=_value_or_none(fields, "yield_strength"),
        outgassing=_value_or_none(fields, "outgassing") or (),
        material_name=fields["screw_material"].value,
        nut_material=fields["nut_material"].value,
        family_id=family.id,
        variant=variant.key,
        traverse_bands=() if family.traverse is None else family.traverse.value,
        provenance=prov,
    )


def build_series(
    family: Family, sid: str, data: Mapping[str, Any], materials: Mapping[str, Material]
) -> Series:
    """Validate one series entry merged over its family's defaults and expand it into
    one candidate per lead and variant, in lead order, variants as listed."""
    entry = Entry(family.file, sid, {**family.defaults, **data})
    entry.check_known(SERIES_FIELDS)
    material = _material(entry, materials)
    fields = {**_geometry_fields(entry, family, material), **_other_fields(entry)}
    if family.traverse is not None:
        fields["traverse_speed"] = family.traverse
    variants = _variants(entry, family)
    for v in variants:
        fields.update({f"{name}_{v.field_suffix}": s for name, s in v.fields.items()})
    series = Series(
        id=sid,
        name=entry.plain_text("name", sid),
        family=family.id,
        family_name=family.name,
        type=fields["type"].value,
        file=family.file,
        fields=fields,
        screws=(),
    )
    offered = entry.prov("nut_variants")
    screws = tuple(
        _screw(family, series, v, lead, offered) for lead in fields["leads"].value for v in variants
    )
    return replace(series, screws=screws)
