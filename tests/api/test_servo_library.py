"""Servos in the motor library and the library held on the loaded catalog: a servo's
peak envelope and rated torque reach the motor checks; the servo model reproduces a
maker's published speed-torque points; a catalog directory's own motors.toml joins the
library, and a bad or duplicate motor stops the load with file, entry and field named."""

import math
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.catalog import Catalog, CatalogError, load_catalog
from app.contract.inputs import ApplicationIn
from app.core.evaluate import evaluate
from app.core.formulas import servo
from app.main import create_app
from app.server.settings import Settings
from tests.motor_library import MOTORS

OZ_IN_NM = 0.0070615518  # 1 oz in [N m]
AXIS = {"load_n": 20.0, "speed_mm_s": 50.0, "length_mm": 350.0, "stroke_mm": 200.0}


@pytest.mark.parametrize(
    ("rpm", "torque_oz_in"),
    [(3780.0, 0.0), (3360.0, 38.0), (3117.0, 60.0), (0.0, 342.0)],
    ids=["no-load", "torque-1", "torque-2", "stall"],
)
def test_the_servo_model_reproduces_a_published_speed_torque_line(
    rpm: float, torque_oz_in: float
) -> None:
    """Magmotor C21-F-300FX performance sheet (48 V): stall 342 oz in, no load 3780 rpm,
    38 oz in at 3360 rpm and 60 oz in at 3117 rpm. The model with rated speed 0 and no
    torque at the top speed is that line: 342 x (1 - 3360 / 3780) = 38.0 oz in, and
    342 x (1 - 3117 / 3780) = 60.0 oz in. Scatter allowed: 1 % of the stall torque
    (3.4 oz in), the sheet's rounding of speeds to the rpm and torques to the oz in."""
    model = servo.peak_torque_nm(rpm, 342 * OZ_IN_NM, 0.0, 3780.0, 0.0) / OZ_IN_NM
    assert model == pytest.approx(torque_oz_in, abs=0.01 * 342)


def test_an_ac_servo_envelope_is_flat_to_rated_then_falls_to_its_top() -> None:
    """Peak 0.48 N m to 3000 rpm, then straight to 0.16 N m at 6000 rpm: at 4500 rpm
    0.48 + (0.16 - 0.48) x 1500 / 3000 = 0.32 N m; nothing past 6000 rpm."""
    assert servo.peak_torque_nm(2000.0, 0.48, 3000.0, 6000.0, 0.16) == 0.48
    assert servo.peak_torque_nm(4500.0, 0.48, 3000.0, 6000.0, 0.16) == pytest.approx(0.32)
    assert servo.peak_torque_nm(6001.0, 0.48, 3000.0, 6000.0, 0.16) == 0.0


def _motor_checks(client: TestClient, params: dict[str, object]) -> dict[str, dict]:  # type: ignore[type-arg]
    r = client.get("/api/v1/select", params={**params, "detail": "full", "limit": 1})
    assert r.status_code == 200
    (candidate,) = r.json()["candidates"]
    return {c["name"]: c for c in candidate["checks"]}


def test_a_library_servo_drives_the_motor_checks(client: TestClient) -> None:
    """Ametek Pittman 14201S003: stall 0.44 N m, no load 4230 rpm, continuous 0.071 N m.
    The axis at 50 mm/s runs the passing screw at v / lead rpm; the curve's limit there is
    0.44 x (1 - n / 4230), the RMS limit the continuous torque, the speed limit where the
    line gives the continuous torque, 4230 x (1 - 0.071 / 0.44) = 3547 rpm."""
    checks = _motor_checks(client, {**AXIS, "motor": "pittman-14201s003"})
    rpm = checks["motor_speed"]["value"]
    assert checks["motor_speed"]["limit"] == pytest.approx(4230.0 * (1 - 0.071 / 0.44), abs=0.5)
    assert checks["motor_rms"]["limit"] == pytest.approx(0.071)
    # the top speed segment governs with no acceleration given; 1e-4: the envelope's end
    # is written to the rpm (3547)
    assert checks["motor_curve"]["limit"] == pytest.approx(0.44 * (1 - rpm / 4230.0), rel=1e-4)


