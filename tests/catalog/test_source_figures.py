"""Catalog values held to the figures their cited sources print (the audit of the
catalog against its sources): each expected number is the source's, written here with
its citation, so a value that drifts from its source fails here."""

import pytest

from app.catalog import Catalog


def test_robotshop_1182_mass_is_the_weight_its_motor_notes_give(catalog: Catalog) -> None:
    """RobotShop datasheet-1182 as listed in Computer-Vision-and-Robotic-Perception/
    asabe-robot-2023, Manipulator/Controller/MotorSpecifications.ino: "Weight: 0.34KG
    (0.75lb)". The library read 0.365 kg, assumed from another motor, with a source
    saying the notes give no mass."""
    mass = catalog.motors["robotshop-1182"].mass()
    assert mass is not None
    assert mass.value == pytest.approx(0.34)
    assert mass.value == pytest.approx(0.75 * 0.45359237, abs=0.001)
    assert mass.provenance.kind == "vendor"
    assert "MotorSpecifications.ino" in mass.provenance.source
    assert "0.34 kg" in mass.provenance.source


# THK Support Unit catalog 513-2E, table of the fixed side's angular ball bearing, axial
# direction: basic dynamic load rating Ca (kN) and permissible load (kN), the note
# calling the latter the static permissible load.
THK_513_2E_KN = {
    "thk-fk6": (1.38, 1.76),
    "thk-fk8": (2.93, 2.15),
    "thk-fk10": (6.08, 3.1),
    "thk-fk12": (6.66, 3.25),
    "thk-fk15": (7.6, 4.0),
    "thk-bk17": (13.7, 5.85),
    "thk-fk20": (17.9, 9.5),
    "thk-bk20": (12.7, 7.55),
    "thk-fk25": (20.2, 11.5),
    "thk-fk30": (28.0, 16.3),
}


@pytest.mark.parametrize(("unit", "ratings_kn"), THK_513_2E_KN.items())
def test_support_units_are_thks_table_in_newtons(
    catalog: Catalog, unit: str, ratings_kn: tuple[float, float]
) -> None:
    support = catalog.supports[unit]
    ca_kn, permissible_kn = ratings_kn
    assert support.value("dynamic_axial_n") == pytest.approx(ca_kn * 1e3)
    assert support.value("static_axial_n") == pytest.approx(permissible_kn * 1e3)
