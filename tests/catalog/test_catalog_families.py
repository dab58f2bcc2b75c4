"""A second family as data (tests/fixtures/catalog_iso/tr-family.toml): its ids follow its
own pattern, its screws carry its thread form and nut variants and none of the seed's
rules, and the selection ranks it beside the seed's families (catalog/README.md)."""

import math
import re
import tomllib
from pathlib import Path

import pytest

from app.catalog import Catalog, CatalogError, load_catalog
from app.catalog.family import DECLARATIONS, VARIANT_FIELDS
from app.catalog.series import SERIES_FIELDS
from app.core.model import Application
from app.core.selection import select

FIXTURES = Path(__file__).parents[1] / "fixtures"
ISO_DIR = FIXTURES / "catalog_iso"
ISO_TEXT = (ISO_DIR / "tr-family.toml").read_text()
ISO = tomllib.loads(ISO_TEXT)
SEED_FAMILIES = {"B", "ZBX", "KHD", "VHD"}


@pytest.fixture(scope="module")
def merged() -> Catalog:
    return load_catalog([ISO_DIR])


def _variant_value(series: dict[str, object], variant: str, field: str) -> float:
    """A variant's value for one series: the series' own override, else the family's."""
    own = series.get("variants", {})
    assert isinstance(own, dict)
    table = own.get(variant, {}).get(field) or ISO["variants"][variant][field]
    return float(table["value"])


def test_ids_follow_the_family_pattern(merged: Catalog) -> None:
    """Pattern "Tr{d_mm:g}x{lead_mm:g}-{variant}": one id per lead and nut, leads as listed
    up to max_lead_to_od x d, nuts in the order of nut_variants."""
    limit = ISO["defaults"]["max_lead_to_od"]["value"]
    variants = ISO["defaults"]["nut_variants"]["value"]
    for series in ISO["series"]:
        d_mm = series["outer_diameter_mm"]["value"]
        leads = [x for x in series["leads_mm"]["value"] if x <= limit * d_mm]
        expected = [f"Tr{d_mm:g}x{lead:g}-{v}-fixture" for lead in leads for v in variants]
        assert [s.id for s in merged.series[series["id"]].screws] == expected


def test_screws_carry_the_family_thread_variants_and_no_seed_rules(merged: Catalog) -> None:
    """15 deg flank half-angle, each nut's own friction and PV limit (with a size's own
    override), no traverse table, no length rule, no coating."""
    half_angle = ISO["family"]["thread_form"]["half_angle_deg"]
    screws = [s for s in merged.screws if s.family_id == "TR"]
    assert len(screws) == 8
    for screw in screws:
        series = next(e for e in ISO["series"] if e["id"] == screw.series_id)
        assert screw.thread_half_angle_rad == pytest.approx(math.radians(half_angle))
        assert screw.friction_dynamic == _variant_value(series, screw.variant, "friction_dynamic")
        pv_limit = _variant_value(series, screw.variant, "pv_limit_mpa_m_s") * 1e6
        assert screw.pv_limit_pa_m_s == pytest.approx(pv_limit)
        assert screw.oil_compatible is ISO["variants"][screw.variant]["oil_compatible"]["value"]
        assert screw.traverse_bands == () and screw.max_length_m is None
        assert not screw.coated and not screw.anti_backlash
        assert screw.friction_static == ISO["defaults"]["friction_static"]["value"]
        assert screw.youngs_modulus_pa == 210e9 and screw.material_name == "c35-steel"
        assert "traverse_speed" not in screw.provenance
        assert screw.provenance["oil_compatible"].kind in {"handbook", "assumed"}
        assert screw.provenance["thread_half_angle"].source == "ISO 2904: 30 deg flank angle"


