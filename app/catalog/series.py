"""One series entry: validate it, derive what it leaves out, expand leads x variants.

The derivation rules are catalog/README.md "Rules"; every derived value's provenance
names its rule so a user can trace it.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from itertools import pairwise
from typing import Any

from app.catalog.entry import Entry
from app.catalog.family import Family, IdVariant
from app.catalog.models import Material, Series, Sourced
from app.core.formulas import bearing, geometry, pv, trapezoidal
from app.core.model import Provenance, ScrewSpec
from app.core.units import SI_UNITS, UNITS, from_si, to_si

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
#: Thread starts at most: a lead of thousands of pitches is a typing error, and its
#: numbers (a screw turning once per kilometre) would fail later, at a request.
MAX_STARTS = 16
#: Half-angle of the ISO 2904 trapezoidal thread, the only form ``pitch_mm`` describes.
ISO_HALF_ANGLE_DEG = 15.0
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
#: Variant values a range may be given for: ScrewSpec field and the catalog's unit.
RANGED_VARIANT = {
    "friction_dynamic": ("friction_dynamic", ""),
    "friction_static": ("friction_static", ""),
    "pv_limit_mpa_m_s": ("pv_limit_pa_m_s", "MPa m/s"),
    "max_pressure_mpa": ("max_pressure_pa", "MPa"),
    "dynamic_pressure_mpa": ("dynamic_pressure_pa", "MPa"),
    "bearing_pv_limit_mpa_m_s": ("nut_pv_limit_pa_m_s", "MPa m/s"),
    "max_sliding_speed_m_s": ("max_sliding_speed_m_s", "m/s"),
    "max_length_mm": ("max_length_m", "mm"),
    "specific_wear_rate_mm3_n_m": ("wear_rate_m2_n", "mm³/(N m)"),
    "allowed_wear_to_flank_height": ("allowed_wear_fraction", ""),
}
#: Variant values that rate the nut by its contact pressure (they need a nut length).
BEARING_VALUES = {
    "max_pressure": ("max_pressure_mpa", "MPa"),
    "dynamic_pressure": ("dynamic_pressure_mpa", "MPa"),
    "bearing_pv_limit": ("bearing_pv_limit_mpa_m_s", "MPa m/s"),
    "max_sliding_speed": ("max_sliding_speed_m_s", "m/s"),
}
#: Variant values that rate the nut's wear life (Archard's law, both needed).
#: A maker's allowable dynamic thrust of the nut by thread size, rows [d mm, P mm, N].
THRUST_TABLE = "dynamic_thrust_n_by_size"
WEAR_VALUES = {
    "wear_rate": ("specific_wear_rate_mm3_n_m", "mm³/(N m)"),
    "allowed_wear": ("allowed_wear_to_flank_height", ""),
}
Ends = Mapping[str, tuple[Mapping[str, Any], Mapping[str, Any]]]
#: What a candidate's provenance says for a nut rating or thread value its family gives
#: none of (the check that reads it does not apply to the candidate).
NOT_GIVEN = {
    name: Provenance("derived", f"no {text} in the catalog for this screw and nut: not checked")
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
    )
}
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
    ends: Ends


def _iso_root(entry: Entry, od_m: float) -> Sourced:
    """The root diameter d3 of an ISO 2904 screw from its pitch; its provenance kind is
    the pitch's (a standard value, "standard")."""
    if entry.has("root_diameter_mm"):
        raise entry.fail("root_diameter_mm", "follows from pitch_mm (ISO 2904): leave it out")
    pitch_m = to_si(entry.number("pitch_mm"), "mm")
    try:
        root_m = trapezoidal.minor_diameter(od_m, pitch_m)
    except ValueError as exc:
        raise entry.fail("pitch_mm", str(exc)) from exc
    ac_mm = from_si(trapezoidal.crest_clearance(pitch_m), "mm")
    p_mm = entry.number("pitch_mm")
    rule = f"ISO 2904: d3 = d - 2 (0.5 P + a_c), P = {p_mm:g} mm, a_c = {ac_mm:g} mm"
    return Sourced(root_m, "m", Provenance(entry.prov("pitch_mm").kind, rule))


