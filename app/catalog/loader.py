"""Load the built-in catalog and any extra directories into one ``Catalog``."""

import hashlib
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from app.catalog.ball import build_ball_series, is_ball_family
from app.catalog.catalog import Catalog
from app.catalog.entry import Entry
from app.catalog.errors import CatalogError
from app.catalog.family import build_family
from app.catalog.files import (
    FAMILY_KEYS,
    GROUP_FILE,
    CatalogFile,
    as_user,
    catalog_dirs,
    check_shape,
    layer_of,
    nested,
    over,
    read_file,
    toml_files,
)
from app.catalog.groups import Groups, read_group
from app.catalog.models import Ends, Material, Series, Sourced
from app.catalog.motors import MOTOR_FILE, load_library
from app.catalog.own import nut_materials
from app.catalog.series import build_series
from app.catalog.supports import SUPPORT_FILE, load_support_library
from app.core.index import CatalogIndex
from app.core.units import to_si
from app.paths import resource_dir

USER = "user"
MATERIAL_FIELDS = frozenset(
    {
        "youngs_modulus_gpa",
        "density_kg_m3",
        "expansion_per_c",
        "yield_strength_mpa",
        "thermal_conductivity_w_m_k",
    }
)


#: Material values a range may be given for: the ScrewSpec field each sets and the
#: catalog's unit. Not the density, whose range no variant carries: a screw's inertia is
#: derived from it, and is not re-derived at an end.
RANGED_MATERIAL = {
    "youngs_modulus_gpa": ("youngs_modulus_pa", "GPa"),
    "expansion_per_c": ("screw_expansion_per_k", ""),
    "yield_strength_mpa": ("yield_strength_pa", "MPa"),
    "thermal_conductivity_w_m_k": ("thermal_conductivity_w_m_k", ""),
}


def _material_ends(entry: Entry) -> Ends:
    """For each ranged material value, its ScrewSpec field at the low and the high end
    (a range on the density is refused: it would be left out of the robustness)."""
    if entry.ends("density_kg_m3") is not None:
        raise entry.fail("density_kg_m3", "a range is not screened here: give the value alone")
    out = {}
    for name, (spec_field, unit) in RANGED_MATERIAL.items():
        span = entry.ends(name)
        if span is not None:
            out[name] = ({spec_field: to_si(span[0], unit)}, {spec_field: to_si(span[1], unit)})
    return out


def _material(file: str, name: str, table: Mapping[str, Any]) -> Material:
    entry = Entry(file, f"materials.{name}", table)
    entry.check_known(MATERIAL_FIELDS)
    return Material(
        Sourced(
            to_si(entry.number("youngs_modulus_gpa"), "GPa"),
            "Pa",
            entry.prov("youngs_modulus_gpa"),
        ),
        Sourced(entry.number("density_kg_m3"), "kg/m3", entry.prov("density_kg_m3")),
        Sourced(entry.number("expansion_per_c"), "1/K", entry.prov("expansion_per_c")),
        (
            Sourced(
                to_si(entry.number("yield_strength_mpa"), "MPa"),
                "Pa",
                entry.prov("yield_strength_mpa"),
            )
            if "yield_strength_mpa" in table
            else None
        ),
        (
            Sourced(
                entry.number("thermal_conductivity_w_m_k"),
                "W/(m K)",
                entry.prov("thermal_conductivity_w_m_k"),
            )
            if "thermal_conductivity_w_m_k" in table
            else None
        ),
        _material_ends(entry),
    )


def _materials(sources: Iterable[CatalogFile]) -> dict[str, Material]:
    """Materials are one namespace across all files: a series names the one it uses."""
    out: dict[str, Material] = {}
    for source in sources:
        for name, table in nested(source.data, "materials", source.name).items():
            if name in out:
                raise CatalogError(source.name, f"materials.{name}", "-", "duplicate material")
            out[name] = _material(source.name, name, table)
    return out


