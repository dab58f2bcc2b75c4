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


#: N m in one ounce-force inch (0.27801385 N x 0.0254 m).
OZ_IN_NM = 0.00706155


def test_qsh4218_47_28_040_holding_torque_is_the_lower_of_its_two_figures(
    catalog: Catalog,
) -> None:
    """Trinamic QSH4218 manual V1.06 (thomasarmel/arduino_polytech_2019_2020,
    datasheets/QSH4218_manual.pdf, commit 1437bba), motor technical data, column
    -47-28-040: "Holding Torque (typ.)" 40 N cm and 56.3 oz in, which disagree (40 N cm is
    56.6 oz in). The lower: 56.3 x 0.00706155 = 0.39757 N m, written 0.3975. The library
    read 0.40, above the 56.3 oz in."""
    motor = catalog.motors["qsh4218-47-28-040"]
    holding = motor.value("holding_torque_nm")
    assert holding == pytest.approx(0.3975)
    assert holding <= 56.3 * OZ_IN_NM
    assert "56.3 oz in" in motor.values["holding_torque_nm"].provenance.source


def test_qsh4218_47_28_040_curve_is_held_to_the_holding_torque(catalog: Catalog) -> None:
    """Figure 5.4 of the same manual plots 0.404 N m at 1000 and 2000 pps (150 and 300 rpm
    half step), above the table's holding torque; the library held 0.4035 there (and down
    to standstill). The lower figure is kept: 0.3975 N m at both, the rest as read."""
    curve = catalog.motors["qsh4218-47-28-040"].published_curve()
    assert curve is not None
    assert curve[:3] == ((0.0, 0.3975), (149.8, 0.3975), (299.9, 0.3975))
    assert curve[3] == (449.8, 0.3894)


def test_robotshop_1182_holding_torque_is_the_lower_of_its_two_figures(catalog: Catalog) -> None:
    """RobotShop datasheet-1182 as listed in asabe-robot-2023's MotorSpecifications.ino:
    "Holding Torque: 0.57N.M (80oz*in)". 80 oz in = 80 x 0.00706155 = 0.56492 N m, below
    0.57 and outside its rounding (0.565 to 0.575 takes in 80 oz in only up to 80.5 oz in
    = 0.5685): the lower is kept, 0.5649. The library read 0.57."""
    motor = catalog.motors["robotshop-1182"]
    holding = motor.value("holding_torque_nm")
    assert holding == pytest.approx(0.5649)
    assert holding <= 80 * OZ_IN_NM
    assert "80oz*in" in motor.values["holding_torque_nm"].provenance.source


def test_no_published_pull_out_point_is_above_the_holding_torque(catalog: Catalog) -> None:
    """A pull-out curve is held down to standstill from its first point: no point of a
    library stepper's published curve may stand above the holding torque its datasheet
    gives (23HS32-4004S 1.841 of 2.40 N m; SY35ST36-1004A 0.0976 of 0.1373; SY42STH47-1684B
    0.31 of 0.4315; QSH4218-51-10-049 0.3963 of 0.49; QSH4218-47-28-040 0.3975 of 0.3975)."""
    curved = [m for m in catalog.motors.values() if m.published_curve() is not None]
    assert len(curved) == 5
    for motor in curved:
        curve = motor.published_curve()
        assert curve is not None
        holding = motor.value("holding_torque_nm")
        assert max(nm for _, nm in curve) <= holding, motor.id