def _diameters(entry: Entry) -> tuple[Sourced, Sourced]:
    """Outer and root diameter; the root from the ISO pitch, else from
    ``root_diameter_ratio`` when not given."""
    od_m = to_si(entry.number("outer_diameter_mm"), "mm")
    if entry.has("pitch_mm"):
        rd_name = "pitch_mm"
        root = _iso_root(entry, od_m)
    elif entry.has("root_diameter_mm"):
        rd_name = "root_diameter_mm"
        root = _sourced(entry, rd_name, "mm")
    else:
        rd_name = "root_diameter_ratio"
        ratio = entry.number(rd_name)
        source = f"{ratio:g} x OD: {entry.prov(rd_name).source}"
        root = Sourced(ratio * od_m, "m", Provenance("assumed", source))
    if root.value >= od_m:
        raise entry.fail(rd_name, "root diameter must be below the outer diameter")
    if root.value <= 0:
        root_mm = from_si(root.value, "mm")
        raise entry.fail(rd_name, f"root diameter must be above 0, got {root_mm:.4g} mm")
    return Sourced(od_m, "m", entry.prov("outer_diameter_mm")), root


def _design_load(entry: Entry, d_p: float, h: float) -> Sourced | None:
    """Given, or derived from contact pressure over the seed's three-thread area (rule 4);
    None when the family rates its nuts otherwise (neither is given)."""
    if entry.has("design_load_n"):
        return Sourced(entry.number("design_load_n"), "N", entry.prov("design_load_n"))
    if not entry.has("design_contact_pressure_mpa"):
        return None
    pressure_mpa = entry.number("design_contact_pressure_mpa")
    factor = entry.number("design_load_factor")
    load = factor * to_si(pressure_mpa, "MPa") * pv.contact_area(math.pi * d_p, h)
    rule = (
        f"{factor:g} x {pressure_mpa:g} MPa x 3 pi d_p h (seed three-thread area; "
        f"pressure and factor assumed)"
    )
    return Sourced(load, "N", Provenance("derived", rule))


def _listed_leads_mm(entry: Entry) -> list[float]:
    """``leads_mm``, or the ``starts`` times ``pitch_mm`` of a standard thread."""
    if entry.has("starts"):
        if entry.has("leads_mm"):
            raise entry.fail("leads_mm", "give either leads_mm or starts (with pitch_mm)")
        return [n * entry.number("pitch_mm") for n in entry.whole_numbers("starts", MAX_STARTS)]
    listed = entry.numbers("leads_mm")
    if len(set(listed)) != len(listed):
        repeated = next(x for x in listed if listed.count(x) > 1)
        raise entry.fail("leads_mm", f"lead {repeated:g} mm is listed twice")
    if entry.has("pitch_mm"):
        pitch = entry.number("pitch_mm")
        for lead in listed:
            starts = round(lead / pitch)
            if starts < 1 or not math.isclose(lead, starts * pitch):
                why = f"lead {lead:g} mm is not a whole number of starts of pitch {pitch:g} mm"
                raise entry.fail("leads_mm", why)
    return listed


def _leads(entry: Entry, od_m: float) -> Sourced:
    """The offered leads, up to ``max_lead_to_od`` x OD when the family limits them."""
    listed = _listed_leads_mm(entry)
    name = "starts" if entry.has("starts") else "leads_mm"
    if not entry.has("max_lead_to_od"):
        return Sourced(tuple(to_si(x, "mm") for x in listed), "m", entry.prov(name))
    max_lead_m = entry.number("max_lead_to_od") * od_m
    leads = tuple(to_si(x, "mm") for x in listed if to_si(x, "mm") <= max_lead_m + 1e-12)
    return Sourced(leads, "m", entry.prov(name))


