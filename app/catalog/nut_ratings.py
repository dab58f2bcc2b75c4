"""A series' nut variants and their ratings: friction, PV limit, life, the pressure
tables by sliding speed, a maker's thrust table by size and the flank pressure it gives
a nut of another size (rule 10), the wear values, and the ends of ranged values.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from itertools import pairwise
from typing import Any

from app.catalog.entry import Entry, optional, sourced
from app.catalog.family import Family, IdVariant
from app.catalog.models import Ends, Sourced
from app.core.dry_run import DRY
from app.core.formulas import bearing, trapezoidal
from app.core.model import Provenance
from app.core.units import from_si, to_si

#: Variant values a range may be given for: ScrewSpec field and the catalog's unit.
RANGED_VARIANT = {
    "friction_dynamic": ("friction_dynamic", ""),
    "friction_static": ("friction_static", ""),
    "dry_friction_dynamic": ("dry_friction_dynamic", ""),
    "dry_friction_static": ("dry_friction_static", ""),
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


#: A nut rated lubricated (``lubricated_rating``) run dry: its running and static friction
#: (``dry_run.DRY``'s fields), read as the ranged values they are.
DRY_FRICTION = {name: RANGED_VARIANT[name] for name in DRY.values()}


#: A maker's allowable dynamic thrust of the nut by thread size, rows [d mm, P mm, N].
THRUST_TABLE = "dynamic_thrust_n_by_size"


#: Variant values that rate the nut's wear life (Archard's law, both needed).
WEAR_VALUES = {
    "wear_rate": ("specific_wear_rate_mm3_n_m", "mm³/(N m)"),
    "allowed_wear": ("allowed_wear_to_flank_height", ""),
}


@dataclass(frozen=True, slots=True)
class Variant:
    """One nut variant of one series, its values read and converted to SI."""

    key: str
    id_part: IdVariant
    field_suffix: str
    coated: bool
    fields: Mapping[str, Sourced]
    ends: Ends


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
        "friction_dynamic": sourced(v, "friction_dynamic", ""),
        "oil_compatible": Sourced(v.flag("oil_compatible"), "", v.prov("oil_compatible")),
    }
    if v.has("lubricated_rating"):
        flag = v.flag("lubricated_rating")
        fields["lubricated_rating"] = Sourced(flag, "", v.prov("lubricated_rating"))
    fields.update(_dry_friction(v, fields))
    if v.has("pv_limit_mpa_m_s"):
        fields["pv_limit"] = sourced(v, "pv_limit_mpa_m_s", "MPa m/s")
    if v.has("max_length_mm"):
        fields["max_length"] = sourced(v, "max_length_mm", "mm")
    if v.has("life_million_cm"):
        low, high = v.range("life_million_cm")
        life = (to_si(low, "million cm"), to_si(high, "million cm"))
        fields["life"] = Sourced(life, "m", v.prov("life_million_cm"))
    if v.has("friction_static"):
        fields["friction_static"] = sourced(v, "friction_static", "")
    if v.has("nut_material"):
        fields["nut_material"] = Sourced(v.text("nut_material"), "", v.prov("nut_material"))
    if v.has("bearing_pressure_mpa_by_speed_m_s"):
        fields["bearing_pressure"] = _bearing_table(v)
    if v.has(THRUST_TABLE):
        fields["dynamic_thrust"] = _thrust_table(v)
    if v.has("temperature_range_c"):
        t_range = v.range("temperature_range_c", positive=False)
        fields["temperature_range"] = Sourced(t_range, "C", v.prov("temperature_range_c"))
    fields.update(optional(v, BEARING_VALUES))
    fields.update(optional(v, WEAR_VALUES))
    if len(WEAR_VALUES.keys() & fields.keys()) == 1:
        missing = next(key for name, (key, _) in WEAR_VALUES.items() if name not in fields)
        raise v.fail(missing, "a wear rating needs both the wear rate and the allowed wear")
    if fields.get("allowed_wear") and not 0.0 < fields["allowed_wear"].value <= 1.0:
        raise v.fail("allowed_wear_to_flank_height", "must be a fraction, above 0 and at most 1")
    return fields


def _dry_friction(v: Entry, fields: Mapping[str, Sourced]) -> dict[str, Sourced]:
    """A nut rated lubricated gives its friction run dry, running and static; no other
    nut has one (an axis that runs it dry takes it, ``table.as_run``)."""
    dry = optional(v, DRY_FRICTION)
    lubricated = "lubricated_rating" in fields and fields["lubricated_rating"].value
    missing = [name for name in DRY_FRICTION if name not in dry]
    if lubricated and missing:
        raise v.fail(missing[0], "a nut rated lubricated needs its friction run dry")
    if dry and not lubricated:
        raise v.fail(next(iter(dry)), "only a nut rated lubricated has a friction run dry")
    return dry


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


def offered_variants(entry: Entry, family: Family) -> list[Variant]:
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


def thrust_rated(variant: Variant, fields: Mapping[str, Sourced], series_ends: Ends) -> Variant:
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


def check_bearing(entry: Entry, fields: Mapping[str, Sourced], variants: list[Variant]) -> None:
    """A nut rated by contact pressure needs the engaged area: pitch and nut length."""
    by_pressure = {"bearing_pressure", "dynamic_thrust", *BEARING_VALUES}
    rated = [v.key for v in variants if by_pressure & v.fields.keys()]
    if rated and not {"pitch", "nut_length"} <= fields.keys():
        raise entry.fail(
            "nut_length_mm",
            f"variant '{rated[0]}' is rated by contact pressure: give pitch_mm and "
            "nut_length_mm or nut_length_to_d",
        )
