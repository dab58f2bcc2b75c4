"""A library motor's published mass (catalog/motors.toml ``mass_kg``): read and checked
with the library, listed with its provenance, and counted on the axis below where the
axis that names the motor types no motor mass of its own."""

from pathlib import Path
from typing import Any
from urllib.parse import urlencode

import pytest
from fastapi.testclient import TestClient

from app.catalog import CatalogError
from app.catalog.motors import load_motors
from tests.api.test_motor_library import LIBRARY
from tests.machine_axes import X, Z, page_query
from tests.motor_library import MOTORS


@pytest.mark.parametrize(
    ("motor", "kg", "kind", "cited"),
    [
        # Changzhou Songyang SY42STH47-1684B specifications: "Weight (Kg) 0.365"
        ("sy42sth47-1684b", 0.365, "vendor", "SY42STH47-1684B.pdf"),
        # Trinamic QSH4218 manual V1.03, Table 1.1: -51-10-049 "Weight (Mass) Kg 0.35"
        ("qsh4218-51-10-049", 0.35, "vendor", "Table 1.1"),
        # Ametek Pittman 14204S004 data sheet: "Weight WM oz (g) 38 (1083)"
        ("pittman-14204s004", 1.083, "vendor", "38 oz (1083 g)"),
        # STEPPERONLINE 17HS19-2004S1 specification: "Weight 390g" (the library had an
        # assumed 0.365 kg, a similar motor's, and said the maker gave none)
        ("17hs19-2004s1", 0.39, "vendor", "weight 390 g"),
    ],
)
def test_a_library_motor_carries_its_datasheet_mass(
    motor: str, kg: float, kind: str, cited: str
) -> None:
    mass = MOTORS[motor].mass()
    assert mass is not None and mass.value == pytest.approx(kg, rel=1e-12)
    assert mass.provenance.kind == kind and cited in mass.provenance.source


def test_the_motor_list_shows_each_mass_with_its_provenance(client: TestClient) -> None:
    motors = {m["id"]: m for m in client.get("/api/v1/motors").json()["motors"]}
    mass = motors["sy35st36-1004a"]["values"]["mass_kg"]
    assert mass["value"] == pytest.approx(0.18) and mass["unit"] == "kg"
    assert mass["provenance"]["kind"] == "vendor" and "0.18 kg" in mass["provenance"]["source"]
    assumed = motors["23hs32-4004s"]["values"]["mass_kg"]["provenance"]
    assert assumed["kind"] == "assumed" and "QSH5718-79-30-163" in assumed["source"]


def _library_with_mass(tmp_path: Path, value: str) -> Path:
    path = tmp_path / "motors.toml"
    mass = f'mass_kg = {{ value = {value}, provenance = "vendor", source = "s" }}\n'
    path.write_text(LIBRARY + mass)
    return path


def test_a_user_library_may_give_a_mass(tmp_path: Path) -> None:
    mass = load_motors(_library_with_mass(tmp_path, "0.35"))["m1"].mass()
    assert mass is not None and mass.value == 0.35 and mass.unit == "kg"


@pytest.mark.parametrize(
    ("value", "reason"),
    [("0.0", "> 0"), ("-0.3", "> 0"), ("inf", "finite"), ('"heavy"', "a number")],
)
def test_a_mass_not_positive_and_finite_is_refused(tmp_path: Path, value: str, reason: str) -> None:
    with pytest.raises(CatalogError) as caught:
        load_motors(_library_with_mass(tmp_path, value))
    text = str(caught.value)
    assert "motors.m1" in text and "mass_kg" in text and reason in text


def machine(z_motor_kg: float | None = None) -> dict[str, Any]:
    """A printer gantry whose Z names the SY42STH47-1684B (0.365 kg) and whose X names
    the QSH4218-47-28-040 (0.35 kg), neither motor's mass typed unless ``z_motor_kg``."""
    typed = {} if z_motor_kg is None else {"motor_kg": z_motor_kg}
    return {
        "axes": [
            {"name": "Z", "inputs": {**Z, "motor": "sy42sth47-1684b"}, "frame_kg": 0.3, **typed},
            {"name": "X", "inputs": {**X, "motor": "qsh4218-47-28-040"}, "frame_kg": 0.5},
            {"name": "Y", "inputs": {**X, "moving_mass_kg": 0.5}},
        ]
    }


