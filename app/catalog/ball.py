"""Ball-screw families: a maker's nut table read into one candidate per size and lead.

A ball-screw family file (``catalog/ballscrew-*.toml``) has a ``[ballscrew]`` table (the
family: its maker's accuracy grade, DN limit, equivalent friction, preload and the
source of each column of the nut table) and one ``[[nut]]`` row per nut of the maker's
table, in its units. Each value's provenance is its column's: the nut table's rows come
from one table of the maker's catalog, cited once per column.
"""

import math
from collections.abc import Mapping
from itertools import pairwise
from typing import Any

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import CatalogFile
from app.catalog.models import Material, Series, Sourced
from app.catalog.series import NOT_GIVEN
from app.core.formulas import ballscrew, column_rules, critical_speed
from app.core.model import Provenance, ScrewSpec
from app.core.record import CERTAINTY
from app.core.units import to_si

#: The table that makes a catalog file a ball-screw family.
BALL_TABLE = "ballscrew"
FILE_KEYS = frozenset({BALL_TABLE, "nut"})
FAMILY_FIELDS = frozenset(
    {
        "id",
        "name",
        "kind",
        "material",
        "anti_backlash",
        "accuracy_grade",
        "lead_accuracy_mm_per_300mm",
        "travel_deviation_mm_by_useful_travel_mm",
        "dn_limit_mm_rpm",
        "critical_speed_rule",
        "buckling_rule",
        "friction_dynamic",
        "friction_static",
        "preload_fraction",
        "preload_friction_factor",
        "temperature_range",
        "columns",
    }
)
#: A nut row's columns: name -> (unit of the row's numbers, required).
COLUMNS: Mapping[str, tuple[str, bool]] = {
    "outer_diameter_mm": ("mm", True),
    "lead_mm": ("mm", True),
    "nut_length_mm": ("mm", True),
    "root_diameter_mm": ("mm", True),
    "dynamic_load_n": ("N", True),
    "static_load_n": ("N", True),
    "axial_play_mm": ("mm", False),
    "ball_diameter_mm": ("mm", False),
    "nominal_diameter_mm": ("mm", False),
}
NUT_KEYS = frozenset({"id", "name", *COLUMNS})
#: The leadscrew's nut ratings, which a ball nut does not have (it rolls): their checks
#: do not run for a ball screw, and each candidate's provenance says why.
NOT_APPLICABLE = Provenance(
    "derived",
    "not applicable to a ball screw: a ball nut rolls, so the sliding nut's PV, flank "
    "pressure, sliding speed, wear and heat ratings do not exist for it; its limits are "
    "the L10 life (Ca), the static load rating (C0a) and the DN speed",
)
LEADSCREW_ONLY = (
    "pv_limit",
    "bearing_pressure",
    "max_pressure",
    "dynamic_pressure",
    "bearing_pv_limit",
    "max_sliding_speed",
    "design_load",
    "wear_rate",
    "allowed_wear",
    "life",
)


def is_ball_family(source: CatalogFile) -> bool:
    """Whether ``source`` is a ball-screw family file."""
    return BALL_TABLE in source.data


def _column_provenance(family: Entry) -> dict[str, Provenance]:
    """Each nut-table column's provenance (the maker's table it is read from)."""
    raw = family.data.get("columns")
    if not isinstance(raw, Mapping):
        raise family.fail("columns", "a table of the nut table's columns, each with its source")
    out = {}
    for name, required in ((n, r) for n, (_, r) in COLUMNS.items()):
        if name in raw:
            out[name] = Entry(family.file, f"{family.entry}.columns", raw).prov(name)
        elif required:
            raise family.fail("columns", f"no source for the column '{name}'")
    unknown = set(raw) - set(COLUMNS)
    if unknown:
        raise family.fail("columns", f"unknown column {sorted(unknown)[0]!r}")
    return out


def _row_value(row: Entry, name: str) -> float | None:
    """A nut row's number in SI (None: not given, for an optional column)."""
    unit, required = COLUMNS[name]
    value = row.data.get(name)
    if value is None and not required:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise row.fail(name, "must be a finite number")
    if value < 0 or (value == 0 and name != "axial_play_mm"):
        raise row.fail(name, "must be > 0")
    return to_si(float(value), unit)


