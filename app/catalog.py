"""The only reader of ``catalog/``: load, validate, derive and expand into candidates.

Layering per directory: ``common.toml`` [defaults] < a family file's [defaults] < the
series entry. An extra directory given by the user is merged in; its own
``common.toml`` layers over the built-in one for its files. Any error stops start-up
with the file, the entry and the field named (``CatalogError``).
"""

import hashlib
import math
import tomllib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from app.core import geometry, pv
from app.core.model import Provenance, ScrewSpec
from app.core.table import CandidateTable
from app.paths import resource_dir

PROVENANCE_KINDS = ("seed", "handbook", "derived", "assumed")
SERIES_TYPES = ("free-wheeling", "anti-backlash")
COATINGS = ("none", "tfe")
MM = 1e-3
INCHES_PER_M = 1 / 0.0254
COMMON = "common.toml"
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
        "life_million_cm_uncoated",
        "life_million_cm_tfe",
        "screw_material",
        "nut_material",
        "thread_half_angle_deg",
        "friction_static",
        "friction_dynamic_uncoated",
        "friction_dynamic_tfe",
        "pv_limit_uncoated_mpa_m_s",
        "pv_limit_tfe_mpa_m_s",
        "max_length_uncoated_mm",
        "max_length_tfe_mm",
        "coatings",
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
#: Seed table "Traverse Speed": (lead from [m], lead to [m], max linear speed [m/s]).
SEED_TRAVERSE_BANDS: tuple[tuple[float, float, float], ...] = (
    (0.0025, 0.012, 0.100),
    (0.012, 0.025, 0.250),
    (0.025, 0.060, 0.760),
)
UNRATED_LIFE = Provenance(
    "derived",
    "no life rating in the catalog for this series (the seed lists N/A for the "
    "free-wheeling B series)",
)


class CatalogError(ValueError):
    """A catalog file that cannot be used; the message names file, entry and field."""

    def __init__(self, file: str, entry: str, field_name: str, reason: str) -> None:
        self.file, self.entry, self.field, self.reason = file, entry, field_name, reason
        super().__init__(f"{file}: entry '{entry}': field '{field_name}': {reason}")


@dataclass(frozen=True, slots=True)
class Sourced:
    """A catalog value with its unit and provenance, as shown to users."""

    value: Any
    unit: str
    provenance: Provenance


@dataclass(frozen=True, slots=True)
class Series:
    """One catalog series (one size): display fields with provenance, and its screws."""

    id: str
    name: str
    family: str
    family_name: str
    type: str
    file: str
    fields: Mapping[str, Sourced]
    screws: tuple[ScrewSpec, ...]


@dataclass(frozen=True, slots=True)
class Catalog:
    """Every series, every expanded candidate, and the candidates as screening columns."""

    version: str
    series: Mapping[str, Series]
    screws: tuple[ScrewSpec, ...]
    table: CandidateTable
    materials: Mapping[str, "Material"]
    by_id: Mapping[str, ScrewSpec] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Material:
    youngs_modulus_pa: Sourced
    density_kg_m3: Sourced
    expansion_per_k: Sourced