def _series_entries(source: CatalogFile) -> list[tuple[str, dict[str, Any]]]:
    """(id, entry without its id) for each ``[[series]]`` of a family file."""
    entries = source.data.get("series")
    if not isinstance(entries, list) or not entries:
        raise CatalogError(source.name, "-", "series", "no [[series]] entries")
    out = []
    for index, raw in enumerate(entries):
        sid = raw.get("id") if isinstance(raw, dict) else None
        if not isinstance(sid, str) or not sid.strip():
            raise CatalogError(source.name, f"series[{index}]", "id", "missing or not text")
        out.append((sid, {k: v for k, v in raw.items() if k != "id"}))
    return out


def _family_series(
    source: CatalogFile, groups: Groups, materials: Mapping[str, Material]
) -> list[Series]:
    """Every series of one family file, built over the group the file layers on."""
    if is_ball_family(source):
        return build_ball_series(source, materials)
    schema = check_shape(source, FAMILY_KEYS)
    own = layer_of(source)
    family = build_family(over(groups.base_of(source, own.family, schema), own))
    return [build_series(family, sid, data, materials) for sid, data in _series_entries(source)]


def _unique(series: Iterable[Series]) -> dict[str, Series]:
    """Family ids (each declared by one file), series ids and candidate ids are unique
    across every directory: a user's family with a built-in family's id would otherwise
    join it silently, in the family filter and on the catalog page."""
    by_series: dict[str, Series] = {}
    owner: dict[str, Series] = {}
    family_file: dict[str, str] = {}
    for s in series:
        declared = family_file.setdefault(s.family, s.file)
        if declared != s.file:
            raise CatalogError(
                s.file, "family", "id", f"family id '{s.family}' is also declared in {declared}"
            )
        if s.id in by_series:
            raise CatalogError(s.file, s.id, "id", f"duplicate id (also in {by_series[s.id].file})")
        by_series[s.id] = s
        for screw in s.screws:
            if screw.id in owner:
                where = f"{owner[screw.id].id} in {owner[screw.id].file}"
                raise CatalogError(
                    s.file, s.id, "id_pattern", f"candidate id '{screw.id}' also made by {where}"
                )
            owner[screw.id] = s
    return by_series


def _file_default(source: CatalogFile) -> CatalogFile:
    """A file with a top-level ``provenance = "user"``: every value in it that names no
    provenance is the user's own (catalog/README.md, "Your own catalog")."""
    if "provenance" not in source.data:
        return source
    if source.data["provenance"] != USER:
        raise CatalogError(
            source.name, "-", "provenance", f'a file-wide provenance must be "{USER}"'
        )
    return CatalogFile(source.name, source.directory, as_user(source.data, source.name))


def load_catalog(extra_dirs: Iterable[Path] = ()) -> Catalog:
    """Load the built-in catalog and any extra directories; raise CatalogError on any fault."""
    digest = hashlib.sha256()
    directories = catalog_dirs([resource_dir("catalog"), *map(Path, extra_dirs)])
    sources = [
        _file_default(read_file(path, digest))
        for directory in directories
        for path in toml_files(directory)
        if path.name not in (MOTOR_FILE, SUPPORT_FILE)
    ]
    motors = load_library(directories, digest)
    supports = load_support_library(directories, digest)
    group_files = [s for s in sources if s.name == GROUP_FILE]
    groups = Groups([read_group(s) for s in group_files])
    materials = _materials(sources)
    series = [
        s
        for source in sources
        if source.name != GROUP_FILE
        for s in _family_series(source, groups, materials)
    ]
    by_series = _unique(series)
    screws = tuple(screw for s in by_series.values() for screw in s.screws)
    versions = [s.data["catalog_version"] for s in group_files if "catalog_version" in s.data]
    return Catalog(
        version=f"{versions[0] if versions else 'catalog'}+{digest.hexdigest()[:8]}",
        series=by_series,
        screws=screws,
        index=CatalogIndex.build(screws),
        materials=materials,
        by_id={screw.id: screw for screw in screws},
        motors=motors,
        supports=supports,
        nut_materials=nut_materials(by_series.values()),
    )