def _drag_torques(family: Entry, ca_n: float, lead_m: float) -> tuple[float, float]:
    """The preloaded nut's idle torque at the low and high preload friction coefficient
    K_p [N m] (HIWIN F 3.2); 0 for a nut with play (no preload)."""
    fraction = family.number("preload_fraction", allow_zero=True)
    low, high = family.range("preload_friction_factor")
    preload_n = fraction * ca_n
    return (
        ballscrew.preload_drag_torque(low, preload_n, lead_m),
        ballscrew.preload_drag_torque(high, preload_n, lead_m),
    )


def _deviation_bands(family: Entry) -> tuple[tuple[float, float], ...]:
    """A positioning class's limit deviation e_p by useful travel (the maker's table),
    rows of (useful travel up to [m], e_p [m]); empty for a transport class (its e_p
    follows ISO 3408-3's rule, ``accuracy.ball_travel_deviation``)."""
    name = "travel_deviation_mm_by_useful_travel_mm"
    if not family.has(name):
        return ()
    rows = family.rows(name, 2)
    travels, deviations = [r[0] for r in rows], [r[1] for r in rows]
    rising = all(a < b for a, b in pairwise(travels))
    if not rows or not rising or min(travels) <= 0 or min(deviations) <= 0:
        raise family.fail(name, "rows of [useful travel up to mm, e_p mm], both > 0, travel rising")
    if any(b < a for a, b in pairwise(deviations)):
        raise family.fail(name, "e_p must not fall as the useful travel grows")
    return tuple((to_si(lu, "mm"), to_si(ep, "mm")) for lu, ep in rows)


def _temperature_range(family: Entry) -> tuple[float | None, float | None]:
    """The family's operating temperature range [deg C], (None, None) when it gives none
    (the temperature check then says it could not run)."""
    if not family.has("temperature_range"):
        return None, None
    return family.range("temperature_range", positive=False)


def _inertia_per_m(material: Material, outer_m: float) -> float:
    """Rotating inertia of the shaft per metre [kg m^2/m], a solid steel cylinder of the
    outer diameter (HIWIN F 3.21 takes the nominal diameter)."""
    return math.pi * float(material.density_kg_m3.value) * outer_m**4 / 32.0


def size_id(family_id: str, nut_id: str) -> str:
    """The series (one nominal size of the family) a nut belongs to: the family and the
    size part of the maker's article number ("HIWIN-ROLLED R16" for R16-05T3-FSIDIN), so
    that the leads of one size sweep together."""
    return f"{family_id} {nut_id.split('-', 1)[0]}"


def _spec(
    family: Entry, row: Entry, material: Material, prov: Mapping[str, Provenance]
) -> ScrewSpec:
    """One ball screw: a nut row of the family's table over the family's values."""
    od, lead = _row_value(row, "outer_diameter_mm"), _row_value(row, "lead_mm")
    root, ca = _row_value(row, "root_diameter_mm"), _row_value(row, "dynamic_load_n")
    assert od is not None and lead is not None and root is not None and ca is not None
    if root >= od:
        raise row.fail("root_diameter_mm", "must be below the outer diameter")
    play = _row_value(row, "axial_play_mm") or 0.0
    drag_min, drag_max = _drag_torques(family, ca, lead)
    t_min, t_max = _temperature_range(family)
    return ScrewSpec(
        id=row.entry,
        series_id=size_id(family.plain_text("id"), row.entry),
        series_name=row.plain_text("name", row.entry),
        anti_backlash=family.plain_flag("anti_backlash"),
        coated=False,
        outer_diameter_m=od,
        root_diameter_m=root,
        lead_m=lead,
        thread_half_angle_rad=0.0,
        friction_static=family.number("friction_static"),
        friction_dynamic=family.number("friction_dynamic"),
        youngs_modulus_pa=material.youngs_modulus_pa.value,
        density_kg_m3=material.density_kg_m3.value,
        screw_expansion_per_k=material.expansion_per_k.value,
        inertia_kg_m2_per_m=_inertia_per_m(material, od),
        drag_torque_min_nm=drag_min,
        drag_torque_max_nm=drag_max,
        backlash_min_m=0.0,
        backlash_max_m=play,
        yield_strength_pa=None
        if material.yield_strength_pa is None
        else material.yield_strength_pa.value,
        material_name=family.plain_text("material"),
        nut_material="steel",
        family_id=family.plain_text("id"),
        variant=family.plain_text("kind"),
        provenance=prov,
        nut_length_m=_row_value(row, "nut_length_mm"),
        screw_type="ball",
        dynamic_load_n=ca,
        static_load_n=_row_value(row, "static_load_n"),
        ball_diameter_m=_row_value(row, "ball_diameter_mm"),
        pitch_circle_diameter_m=_row_value(row, "nominal_diameter_mm"),
        dn_limit_mm_rpm=family.number("dn_limit_mm_rpm"),
        critical_speed_rule=family.text("critical_speed_rule", critical_speed.MAKER_RULES)
        if family.has("critical_speed_rule")
        else None,
        buckling_rule=family.text("buckling_rule", column_rules.BUCKLING_RULES)
        if family.has("buckling_rule")
        else None,
        accuracy_grade=family.text("accuracy_grade"),
        temperature_min_c=t_min,
        temperature_max_c=t_max,
        preload_n=family.number("preload_fraction", allow_zero=True) * ca,
        travel_variation_300mm_m=to_si(family.number("lead_accuracy_mm_per_300mm"), "mm"),
        travel_deviation_bands=_deviation_bands(family),
        assumption_ends=material.ends,
    )


