"""One series entry: validate it, derive what it leaves out, expand leads x variants.

The derivation rules are catalog/README.md "Rules"; every derived value's provenance
names its rule so a user can trace it.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Any

from app.catalog.entry import Entry
from app.catalog.family import Family
from app.catalog.models import Ends, Material, Series, Sourced
from app.catalog.nut_ratings import Variant, check_bearing, offered_variants, thrust_rated
from app.catalog.screw_geometry import geometry_fields, other_fields, screw_material
from app.core.model import Provenance, ScrewSpec

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
        "pitch_mm",
        "starts",
        "nut_length_mm",
        "nut_length_to_d",
    }
)


#: Series values a range may be given for, whose ends change the candidate's numbers.
RANGED_SERIES = (
    "root_diameter_ratio",
    "design_contact_pressure_mpa",
    "design_load_factor",
    "design_load_n",
    "friction_static",
    "nut_length_to_d",
    "nut_length_mm",
)


#: What a candidate's provenance says for a nut rating or thread value its family gives
#: none of (a check that needs it does not apply; one that reads it among others runs on
#: the others).
NOT_GIVEN = {
    name: Provenance(
        "derived", f"no {text} in the catalog for this screw and nut: the checks go without it"
    )
    for name, text in (
        ("bearing_pressure", "pressure-speed table"),
        ("max_pressure", "maximum contact pressure"),
        ("dynamic_pressure", "dynamic flank pressure rating of a polymer nut"),
        ("bearing_pv_limit", "PV limit over the engaged flanks"),
        ("max_sliding_speed", "maximum sliding speed"),
        ("nut_length", "nut length"),
        ("pitch", "thread pitch"),
        ("pv_limit", "three-thread PV limit"),
        ("design_load", "design load"),
        ("thermal_conductivity", "screw thermal conductivity"),
        ("wear_rate", "specific wear rate"),
        ("allowed_wear", "allowed wear depth"),
        ("backlash", "axial play"),
    )
} | {
    # the accuracy check runs without these, on the terms the screw has
    "lead_accuracy": Provenance(
        "derived",
        "no lead accuracy in the catalog for this screw: the accuracy check leaves its "
        "lead error out and says so",
    ),
    "repeatability": Provenance(
        "derived", "no repeatability in the catalog for this screw: the accuracy check counts none"
    ),
    # the life check runs on the wear life where there is a wear rate, else fails unrated
    "life": Provenance(
        "derived",
        "no rated life in the catalog for this screw and nut (the seed lists N/A for its "
        "free-wheeling B series): its life is its wear life where a wear rate is given",
    ),
    # the vacuum check warns on a nut without data: it is judged, not left out
    "outgassing": Provenance(
        "derived",
        "no outgassing data in the catalog for this nut: in a vacuum its use is unproven "
        "(the vacuum check warns)",
    ),
}


def _value_or_none(fields: Mapping[str, Sourced], name: str) -> Any:
    return fields[name].value if name in fields else None


def _flag_or_false(fields: Mapping[str, Sourced], name: str) -> bool:
    """A variant's yes/no value, false where the family does not give it."""
    return bool(fields[name].value) if name in fields else False


#: Series fields that become ScrewSpec numbers, to compare at the ends of a range.
SPEC_OF_FIELD = {
    "root_diameter": "root_diameter_m",
    "design_load": "design_load_n",
    "friction_static": "friction_static",
    "nut_length": "nut_length_m",
    "inertia_per_length": "inertia_kg_m2_per_m",
}


def _spec_numbers(entry: Entry, family: Family, material: Material) -> dict[str, Any]:
    """The ScrewSpec numbers that a series' own values derive (``SPEC_OF_FIELD``)."""
    fields = {**geometry_fields(entry, family, material)}
    return {spec: _value_or_none(fields, name) for name, spec in SPEC_OF_FIELD.items()}


def _series_ends(entry: Entry, family: Family, material: Material) -> Ends:
    """For each ranged series value: the ScrewSpec numbers it changes, at each end,
    derived values recomputed by the same rules (a low root ratio lowers the root and
    the derived design load); then the screw material's ranged values."""
    nominal = _spec_numbers(entry, family, material)
    out = {}
    for name in RANGED_SERIES:
        span = entry.ends(name)
        if span is None:
            continue
        ends = []
        for value in span:
            changed = _spec_numbers(entry.at(name, value), family, material)
            ends.append({k: v for k, v in changed.items() if v != nominal[k]})
        out[name] = (ends[0], ends[1])
    return {**out, **material.ends}


def _ends(series_ends: Ends, variant: Variant) -> Ends:
    """The candidate's ranged values: the series', then the variant's (a variant's own
    static friction replaces the series' one)."""
    own = {k: v for k, v in series_ends.items() if k not in variant.fields}
    return {**own, **variant.ends}


def _field(fields: Mapping[str, Sourced], variant: Variant, name: str) -> Any:
    """A value the variant may set for itself (static friction, nut material)."""
    return (variant.fields.get(name) or fields[name]).value


