"""A screw of the user's own (app.catalog.own): the same candidate the API's custom-screw
request gives (``report.present.custom_screw``), its values of provenance "user", and its
inertia, when not given, that of a solid rod at its pitch diameter, as a catalog screw's."""

import math
from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.catalog.own import OwnGeometry, own_screw, user_material
from app.contract.screws import CustomScrewIn, MaterialIn
from app.core.checks.wear_life import life_band
from app.core.evaluate import evaluate
from app.core.model import Application
from app.core.quantities import NAMES, quantity
from app.report.present import custom_screw

#: a 10 mm screw with a 2 mm lead (mm, as the API takes it)
GIVEN = {
    "outer_diameter_mm": 10.0,
    "root_diameter_mm": 8.0,
    "lead_mm": 2.0,
    "friction_dynamic": 0.15,
    "friction_static": 0.2,
}
GEOMETRY = OwnGeometry(0.010, 0.008, 0.002, math.radians(14.5), 0.2, 0.15)
OWN_STEEL = MaterialIn(youngs_modulus_pa=200e9, density_kg_m3=7800.0, yield_strength_pa=3e8)


@pytest.mark.parametrize("name", ["steel", "stainless-303"])
def test_a_catalog_material_gives_the_requests_screw(catalog: Catalog, name: str) -> None:
    built = own_screw(GEOMETRY, catalog.materials[name], name)
    assert built == custom_screw(CustomScrewIn(**GIVEN, material=name), catalog.materials)


def test_the_users_material_gives_the_requests_screw(catalog: Catalog) -> None:
    steel = catalog.materials["steel"]
    material = user_material(200e9, 7800.0, 3e8, steel)
    built = own_screw(GEOMETRY, material, "custom")
    request = CustomScrewIn(**GIVEN, material=OWN_STEEL)
    assert built == custom_screw(request, catalog.materials)
    assert built.provenance["youngs_modulus"].kind == "user"
    assert built.screw_expansion_per_k == steel.expansion_per_k.value


def test_the_inertia_is_a_solid_rod_at_the_pitch_diameter_unless_given(catalog: Catalog) -> None:
    """J/L = rho pi d_p^4 / 32 at d_p = (10 + 8) / 2 = 9 mm without a pitch: 7850 kg/m^3 x
    pi x (9 mm)^4 / 32 = 5.057e-6 kg m^2/m, not the root's 3.157e-6 (a rod at the root
    is 0.37 of one at the outer diameter where the seed's screws are 0.65-0.84)."""
    steel = catalog.materials["steel"]
    built = own_screw(GEOMETRY, steel, "steel")
    rho = steel.density_kg_m3.value
    assert built.inertia_kg_m2_per_m == pytest.approx(rho * math.pi * 0.009**4 / 32, rel=1e-12)
    assert built.inertia_kg_m2_per_m == pytest.approx(5.057e-6, rel=1e-3)
    assert built.provenance["inertia_per_length"].kind == "derived"
    given = own_screw(replace(GEOMETRY, inertia_kg_m2_per_m=1e-5), steel, "steel")
    assert given.inertia_kg_m2_per_m == 1e-5
    assert given.provenance["inertia_per_length"].kind == "user"


@pytest.mark.parametrize("catalog_id", ["Tr16x4-bronze", "Tr12x6(P3)-acetal", "Tr40x7-304-ptfe"])
def test_an_iso_screw_typed_in_without_its_inertia_takes_the_catalogs(
    catalog: Catalog, catalog_id: str
) -> None:
    """The catalog derives an ISO screw's inertia as a solid rod at d2 = d - 0.5 P (rule 9):
    Tr16x4 in C45, 7800 kg/m^3 x pi x (14 mm)^4 / 32 = 2.942e-5 kg m^2/m. The same screw
    typed in with its pitch and no inertia takes the same, not the 1.339e-5 of a rod at
    its 11.5 mm root, which cut the screw's share of the accelerating torque by half."""
    listed = catalog.by_id[catalog_id]
    data = CustomScrewIn(
        outer_diameter_mm=listed.outer_diameter_m * 1e3,
        root_diameter_mm=listed.root_diameter_m * 1e3,
        lead_mm=listed.lead_m * 1e3,
        pitch_mm=(listed.pitch_m or 0.0) * 1e3,
        thread_half_angle_deg=15.0,
        friction_dynamic=listed.friction_dynamic,
        friction_static=listed.friction_static,
        material=listed.material_name,
        nut_material=listed.variant,
    )
    own = custom_screw(data, catalog.materials, catalog.nut_materials)
    assert own.inertia_kg_m2_per_m == pytest.approx(listed.inertia_kg_m2_per_m, rel=1e-12)
    if catalog_id == "Tr16x4-bronze":
        assert own.inertia_kg_m2_per_m == pytest.approx(2.942e-5, rel=1e-3)