class _Entry:
    """Reads typed fields of one merged series entry, naming the place on error."""

    def __init__(self, file: str, entry: str, data: Mapping[str, Any]) -> None:
        self.file, self.entry, self.data = file, entry, data

    def fail(self, name: str, reason: str) -> CatalogError:
        return CatalogError(self.file, self.entry, name, reason)

    def leaf(self, name: str) -> Mapping[str, Any]:
        if name not in self.data:
            raise self.fail(name, "missing")
        raw = self.data[name]
        if not isinstance(raw, Mapping):
            raise self.fail(name, "must be a table {value = ..., provenance = ..., source = ...}")
        kind = raw.get("provenance")
        if kind not in PROVENANCE_KINDS:
            raise self.fail(name, f"provenance must be one of {', '.join(PROVENANCE_KINDS)}")
        source = raw.get("source")
        if kind != "seed" and not (isinstance(source, str) and source.strip()):
            raise self.fail(name, f"a '{kind}' value needs a source or rule")
        return raw

    def prov(self, name: str) -> Provenance:
        raw = self.leaf(name)
        return Provenance(raw["provenance"], str(raw.get("source", "seed pages")))

    def number(
        self, name: str, key: str = "value", *, positive: bool = True, allow_zero: bool = False
    ) -> float:
        raw = self.leaf(name)
        value = raw.get(key)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(name, f"'{key}' must be a number")
        value = float(value)
        if not math.isfinite(value):
            raise self.fail(name, f"'{key}' must be finite")
        if positive and (value < 0 or (value == 0 and not allow_zero)):
            raise self.fail(
                name, f"'{key}' must be {'>= 0' if allow_zero else '> 0'}, got {value:g}"
            )
        return value

    def range(self, name: str) -> tuple[float, float]:
        low = self.number(name, "min", allow_zero=True)
        high = self.number(name, "max", allow_zero=True)
        if low > high:
            raise self.fail(name, f"min {low:g} is above max {high:g}")
        return low, high

    def text(self, name: str, choices: Iterable[str] | None = None) -> str:
        value = self.leaf(name).get("value")
        if not isinstance(value, str):
            raise self.fail(name, "'value' must be text")
        if choices is not None and value not in choices:
            raise self.fail(name, f"must be one of {', '.join(choices)}, got '{value}'")
        return value

    def pairs(self, name: str) -> tuple[tuple[float, float], ...]:
        value = self.leaf(name).get("value")
        ok = isinstance(value, list) and all(
            isinstance(pair, list)
            and len(pair) == 2
            and all(
                isinstance(x, int | float)
                and not isinstance(x, bool)
                and math.isfinite(x)
                and x >= 0
                for x in pair
            )
            for pair in value
        )
        if not ok or not isinstance(value, list):
            raise self.fail(name, "'value' must be a list of [number, number] pairs >= 0")
        return tuple((float(a), float(b)) for a, b in value)

    def check_known(self, known: frozenset[str]) -> None:
        """Every field of the entry is one the loader reads (catches misspelt names)."""
        for name in self.data:
            if name not in known:
                raise self.fail(name, "unknown field (see catalog/README.md for the fields)")

    def numbers(self, name: str) -> list[float]:
        value = self.leaf(name).get("value")
        if not isinstance(value, list) or not value:
            raise self.fail(name, "'value' must be a non-empty list of numbers")
        out = []
        for item in value:
            if isinstance(item, bool) or not isinstance(item, int | float):
                raise self.fail(name, "every item must be a number")
            if not (math.isfinite(item) and item > 0):
                raise self.fail(name, f"every item must be finite and > 0, got {item}")
            out.append(float(item))
        return out


def _read_toml(path: Path) -> dict[str, Any]:
    try:
        with path.open("rb") as handle:
            return tomllib.load(handle)
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(path.name, "-", "-", f"invalid TOML: {exc}") from exc


def _materials(path: Path, data: Mapping[str, Any]) -> dict[str, Material]:
    out = {}
    for name, table in data.get("materials", {}).items():
        entry = _Entry(path.name, f"materials.{name}", table)
        out[name] = Material(
            Sourced(
                entry.number("youngs_modulus_gpa") * 1e9, "Pa", entry.prov("youngs_modulus_gpa")
            ),
            Sourced(entry.number("density_kg_m3"), "kg/m3", entry.prov("density_kg_m3")),
            Sourced(entry.number("expansion_per_c"), "1/K", entry.prov("expansion_per_c")),
        )
    return out


def _derived(source: str) -> Provenance:
    return Provenance("derived", source)