def _nut_spec(
    fields: Mapping[str, Sourced], variant: Variant, context: "_Context"
) -> dict[str, Any]:
    """The ScrewSpec values of the thread and the nut rating, and the range ends."""
    bearing = variant.fields.get("bearing_pressure")
    return {
        "pitch_m": _value_or_none(fields, "pitch"),
        "flank_pitch_diameter_m": _value_or_none(fields, "flank_pitch_diameter"),
        "flank_height_m": _value_or_none(fields, "flank_height"),
        "nut_length_m": _value_or_none(fields, "nut_length"),
        "bearing_pressure_table": () if bearing is None else bearing.value,
        "max_pressure_pa": _value_or_none(variant.fields, "max_pressure"),
        "dynamic_pressure_pa": _value_or_none(variant.fields, "dynamic_pressure"),
        "nut_pv_limit_pa_m_s": _value_or_none(variant.fields, "bearing_pv_limit"),
        "max_sliding_speed_m_s": _value_or_none(variant.fields, "max_sliding_speed"),
        "wear_rate_m2_n": _value_or_none(variant.fields, "wear_rate"),
        "allowed_wear_fraction": _value_or_none(variant.fields, "allowed_wear"),
        "assumption_ends": _ends(context.ends, variant),
    }


def _screw(
    family: Family, series: Series, variant: Variant, lead_m: float, context: "_Context"
) -> ScrewSpec:
    """One candidate: the series' fields with one variant's values at one lead."""
    fields = series.fields
    prov = {k: s.provenance for k, s in fields.items()}
    prov.update({k: s.provenance for k, s in variant.fields.items()})
    for name, not_given in NOT_GIVEN.items():
        prov.setdefault(name, not_given)
    prov["lead"] = fields["leads"].provenance
    prov["coating"] = context.offered
    life = variant.fields.get("life")
    temperature = variant.fields.get("temperature_range") or fields.get("temperature_range")
    t_min, t_max = (None, None) if temperature is None else temperature.value
    od, rd = fields["outer_diameter"].value, fields["root_diameter"].value
    return ScrewSpec(
        id=family.screw_id(series.id, lead_m, od, variant.id_part, _value_or_none(fields, "pitch")),
        series_id=series.id,
        series_name=series.name,
        anti_backlash=family.anti_backlash_by_type[series.type],
        coated=variant.coated,
        outer_diameter_m=od,
        root_diameter_m=rd,
        lead_m=lead_m,
        thread_half_angle_rad=math.radians(family.half_angle_deg.value),
        friction_static=_field(fields, variant, "friction_static"),
        friction_dynamic=variant.fields["friction_dynamic"].value,
        youngs_modulus_pa=fields["youngs_modulus"].value,
        density_kg_m3=fields["density"].value,
        screw_expansion_per_k=fields["screw_expansion"].value,
        inertia_kg_m2_per_m=fields["inertia_per_length"].value,
        drag_torque_min_nm=fields["drag_torque"].value[0],
        drag_torque_max_nm=fields["drag_torque"].value[1],
        pv_limit_pa_m_s=_value_or_none(variant.fields, "pv_limit"),
        design_load_n=_value_or_none(fields, "design_load"),
        max_length_m=_value_or_none(variant.fields, "max_length"),
        backlash_min_m=fields["backlash"].value[0],
        backlash_max_m=fields["backlash"].value[1],
        life_min_m=None if life is None else life.value[0],
        life_max_m=None if life is None else life.value[1],
        lead_accuracy_m_per_m=_value_or_none(fields, "lead_accuracy"),
        repeatability_m=_value_or_none(fields, "repeatability"),
        temperature_min_c=t_min,
        temperature_max_c=t_max,
        oil_compatible=variant.fields["oil_compatible"].value,
        lubricated_rating=_flag_or_false(variant.fields, "lubricated_rating"),
        dry_friction_dynamic=_value_or_none(variant.fields, "dry_friction_dynamic"),
        dry_friction_static=_value_or_none(variant.fields, "dry_friction_static"),
        yield_strength_pa=_value_or_none(fields, "yield_strength"),
        thermal_conductivity_w_m_k=_value_or_none(fields, "thermal_conductivity"),
        outgassing=_value_or_none(fields, "outgassing") or (),
        material_name=fields["screw_material"].value,
        nut_material=_field(fields, variant, "nut_material"),
        family_id=family.id,
        variant=variant.key,
        traverse_bands=() if family.traverse is None else family.traverse.value,
        provenance=prov,
        **_nut_spec(fields, variant, context),
    )


@dataclass(frozen=True, slots=True)
class _Context:
    """What every candidate of one series shares beyond its fields."""

    offered: Provenance
    ends: Ends


def _check_static_friction(
    entry: Entry, fields: Mapping[str, Sourced], variants: list[Variant]
) -> None:
    """Static friction comes from the series, or from every variant it offers."""
    if "friction_static" in fields:
        return
    missing = [v.key for v in variants if "friction_static" not in v.fields]
    if missing:
        raise entry.fail("friction_static", f"missing (here or in variant '{missing[0]}')")


def build_series(
    family: Family, sid: str, data: Mapping[str, Any], materials: Mapping[str, Material]
) -> Series:
    """Validate one series entry merged over its family's defaults and expand it into
    one candidate per lead and variant, in lead order, variants as listed."""
    entry = Entry(family.file, sid, {**family.defaults, **data})
    entry.check_known(SERIES_FIELDS)
    material = screw_material(entry, materials)
    fields = {**geometry_fields(entry, family, material), **other_fields(entry)}
    if family.traverse is not None:
        fields["traverse_speed"] = family.traverse
    variants = offered_variants(entry, family)
    check_bearing(entry, fields, variants)
    _check_static_friction(entry, fields, variants)
    series_ends = _series_ends(entry, family, material)
    variants = [thrust_rated(v, fields, series_ends) for v in variants]
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
    context = _Context(entry.prov("nut_variants"), series_ends)
    screws = tuple(
        _screw(family, series, v, lead, context) for lead in fields["leads"].value for v in variants
    )
    return replace(series, screws=screws)