#: Candidate fields -> the family value or nut-table column their provenance is.
FAMILY_PROVENANCE = {
    "friction_static": "friction_static",
    "friction_dynamic": "friction_dynamic",
    "lead_accuracy": "lead_accuracy_mm_per_300mm",
    "travel_deviation": "travel_deviation_mm_by_useful_travel_mm",
    "dn_limit": "dn_limit_mm_rpm",
    "critical_speed_rule": "critical_speed_rule",
    "buckling_rule": "buckling_rule",
    "accuracy_grade": "accuracy_grade",
    "preload": "preload_fraction",
    "temperature_range": "temperature_range",
}
COLUMN_PROVENANCE = {
    "outer_diameter": "outer_diameter_mm",
    "lead": "lead_mm",
    "nut_length": "nut_length_mm",
    "root_diameter": "root_diameter_mm",
    "dynamic_load": "dynamic_load_n",
    "static_load": "static_load_n",
    "backlash": "axial_play_mm",
    "ball_diameter": "ball_diameter_mm",
    "pitch_diameter": "nominal_diameter_mm",
}


def _provenance(
    family: Entry, columns: Mapping[str, Provenance], material: Material
) -> dict[str, Provenance]:
    """Each candidate field's provenance: its column's, the family value's, the
    material's, or 'not applicable to a ball screw' for a leadscrew's nut rating."""
    prov = {name: NOT_APPLICABLE for name in LEADSCREW_ONLY}
    prov.update({k: columns[c] for k, c in COLUMN_PROVENANCE.items() if c in columns})
    prov.update({k: family.prov(v) for k, v in FAMILY_PROVENANCE.items() if family.has(v)})
    prov.update(_preload_provenance(family, columns))
    prov["thread_half_angle"] = Provenance(
        "derived", "rolling contact: the thread-efficiency formula with a 0 flank angle"
    )
    prov["youngs_modulus"] = material.youngs_modulus_pa.provenance
    prov["density"] = material.density_kg_m3.provenance
    prov["screw_expansion"] = material.expansion_per_k.provenance
    not_published = Provenance(
        "derived", "not published in the maker's ball-screw table: the checks go without it"
    )
    for name in ("max_length", "repeatability", "temperature_range", "pitch"):
        prov.setdefault(name, not_published)
    prov["outgassing"] = NOT_GIVEN["outgassing"]
    prov["traverse_speed"] = NOT_APPLICABLE
    prov["type"] = Provenance("vendor", "ball screw: the maker's nut table")
    prov["oil_compatible"] = Provenance(
        "vendor", "HIWIN BS-08-2-EN-1704-K sec. 3.9: lubricated with grease or oil"
    )
    for name, value in (
        ("yield_strength", material.yield_strength_pa),
        ("thermal_conductivity", material.thermal_conductivity_w_m_k),
    ):
        if value is not None:
            prov[name] = value.provenance
    prov["inertia_per_length"] = Provenance(
        "derived", "solid shaft of the outer diameter: J/L = pi rho d^4 / 32"
    )
    return prov


def _preload_provenance(family: Entry, columns: Mapping[str, Provenance]) -> dict[str, Provenance]:
    """The provenance of what the nut's preload sets, derived and no more certain than
    what it is worked from: the idle (drag) torque from K_p and the preload (HIWIN F 3.2),
    and, where the nut table gives no axial play, a preloaded nut's zero play."""
    preload, factor = family.prov("preload_fraction"), family.prov("preload_friction_factor")
    out = {
        "drag_torque": Provenance(
            min(("derived", preload.kind, factor.kind), key=CERTAINTY.index),
            "idle torque T_d = K_p F_pr P / (2 pi), from K_p "
            f"({factor.kind}: {factor.source}) and the preload F_pr "
            f"({preload.kind}: {preload.source})",
        )
    }
    if "axial_play_mm" not in columns:
        preloaded = family.plain_flag("anti_backlash")
        out["backlash"] = Provenance(
            min(("derived", preload.kind), key=CERTAINTY.index),
            f"no axial play: a preloaded nut, its play taken up by the preload F_pr "
            f"({preload.kind}: {preload.source})"
            if preloaded
            else "no axial play column in the maker's nut table: none counted",
        )
    return out