def test_a_servo_too_slow_for_the_axis_is_rejected_by_its_speed(catalog: Catalog) -> None:
    """1 m/s on Tr24x10(P5) (no stroke: the top speed is reached) is 1000 / 10 x 60 =
    6000 rpm, beyond the 14204S004's 3702 rpm no-load speed and its envelope's end at
    the continuous torque, 3702 x (1 - 0.18 / 1.4) = 3226 rpm: the speed check fails."""
    params: dict[str, object] = {"load_n": 20.0, "speed_mm_s": 1000.0, "length_mm": 350.0}
    params["motor"] = "pittman-14204s004"
    app = ApplicationIn.model_validate(params).to_core(catalog.motors)
    result = evaluate(app, catalog.by_id["Tr24x10(P5)-bronze"])
    speed = next(c for c in result.checks if c.name == "motor_speed")
    assert not speed.passed and speed in result.failed_checks
    assert speed.value == pytest.approx(6000.0)
    assert speed.limit == pytest.approx(3702.0 * (1 - 0.18 / 1.4), abs=0.5)


def test_the_100_w_ac_servo_carries_its_cited_ratings() -> None:
    """Yaskawa SGM7J-01A (Sigma-7 rotary servomotor product manual, 4.2.2): rated torque
    0.318 N m, which is its 100 W at 3000 min-1: 100 / (3000 x 2 pi / 60) = 0.3183 N m;
    instantaneous maximum 1.11 N m; 3000 min-1 rated, 6000 min-1 maximum; 0.0659 x 1e-4
    kg m2 = 6.59e-6 kg m2. The torque at 6000 min-1 is not published as a number: the
    rated torque is assumed there, and the envelope is peak, peak at rated speed, that."""
    motor = MOTORS["yaskawa-sgm7j-01a"]
    assert motor.kind == "servo"
    assert motor.value("rated_torque_nm") == pytest.approx(100 / (3000 * 2 * math.pi / 60), 1e-3)
    assert motor.value("rated_torque_nm") == 0.318
    assert (motor.value("peak_torque_nm"), motor.value("rated_rpm")) == (1.11, 3000.0)
    assert motor.value("max_rpm") == 6000.0
    assert motor.value("rotor_inertia_g_cm2") == pytest.approx(0.0659e-4)
    assert motor.curve() == ((0.0, 1.11), (3000.0, 1.11), (6000.0, 0.318))
    kinds = {name: value.provenance.kind for name, value in motor.values.items()}
    assumed = dict.fromkeys(("top_speed_torque_nm", "top_speed_continuous_nm"), "assumed")
    assert kinds == {**dict.fromkeys(kinds, "vendor"), **assumed}
    assert motor.continuous_torque_nm() == 0.318 and motor.step_angle_deg() is None


def test_a_pick_and_place_axis_sized_with_the_100_w_servo(client: TestClient) -> None:
    """A 1.5 kg head at 300 mm/s and 3 m/s2 on 300 mm strokes (the stepper's pick-and-place
    axis without the step controller, on trapezoidal screws at a 0.5 mm tolerance: their
    nuts' play, up to 0.3 mm, counts in full): on an 8 mm lead the screw turns 300 / 8 x 60 =
    2250 rpm, below the 3000 min-1 rated speed, so the peak envelope gives the whole
    1.11 N m there (on the published part of the envelope, not the assumed top). The
    motor's share is the largest of the segment torque over 1.11 N m, the RMS torque over
    0.318 N m and 2250 / 6000 = 0.375: the speed governs."""
    params = {
        "family": ["TR-C45", "TR-304"],
        "load_n": 5.0,
        "moving_mass_kg": 1.5,
        "speed_mm_s": 300.0,
        "accel_mm_s2": 3000.0,
        "length_mm": 500.0,
        "stroke_mm": 300.0,
        "dwell_s": 0.1,
        "cycles_per_day": 10000.0,
        "required_life_years": 2.0,
        "positioning_tolerance_mm": 0.5,
        "rank_by": "motor_margin",
        "motor": "yaskawa-sgm7j-01a",
    }
    body = client.get("/api/v1/select", params={**params, "detail": "full"}).json()
    best = body["candidates"][0]
    assert best["lead_mm"] == 8.0
    checks = {c["name"]: c for c in best["checks"]}
    assert checks["motor_speed"]["value"] == pytest.approx(2250.0)
    assert checks["motor_speed"]["limit"] == pytest.approx(6000.0)
    assert checks["motor_curve"]["limit"] == pytest.approx(1.11)
    assert checks["motor_rms"]["limit"] == pytest.approx(0.318)
    shares = [checks[n]["value"] / checks[n]["limit"] for n in ("motor_curve", "motor_rms")]
    assert max(shares) < 2250.0 / 6000.0
    assert best["motor_use"] == pytest.approx(2250.0 / 6000.0)


