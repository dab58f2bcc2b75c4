"""GET /api/v1/motors: every value in the unit its name carries, as the datasheet and
``catalog/motors.toml`` give it (the library holds SI; the API converts at its edge)."""

import tomllib

import pytest
from fastapi.testclient import TestClient

from app.paths import resource_dir

#: The library file as written: motor id -> field -> its datasheet value.
LIBRARY = resource_dir("catalog") / "motors.toml"
FILE = tomllib.loads(LIBRARY.read_text(encoding="utf-8"))["motors"]


@pytest.fixture(scope="module")
def motors(client: TestClient) -> dict[str, dict]:  # type: ignore[type-arg]
    r = client.get("/api/v1/motors")
    assert r.status_code == 200
    return {m["id"]: m for m in r.json()["motors"]}


@pytest.mark.parametrize(
    ("field", "value", "unit"),
    [
        # STEPPERONLINE 17HS19-2004S1 as tabled in the stepper-simulator motor list
        # (data/steppers.csv): 3 mH, rotor inertia 82 g cm², holding torque 59 N cm
        ("inductance_mh", 3.0, "mH"),
        ("rotor_inertia_g_cm2", 82.0, "g cm²"),
        ("holding_torque_nm", 0.59, "N m"),
        ("phase_current_a", 2.0, "A"),
        ("step_angle_deg", 1.8, "deg"),
    ],
    ids=["inductance", "rotor-inertia", "holding-torque", "current", "step-angle"],
)
def test_17hs19_values_are_its_datasheet_s(
    motors: dict[str, dict],  # type: ignore[type-arg]
    field: str,
    value: float,
    unit: str,
) -> None:
    shown = motors["17hs19-2004s1"]["values"][field]
    assert shown["value"] == pytest.approx(value, rel=1e-12)
    assert shown["unit"] == unit


def test_every_value_is_the_file_s_in_the_unit_of_its_name(
    motors: dict[str, dict],  # type: ignore[type-arg]
) -> None:
    """Each motor's every value reads back as written in the file, whatever the unit
    (a rotor inertia of 1e-5 kg m² would be 100 g cm²: caught here)."""
    assert set(motors) == set(FILE)
    for motor_id, written in FILE.items():
        values = motors[motor_id]["values"]
        for field, entry in written.items():
            if isinstance(entry, dict):
                shown, raw = values[field]["value"], entry["value"]
                # a published curve is rows of (rpm, N m), read back row by row
                rows = raw if isinstance(raw, list) else [[raw]]
                got = shown if isinstance(raw, list) else [[shown]]
                for row, back in zip(rows, got, strict=True):
                    assert back == pytest.approx(row, rel=1e-12), (motor_id, field)
    suffixes = {"_mh": "mH", "_g_cm2": "g cm²", "_nm": "N m", "_rpm": "rpm", "_deg": "deg"}
    for motor in motors.values():
        for field, shown in motor["values"].items():
            for suffix, unit in suffixes.items():
                if field.endswith(suffix):
                    assert shown["unit"] == unit, (motor["id"], field)
