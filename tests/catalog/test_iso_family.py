"""The shipped ISO metric trapezoidal family (catalog/iso-trapezoidal/): dimensions by the
ISO 2904 rule, its nuts and their limits, selections beside the seed checked by hand, the
family and nut-material filters, robustness over assumed ranges, and a user's own family
(examples/my-family)."""

import math
import tomllib
from pathlib import Path
from urllib.parse import parse_qsl

import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog, load_catalog
from app.contract.form import parse_inputs, parse_units
from app.contract.inputs import ApplicationIn
from app.contract.share_link import share_query
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.robustness import at_values, robustness
from app.core.selection import select
from tests.motor_library import MOTORS

ROOT = Path(__file__).resolve().parents[2]
ISO_DIR = ROOT / "catalog" / "iso-trapezoidal"
FAMILY_FILES = {"TR-C45": "tr-c45.toml", "TR-304": "tr-304.toml"}
ISO_FAMILIES = set(FAMILY_FILES)
SEED_FAMILIES = {"B", "ZBX", "KHD", "VHD"}
#: ISO 2904 crest clearance a_c [mm] by pitch [mm] (iso-trapezoidal.md)
CREST_CLEARANCE_MM = {1.5: 0.15, 2.0: 0.25, 3.0: 0.25, 4.0: 0.25, 5.0: 0.25, 6.0: 0.5, 7.0: 0.5}
CREST_CLEARANCE_MM |= {8.0: 0.5}
#: iso-trapezoidal.md worked values: (d, P) -> (d2, d3) [mm]
WORKED = {
    (8, 1.5): (7.25, 6.2),
    (10, 2): (9.0, 7.5),
    (12, 3): (10.5, 8.5),
    (16, 4): (14.0, 11.5),
    (20, 4): (18.0, 15.5),
    (24, 5): (21.5, 18.5),
    (30, 6): (27.0, 23.0),
    (40, 7): (36.5, 32.0),
}
PREFERRED = {(8, 1.5), (10, 2), (12, 3), (14, 3), (16, 4), (18, 4), (20, 4), (22, 5), (24, 5)}
PREFERRED |= {(26, 5), (28, 5), (30, 6), (32, 6), (36, 6), (40, 7), (44, 7), (50, 8)}


def _series(family: str) -> list[dict[str, object]]:
    with (ISO_DIR / FAMILY_FILES[family]).open("rb") as handle:
        data: list[dict[str, object]] = tomllib.load(handle)["series"]
    return data


def _value(entry: dict[str, object], key: str) -> float:
    table = entry[key]
    assert isinstance(table, dict)
    return float(table["value"])


@pytest.mark.parametrize("family", sorted(ISO_FAMILIES))
def test_every_size_follows_the_iso_rule(catalog: Catalog, family: str) -> None:
    """d2 = d - 0.5 P, d3 = d - 2 (0.5 P + a_c), H1 = 0.5 P, for every size of the file."""
    sizes = set()
    for entry in _series(family):
        d, p = _value(entry, "outer_diameter_mm"), _value(entry, "pitch_mm")
        sizes.add((d, p))
        for screw in catalog.series[str(entry["id"])].screws:
            assert screw.flank_pitch_diameter_m == pytest.approx((d - 0.5 * p) / 1e3)
            d3 = d - 2 * (0.5 * p + CREST_CLEARANCE_MM[p])
            assert screw.root_diameter_m == pytest.approx(d3 / 1e3)
            assert screw.flank_height_m == pytest.approx(0.5 * p / 1e3)
            assert screw.thread_half_angle_rad == pytest.approx(math.radians(15.0))
    assert sizes >= PREFERRED


@pytest.mark.parametrize(("size", "expected"), WORKED.items())
def test_worked_values_of_the_reference(
    catalog: Catalog, size: tuple[float, float], expected: tuple[float, float]
) -> None:
    d, p = size
    screw = catalog.by_id[f"Tr{d:g}x{p:g}-bronze"]
    assert screw.flank_pitch_diameter_m * 1e3 == pytest.approx(expected[0])
    assert screw.root_diameter_m * 1e3 == pytest.approx(expected[1])


