"""The catalog data (catalog/*.toml) and its loader (app.catalog) against the seed pages,
catalog-notes.md and catalog/README.md; broken fixtures must stop the loader with the file,
the entry and the field named."""

import math
import re
import tomllib
from collections.abc import Iterable
from pathlib import Path

import pytest

from app.catalog import PROVENANCE_KINDS, Catalog, CatalogError, load_catalog
from app.core.model import ScrewSpec
from app.paths import resource_dir

CATALOG_DIR = resource_dir("catalog")
FILES = sorted(CATALOG_DIR.glob("*.toml"))
FIXTURES = Path(__file__).parents[1] / "fixtures" / "catalog_extra"
PSI_FT_MIN = 6894.757293168 * 0.00508  # Pa m/s
G = 9.80665

#: catalog-notes.md "Series in the seed" (seed table "Screw / nut series"): static drag
#: torque [N m], life uncoated and TFE [million cm]; None = N/A (free-wheeling).
SEED_SERIES = {
    "B4000": ((0.0, 0.0), None, None),
    "B6000": ((0.0, 0.0), None, None),
    "B7000": ((0.0, 0.0), None, None),
    "B8000": ((0.0, 0.0), None, None),
    "B10000": ((0.0, 0.0), None, None),
    "B12000": ((0.0, 0.0), None, None),
    "B14000": ((0.0, 0.0), None, None),
    "ZBX4000": ((0.007, 0.03), (100, 150), (380, 500)),
    "ZBX6000": ((0.010, 0.03), (100, 150), (380, 500)),
    "ZBX7000": ((0.020, 0.04), (100, 150), (380, 500)),
    "ZBX8000": ((0.020, 0.04), (100, 150), (380, 500)),
    "ZBX10000": ((0.030, 0.05), (200, 250), (450, 580)),
    "KHD6000": ((0.007, 0.02), (200, 250), (450, 580)),
    "VHD8000": ((0.010, 0.04), (500, 570), (760, 880)),
    "VHD10000": ((0.010, 0.04), (500, 570), (760, 880)),
    "VHD12000": ((0.020, 0.05), (500, 570), (760, 880)),
}

#: catalog-notes.md "Screw inertia per inch": printed mantissa, corrected exponent.
SEED_INERTIA_PER_IN = {
    4000: 2.11e-8,
    6000: 1.06e-7,
    7000: 2.47e-7,
    8000: 3.67e-7,
    10000: 1.00e-6,
    12000: 2.15e-6,
    14000: 4.09e-6,
}


#: The seed's families (catalog/*-series.toml); values of the seed hold for their screws only.


def _family_ids(paths: Iterable[Path]) -> set[str]:
    """The family ids that catalog files declare (a group's common file declares none)."""
    found = set()
    for path in paths:
        data = tomllib.loads(path.read_text())
        family = data.get("family", data.get("ballscrew", {}))
        if "id" in family:
            found.add(family["id"])
    return found


#: The seed maker's families: the family files beside the seed group's common file.
SEED_FAMILIES = _family_ids(FILES)
#: Every family of the built-in catalog, in any group's directory.
ALL_FAMILIES = _family_ids(CATALOG_DIR.rglob("*.toml"))
SEED_IDS = (Path(__file__).parents[1] / "fixtures" / "seed_candidate_ids.txt").read_text().split()


def seed_screws(catalog: Catalog) -> list[ScrewSpec]:
    """The seed families' screws, so that another family in the catalog leaves the seed
    assertions alone."""
    return [s for s in catalog.screws if s.family_id in SEED_FAMILIES]


def size_number(series_id: str) -> int:
    return int(re.sub(r"\D", "", series_id))


# ---------------------------------------------------------------------------------------
# every file, every value


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_catalog_file_is_valid_toml(path: Path) -> None:
    with path.open("rb") as handle:
        assert tomllib.load(handle)