def test_the_selection_ranks_the_family_beside_the_seed(merged: Catalog) -> None:
    """200 N at 50 mm/s over 0.4 m: light enough for the seed's larger screws, and for an
    ISO screw exactly where its nut's PV limit allows it. PV by the seed's three-thread
    method is n F / (3 h), n = v / lead [rev/s], h = (d - d3) / 2; computed here from the
    fixture's data, it admits Tr16x8 with the bronze nut only (0.185 MPa m/s against 0.35;
    acetal's 0.12 and the shorter leads fail)."""
    app = Application(load_n=200.0, speed_m_s=0.05, length_m=0.4, limit=1000)
    expected = set()
    for series in ISO["series"]:
        h_m = (series["outer_diameter_mm"]["value"] - series["root_diameter_mm"]["value"]) / 2e3
        for screw in merged.series[series["id"]].screws:
            pv = app.speed_m_s / screw.lead_m * app.load_n / (3 * h_m)
            if pv <= _variant_value(series, screw.variant, "pv_limit_mpa_m_s") * 1e6:
                expected.add(screw.id)
    assert expected == {"Tr16x8-bronze-fixture"}
    ranked = select(app, merged.index).candidates
    assert {ev.screw.id for ev in ranked if ev.screw.family_id == "TR"} == expected
    assert {ev.screw.family_id for ev in ranked} >= SEED_FAMILIES
    bronze = next(ev for ev in ranked if ev.screw.id == "Tr16x8-bronze-fixture")
    assert bronze.traverse_speed_limit_m_s is None


def _write(tmp_path: Path, files: dict[str, str]) -> Path:
    directory = tmp_path / "extra"
    directory.mkdir()
    for name, text in files.items():
        (directory / name).write_text(text)
    return directory


def test_a_family_that_extends_nothing_inherits_nothing(tmp_path: Path) -> None:
    """catalog/README.md "Layering": without `extends` (and no common.toml beside it) a
    family takes no value from the seed's group: a value it leaves out is missing, not
    the seed's 0.08."""
    text = "\n".join(
        line for line in ISO_TEXT.splitlines() if not line.startswith("friction_static =")
    )
    with pytest.raises(CatalogError) as caught:
        load_catalog([_write(tmp_path, {"tr-family.toml": text})])
    assert (caught.value.file, caught.value.entry, caught.value.field) == (
        "tr-family.toml",
        "Tr10x2",
        "friction_static",
    )
    assert "missing" in str(caught.value)


def test_a_users_group_extends_the_seed_and_its_families_layer_over_it(
    tmp_path: Path,
) -> None:
    """A user's common.toml naming `extends = "seed"` changes one seed default for the
    families beside it; the seed's own screws keep theirs."""
    group = (
        'schema = 2\n[group]\nid = "mine"\nextends = "seed"\n[defaults]\n'
        'friction_static = { value = 0.1, provenance = "assumed", source = "my nuts" }\n'
    )
    family = (FIXTURES / "catalog_extra" / "my-series.toml").read_text()
    family = family.replace('extends = "seed"\n', "")
    catalog = load_catalog([_write(tmp_path, {"common.toml": group, "my-series.toml": family})])
    assert {s.friction_static for s in catalog.series["MY10"].screws} == {0.1}
    assert {s.friction_dynamic for s in catalog.series["MY10"].screws} == {0.15, 0.09}
    assert {s.friction_static for s in catalog.series["B8000"].screws} == {0.08}


def test_the_readme_schema_example_uses_the_loaders_names() -> None:
    """catalog/README.md "Family file schema": the example's keys are the ones read."""
    readme = (Path(__file__).resolve().parents[2] / "catalog" / "README.md").read_text()
    section = readme.split("## Family file schema", 1)[1]
    example = tomllib.loads(re.findall(r"```toml\n(.*?)```", section, flags=re.S)[0])
    assert set(example["family"]) <= DECLARATIONS
    for variant in example["variants"].values():
        assert set(variant) <= VARIANT_FIELDS
    for series in example["series"]:
        assert set(series) - {"id"} <= SERIES_FIELDS
    assert set(example["defaults"]) <= SERIES_FIELDS