def test_multi_start_ids_and_leads(catalog: Catalog) -> None:
    """Lead = starts x pitch; a multi-start screw is named Tr d x lead (P pitch)."""
    for cid, lead_mm, pitch_mm in [
        ("Tr8x2-acetal", 2.0, 2.0),
        ("Tr8x4(P2)-acetal", 4.0, 2.0),
        ("Tr8x8(P2)-acetal", 8.0, 2.0),
        ("Tr10x4(P2)-bronze", 4.0, 2.0),
        ("Tr12x6(P3)-ptfe", 6.0, 3.0),
        ("Tr16x8(P4)-304-bronze", 8.0, 4.0),
        ("Tr20x8(P4)-304-acetal", 8.0, 4.0),
    ]:
        screw = catalog.by_id[cid]
        assert screw.lead_m == pytest.approx(lead_mm / 1e3)
        assert screw.pitch_m == pytest.approx(pitch_mm / 1e3)


def test_nuts_carry_their_own_limits_and_no_seed_rules(catalog: Catalog) -> None:
    """Bronze by Shigley's pressure-speed table (low end of each range), acetal and PTFE
    by Neale's maximum pressure and PV; no traverse table, length, design load or seed PV;
    the nut length is 2 d; materials and inertia from the file."""
    screws = [s for s in catalog.screws if s.family_id in ISO_FAMILIES]
    assert {s.nut_material for s in screws} == {"bronze", "acetal", "PTFE-filled polymer"}
    for s in screws:
        assert s.traverse_bands == () and s.max_length_m is None and s.design_load_n is None
        assert s.pv_limit_pa_m_s is None and not s.anti_backlash and not s.coated
        assert s.nut_length_m == pytest.approx(2 * s.outer_diameter_m)
        d2 = s.flank_pitch_diameter_m or 0.0
        assert s.inertia_kg_m2_per_m == pytest.approx(s.density_kg_m3 * math.pi * d2**4 / 32)
        assert "traverse_speed" not in s.provenance
    bronze = catalog.by_id["Tr16x4-bronze"]
    assert bronze.bearing_pressure_table == (
        (0.05, 11e6),
        (0.1, 5.5e6),
        (0.2, 5.5e6),
        (0.25, 1e6),
    )
    assert (bronze.friction_dynamic, bronze.friction_static) == (0.13, 0.16)
    acetal = catalog.by_id["Tr16x4-acetal"]
    assert (acetal.max_pressure_pa, acetal.nut_pv_limit_pa_m_s) == (10e6, 0.07e6)
    ptfe = catalog.by_id["Tr16x4-304-ptfe"]
    assert (ptfe.max_pressure_pa, ptfe.nut_pv_limit_pa_m_s) == (7e6, 0.2e6)
    assert ptfe.youngs_modulus_pa == 193e9 and ptfe.material_name == "stainless-304"
    assert bronze.youngs_modulus_pa == 207e9 and bronze.material_name == "c45-steel"
    assert "ISO 2904" in bronze.provenance["root_diameter"].source