SERVO = """schema = 1

[motors.my-servo]
name = "A servo of my own"
frame = "60 mm"
kind = "servo"
rated_torque_nm = { value = 0.32, provenance = "vendor", source = "s" }
peak_torque_nm = { value = 0.95, provenance = "vendor", source = "s" }
rated_rpm = { value = 3000.0, provenance = "vendor", source = "s" }
max_rpm = { value = 5000.0, provenance = "vendor", source = "s" }
top_speed_torque_nm = { value = 0.32, provenance = "assumed", source = "the rated torque" }
rotor_inertia_g_cm2 = { value = 37.0, provenance = "vendor", source = "s" }
"""


def test_a_catalog_directory_adds_its_motors_to_the_library(tmp_path: Path) -> None:
    (tmp_path / "motors.toml").write_text(SERVO)
    catalog = load_catalog([tmp_path])
    assert "my-servo" in catalog.motors and "pololu-1205" in catalog.motors
    assert catalog.motors["my-servo"].curve() == ((0.0, 0.95), (3000.0, 0.95), (5000.0, 0.32))
    client = TestClient(create_app(Settings(catalog_dirs=[tmp_path])))
    checks = _motor_checks(client, {**AXIS, "motor": "my-servo"})
    assert checks["motor_rms"]["limit"] == pytest.approx(0.32)
    assert checks["motor_speed"]["limit"] == pytest.approx(5000.0)


def test_the_built_in_app_does_not_know_another_directory_s_motor(client: TestClient) -> None:
    r = client.post("/api/v1/select", json={**AXIS, "motor": "my-servo"})
    assert r.status_code == 422
    (detail,) = r.json()["detail"]
    assert detail["field"] == "motor" and "unknown motor 'my-servo'" in detail["message"]


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ("peak_torque_nm = { value = 0.95", "peak_torque_nm = { value = 0.2", "peak_torque_nm"),
        ("rated_rpm = { value = 3000.0", "rated_rpm = { value = 6000.0", "rated_rpm"),
        ('kind = "servo"', 'kind = "linear"', "kind"),
        (
            "top_speed_torque_nm = { value = 0.32",
            "top_speed_torque_nm = { value = 2.0",
            "top_speed_torque_nm",
        ),
        (
            'provenance = "assumed", source = "the rated torque"',
            'provenance = "assumed"',
            "top_speed_torque_nm",
        ),
        (
            'top_speed_torque_nm = { value = 0.32, provenance = "assumed", source = "the rated '
            'torque" }',
            'top_speed_torque_nm = { value = 0.32, provenance = "assumed", source = "the rated '
            'torque" }\ntop_speed_continuous_nm = { value = 0.33, provenance = "vendor", '
            'source = "s" }',
            "top_speed_continuous_nm",
        ),
    ],
    ids=[
        "peak-below-rated",
        "rated-above-max",
        "unknown-kind",
        "top-above-peak",
        "no-source",
        "continuous-above-rated",
    ],
)
def test_a_bad_servo_stops_the_load_naming_the_field(
    tmp_path: Path, old: str, new: str, field: str
) -> None:
    assert old in SERVO
    (tmp_path / "motors.toml").write_text(SERVO.replace(old, new))
    with pytest.raises(CatalogError) as caught:
        load_catalog([tmp_path])
    text = str(caught.value)
    assert "motors.toml" in text and "motors.my-servo" in text and field in text


def test_a_motor_id_twice_across_directories_stops_the_load(tmp_path: Path) -> None:
    (tmp_path / "motors.toml").write_text(SERVO.replace("my-servo", "pololu-1205"))
    with pytest.raises(CatalogError, match="duplicate motor id"):
        load_catalog([tmp_path])