def _each(values: list[Any]) -> Any:
    """A size's value: the one every nut has, else each nut's in the order of its leads
    (two of them read as the range of the size's nuts)."""
    return values[0] if all(v == values[0] for v in values) else values


def _display(specs: list[ScrewSpec], prov: Mapping[str, Provenance]) -> dict[str, Sourced]:
    """A size's fields as the catalog page and API show them: the family's values, the
    leads it is made in and its nuts' diameters, lengths and ratings (one value where
    every nut has it, else each nut's in the order of the leads)."""
    specs = sorted(specs, key=lambda s: s.lead_m)
    first = specs[0]
    values: dict[str, tuple[Any, str]] = {
        "screw_type": ("ball", ""),
        "leads": ([s.lead_m for s in specs], "m"),
        "outer_diameter": (_each([s.outer_diameter_m for s in specs]), "m"),
        "root_diameter": (_each([s.root_diameter_m for s in specs]), "m"),
        "ball_diameter": (_each([s.ball_diameter_m for s in specs]), "m"),
        "nut_length": (_each([s.nut_length_m for s in specs]), "m"),
        "dynamic_load": (_each([s.dynamic_load_n for s in specs]), "N"),
        "static_load": (_each([s.static_load_n for s in specs]), "N"),
        "preload": (_each([s.preload_n for s in specs]), "N"),
        "temperature_range": ((first.temperature_min_c, first.temperature_max_c), "C"),
        "dn_limit": (first.dn_limit_mm_rpm, "mm rpm"),
        "critical_speed_rule": (first.critical_speed_rule, ""),
        "buckling_rule": (first.buckling_rule, ""),
        "accuracy_grade": (first.accuracy_grade, ""),
        "lead_accuracy_per_300mm": (first.travel_variation_300mm_m, "m"),
        "travel_deviation": (first.travel_deviation_bands or None, "m"),
        "friction_dynamic": (first.friction_dynamic, ""),
        "friction_static": (first.friction_static, ""),
    }
    family_prov = Provenance("vendor", "ball screw family")
    named = {**prov, "leads": prov["lead"], "lead_accuracy_per_300mm": prov["lead_accuracy"]}
    return {
        k: Sourced(v, unit, named.get(k, family_prov))
        for k, (v, unit) in values.items()
        if v is not None
    }


def build_ball_series(source: CatalogFile, materials: Mapping[str, Material]) -> list[Series]:
    """Every nut of a ball-screw family file as one series of one candidate."""
    unknown = set(source.data) - FILE_KEYS
    if unknown:
        raise CatalogError(source.name, "-", sorted(unknown)[0], "unknown top-level key")
    family = Entry(source.name, BALL_TABLE, source.data[BALL_TABLE])
    family.check_known(FAMILY_FIELDS)
    material_name = family.plain_text("material")
    if material_name not in materials:
        raise family.fail("material", f"unknown material '{material_name}'")
    material = materials[material_name]
    prov = _provenance(family, _column_provenance(family), material)
    rows = source.data.get("nut")
    if not isinstance(rows, list) or not rows:
        raise CatalogError(source.name, "-", "nut", "no [[nut]] rows")
    sizes: dict[str, list[ScrewSpec]] = {}
    for index, raw in enumerate(rows):
        if not isinstance(raw, Mapping) or not isinstance(raw.get("id"), str):
            raise CatalogError(source.name, f"nut[{index}]", "id", "missing or not text")
        row = Entry(source.name, raw["id"], raw)
        row.check_known(NUT_KEYS)
        spec = _spec(family, row, material, prov)
        sizes.setdefault(spec.series_id, []).append(spec)
    return [
        Series(
            id=sid,
            name=sid,
            family=specs[0].family_id,
            family_name=family.plain_text("name"),
            type=f"ball screw, {specs[0].variant}",
            file=source.name,
            fields=_display(specs, prov),
            screws=tuple(sorted(specs, key=lambda s: s.lead_m)),
        )
        for sid, specs in sizes.items()
    ]