def test_an_iso_screw_wins_where_no_seed_nut_carries_the_load(catalog: Catalog) -> None:
    """2000 N pulled at 10 mm/s over 0.3 m, smallest size first.

    Seed: design load = factor x 3 MPa x 3 pi d_p h; the largest are VHD12000
    (OD 19.05, RD 0.78 OD = 14.859 mm: 1.5 x 3 x 3 pi x 16.9545 x 2.0955 = 1507 N) and
    B14000 (22.225 / 17.3355 mm: 3 x 3 pi x 19.780 x 2.4448 = 1367 N): none reaches 2000 N.
    ISO, nut 2 d long, area (L / P) pi d2 H1: Tr8 (d2 7.25 or 7.0) gives 182.2 or 175.9 mm2,
    so 11.0 or 11.4 MPa, at or above bronze's 11 MPa even at the slowest sliding speed.
    Tr10x4(P2): 10 turns x pi x 9.0 x 1.0 = 282.74 mm2, p = 7.074 MPa; n = 2.5 rev/s,
    helix sqrt(4^2 + (9 pi)^2) = 28.556 mm, v = 0.07139 m/s, allowed 11 - 5.5 x 0.4278 =
    8.647 MPa (Shigley 11 MPa at 0.05 m/s to 5.5 MPa at 0.1 m/s): it passes, 0.818 used.
    Tr10x2 slides at 5 x 28.345 = 0.1417 m/s where 5.5 MPa is allowed: it fails. The
    nut is greased, as a bronze nut's ratings are a lubricated nut's.
    """
    app = Application(
        load_n=2000.0, speed_m_s=0.01, length_m=0.3, compression=False, lubrication="greased"
    )
    # the leadscrew families by name: ball screws carry this load too
    lead = tuple(sorted({s.family_id for s in catalog.screws if s.screw_type == "lead"}))
    query = {**_fields(app), "rank_by": "size", "limit": 100, "families": lead}
    sel = select(Application(**query), catalog.index)
    vhd12000 = 1.5 * 3e6 * 3 * math.pi * 16.9545e-3 * 2.0955e-3
    b14000 = 3e6 * 3 * math.pi * 19.780e-3 * 2.4448e-3
    assert (round(vhd12000), round(b14000)) == (1507, 1367)
    assert all(s.design_load_n is None or s.design_load_n <= 1507.0 for s in catalog.screws)
    assert {ev.screw.family_id for ev in sel.candidates} <= ISO_FAMILIES
    winner = sel.candidates[0]
    assert winner.screw.id == "Tr10x4(P2)-bronze"
    area_mm2 = 20.0 / 2.0 * math.pi * 9.0 * 1.0
    pressure_mpa = 2000.0 / area_mm2
    speed = 10.0 / 4.0 * math.hypot(4.0, 9.0 * math.pi) / 1e3
    allowed_mpa = 11.0 - (speed - 0.05) / 0.05 * 5.5
    assert (round(area_mm2, 2), round(pressure_mpa, 3)) == (282.74, 7.074)
    assert (round(speed, 5), round(allowed_mpa, 3)) == (0.07139, 8.647)
    check = next(c for c in winner.checks if c.name == "bearing_pressure")
    assert check.utilization == pytest.approx(pressure_mpa / allowed_mpa)
    assert winner.governing_check == "bearing_pressure"
    assert not any(ev.screw.outer_diameter_m < 0.0099 for ev in sel.candidates)
    assert "Tr10x2-bronze" not in {ev.screw.id for ev in sel.candidates}


def _fields(app: Application) -> dict[str, object]:
    return {name: getattr(app, name) for name in app.__dataclass_fields__}


def test_a_seed_screw_wins_where_it_is_the_smallest(catalog: Catalog) -> None:
    """20 N at 20 mm/s over 0.2 m, smallest size first: the seed's 1/4 in screws
    (6.35 mm) are smaller than any ISO screw (8 mm). B4000 at 2 mm lead: n = 10 rev/s,
    h = (6.35 - 4.953) / 2 = 0.6985 mm, PV = n F / (3 h) = 10 x 20 / 2.0955e-3 =
    95 443 Pa m/s, within TFE's 0.175 MPa m/s (0.545 used); at 1 mm lead PV doubles to
    0.191 MPa m/s, over both limits, so L1 fails."""
    app = Application(load_n=20.0, speed_m_s=0.02, length_m=0.2, rank_by="size", limit=20)
    sel = select(app, catalog.index)
    winner = sel.candidates[0]
    assert winner.screw.family_id in SEED_FAMILIES
    assert winner.screw.outer_diameter_m == pytest.approx(0.00635)
    assert min(s.outer_diameter_m for s in catalog.screws if s.family_id in ISO_FAMILIES) == 0.008
    assert winner.screw.id == "B4000-L2-TFE"
    pv = 10.0 * 20.0 / (3 * 0.6985e-3)
    assert round(pv) == 95443
    pv_check = next(c for c in winner.checks if c.name == "pv")
    assert pv_check.value == pytest.approx(pv, rel=1e-3)
    assert pv_check.utilization == pytest.approx(pv / 0.175e6, rel=1e-3)
    assert 2 * pv > 0.175e6
    assert not {"B4000-L1", "B4000-L1-TFE"} & {ev.screw.id for ev in sel.candidates}


