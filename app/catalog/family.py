"""A family's own declarations: thread form, id pattern, nut types, variants and rules.

Nothing here is specific to one maker: the seed's coatings, its traverse-speed table and
its length and oil rules are data in ``catalog/common.toml``, read by the same code that reads
any other family (catalog/README.md, "Family files").
"""

import re
import string
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.files import Layer
from app.catalog.models import Sourced
from app.core.units import from_si, to_si

DECLARATIONS = frozenset({"id", "name", "extends", "id_pattern", "thread_form"})
VARIANT_FIELDS = frozenset(
    {
        "suffix",
        "field_suffix",
        "coated",
        "oil_compatible",
        "lubricated_rating",
        "friction_dynamic",
        "pv_limit_mpa_m_s",
        "max_length_mm",
        "life_million_cm",
        "friction_static",
        "dry_friction_dynamic",
        "dry_friction_static",
        "nut_material",
        "bearing_pressure_mpa_by_speed_m_s",
        "max_pressure_mpa",
        "dynamic_pressure_mpa",
        "dynamic_thrust_n_by_size",
        "bearing_pv_limit_mpa_m_s",
        "max_sliding_speed_m_s",
        "temperature_range_c",
        "specific_wear_rate_mm3_n_m",
        "allowed_wear_to_flank_height",
    }
)
TRAVERSE_RULE = "traverse_speed"
TRAVERSE_FIELD = "bands_lead_mm_speed_mm_s"
RULES = {TRAVERSE_RULE: frozenset({TRAVERSE_FIELD})}
#: A candidate's id has at most this many characters (the built-in ones up to 22): ids
#: go in links, tables and file names.
MAX_ID_CHARS = 60
#: Placeholders an id pattern may use; anything else (attribute walks included) is refused.
ID_FIELDS = frozenset(
    {
        "series",
        "lead_mm",
        "d_mm",
        "pitch_mm",
        "starts",
        "multi_start",
        "variant",
        "variant.key",
        "variant.suffix",
    }
)


@dataclass(frozen=True, slots=True)
class IdVariant:
    """The ``variant`` of an id pattern: ``{variant}`` is its key, ``.suffix`` its suffix."""

    key: str
    suffix: str

    def __format__(self, spec: str) -> str:
        return format(self.key, spec)


@dataclass(frozen=True, slots=True)
class Family:
    """One family file resolved over its group: everything its series share."""

    id: str
    name: str
    file: str
    id_pattern: str
    thread_form: Sourced
    half_angle_deg: Sourced
    anti_backlash_by_type: Mapping[str, bool]
    variants: Mapping[str, Mapping[str, Any]]
    traverse: Sourced | None
    defaults: Mapping[str, Any]

    def screw_id(
        self, series: str, lead_m: float, d_m: float, variant: IdVariant, pitch_m: float | None
    ) -> str:
        """A candidate's id from the family's pattern (seed: ``B4000-L2-TFE``; ISO:
        ``Tr8x8(P2)-acetal``, where ``{multi_start}`` is "(P2)" for a multi-start screw
        and empty for a single start). Without a pitch, the pitch is the lead."""
        lead_mm = from_si(lead_m, "mm")
        pitch_mm = lead_mm if pitch_m is None else from_si(pitch_m, "mm")
        starts = round(lead_mm / pitch_mm)
        made = self.id_pattern.format(
            series=series,
            lead_mm=lead_mm,
            d_mm=from_si(d_m, "mm"),
            pitch_mm=pitch_mm,
            starts=starts,
            multi_start=f"(P{pitch_mm:g})" if starts > 1 else "",
            variant=variant,
        )
        if len(made) > MAX_ID_CHARS:
            raise CatalogError(
                self.file, series, "id_pattern", f"id longer than {MAX_ID_CHARS}: {made[:40]}..."
            )
        return made