def test_the_built_in_catalog_loads(catalog: Catalog) -> None:
    """The seed's series, and the ISO trapezoidal families of catalog/iso-trapezoidal/."""
    seed = {sid for sid, s in catalog.series.items() if s.family in SEED_FAMILIES}
    assert seed == set(SEED_SERIES)
    assert len(catalog.screws) == len(catalog.by_id) > 0
    assert catalog.version.startswith("seed-")
    assert {s.family_id for s in catalog.screws} == ALL_FAMILIES
    assert tomllib.loads((CATALOG_DIR / "common.toml").read_text())["group"]["id"] == "seed"
    assert {"B", "TR-C45"} <= ALL_FAMILIES and "TR-C45" not in SEED_FAMILIES


def test_seed_candidate_ids_are_unchanged_by_the_family_schema(catalog: Catalog) -> None:
    """The ids users have saved and shared stay valid: the id pattern of the seed's group
    gives, in the same order, every id the per-coating schema gave (the list was written
    by that loader)."""
    assert [s.id for s in seed_screws(catalog)] == SEED_IDS


def test_seed_variants_carry_their_own_rules(catalog: Catalog) -> None:
    """Seed: the traverse-speed table (2.5-12 mm lead 100 mm/s, 12-25 mm 250, 25-60 mm 760)
    belongs to every seed screw; the variant key names the coating; TFE is kept from oil."""
    bands = ((0.0025, 0.012, 0.100), (0.012, 0.025, 0.250), (0.025, 0.060, 0.760))
    for s in seed_screws(catalog):
        assert [pytest.approx(band) for band in bands] == list(s.traverse_bands)
        assert s.variant == ("tfe" if s.coated else "none")
        assert s.id.endswith("-TFE") is s.coated
        assert s.oil_compatible is not s.coated
        assert s.provenance["traverse_speed"].kind == "seed"
        assert s.provenance["oil_compatible"].kind == "seed"


def _values_of(entry: str, table: dict[str, object]) -> list[tuple[str, str, object]]:
    """(entry, field, raw) for the values of one table; plain-text and true/false keys
    (ids, names, id suffixes, classifications) name things rather than measure them."""
    out: list[tuple[str, str, object]] = []
    for name, raw in table.items():
        if name == "variants" and isinstance(raw, dict):
            for key, values in raw.items():
                out += _values_of(f"{entry}.variants.{key}", values)
        elif not isinstance(raw, str | bool):
            out.append((entry, name, raw))
    return out


def _valued_tables(path: Path) -> list[tuple[str, str, object]]:
    """(entry, field, raw) for every catalog value of a file: [defaults], [[series]],
    [variants.*], [rules.*], [materials.*] and the thread form."""
    with path.open("rb") as handle:
        data = tomllib.load(handle)
    out = _values_of("defaults", data.get("defaults", {}))
    for entry in data.get("series", []):
        out += _values_of(entry["id"], {k: v for k, v in entry.items() if k != "id"})
    for table in ("variants", "rules", "materials", "motors", "supports"):
        for name, values in data.get(table, {}).items():
            out += _values_of(f"{table}.{name}", values)
    if "thread_form" in data.get("family", {}):
        out.append(("family", "thread_form", data["family"]["thread_form"]))
    return out


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_value_carries_its_provenance(path: Path) -> None:
    """catalog-notes.md: every value in catalog/ carries a provenance in {seed, handbook,
    derived, assumed}; non-seed ones name their source or rule (catalog/README.md)."""
    values = _valued_tables(path)
    assert values
    for entry, name, raw in values:
        where = f"{path.name} {entry}.{name}"
        assert isinstance(raw, dict), where
        number_keys = {"value"}, {"min", "max"}, {"half_angle_deg"}  # thread form
        assert any(keys <= raw.keys() for keys in number_keys), where
        assert raw.get("provenance") in PROVENANCE_KINDS, where
        if raw["provenance"] != "seed":
            assert isinstance(raw.get("source"), str) and raw["source"].strip(), where


def test_loaded_fields_and_candidates_carry_provenance(catalog: Catalog) -> None:
    """The loader keeps the provenance of every field it shows and of every value a
    candidate's checks use."""
    for series in catalog.series.values():
        for name, sourced in series.fields.items():
            assert sourced.provenance.kind in PROVENANCE_KINDS, (series.id, name)
            if sourced.provenance.kind != "seed":
                assert sourced.provenance.source.strip(), (series.id, name)
    for screw in catalog.screws:
        for name in ("root_diameter", "youngs_modulus", "density", "pv_limit", "design_load"):
            assert screw.provenance[name].kind in PROVENANCE_KINDS, (screw.id, name)
            assert screw.provenance[name].source.strip(), (screw.id, name)