def _ids(body: dict[str, list[dict[str, str]]]) -> list[str]:
    return [c["id"] for c in body["candidates"] + body["rejected"]]


def test_family_and_nut_material_filter_the_api(client: TestClient, catalog: Catalog) -> None:
    base = {"load_n": 100, "speed_mm_s": 50, "length_mm": 500, "limit": 100}
    body = client.get(
        "/api/v1/select", params={**base, "family": "TR-C45", "nut_material": "bronze"}
    ).json()
    ids = _ids(body)
    assert ids and all(catalog.by_id[i].family_id == "TR-C45" for i in ids)
    assert all(catalog.by_id[i].nut_material == "bronze" for i in ids)
    repeated = client.get(
        "/api/v1/select", params=[*base.items(), ("family", "B"), ("family", "VHD")]
    )
    assert {catalog.by_id[i].family_id for i in _ids(repeated.json())} == {"B", "VHD"}
    posted = client.post("/api/v1/select", json={**base, "family": ["KHD"], "nut_material": "any"})
    assert {catalog.by_id[i].family_id for i in _ids(posted.json())} == {"KHD"}
    everything = client.get("/api/v1/select", params=base).json()
    assert {catalog.by_id[i].family_id for i in _ids(everything)} >= ISO_FAMILIES
    bad = client.get("/api/v1/select", params={**base, "family": "<script>"})
    assert bad.status_code == 422


def test_family_and_nut_material_survive_a_share_link() -> None:
    inputs = ApplicationIn.model_validate(
        {
            "load_n": 100,
            "speed_mm_s": 50,
            "length_mm": 500,
            "family": ["TR-C45", "B"],
            "nut_material": "acetal",
        }
    )
    params = dict(parse_qsl(share_query(inputs)))
    assert params["family"] == "TR-C45,B" and params["nut_material"] == "acetal"
    parsed, errors = parse_inputs(params, parse_units(params))
    assert errors == {} and parsed is not None
    core = parsed.to_core(MOTORS)
    assert core.families == ("TR-C45", "B") and core.nut_material == "acetal"


def test_robust_flips_when_an_assumed_limit_moves_inside_its_range(catalog: Catalog) -> None:
    """B4000-L2 (uncoated) at 20 mm/s: PV = n F / (3 h), n = 10 rev/s, h = 0.6985 mm.
    At 20 N, PV = 95 443 Pa m/s: within the assumed 0.105 MPa m/s, but not within the low
    end of its range (0.07), nor with h = (6.35 - 0.81 x 6.35) / 2 = 0.60325 mm at the high
    root ratio (110 513 Pa m/s): marginal. At 14 N, PV = 66 810 and 77 359 Pa m/s: robust."""
    screw = catalog.by_id["B4000-L2"]
    at = catalog.index.positions[screw.id]
    variants = catalog.index.variants
    assert variants is not None
    light = Application(load_n=14.0, speed_m_s=0.02, length_m=0.2)
    heavier = Application(load_n=20.0, speed_m_s=0.02, length_m=0.2)
    h_low = (6.35 - 0.81 * 6.35) / 2 * 1e-3
    assert round(10 * 20 / (3 * h_low)) == 110513 and round(10 * 14 / (3 * h_low)) == 77359
    assert round(10 * 14 / (3 * 0.6985e-3)) == 66810
    assert evaluate(light, screw).passed and robustness(light, variants, [at])[0].robust
    (marginal,) = robustness(heavier, variants, [at])
    assert evaluate(heavier, screw).passed and not marginal.robust
    assert marginal.hinges_on == ("root_diameter_ratio", "pv_limit_mpa_m_s")
    low_end = at_values(screw, screw.assumption_ends["pv_limit_mpa_m_s"][0])
    assert low_end.pv_limit_pa_m_s == pytest.approx(0.07e6)
    assert not evaluate(heavier, low_end).passed and evaluate(light, low_end).passed