def _inertia(entry: Entry, d2: Sourced | None, material: Material) -> Sourced:
    """Inertia per length: given per inch; for a standard (ISO) screw that gives none, a
    solid rod at its pitch diameter d2 (derived); otherwise required."""
    if d2 is None or entry.has("inertia_kg_m2_per_in"):
        inertia = to_si(entry.number("inertia_kg_m2_per_in"), "kg m²/in")
        return Sourced(inertia, "kg m2/m", entry.prov("inertia_kg_m2_per_in"))
    inertia = trapezoidal.solid_rod_inertia_per_length(material.density_kg_m3.value, d2.value)
    d2_mm = from_si(d2.value, "mm")
    rule = f"solid rod rho pi d^4 / 32 at the pitch diameter d2 = {d2_mm:g} mm"
    return Sourced(inertia, "kg m2/m", Provenance("derived", rule))


def _thread_fields(entry: Entry, od_m: float, family: Family) -> dict[str, Sourced]:
    """Pitch, pitch diameter d2, flank height H1 and nut length of an ISO 2904 screw."""
    if not entry.has("pitch_mm"):
        return {}
    if not math.isclose(family.half_angle_deg.value, ISO_HALF_ANGLE_DEG):
        raise entry.fail("pitch_mm", "pitch_mm describes an ISO 2904 thread (15 deg half-angle)")
    pitch_m = to_si(entry.number("pitch_mm"), "mm")
    rule = "ISO 2904 basic profile: d2 = d - 0.5 P, H1 = 0.5 P"
    standard = Provenance(entry.prov("pitch_mm").kind, rule)
    fields = {
        "pitch": Sourced(pitch_m, "m", entry.prov("pitch_mm")),
        "flank_pitch_diameter": Sourced(trapezoidal.pitch_diameter(od_m, pitch_m), "m", standard),
        "flank_height": Sourced(trapezoidal.flank_height(pitch_m), "m", standard),
    }
    if entry.has("nut_length_mm"):
        fields["nut_length"] = _sourced(entry, "nut_length_mm", "mm")
    elif entry.has("nut_length_to_d"):
        ratio = entry.number("nut_length_to_d")
        rule = f"{ratio:g} x d: {entry.prov('nut_length_to_d').source}"
        kind = entry.prov("nut_length_to_d").kind
        fields["nut_length"] = Sourced(ratio * od_m, "m", Provenance(kind, rule))
    return fields


def _material(entry: Entry, materials: Mapping[str, Material]) -> Material:
    name = entry.text("screw_material")
    if name not in materials:
        raise entry.fail("screw_material", f"unknown material '{name}'")
    return materials[name]


def _sourced(entry: Entry, name: str, unit: str = "") -> Sourced:
    """A catalog number given in ``unit``, in SI with its SI unit."""
    si_unit = SI_UNITS[UNITS[unit].dimension]
    return Sourced(to_si(entry.number(name), unit), si_unit, entry.prov(name))


def _geometry_fields(entry: Entry, family: Family, material: Material) -> dict[str, Sourced]:
    """Size, thread, material, drag and load fields: what the core's geometry checks read."""
    od, rd = _diameters(entry)
    d_p = geometry.pitch_diameter(od.value, rd.value)
    thread = _thread_fields(entry, od.value, family)
    d2 = thread.get("flank_pitch_diameter")
    if d2 is not None and not rd.value < d2.value < od.value:
        raise entry.fail("pitch_mm", "the pitch diameter d2 must lie between root and outer")
    inertia = _inertia(entry, thread.get("flank_pitch_diameter"), material)
    low, high = entry.range("backlash_mm")
    load = _design_load(entry, d_p, geometry.thread_depth(od.value, rd.value))
    return {
        "type": Sourced(entry.text("type", family.anti_backlash_by_type), "", entry.prov("type")),
        "outer_diameter": od,
        "root_diameter": rd,
        "pitch_diameter": thread.get("flank_pitch_diameter")
        or Sourced(d_p, "m", Provenance("derived", "(OD + RD) / 2 (seed P_o)")),
        "inertia_per_length": inertia,
        "youngs_modulus": material.youngs_modulus_pa,
        "density": material.density_kg_m3,
        "screw_expansion": material.expansion_per_k,
        "thread_half_angle": family.half_angle_deg,
        "thread_form": family.thread_form,
        **_optional(entry, {"friction_static": ("friction_static", "")}),
        "drag_torque": Sourced(entry.range("drag_torque_nm"), "N m", entry.prov("drag_torque_nm")),
        "backlash": Sourced((to_si(low, "mm"), to_si(high, "mm")), "m", entry.prov("backlash_mm")),
        **({} if load is None else {"design_load": load}),
        "leads": _leads(entry, od.value),
        **thread,
        **({"yield_strength": material.yield_strength_pa} if material.yield_strength_pa else {}),
        **(
            {"thermal_conductivity": material.thermal_conductivity_w_m_k}
            if material.thermal_conductivity_w_m_k
            else {}
        ),
    }