def _build_series(
    file: str, family: Mapping[str, Any], entry: _Entry, materials: Mapping[str, Material]
) -> Series:
    """Validate one merged entry, derive what it leaves out, expand leads x coatings."""
    sid = entry.entry
    entry.check_known(SERIES_FIELDS)
    kind = entry.text("type", SERIES_TYPES)
    od_m = entry.number("outer_diameter_mm") * MM
    if "root_diameter_mm" in entry.data:
        rd_m = entry.number("root_diameter_mm") * MM
        rd_prov = entry.prov("root_diameter_mm")
    else:
        ratio = entry.number("root_diameter_ratio")
        rd_m = ratio * od_m
        rd_prov = Provenance(
            "assumed", f"{ratio:g} x OD: {entry.prov('root_diameter_ratio').source}"
        )
    if rd_m >= od_m:
        field_name = (
            "root_diameter_mm" if "root_diameter_mm" in entry.data else ("root_diameter_ratio")
        )
        raise entry.fail(field_name, "root diameter must be below the outer diameter")
    material_name = entry.text("screw_material")
    if material_name not in materials:
        raise entry.fail("screw_material", f"unknown material '{material_name}'")
    material = materials[material_name]
    inertia_per_m = entry.number("inertia_kg_m2_per_in") * INCHES_PER_M
    half_angle = entry.number("thread_half_angle_deg", allow_zero=True)
    if half_angle >= 45:
        raise entry.fail("thread_half_angle_deg", "must be below 45 degrees")
    friction_static = entry.number("friction_static")
    drag_min, drag_max = entry.range("drag_torque_nm")
    backlash_min, backlash_max = entry.range("backlash_mm")
    t_min, t_max = (
        entry.range("temperature_range_c") if "temperature_range_c" in entry.data else (None, None)
    )
    coatings = entry.leaf("coatings").get("value")
    if not isinstance(coatings, list) or not coatings or any(c not in COATINGS for c in coatings):
        raise entry.fail("coatings", f"'value' must be a list drawn from {', '.join(COATINGS)}")
    max_lead_m = entry.number("max_lead_to_od") * od_m
    leads_m = [x * MM for x in entry.numbers("leads_mm") if x * MM <= max_lead_m + 1e-12]

    d_p = geometry.pitch_diameter(od_m, rd_m)
    h = geometry.thread_depth(od_m, rd_m)
    if "design_load_n" in entry.data:
        design_load, design_prov = entry.number("design_load_n"), entry.prov("design_load_n")
    else:
        pressure = entry.number("design_contact_pressure_mpa") * 1e6
        factor = entry.number("design_load_factor")
        design_load = factor * pressure * pv.contact_area(math.pi * d_p, h)
        design_prov = _derived(
            f"{factor:g} x {pressure / 1e6:g} MPa x 3 pi d_p h (seed three-thread area; "
            f"pressure and factor assumed)"
        )
    outgassing = entry.pairs("outgassing_percent")

    fields: dict[str, Sourced] = {
        "type": Sourced(kind, "", entry.prov("type")),
        "outer_diameter": Sourced(od_m, "m", entry.prov("outer_diameter_mm")),
        "root_diameter": Sourced(rd_m, "m", rd_prov),
        "pitch_diameter": Sourced(d_p, "m", _derived("(OD + RD) / 2 (seed P_o)")),
        "inertia_per_length": Sourced(inertia_per_m, "kg m2/m", entry.prov("inertia_kg_m2_per_in")),
        "youngs_modulus": material.youngs_modulus_pa,
        "density": material.density_kg_m3,
        "screw_expansion": material.expansion_per_k,
        "thread_half_angle": Sourced(half_angle, "deg", entry.prov("thread_half_angle_deg")),
        "friction_static": Sourced(friction_static, "", entry.prov("friction_static")),
        "drag_torque": Sourced((drag_min, drag_max), "N m", entry.prov("drag_torque_nm")),
        "backlash": Sourced((backlash_min * MM, backlash_max * MM), "m", entry.prov("backlash_mm")),
        "design_load": Sourced(design_load, "N", design_prov),
        "leads": Sourced(tuple(leads_m), "m", entry.prov("leads_mm")),
        "lead_accuracy": Sourced(
            entry.number("lead_accuracy_mm_per_mm"), "m/m", entry.prov("lead_accuracy_mm_per_mm")
        ),
        "repeatability": Sourced(
            entry.number("repeatability_mm") * MM, "m", entry.prov("repeatability_mm")
        ),
        "nut_material": Sourced(entry.text("nut_material"), "", entry.prov("nut_material")),
        "screw_material": Sourced(material_name, "", entry.prov("screw_material")),
        "straightness": Sourced(
            entry.number("straightness_mm_per_300mm") * MM / 0.3,
            "m/m",
            entry.prov("straightness_mm_per_300mm"),
        ),
        "nut_expansion": Sourced(
            entry.number("nut_expansion_per_c"), "1/K", entry.prov("nut_expansion_per_c")
        ),
        "nut_tensile_strength": Sourced(
            entry.number("nut_tensile_strength_mpa") * 1e6,
            "Pa",
            entry.prov("nut_tensile_strength_mpa"),
        ),
        "outgassing": Sourced(outgassing, "h, %", entry.prov("outgassing_percent")),
    }
    if t_min is not None:
        fields["temperature_range"] = Sourced(
            (t_min, t_max), "C", entry.prov("temperature_range_c")
        )
    variants: dict[bool, dict[str, Sourced]] = {}
    for coating in coatings:
        key = "tfe" if coating == "tfe" else "uncoated"
        coated = coating == "tfe"
        v = {
            "friction_dynamic": Sourced(
                entry.number(f"friction_dynamic_{key}"), "", entry.prov(f"friction_dynamic_{key}")
            ),
            "pv_limit": Sourced(
                entry.number(f"pv_limit_{key}_mpa_m_s") * 1e6,
                "Pa m/s",
                entry.prov(f"pv_limit_{key}_mpa_m_s"),
            ),
            "max_length": Sourced(
                entry.number(f"max_length_{key}_mm") * MM, "m", entry.prov(f"max_length_{key}_mm")
            ),
        }
        if f"life_million_cm_{key}" in entry.data:
            low, high = entry.range(f"life_million_cm_{key}")
            v["life"] = Sourced((low * 1e4, high * 1e4), "m", entry.prov(f"life_million_cm_{key}"))
        variants[coated] = v
        fields.update({f"{name}_{key}": value for name, value in v.items()})

    name = str(family.get("series_names", {}).get(sid, entry.data.get("name", sid)))
    screws = []
    for lead in leads_m:
        for coated, v in variants.items():
            prov = {k: s.provenance for k, s in fields.items()}
            prov.update({k: s.provenance for k, s in v.items()})
            prov.setdefault("life", UNRATED_LIFE)
            prov["lead"] = entry.prov("leads_mm")
            prov["coating"] = entry.prov("coatings")
            prov["oil_compatible"] = entry.prov("coatings")
            prov["traverse_speed"] = Provenance("seed", "Traverse Speed table")
            life = v.get("life")
            screws.append(
                ScrewSpec(
                    id=f"{sid}-L{lead / MM:g}" + ("-TFE" if coated else ""),
                    series_id=sid,
                    series_name=name,
                    anti_backlash=kind == "anti-backlash",
                    coated=coated,
                    outer_diameter_m=od_m,
                    root_diameter_m=rd_m,
                    lead_m=lead,
                    thread_half_angle_rad=math.radians(half_angle),
                    friction_static=friction_static,
                    friction_dynamic=v["friction_dynamic"].value,
                    youngs_modulus_pa=material.youngs_modulus_pa.value,
                    density_kg_m3=material.density_kg_m3.value,
                    screw_expansion_per_k=material.expansion_per_k.value,
                    inertia_kg_m2_per_m=inertia_per_m,
                    drag_torque_min_nm=drag_min,
                    drag_torque_max_nm=drag_max,
                    pv_limit_pa_m_s=v["pv_limit"].value,
                    design_load_n=design_load,
                    max_length_m=v["max_length"].value,
                    backlash_min_m=backlash_min * MM,
                    backlash_max_m=backlash_max * MM,
                    life_min_m=life.value[0] if life else None,
                    life_max_m=life.value[1] if life else None,
                    lead_accuracy_m_per_m=fields["lead_accuracy"].value,
                    repeatability_m=fields["repeatability"].value,
                    temperature_min_c=t_min,
                    temperature_max_c=t_max,
                    oil_compatible=not coated,
                    outgassing=outgassing,
                    material_name=material_name,
                    nut_material=fields["nut_material"].value,
                    family_id=str(family.get("id", file)),
                    variant=coating,
                    traverse_bands=SEED_TRAVERSE_BANDS,
                    provenance=prov,
                )
            )
    return Series(
        id=sid,
        name=name,
        family=str(family.get("id", file)),
        family_name=str(family.get("name", family.get("id", file))),
        type=kind,
        file=file,
        fields=fields,
        screws=tuple(screws),
    )