def test_design_pressure_range_reaches_the_published_cmp_rating(catalog: Catalog) -> None:
    """The low end of the design contact pressure (0.6 MPa) gives a 1/4 in screw the CMP's
    published 5 lb (22.2 N): 0.6 MPa x 3 pi x 5.6515 x 0.6985 mm2 = 22.3 N."""
    low, _ = catalog.by_id["ZBX4000-L2"].assumption_ends["design_contact_pressure_mpa"]
    assert low["design_load_n"] == pytest.approx(0.6e6 * 3 * math.pi * 5.6515e-3 * 0.6985e-3)
    assert low["design_load_n"] / 4.4482216 == pytest.approx(5.0, abs=0.1)


def test_a_polymer_nut_starts_at_no_more_than_its_published_static_friction(
    catalog: Catalog,
) -> None:
    """Holding with the power off rests on the static friction, so a polymer nut's is
    never put above what is published: acetal (POM homopolymer) on steel 0.1-0.3
    (Shackelford and Alexander, CRC Materials Science and Engineering Handbook, 3rd ed.,
    Table 399), taken 0.20; PTFE starts at its running friction (no stick-slip), so its
    static value and range are its running ones. They were assumed above the running
    friction (0.30 and 0.20), which held vertical loads the published friction does not."""
    iso = [s for s in catalog.by_id.values() if s.series_id.startswith("Tr")]
    acetal = [s for s in iso if s.id.endswith("-acetal")]
    ptfe = [s for s in iso if s.id.endswith("-ptfe")]
    assert len(acetal) > 40 and len(ptfe) > 40
    for s in acetal:
        low, high = s.assumption_ends["friction_static"]
        assert (s.friction_static, low["friction_static"], high["friction_static"]) == (
            0.20,
            0.10,
            0.30,
        )
    for s in ptfe:
        low, high = s.assumption_ends["friction_static"]
        assert s.friction_static == s.friction_dynamic == 0.15
        assert low == {"friction_static": 0.05} and high == {"friction_static": 0.35}


def test_every_assumed_number_a_check_uses_has_a_range() -> None:
    """Assumed single numbers carry `range = [low, high]` (catalog/README.md); the lists
    that choose what is offered (leads) and the thread form are not limits."""
    exempt = {"leads_mm", "max_lead_to_od", "thread_form", "friction_static"}
    for path in sorted((ROOT / "catalog").rglob("*.toml")):
        data = tomllib.loads(path.read_text())
        for table in _value_tables(data):
            name, value = table
            number = value.get("value")
            is_number = isinstance(number, int | float) and not isinstance(number, bool)
            if value.get("provenance") == "assumed" and is_number and name not in exempt:
                assert "range" in value, (path.name, name)


def _value_tables(data: object, name: str = "") -> list[tuple[str, dict[str, object]]]:
    if isinstance(data, list):
        return [t for item in data for t in _value_tables(item, name)]
    if not isinstance(data, dict):
        return []
    if "provenance" in data:
        return [(name, data)]
    return [t for key, value in data.items() for t in _value_tables(value, str(key))]


def test_the_example_family_loads_with_user_provenance() -> None:
    merged = load_catalog([ROOT / "examples" / "my-family"])
    mine = [s for s in merged.screws if s.family_id == "MY"]
    assert [s.id for s in mine] == ["MY-Tr8x8(P2)-pom", "MY-Tr12x3-pom", "MY-Tr12x6(P3)-pom"]
    screw = mine[0]
    for name in ("outer_diameter", "friction_dynamic", "max_pressure", "nut_length", "pitch"):
        assert screw.provenance[name].kind == "user", name
    assert screw.provenance["root_diameter"].kind == "user"
    assert screw.provenance["thread_form"].kind == "handbook"
    assert screw.provenance["inertia_per_length"].kind == "derived"
    assert screw.root_diameter_m == pytest.approx(5.5e-3)
    assert screw.assumption_ends["bearing_pv_limit_mpa_m_s"][0] == {"nut_pv_limit_pa_m_s": 0.05e6}