# ---------------------------------------------------------------------------------------
# the seed's series and values


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_seed_series_drag_torque_and_life(catalog: Catalog, series_id: str) -> None:
    """Seed table "Screw / nut series": static frictional drag torque and anti-backlash
    life (blank cells are merged: a value covers the rows below it), catalog-notes.md."""
    drag, life_uncoated, life_tfe = SEED_SERIES[series_id]
    fields = catalog.series[series_id].fields
    assert fields["drag_torque"].value == pytest.approx(drag)
    assert fields["drag_torque"].provenance.kind == "seed"
    for key, expected in (("life_uncoated", life_uncoated), ("life_tfe", life_tfe)):
        if expected is None:
            assert key not in fields
        else:
            low, high = fields[key].value
            assert (low / 1e4, high / 1e4) == pytest.approx(expected)  # m -> million cm
            assert fields[key].provenance.kind == "seed"
    kind = "free-wheeling" if series_id.startswith("B") else "anti-backlash"
    assert catalog.series[series_id].type == kind


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_size_is_the_series_number_in_sixteenths_of_an_inch(
    catalog: Catalog, series_id: str
) -> None:
    """catalog-notes.md: 4000 = 4/16 in = 6.35 mm, ..., 14000 = 7/8 in (derived)."""
    od = catalog.series[series_id].fields["outer_diameter"]
    assert od.value == pytest.approx(size_number(series_id) / 1000 / 16 * 0.0254, rel=1e-9)
    assert od.provenance.kind == "derived"


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_inertia_is_the_ocr_corrected_seed_value(catalog: Catalog, series_id: str) -> None:
    """catalog-notes.md inertia table (kg m^2 per inch, exponents corrected), loaded per m."""
    per_m = catalog.series[series_id].fields["inertia_per_length"].value
    assert per_m * 0.0254 == pytest.approx(SEED_INERTIA_PER_IN[size_number(series_id)], rel=1e-9)


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_inertia_lies_between_half_and_all_of_a_solid_303_rod(
    catalog: Catalog, series_id: str
) -> None:
    """catalog-notes.md: every inertia between 0.5 and 1.0 of a solid 303 rod at the OD,
    J / L = rho pi d^4 / 32, rho 8000 kg/m^3 (smallmotors.com lead-screw page gives the
    same J = D^4 l pi / 32 x density for a steel screw)."""
    fields = catalog.series[series_id].fields
    od = fields["outer_diameter"].value
    solid = 8000.0 * math.pi * od**4 / 32
    assert 0.5 < fields["inertia_per_length"].value / solid < 1.0


@pytest.mark.parametrize(
    ("series_id", "kg", "rel"),
    [
        pytest.param("ZBX4000", 11.4, 0.005, id="quarter-inch-11.4kg"),
        pytest.param("ZBX8000", 45.5, 0.005, id="half-inch-45.5kg"),
        pytest.param("B4000", 11.0, 0.05, id="quarter-inch-about-11kg"),
        pytest.param("B8000", 45.0, 0.05, id="half-inch-about-45kg"),
        pytest.param("VHD8000", 1.5 * 45.5, 0.005, id="VHD-half-inch-1.5x"),
    ],
)
def test_design_load(catalog: Catalog, series_id: str, kg: float, rel: float) -> None:
    """catalog-notes.md "Design load": 3 MPa x the seed's three-thread area: about 11 kg
    (25 lb) for 1/4 in, about 45 kg (100 lb) for 1/2 in; catalog/README.md rule 4 prints
    11.4 and 45.5 kg, and 1.5 x for the heavy-duty VHD nuts; worked from the assumed
    pressure, the load is assumed, and its rule says what it assumes."""
    design = catalog.series[series_id].fields["design_load"]
    assert design.value / G == pytest.approx(kg, rel=rel)
    assert design.provenance.kind == "assumed"
    assert "pressure" in design.provenance.source.split("; ")[-1]