def test_a_library_motor_s_mass_rides_on_the_axis_below(client: TestClient) -> None:
    """Z brings X its payload, frame, chosen screw and motor: 0.5 + 0.3 + 0.0502 (its
    B4000-L8-TFE over 250 mm, screw_kg: 8000 x pi x 5.6515^2 mm^2 / 4 x 0.25 m) + 0.365
    (the SY42STH47-1684B's datasheet weight) = 1.2152 kg, where the old answer left the
    motor out (0.8502 kg). X brings Y 0.8 + 0.5 + 1.2152 + its screw (0.0803) + 0.35 (the
    QSH4218-47-28-040's) = 2.9455 kg."""
    z, x, y = client.post("/api/v1/machine", json=machine()).json()["axes"]
    assert z["motor_kg"] == 0.365 and z["motor_mass_origin"] == "library"
    assert z["motor_mass_motor"] == "sy42sth47-1684b"
    assert z["motor_mass_provenance"]["kind"] == "vendor"
    assert "0.365 kg" in z["motor_mass_provenance"]["source"]
    assert z["screw_kg"] == pytest.approx(0.0502, abs=1e-4)
    assert x["carried_kg"] == pytest.approx(0.5 + 0.3 + z["screw_kg"] + 0.365, rel=1e-12)
    assert x["carried_kg"] == pytest.approx(1.2152, abs=1e-4)
    assert x["motor_kg"] == 0.35 and x["motor_mass_origin"] == "library"
    assert y["carried_kg"] == pytest.approx(0.8 + 0.5 + 1.2152 + x["screw_kg"] + 0.35, abs=1e-4)
    assert y["motor_mass_origin"] == "library" and y["motor_mass_motor"] == "17hs19-2004s1"


def test_a_typed_motor_mass_wins_over_the_library_s(client: TestClient) -> None:
    """Z's 0.4 kg typed replaces its motor's 0.365 kg: X carries 0.035 kg more, and the
    answer names the typed value as the source, with no library provenance."""
    library = client.post("/api/v1/machine", json=machine()).json()["axes"]
    typed = client.post("/api/v1/machine", json=machine(z_motor_kg=0.4)).json()["axes"]
    assert typed[0]["motor_kg"] == 0.4 and typed[0]["motor_mass_origin"] == "typed"
    assert typed[0]["motor_mass_provenance"] is None and typed[0]["motor_mass_motor"] is None
    change = typed[1]["carried_kg"] - library[1]["carried_kg"]
    assert change == pytest.approx(0.4 - 0.365, abs=1e-9)
    zero = client.post("/api/v1/machine", json=machine(z_motor_kg=0.0)).json()["axes"]
    assert zero[0]["motor_kg"] == 0.0 and zero[0]["motor_mass_origin"] == "typed"


def test_an_axis_without_a_library_mass_carries_none(client: TestClient) -> None:
    """The SGM7J-01A carries no published mass in the library: its axis's motor mass is
    0 kg, said to come from nowhere (type motor_kg)."""
    body = {"axes": [{"name": "X", "inputs": {**X, "motor": "yaskawa-sgm7j-01a"}}]}
    (x,) = client.post("/api/v1/machine", json=body).json()["axes"]
    assert x["motor_kg"] == 0.0 and x["motor_mass_origin"] == "none"


def test_a_ranged_library_mass_counts_at_the_top_of_its_range(client: TestClient) -> None:
    """The Pololu 1205 weighs 0.12 kg on its datasheet and up to 0.14 kg as listed
    (catalog/motors.toml): the axis below carries 0.14 kg of it, the safe side; the
    23HS32-4004S's assumed 1.0 kg (range to 1.15 kg) counts 1.15 kg."""
    for motor, heaviest in (("pololu-1205", 0.14), ("23hs32-4004s", 1.15)):
        body = {
            "axes": [{"name": "Z", "inputs": {**Z, "motor": motor}}, {"name": "X", "inputs": X}]
        }
        z, x = client.post("/api/v1/machine", json=body).json()["axes"]
        assert z["motor_kg"] == heaviest and z["motor_mass_origin"] == "library"
        assert x["carried_kg"] == pytest.approx(0.5 + heaviest + z["screw_kg"], rel=1e-12)


def test_the_page_says_a_motor_mass_of_0_is_assumed(client: TestClient) -> None:
    """No motor mass typed and none published: the page's 0 kg says it is assumed."""
    x = page_query({**X, "motor": "yaskawa-sgm7j-01a"})
    page = client.get("/machine?" + urlencode({"link1": x, "name1": "X"}))
    assert "assumed: none typed and none published; type it" in page.text


def test_the_machine_page_says_whose_motor_mass_it_counts(client: TestClient) -> None:
    """Z's link names the SY42STH47-1684B and no motor mass is typed: the page counts the
    library's 0.365 kg (vendor) and says whose it is; a typed one is shown as typed."""
    z, x = page_query(machine()["axes"][0]["inputs"]), page_query(X)
    page = client.get("/machine?" + urlencode({"link1": z, "link2": x, "name2": "X"}))
    assert page.status_code == 200
    assert "library motor sy42sth47-1684b's published mass, the top of its range where" in page.text
    typed = urlencode({"link1": z, "motor1": "0.4", "link2": x, "name2": "X"})
    assert "as typed" in client.get("/machine?" + typed).text
    assert "Typed, it wins." in page.text