def test_a_catalog_nut_brings_its_ranged_values_to_the_users_screw(catalog: Catalog) -> None:
    """Tr16x4 in C45 with the catalog's bronze nut, given as the user's own screw: the nut's
    ranged values come with it as a catalog screw of that size has them (the wear rate's
    3:1 scatter either way, the allowed wear depth, the nut length 1.5-2.5 d when none is
    given), so its wear life is the same band as the catalog's Tr16x4-bronze, not the
    nominal value alone (life_band); the user's friction has no range."""
    data = CustomScrewIn(
        outer_diameter_mm=16.0,
        root_diameter_mm=11.5,
        lead_mm=4.0,
        pitch_mm=4.0,
        friction_dynamic=0.13,
        friction_static=0.16,
        material="c45-steel",
        nut_material="bronze",
    )
    own = custom_screw(data, catalog.materials, catalog.nut_materials)
    listed = catalog.by_id["Tr16x4-bronze"]
    assert set(own.assumption_ends) == set(listed.assumption_ends) - {
        "friction_dynamic",
        "friction_static",
    }
    for name, ends in own.assumption_ends.items():
        for mine, theirs in zip(ends, listed.assumption_ends[name], strict=True):
            assert mine == pytest.approx(theirs, rel=1e-12), name
    assert life_band(own) == pytest.approx(life_band(listed))
    assert life_band(own) == pytest.approx((1 / 3, 1 / 0.33))  # 1e-17 over 3e-17, 3.3e-18
    bare = custom_screw(data.model_copy(update={"nut_material": None}), catalog.materials)
    assert bare.assumption_ends == {}  # no nut material: nothing assumed with a range


#: Two axes that reach every nut check: a slow long-life horizontal one, and a vertical
#: one with a move, a mass and a warm ambient.
AXES = (
    Application(
        load_n=300.0,
        speed_m_s=0.02,
        length_m=0.8,
        stroke_m=0.6,
        cycles_per_day=200.0,
        required_life_years=5.0,
    ),
    Application(
        load_n=50.0,
        speed_m_s=0.1,
        length_m=0.5,
        stroke_m=0.3,
        accel_m_s2=1.0,
        moving_mass_kg=5.0,
        orientation="vertical",
        ambient_c=60.0,
    ),
)


def test_a_catalog_iso_screw_given_as_ones_own_is_rated_as_the_catalog_rates_it(
    catalog: Catalog,
) -> None:
    """Every eighth ISO trapezoidal screw of the catalog, typed in as the user's own (its
    geometry, friction, material, inertia and nut material): every number of the
    operating point and every check's verdict equal the catalog screw's, on both axes,
    and so do its values but the friction's range (the user's own friction has none)."""
    iso = [s for s in catalog.screws if s.family_id.startswith("TR-")][::8]
    assert len(iso) >= 20
    for listed in iso:
        data = CustomScrewIn(
            outer_diameter_mm=listed.outer_diameter_m * 1e3,
            root_diameter_mm=listed.root_diameter_m * 1e3,
            lead_mm=listed.lead_m * 1e3,
            pitch_mm=(listed.pitch_m or 0.0) * 1e3,
            thread_half_angle_deg=math.degrees(listed.thread_half_angle_rad),
            friction_dynamic=listed.friction_dynamic,
            friction_static=listed.friction_static,
            material=listed.material_name,
            nut_material=listed.variant,
            inertia_kg_m2_per_m=listed.inertia_kg_m2_per_m,
        )
        own = custom_screw(data, catalog.materials, catalog.nut_materials)
        assert (own.backlash_min_m, own.backlash_max_m) == pytest.approx(
            (listed.backlash_min_m, listed.backlash_max_m)
        )
        ranged = set(listed.assumption_ends) - {"friction_dynamic", "friction_static"}
        assert set(own.assumption_ends) == ranged, listed.id
        for app in AXES:
            mine, theirs = evaluate(app, own), evaluate(app, listed)
            for name in NAMES:
                a, b = quantity(mine.quantities, name), quantity(theirs.quantities, name)
                assert a == pytest.approx(b, rel=1e-9, nan_ok=True), (listed.id, name)
            verdicts = {c.name: c.passed for c in mine.checks}
            assert verdicts == {c.name: c.passed for c in theirs.checks}, listed.id