def test_design_load_rule_by_hand(catalog: Catalog) -> None:
    """catalog/README.md rule 4: 1.0 x 3 MPa x 3 pi d_p h with d_p, h from OD and 0.78 OD."""
    od = 0.0127
    rd = 0.78 * od
    d_p, h = (od + rd) / 2, (od - rd) / 2
    expected = 3e6 * 3 * math.pi * d_p * h
    assert catalog.series["B8000"].fields["design_load"].value == pytest.approx(expected)


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_root_diameter_defaults_to_0_78_od(catalog: Catalog, series_id: str) -> None:
    """catalog-notes.md: root not in the seed; 0.78 x OD (ASME B1.5 Acme 2G 0.75-0.81),
    assumed, per size; critical speed and buckling use it."""
    fields = catalog.series[series_id].fields
    root = fields["root_diameter"]
    assert root.value == pytest.approx(0.78 * fields["outer_diameter"].value, rel=1e-12)
    assert root.provenance.kind == "assumed"
    for screw in catalog.series[series_id].screws:
        assert screw.root_diameter_m == root.value


@pytest.mark.parametrize("series_id", sorted(SEED_SERIES))
def test_leads_are_the_common_list_up_to_4_od(catalog: Catalog, series_id: str) -> None:
    """catalog-notes.md "Leads": common metric and inch leads limited to lead <= 4 x OD; each
    series offers every one of them up to that limit, uncoated and TFE-coated."""
    common = [1, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 12.7, 15, 20, 25, 25.4, 30, 40, 50, 60]
    series = catalog.series[series_id]
    od_mm = series.fields["outer_diameter"].value * 1000
    leads_mm = [round(x * 1000, 6) for x in series.fields["leads"].value]
    assert leads_mm == [x for x in common if x <= 4 * od_mm + 1e-9]
    assert max(leads_mm) <= 4 * od_mm + 1e-9
    ids = {s.id for s in series.screws}
    for lead in leads_mm:
        assert {f"{series_id}-L{lead:g}", f"{series_id}-L{lead:g}-TFE"} <= ids
    assert len(series.screws) == 2 * len(leads_mm)


@pytest.mark.parametrize(
    ("coated", "mu_dynamic", "pv_psi_ft_min", "max_length_m"),
    [
        pytest.param(False, 0.15, 3000, 4.0, id="uncoated"),
        pytest.param(True, 0.09, 5000, 2.4, id="TFE-coated"),
    ],
)
def test_coating_variants(
    catalog: Catalog, coated: bool, mu_dynamic: float, pv_psi_ft_min: float, max_length_m: float
) -> None:
    """Seed physical properties: friction static 0.08, dynamic 0.09 with TFE, 0.15 uncoated;
    lengths up to 4 m, 2.4 m (8 ft) with TFE coating. engineering.md section 6: PV limits
    (assumed) 3,000 psi ft/min uncoated, 5,000 with TFE."""
    screws = [s for s in seed_screws(catalog) if s.coated is coated]
    assert screws
    for s in screws:
        assert s.friction_static == 0.08
        assert s.friction_dynamic == mu_dynamic
        assert s.pv_limit_pa_m_s == pytest.approx(pv_psi_ft_min * PSI_FT_MIN, rel=0.01)
        assert s.max_length_m == pytest.approx(max_length_m)
        assert s.oil_compatible is not coated


def test_common_seed_values(catalog: Catalog) -> None:
    """Seed: 303 stainless screw; polyacetal nut; lead accuracy .0006 mm/mm; repeatability
    0.0013 mm; 0-93 C; B series backlash 0.076-0.25 mm, anti-backlash none; vacuum weight
    loss 24/48/96/330 h: 0.20/0.26/0.35/0.37 %. Handbook: 303 E 193 GPa, 8000 kg/m^3,
    17.3e-6 /C; Acme 14.5 deg (assumed)."""
    for s in seed_screws(catalog):
        assert s.material_name == "stainless-303" and s.nut_material == "polyacetal"
        assert s.youngs_modulus_pa == 193e9 and s.density_kg_m3 == 8000.0
        assert s.screw_expansion_per_k == pytest.approx(17.3e-6)
        assert s.thread_half_angle_rad == pytest.approx(math.radians(14.5))
        assert s.lead_accuracy_m_per_m == 0.0006
        assert s.repeatability_m == pytest.approx(0.0013e-3)
        assert (s.temperature_min_c, s.temperature_max_c) == (0.0, 93.0)
        assert s.outgassing == ((24.0, 0.20), (48.0, 0.26), (96.0, 0.35), (330.0, 0.37))
        backlash = (0.076e-3, 0.25e-3) if s.series_id.startswith("B") else (0.0, 0.0)
        assert (s.backlash_min_m, s.backlash_max_m) == pytest.approx(backlash)
        assert s.anti_backlash is not s.series_id.startswith("B")


