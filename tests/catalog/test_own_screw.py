"""A screw of the user's own (app.catalog.own): the same candidate the API's custom-screw
request gives (``report.present.custom_screw``), its values of provenance "user", and its
inertia, when not given, that of a solid rod at the root diameter."""

import math
from dataclasses import replace

import pytest

from app.catalog import Catalog
from app.catalog.own import OwnGeometry, own_screw, user_material
from app.contract.screws import CustomScrewIn, MaterialIn
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


def test_the_inertia_is_a_solid_rod_at_the_root_unless_given(catalog: Catalog) -> None:
    """J/L = rho pi d_r^4 / 32: 7850 kg/m^3 x pi x (8 mm)^4 / 32 = 3.157e-6 kg m^2/m."""
    steel = catalog.materials["steel"]
    built = own_screw(GEOMETRY, steel, "steel")
    rho = steel.density_kg_m3.value
    assert built.inertia_kg_m2_per_m == pytest.approx(rho * math.pi * 0.008**4 / 32, rel=1e-12)
    assert built.provenance["inertia_per_length"].kind == "derived"
    given = own_screw(replace(GEOMETRY, inertia_kg_m2_per_m=1e-5), steel, "steel")
    assert given.inertia_kg_m2_per_m == 1e-5
    assert given.provenance["inertia_per_length"].kind == "user"