#: Values a family may leave out (a vendor-neutral family has no vacuum or accuracy data):
#: field name -> (catalog key, the catalog's unit), in display order.
ACCURACY_VALUES = {
    "lead_accuracy": ("lead_accuracy_mm_per_mm", "m/m"),
    "repeatability": ("repeatability_mm", "mm"),
}
NUT_VALUES = {
    "straightness": ("straightness_mm_per_300mm", "mm/300 mm"),
    "nut_expansion": ("nut_expansion_per_c", "1/K"),
    "nut_tensile_strength": ("nut_tensile_strength_mpa", "MPa"),
}


def _optional(entry: Entry, values: Mapping[str, tuple[str, str]]) -> dict[str, Sourced]:
    return {
        name: _sourced(entry, key, unit) for name, (key, unit) in values.items() if entry.has(key)
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


def _bearing_table(v: Entry) -> Sourced:
    """Allowable contact pressure by sliding speed, rows [speed m/s, pressure MPa] rising
    in speed, to SI (m/s, Pa)."""
    name = "bearing_pressure_mpa_by_speed_m_s"
    rows = v.rows(name, 2)
    speeds = [row[0] for row in rows]
    if not rows or any(b <= a for a, b in pairwise(speeds)):
        raise v.fail(name, "rows must rise in sliding speed, at least one row")
    if any(row[1] <= 0 for row in rows):
        raise v.fail(name, "every allowable pressure must be > 0")
    # a sliding nut heats more the faster it slides: a row allowing more pressure than a
    # slower one would let a larger, faster-sliding size pass where a smaller one fails
    if any(b[1] > a[1] for a, b in pairwise(rows)):
        raise v.fail(name, "the allowable pressure must not rise with the sliding speed")
    table = tuple((speed, to_si(pressure, "MPa")) for speed, pressure in rows)
    return Sourced(table, "m/s, Pa", v.prov(name))


def _thrust_table(v: Entry) -> Sourced:
    """A maker's allowable dynamic thrust by thread size, rows [d mm, P mm, thrust N],
    to SI (m, m, N): each size once, its pitch above 0 and below its diameter, every
    thrust above 0; not beside a ``dynamic_pressure_mpa`` (one rating in motion)."""
    if v.has("dynamic_pressure_mpa"):
        raise v.fail(THRUST_TABLE, "give either this or dynamic_pressure_mpa, not both")
    rows = v.rows(THRUST_TABLE, 3)
    if not rows:
        raise v.fail(THRUST_TABLE, "at least one row [d mm, P mm, thrust N]")
    for d_mm, p_mm, thrust_n in rows:
        if not 0.0 < p_mm < d_mm:
            raise v.fail(
                THRUST_TABLE, f"row [{d_mm:g}, {p_mm:g}]: the pitch must be > 0 and below d"
            )
        if thrust_n <= 0.0:
            raise v.fail(THRUST_TABLE, f"row Tr{d_mm:g}x{p_mm:g}: the thrust must be > 0")
    sizes = [row[:2] for row in rows]
    twice = next((size for size in sizes if sizes.count(size) > 1), None)
    if twice is not None:
        raise v.fail(THRUST_TABLE, f"size Tr{twice[0]:g}x{twice[1]:g} is listed twice")
    table = tuple((to_si(d, "mm"), to_si(p, "mm"), thrust) for d, p, thrust in rows)
    return Sourced(table, "m, m, N", v.prov(THRUST_TABLE))


def _variant_fields(v: Entry) -> dict[str, Sourced]:
    """A variant's values in SI; the optional ones only when the data gives them."""
    fields = {
        "friction_dynamic": _sourced(v, "friction_dynamic", ""),
        "oil_compatible": Sourced(v.flag("oil_compatible"), "", v.prov("oil_compatible")),
    }
    if v.has("pv_limit_mpa_m_s"):
        fields["pv_limit"] = _sourced(v, "pv_limit_mpa_m_s", "MPa m/s")
    if v.has("max_length_mm"):
        fields["max_length"] = _sourced(v, "max_length_mm", "mm")
    if v.has("life_million_cm"):
        low, high = v.range("life_million_cm")
        life = (to_si(low, "million cm"), to_si(high, "million cm"))
        fields["life"] = Sourced(life, "m", v.prov("life_million_cm"))
    if v.has("friction_static"):
        fields["friction_static"] = _sourced(v, "friction_static", "")
    if v.has("nut_material"):
        fields["nut_material"] = Sourced(v.text("nut_material"), "", v.prov("nut_material"))
    if v.has("bearing_pressure_mpa_by_speed_m_s"):
        fields["bearing_pressure"] = _bearing_table(v)
    if v.has(THRUST_TABLE):
        fields["dynamic_thrust"] = _thrust_table(v)
    if v.has("temperature_range_c"):
        t_range = v.range("temperature_range_c", positive=False)
        fields["temperature_range"] = Sourced(t_range, "C", v.prov("temperature_range_c"))
    fields.update(_optional(v, BEARING_VALUES))
    fields.update(_optional(v, WEAR_VALUES))
    if len(WEAR_VALUES.keys() & fields.keys()) == 1:
        missing = next(key for name, (key, _) in WEAR_VALUES.items() if name not in fields)
        raise v.fail(missing, "a wear rating needs both the wear rate and the allowed wear")
    if fields.get("allowed_wear") and not 0.0 < fields["allowed_wear"].value <= 1.0:
        raise v.fail("allowed_wear_to_flank_height", "must be a fraction, above 0 and at most 1")
    return fields


def _variant_ends(v: Entry) -> dict[str, tuple[dict[str, float], dict[str, float]]]:
    """For each ranged variant value, its ScrewSpec field at the low and the high end."""
    out = {}
    for name, (spec_field, unit) in RANGED_VARIANT.items():
        span = v.ends(name)
        if span is not None:
            out[name] = ({spec_field: to_si(span[0], unit)}, {spec_field: to_si(span[1], unit)})
    return out


def _variant(entry: Entry, key: str, family_data: Mapping[str, Any]) -> Variant:
    """One variant's values: the family's declaration under the series' own overrides."""
    own = entry.data.get("variants", {}).get(key, {})
    v = Entry(entry.file, f"{entry.entry}.variants.{key}", {**family_data, **own})
    fields = _variant_fields(v)
    id_part = IdVariant(key, v.plain_text("suffix", ""))
    suffix = v.plain_text("field_suffix", key)
    return Variant(key, id_part, suffix, v.plain_flag("coated"), fields, _variant_ends(v))


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
    fields = {**_geometry_fields(entry, family, material)}
    return {spec: _value_or_none(fields, name) for name, spec in SPEC_OF_FIELD.items()}


def _series_ends(entry: Entry, family: Family, material: Material) -> Ends:
    """For each ranged series value: the ScrewSpec numbers it changes, at each end,
    derived values recomputed by the same rules (a low root ratio lowers the root and
    the derived design load)."""
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
    return out


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
    prov.setdefault("life", UNRATED_LIFE)
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


def _flank_pressure(row: tuple[float, ...], length_to_d: float) -> tuple[float, float]:
    """A table row's thrust over the engaged flanks of its size's nut, ``length_to_d``
    x d long (rule 10): (pressure Pa, area m^2)."""
    d_m, pitch_m, thrust_n = row
    area = bearing.engaged_flank_area(
        length_to_d * d_m,
        pitch_m,
        trapezoidal.pitch_diameter(d_m, pitch_m),
        trapezoidal.flank_height(pitch_m),
    )
    return float(bearing.bearing_pressure(thrust_n, area)), float(area)


def thrust_pressure(
    table: Sourced, d_m: float, pitch_m: float, nut_length_m: float
) -> tuple[float, Provenance]:
    """The nut's flank pressure in motion from its maker's thrust table (rule 10): for a
    listed size, its thrust over this nut's engaged flanks; for another size, the lowest
    pressure of the listed sizes, each over a nut of this nut's length-to-d ratio."""
    ratio = nut_length_m / d_m
    rows = table.value
    own = [r for r in rows if math.isclose(r[0], d_m) and math.isclose(r[1], pitch_m)]
    row = own[0] if own else min(rows, key=lambda r: _flank_pressure(r, ratio)[0])
    pressure, area = _flank_pressure(row, ratio)
    size = f"Tr{from_si(row[0], 'mm'):g}x{from_si(row[1], 'mm'):g}"
    rated = (
        f"{size} {row[2]:g} N over {area / to_si(1.0, 'mm') ** 2:.0f} mm^2 of engaged flanks "
        f"({ratio * row[0] / row[1]:g} turns x pi d2 H1) = {from_si(pressure, 'MPa'):.3g} MPa"
    )
    if own:
        return pressure, Provenance(table.provenance.kind, f"{rated}: {table.provenance.source}")
    rule = (
        f"this size is not in the maker's table: the lowest flank pressure of its sizes, "
        f"{rated} for a nut {ratio:g} d long"
    )
    return pressure, Provenance("derived", f"{rule}: {table.provenance.source}")


def _thrust_rated(variant: Variant, fields: Mapping[str, Sourced], series_ends: Ends) -> Variant:
    """A variant rated by its maker's thrust table, with the flank pressure in motion it
    gives this size (``dynamic_pressure``), recomputed at each end of an assumed nut
    length so that the catalog nut's rating stays the maker's thrust."""
    table = variant.fields.get("dynamic_thrust")
    if table is None:
        return variant
    d_m, pitch_m = fields["outer_diameter"].value, fields["pitch"].value
    length_m = fields["nut_length"].value
    pressure, prov = thrust_pressure(table, d_m, pitch_m, length_m)
    ends = dict(variant.ends)
    for name, pair in series_ends.items():
        if any("nut_length_m" in end for end in pair):
            low, high = (
                {
                    **end,
                    "dynamic_pressure_pa": thrust_pressure(
                        table, d_m, pitch_m, end["nut_length_m"]
                    )[0],
                }
                if "nut_length_m" in end
                else end
                for end in pair
            )
            ends[name] = (low, high)
    rated = {**variant.fields, "dynamic_pressure": Sourced(pressure, "Pa", prov)}
    return replace(variant, fields=rated, ends=ends)


@dataclass(frozen=True, slots=True)
class _Context:
    """What every candidate of one series shares beyond its fields."""

    offered: Provenance
    ends: Ends


def _check_bearing(entry: Entry, fields: Mapping[str, Sourced], variants: list[Variant]) -> None:
    """A nut rated by contact pressure needs the engaged area: pitch and nut length."""
    by_pressure = {"bearing_pressure", "dynamic_thrust", *BEARING_VALUES}
    rated = [v.key for v in variants if by_pressure & v.fields.keys()]
    if rated and not {"pitch", "nut_length"} <= fields.keys():
        raise entry.fail(
            "nut_length_mm",
            f"variant '{rated[0]}' is rated by contact pressure: give pitch_mm and "
            "nut_length_mm or nut_length_to_d",
        )


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
    material = _material(entry, materials)
    fields = {**_geometry_fields(entry, family, material), **_other_fields(entry)}
    if family.traverse is not None:
        fields["traverse_speed"] = family.traverse
    variants = _variants(entry, family)
    _check_bearing(entry, fields, variants)
    _check_static_friction(entry, fields, variants)
    series_ends = _series_ends(entry, family, material)
    variants = [_thrust_rated(v, fields, series_ends) for v in variants]
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