def test_khd_is_the_6000_size_printed_khd_600(catalog: Catalog) -> None:
    """catalog-notes.md: the seed prints "KHD 600"; its inertia is the 6000 row."""
    khd = catalog.series["KHD6000"]
    assert khd.name == "KHD 6000"
    assert khd.fields["outer_diameter"].value == pytest.approx(0.375 * 0.0254)


def test_nut_tensile_strength_is_9700_psi() -> None:
    """catalog-notes.md: the seed's "1.4N/m2" is an OCR error; 9,700 psi = 67 MPa."""
    with (CATALOG_DIR / "common.toml").open("rb") as handle:
        defaults = tomllib.load(handle)["defaults"]
    assert defaults["nut_tensile_strength_mpa"]["value"] == pytest.approx(
        9700 * 6894.757e-6, rel=0.01
    )


# ---------------------------------------------------------------------------------------
# extra directories and broken files


def test_an_extra_directory_adds_its_series(catalog: Catalog) -> None:
    """README "Adding a series to the seed's group": a user's directory is merged in; its
    values keep their provenance; the seed group it extends fills what it leaves out."""
    merged = load_catalog([FIXTURES])
    assert set(merged.series) == set(catalog.series) | {"MY10"}
    mine = merged.series["MY10"]
    assert mine.name == "My Tr10x2" and mine.family == "MY" and mine.file == "my-series.toml"
    assert mine.fields["root_diameter"].value == pytest.approx(0.0075)
    assert mine.fields["root_diameter"].provenance.kind == "handbook"
    assert [s.id for s in mine.screws] == [
        "MY10-L2",
        "MY10-L2-TFE",
        "MY10-L4",
        "MY10-L4-TFE",
        "MY10-L8",
        "MY10-L8-TFE",
    ]
    screw = merged.by_id["MY10-L4"]
    assert screw.thread_half_angle_rad == pytest.approx(math.radians(15.0))
    assert screw.friction_dynamic == 0.15  # built-in default, uncoated
    assert merged.version != catalog.version


FIXTURE_TEXT = (FIXTURES / "my-series.toml").read_text()


def _write(tmp_path: Path, text: str, name: str = "my-series.toml") -> Path:
    directory = tmp_path / "extra"
    directory.mkdir(exist_ok=True)
    (directory / name).write_text(text)
    return directory


def _with_line(line: str) -> str:
    """The fixture with one more line in its series entry."""
    anchor = 'name = "My Tr10x2"'
    assert anchor in FIXTURE_TEXT
    return FIXTURE_TEXT.replace(anchor, f"{anchor}\n{line}")


def _replace_line(key: str, line: str | None) -> str:
    """The fixture with the line that sets ``key`` replaced (None: removed)."""
    out = []
    for old in FIXTURE_TEXT.splitlines():
        if old.startswith(f"{key} ="):
            if line is not None:
                out.append(line)
        else:
            out.append(old)
    assert out != FIXTURE_TEXT.splitlines(), key
    return "\n".join(out) + "\n"


