"""Where a motor or support check's limit comes from: the motor's curve and rated torque
and the support unit's ratings carry the provenance of the library entry they are taken
from (catalog/motors.toml, catalog/supports.toml), or the user's where typed in. A curve
the stepper or servo model draws is derived, and assumed where the model reads an
assumed value of the entry (17HS19-2004S1's 24 V drive, the Yaskawa servo's torque at
top speed)."""

from typing import Any

from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate

#: a light axis with a move on a small TFE-coated leadscrew: the motor's curve governs
AXIS = {"load_n": 5, "speed_mm_s": 60, "length_mm": 300, "moving_mass_kg": 1,
        "accel_mm_s2": 1000}  # fmt: skip
SCREW = "B4000-L8-TFE"


def _curve(c: dict[str, Any]) -> dict[str, str]:
    """The motor curve's provenance, as the candidate and its curve check give it."""
    assert "motor_curve" in check(c, "motor_curve")["sources"]
    return c["provenance"]["motor_curve"]  # type: ignore[no-any-return]


def test_a_library_steppers_modelled_curve_is_derived_not_the_users(client: TestClient) -> None:
    """Pololu #1205's curve is drawn by the microstepping model from its datasheet values
    (all the maker's): the limit it sets is derived, as the curve's provenance says."""
    c = evaluate(client, SCREW, **AXIS, motor="pololu-1205")
    assert c["governing_check"] == "motor_curve"
    assert c["governing_limit_provenance"] == "derived"
    curve = _curve(c)
    assert curve["kind"] == "derived" and "microstepping model" in curve["source"]
    assert "Pololu #1205" in curve["source"]


def test_a_curve_drawn_at_an_assumed_drive_voltage_is_assumed(client: TestClient) -> None:
    """The library takes a 24 V drive for 17HS19-2004S1 (assumed): the curve drawn at it
    is assumed, its source names the assumption, and a pass it governs rests on it."""
    c = evaluate(client, SCREW, **{**AXIS, "load_n": 20}, motor="17hs19-2004s1")
    curve = _curve(c)
    assert curve["kind"] == "assumed" and "assumed supply_v: a 24 V drive" in curve["source"]
    # typed in, the drive voltage is the user's: the curve is derived again
    typed = evaluate(
        client, SCREW, **{**AXIS, "load_n": 20}, motor="17hs19-2004s1", motor_supply_v=24
    )
    assert _curve(typed)["kind"] == "derived"


def test_a_pass_governed_by_an_assumed_curve_says_it_rests_on_it(client: TestClient) -> None:
    """The Yaskawa servo's envelope falls to a torque at top speed the library assumes:
    where that curve governs a pass (35 kg at 600 mm/s, 10 m/s² on a 10 mm lead ball
    screw), the verdict says the pass rests on it."""
    axis = {"load_n": 50, "speed_mm_s": 600, "length_mm": 400, "moving_mass_kg": 35,
            "accel_mm_s2": 10000}  # fmt: skip
    c = evaluate(client, "R16-10K3-FSCDIN", **axis, motor="yaskawa-sgm7j-01a")
    assert c["passed"] and c["governing_check"] == "motor_curve"
    assert c["governing_limit_provenance"] == "assumed"
    assert "Rests on assumed motor torque-speed curve" in c["verdict"]["text"]
    assert "assumed top_speed_torque_nm" in _curve(c)["source"]
    # over a 300 mm stroke back and forth the RMS torque governs: its limit is the
    # servo's rated torque, the maker's, but at 3600 rpm, above the rated 3000, held to the
    # continuous duty zone the library assumes above it
    moving = evaluate(client, "R16-10K3-FSCDIN", **axis, stroke_mm=300, motor="yaskawa-sgm7j-01a")
    assert moving["governing_check"] == "motor_rms"
    assert moving["governing_limit_provenance"] == "assumed"
    source = moving["provenance"]["motor_rms_torque"]["source"]
    assert "rated torque 0.318 N m" in source and "continuous duty zone" in source
    # below the rated speed the zone is flat: the limit is the maker's alone (over a 250 mm
    # stroke: over 300 mm the stroke with the 45 mm nut, 86 % of the screw, governs)
    slow = {**axis, "speed_mm_s": 400}
    slower = evaluate(client, "R16-10K3-FSCDIN", **slow, stroke_mm=250, motor="yaskawa-sgm7j-01a")
    assert slower["governing_check"] == "motor_rms"
    assert slower["governing_limit_provenance"] == "vendor"


def test_a_published_curve_is_the_makers_and_a_typed_one_the_users(client: TestClient) -> None:
    published = evaluate(client, SCREW, **{**AXIS, "load_n": 20}, motor="sy35st36-1004a")
    assert published["governing_check"] == "motor_curve"
    assert published["governing_limit_provenance"] == "vendor"
    assert "SY35ST36-1004A" in _curve(published)["source"]
    typed = evaluate(client, SCREW, **AXIS, motor_curve="0:0.2,1000:0.1")
    assert _curve(typed) == {"kind": "user", "source": "the torque-speed curve typed in"}
    assert typed["governing_limit_provenance"] == "user"


def test_a_library_support_units_rating_is_the_makers(client: TestClient) -> None:
    """3 kN on THK's FK6 (static rating 1.76 kN): the thrust bearing's check governs on
    the maker's rating; typed in, the rating is the user's."""
    axis = {"load_n": 3000, "speed_mm_s": 5, "length_mm": 300}
    c = evaluate(client, "Tr20x4-bronze", **axis, support_id="thk-fk6")
    assert c["governing_check"] == "support_static"
    assert c["governing_limit_provenance"] == "vendor"
    assert "EK 6 / FK 6" in c["provenance"]["support_static"]["source"]
    typed = evaluate(client, "Tr20x4-bronze", **axis, support_static_n=1760)
    assert typed["governing_check"] == "support_static"
    assert typed["governing_limit_provenance"] == "user"


def test_a_library_steppers_holding_and_detent_torques_are_the_libraries(
    client: TestClient,
) -> None:
    """A vertical axis held by SY42STH47-1684B energised, and by its detent torque with the
    power off, on a ball screw that back-drives: the limits the holding checks hold it to
    are the library's (vendor), not values the user typed; typed in, they are the user's."""
    axis = {"load_n": 10, "speed_mm_s": 20, "length_mm": 300, "orientation": "vertical",
            "holding_source": "energised"}  # fmt: skip
    c = evaluate(client, "R16-10K3-FSCDIN", **axis, motor="sy42sth47-1684b")
    assert c["passed"] and c["governing_check"] == "holding_power_off"
    assert c["governing_limit_provenance"] == "vendor"
    assert "detent torque" in c["provenance"]["motor_detent"]["source"]
    assert c["provenance"]["motor_holding"]["kind"] == "vendor"
    assert "motor_detent" in check(c, "holding_power_off")["sources"]
    typed = evaluate(
        client, "R16-10K3-FSCDIN", **axis, motor="sy42sth47-1684b", detent_torque_nm=0.02,
        brake_torque_nm=0.5,
    )  # fmt: skip
    assert typed["governing_limit_provenance"] == "user"
    assert typed["provenance"]["motor_holding"]["kind"] == "user"