def _id_pattern(entry: Entry) -> str:
    """The id pattern, checked once here so that no candidate's id can fail later; a
    field width or precision of three digits or more is refused before any id is made
    (``{lead_mm:99999999999}`` would ask for 100 GB)."""
    pattern = entry.plain_text("id_pattern")
    try:
        parts = [(name, spec) for _, name, spec, _ in string.Formatter().parse(pattern)]
    except ValueError as exc:
        raise entry.fail("id_pattern", f"not a usable format string: {exc}") from exc
    names = {name for name, _ in parts if name is not None}
    unknown = names - ID_FIELDS
    if unknown:
        raise entry.fail("id_pattern", f"unknown placeholder {sorted(unknown)[0]!r}")
    for name, spec in parts:
        if spec and ("{" in spec or re.search(r"[0-9]{3}", spec)):
            why = "a width or precision of at most 99, without placeholders"
            raise entry.fail("id_pattern", f"{{{name}:{spec[:20]}}}: {why}")
    try:
        sample = {"pitch_mm": 1.0, "starts": 1, "multi_start": ""}
        pattern.format(series="S", lead_mm=1.0, d_mm=1.0, variant=IdVariant("v", "-V"), **sample)
    except (ValueError, IndexError) as exc:
        raise entry.fail("id_pattern", f"not a usable format string: {exc}") from exc
    if "lead_mm" not in names:
        raise entry.fail("id_pattern", "must contain {lead_mm}, or leads would share an id")
    return pattern


def _thread_form(entry: Entry) -> tuple[Sourced, Sourced]:
    """Thread form name and flank half-angle; the core's torque and efficiency use it."""
    prov = entry.prov("thread_form")
    half_angle = entry.number("thread_form", "half_angle_deg", allow_zero=True)
    if half_angle >= 45:
        raise entry.fail("thread_form", "half_angle_deg must be below 45 degrees")
    name = entry.text("thread_form", key="name")
    return Sourced(name, "", prov), Sourced(half_angle, "deg", prov)


def _nut_types(layer: Layer) -> dict[str, bool]:
    """Nut type name -> anti-backlash; a series' ``type`` must be one of these."""
    if not layer.nut_types:
        raise CatalogError(layer.file, "nut_types", "-", "no [nut_types.NAME] declared")
    out = {}
    for name, table in layer.nut_types.items():
        entry = Entry(layer.file, f"nut_types.{name}", table)
        entry.check_known(frozenset({"anti_backlash"}))
        out[name] = entry.plain_flag("anti_backlash")
    return out


def _traverse(layer: Layer) -> Sourced | None:
    """The recommended-speed table by lead in SI, or None when the family has none."""
    for name, table in layer.rules.items():
        if name not in RULES:
            raise CatalogError(
                layer.file, "rules", name, f"unknown rule (known: {', '.join(RULES)})"
            )
        Entry(layer.file, f"rules.{name}", table).check_known(RULES[name])
    if TRAVERSE_RULE not in layer.rules:
        return None
    entry = Entry(layer.file, f"rules.{TRAVERSE_RULE}", layer.rules[TRAVERSE_RULE])
    rows = entry.rows(TRAVERSE_FIELD, 3)
    if not rows:
        raise entry.fail(TRAVERSE_FIELD, "needs at least one band")
    previous_to = 0.0
    for low, high, speed in rows:
        if not (low < high and speed > 0 and low >= previous_to - 1e-12):
            raise entry.fail(TRAVERSE_FIELD, "bands must run upward in lead, from < to, speed > 0")
        previous_to = high
    bands = tuple(
        (to_si(low, "mm"), to_si(high, "mm"), to_si(speed, "mm/s")) for low, high, speed in rows
    )
    return Sourced(bands, "m, m, m/s", entry.prov(TRAVERSE_FIELD))


def _variants(layer: Layer) -> dict[str, Mapping[str, Any]]:
    """The declared variants, with their field names checked (values are read per series)."""
    if not layer.variants:
        raise CatalogError(layer.file, "variants", "-", "no [variants.NAME] declared")
    for key, table in layer.variants.items():
        Entry(layer.file, f"variants.{key}", table).check_known(VARIANT_FIELDS)
    return dict(layer.variants)


def build_family(layer: Layer) -> Family:
    """A family from its file's layer merged over its group's (``groups.Groups.base_of``,
    ``files.over``)."""
    entry = Entry(layer.file, "family", layer.family)
    entry.check_known(DECLARATIONS)
    family_id = entry.plain_text("id")
    if not family_id.strip():
        raise entry.fail("id", "must not be empty")
    thread_form, half_angle = _thread_form(entry)
    return Family(
        id=family_id,
        name=entry.plain_text("name", family_id),
        file=layer.file,
        id_pattern=_id_pattern(entry),
        thread_form=thread_form,
        half_angle_deg=half_angle,
        anti_backlash_by_type=_nut_types(layer),
        variants=_variants(layer),
        traverse=_traverse(layer),
        defaults=layer.defaults,
    )