BROKEN = [
    pytest.param(
        _replace_line("inertia_kg_m2_per_in", None),
        "MY10",
        "inertia_kg_m2_per_in",
        "missing",
        id="missing-field",
    ),
    pytest.param(
        _replace_line(
            "outer_diameter_mm",
            'outer_diameter_mm = { value = -10.0, provenance = "handbook", source = "ISO" }',
        ),
        "MY10",
        "outer_diameter_mm",
        "> 0",
        id="negative-diameter",
    ),
    pytest.param(
        _replace_line(
            "root_diameter_mm",
            'root_diameter_mm = { value = 10.0, provenance = "handbook", source = "ISO" }',
        ),
        "MY10",
        "root_diameter_mm",
        "below the outer diameter",
        id="root-equals-outer-diameter",
    ),
    pytest.param(
        _replace_line(
            "root_diameter_mm",
            'root_diameter_mm = { value = 12.0, provenance = "handbook", source = "ISO" }',
        ),
        "MY10",
        "root_diameter_mm",
        "below the outer diameter",
        id="root-above-outer-diameter",
    ),
    pytest.param(
        _replace_line("inertia_kg_m2_per_in", "inertia_kg_m2_per_in = { value = 1.2e-7 }"),
        "MY10",
        "inertia_kg_m2_per_in",
        "provenance",
        id="provenance-missing",
    ),
    pytest.param(
        _replace_line(
            "inertia_kg_m2_per_in",
            'inertia_kg_m2_per_in = { value = 1.2e-7, provenance = "guessed", source = "x" }',
        ),
        "MY10",
        "inertia_kg_m2_per_in",
        "provenance",
        id="provenance-unknown-kind",
    ),
    pytest.param(
        _replace_line(
            "outer_diameter_mm", 'outer_diameter_mm = { value = 10.0, provenance = "handbook" }'
        ),
        "MY10",
        "outer_diameter_mm",
        "source",
        id="non-seed-value-without-source",
    ),
    pytest.param(
        _with_line('screw_material = { value = "titanium", provenance = "assumed", source = "x" }'),
        "MY10",
        "screw_material",
        "unknown material",
        id="unknown-material",
    ),
    pytest.param(
        FIXTURE_TEXT.replace('id = "MY10"', 'id = "ZBX8000"'),
        "ZBX8000",
        "id",
        "duplicate",
        id="duplicate-id-across-directories",
    ),
]


@pytest.mark.parametrize(("text", "entry", "field", "reason"), BROKEN)
def test_broken_fixture_names_file_entry_and_field(
    tmp_path: Path, text: str, entry: str, field: str, reason: str
) -> None:
    """DESIGN.md / catalog/README.md: any error stops start-up with the file, the entry and
    the field named (app.catalog.CatalogError)."""
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, text)])
    error = caught.value
    assert (error.file, error.entry, error.field) == ("my-series.toml", entry, field)
    message = str(error)
    assert "my-series.toml" in message and f"'{entry}'" in message and f"'{field}'" in message
    assert reason in message


def test_bad_toml_names_the_file_and_the_line(tmp_path: Path) -> None:
    """A syntax error has no entry or field yet: the file and the parser's position."""
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, FIXTURE_TEXT.replace('id = "MY10"', 'id = "MY10'))])
    assert caught.value.file == "my-series.toml"
    assert "invalid TOML" in str(caught.value) and "line" in str(caught.value)


def test_missing_extra_directory(tmp_path: Path) -> None:
    with pytest.raises(CatalogError, match="not found"):
        load_catalog([tmp_path / "nowhere"])


def test_root_ratio_error_names_the_ratio(tmp_path: Path) -> None:
    text = _replace_line(
        "root_diameter_mm",
        'root_diameter_ratio = { value = 1.2, provenance = "assumed", source = "x" }',
    )
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, text)])
    assert caught.value.field == "root_diameter_ratio"


def test_malformed_outgassing_is_a_catalog_error(tmp_path: Path) -> None:
    text = _with_line('outgassing_percent = { value = [[24.0]], provenance = "seed" }')
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, text)])
    assert (caught.value.entry, caught.value.field) == ("MY10", "outgassing_percent")


def test_every_field_provenance_is_validated_at_load(tmp_path: Path) -> None:
    """catalog-notes.md: every value in catalog/ must carry its provenance; DESIGN.md: the
    loader validates every file at start-up."""
    text = _with_line("straightness_mm_per_300mm = { value = 0.075 }")
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, text)])
    assert caught.value.field == "straightness_mm_per_300mm"