def _load_dir(
    directory: Path,
    base_defaults: Mapping[str, Any],
    base_materials: Mapping[str, Material],
    digest: Any,
) -> tuple[list[Series], dict[str, Material], str | None]:
    if not directory.is_dir():
        raise CatalogError(str(directory), "-", "-", "catalog directory not found")
    defaults = dict(base_defaults)
    materials = dict(base_materials)
    version = None
    common = directory / COMMON
    if common.is_file():
        digest.update(common.read_bytes())
        data = _read_toml(common)
        defaults.update(data.get("defaults", {}))
        for name, material in _materials(common, data).items():
            if name in materials:
                raise CatalogError(COMMON, f"materials.{name}", "-", "duplicate material")
            materials[name] = material
        version = data.get("catalog_version")
    series = []
    for path in sorted(directory.glob("*.toml")):
        if path.name == COMMON:
            continue
        digest.update(path.read_bytes())
        data = _read_toml(path)
        family = data.get("family", {})
        file_defaults = {**defaults, **data.get("defaults", {})}
        entries = data.get("series")
        if not isinstance(entries, list) or not entries:
            raise CatalogError(path.name, "-", "series", "no [[series]] entries")
        for index, raw in enumerate(entries):
            sid = raw.get("id") if isinstance(raw, dict) else None
            if not isinstance(sid, str) or not sid.strip():
                raise CatalogError(path.name, f"series[{index}]", "id", "missing or not text")
            merged = {**file_defaults, **{k: v for k, v in raw.items() if k != "id"}}
            series.append(
                _build_series(path.name, family, _Entry(path.name, sid, merged), materials)
            )
    return series, materials, version


def load_catalog(extra_dirs: Iterable[Path] = ()) -> Catalog:
    """Load the built-in catalog and any extra directories; raise CatalogError on any fault."""
    digest = hashlib.sha256()
    builtin = resource_dir("catalog")
    series, materials, version = _load_dir(builtin, {}, {}, digest)
    base_defaults = _read_toml(builtin / COMMON).get("defaults", {})
    for directory in extra_dirs:
        more, materials, _ = _load_dir(Path(directory), base_defaults, materials, digest)
        series.extend(more)
    by_series: dict[str, Series] = {}
    for s in series:
        if s.id in by_series:
            raise CatalogError(s.file, s.id, "id", f"duplicate id (also in {by_series[s.id].file})")
        by_series[s.id] = s
    screws = tuple(screw for s in by_series.values() for screw in s.screws)
    return Catalog(
        version=f"{version or 'catalog'}+{digest.hexdigest()[:8]}",
        series=by_series,
        screws=screws,
        table=CandidateTable.build(screws),
        materials=materials,
        by_id={screw.id: screw for screw in screws},
    )
