"""A series' screw: its diameters, thread, leads, inertia and design load, its
material, and the accuracy, nut and environment values shown with it; each derived
value's provenance names its rule (catalog/README.md "Rules")."""

import math
from collections.abc import Mapping

from app.catalog.entry import Entry, optional, sourced
from app.catalog.family import Family
from app.catalog.models import Material, Sourced
from app.core.formulas import geometry, pv, torque, trapezoidal
from app.core.model import Provenance
from app.core.phrase import in_words
from app.core.units import from_si, to_si

#: Thread starts at most: a lead of thousands of pitches is a typing error, and its
#: numbers (a screw turning once per kilometre) would fail later, at a request.
MAX_STARTS = 16


#: Half-angle of the ISO 2904 trapezoidal thread, the only form ``pitch_mm`` describes.
ISO_HALF_ANGLE_DEG = 15.0


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
        root = sourced(entry, rd_name, "mm")
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


def _design_load(entry: Entry, d_p: float, h: float, root: Provenance) -> Sourced | None:
    """Given, or derived from contact pressure over the seed's three-thread area (rule 4);
    None when the family rates its nuts otherwise (neither is given). A derived load is
    no more certain than the least certain value it is worked from (the pressure, the
    factor and the root diameter): from an assumed one, it is assumed."""
    if entry.has("design_load_n"):
        return Sourced(entry.number("design_load_n"), "N", entry.prov("design_load_n"))
    if not entry.has("design_contact_pressure_mpa"):
        return None
    pressure_mpa = entry.number("design_contact_pressure_mpa")
    factor = entry.number("design_load_factor")
    load = factor * to_si(pressure_mpa, "MPa") * pv.contact_area(math.pi * d_p, h)
    read = {
        "pressure": entry.prov("design_contact_pressure_mpa"),
        "factor": entry.prov("design_load_factor"),
        "root diameter": root,
    }
    assumed = [name for name, p in read.items() if p.kind == "assumed"]
    rule = f"{factor:g} x {pressure_mpa:g} MPa x 3 pi d_p h (seed three-thread area"
    if assumed:
        rule += f"; {in_words(assumed)} assumed"
    return Sourced(load, "N", Provenance("assumed" if assumed else "derived", rule + ")"))


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
    inertia = torque.solid_rod_inertia_per_length(material.density_kg_m3.value, d2.value)
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
        fields["nut_length"] = sourced(entry, "nut_length_mm", "mm")
    elif entry.has("nut_length_to_d"):
        ratio = entry.number("nut_length_to_d")
        rule = f"{ratio:g} x d: {entry.prov('nut_length_to_d').source}"
        kind = entry.prov("nut_length_to_d").kind
        fields["nut_length"] = Sourced(ratio * od_m, "m", Provenance(kind, rule))
    return fields


def screw_material(entry: Entry, materials: Mapping[str, Material]) -> Material:
    name = entry.text("screw_material")
    if name not in materials:
        raise entry.fail("screw_material", f"unknown material '{name}'")
    return materials[name]


def geometry_fields(entry: Entry, family: Family, material: Material) -> dict[str, Sourced]:
    """Size, thread, material, drag and load fields: what the core's geometry checks read."""
    od, rd = _diameters(entry)
    d_p = geometry.pitch_diameter(od.value, rd.value)
    thread = _thread_fields(entry, od.value, family)
    d2 = thread.get("flank_pitch_diameter")
    if d2 is not None and not rd.value < d2.value < od.value:
        raise entry.fail("pitch_mm", "the pitch diameter d2 must lie between root and outer")
    inertia = _inertia(entry, thread.get("flank_pitch_diameter"), material)
    low, high = entry.range("backlash_mm")
    load = _design_load(entry, d_p, geometry.thread_depth(od.value, rd.value), rd.provenance)
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
        **optional(entry, {"friction_static": ("friction_static", "")}),
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


def other_fields(entry: Entry) -> dict[str, Sourced]:
    """Accuracy, material names, nut and environment fields: shown, some checked; the
    optional ones only when the data gives them, so nothing unknown is shown as known."""
    fields = {
        **optional(entry, ACCURACY_VALUES),
        "nut_material": Sourced(entry.text("nut_material"), "", entry.prov("nut_material")),
        "screw_material": Sourced(entry.text("screw_material"), "", entry.prov("screw_material")),
        **optional(entry, NUT_VALUES),
    }
    if entry.has("outgassing_percent"):
        rows = entry.rows("outgassing_percent", 2)
        fields["outgassing"] = Sourced(rows, "h, %", entry.prov("outgassing_percent"))
    if entry.has("temperature_range_c"):
        t_range = entry.range("temperature_range_c", positive=False)
        fields["temperature_range"] = Sourced(t_range, "C", entry.prov("temperature_range_c"))
    return fields