def test_a_library_file_that_is_not_a_regular_file_is_refused(tmp_path: Path) -> None:
    """The same hostile-file rule as the catalog's files: a FIFO or a directory named
    motors.toml is not read."""
    (tmp_path / "motors.toml").mkdir()
    with pytest.raises(CatalogError):
        load_catalog([tmp_path])


def test_every_library_value_carries_provenance_with_a_source(catalog: Catalog) -> None:
    for motor in catalog.motors.values():
        for name, value in motor.values.items():
            assert value.provenance.kind in {"vendor", "derived", "assumed"}, (motor.id, name)
            assert value.provenance.source, (motor.id, name)


#: The axis run above the 100 W servo's rated speed: 800 mm/s on a 10 mm lead is 4800 rpm.
FAST = {
    "load_n": 20.0,
    "moving_mass_kg": 5.0,
    "lead_mm": 10.0,
    "speed_mm_s": 800.0,
    "length_mm": 600.0,
    "accel_mm_s2": 5000.0,
    "stroke_mm": 500.0,
    "motor": "yaskawa-sgm7j-01a",
    "detail": "full",
}


def _first(client: TestClient, params: dict[str, object]) -> dict:  # type: ignore[type-arg]
    """The first candidate of the selection, passing or not."""
    r = client.get("/api/v1/select", params=params)
    assert r.status_code == 200, r.text
    body = r.json()
    first: dict = (body["candidates"] or body["rejected"])[0]  # type: ignore[type-arg]
    return first


def test_above_its_rated_speed_a_servo_allows_less_continuous_torque(client: TestClient) -> None:
    """Yaskawa's rule: the effective torque within the continuous duty zone (Sigma-II
    manual sec. 3.2.3), which narrows above the rated speed. The library takes the
    SGM7J-01A's zone straight from 0.318 N m at 3000 rpm to an assumed 0.159 N m at
    6000 rpm: at 4800 rpm 0.318 - 0.159 x 1800 / 3000 = 0.2226 N m. Every moving segment
    runs at 4800 rpm and the dwells carry nothing, so the RMS torque held to the zone is
    the plain RMS times 0.318 / 0.2226 (it was the plain RMS, as if the rated torque held
    at every speed), against 0.318 N m; the limit rests on the assumed zone."""
    candidate = _first(client, {**FAST, "limit": 1})
    check = next(c for c in candidate["checks"] if c["name"] == "motor_rms")
    zone_nm = 0.318 - (0.318 - 0.159) * (4800.0 - 3000.0) / (6000.0 - 3000.0)
    assert zone_nm == pytest.approx(0.2226)
    assert candidate["rpm"] == pytest.approx(4800.0)
    assert check["limit"] == 0.318
    assert check["value"] == pytest.approx(candidate["torque"]["rms_nm"] * 0.318 / zone_nm)
    assert "narrows with speed (to 0.159 N m at 6000 rpm)" in check["message"]
    assert candidate["provenance"]["motor_rms_torque"]["kind"] == "assumed"


def test_a_continuous_torque_typed_in_holds_at_every_speed_unless_a_zone_is_typed(
    client: TestClient,
) -> None:
    """A continuous torque typed for the library servo replaces its rating and zone (the
    RMS held to it is the plain RMS); a zone typed with it narrows it again: 0.3 N m to
    3000 rpm, 0.15 N m at 6000 rpm gives 0.3 - 0.15 x 1800 / 3000 = 0.21 N m at 4800 rpm."""
    params = {**FAST, "limit": 1, "motor_rms_torque_nm": 0.3}
    flat = _first(client, params)
    check = next(c for c in flat["checks"] if c["name"] == "motor_rms")
    assert check["limit"] == 0.3
    assert check["value"] == pytest.approx(flat["torque"]["rms_nm"])
    params["motor_rms_curve"] = "0:0.3,3000:0.3,6000:0.15"
    zoned = _first(client, params)
    check = next(c for c in zoned["checks"] if c["name"] == "motor_rms")
    assert check["value"] == pytest.approx(zoned["torque"]["rms_nm"] * 0.3 / 0.21)
