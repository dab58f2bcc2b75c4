"""A cycle of moves through the API: the moves as JSON and as the query's compact text,
refused move by move, carried by share links, and their energy per cycle reported."""

from typing import Any
from urllib.parse import parse_qs, urlsplit

import pytest
from fastapi.testclient import TestClient

from app.contract.cycle import MoveIn, moves_text, parse_moves_text
from tests.api.calls import API, check, evaluate

#: A pick-and-place: 2.5 kg out, 0.5 kg back, 300 mm at 250 mm/s, 0.2 s dwells.
MOVES = [
    {"distance_mm": 300, "speed_mm_s": 250, "accel_mm_s2": 2500, "decel_mm_s2": 2500,
     "dwell_s": 0.2, "moving_mass_kg": 2.5, "load_n": 10, "load_direction": "opposes"},
    {"distance_mm": -300, "speed_mm_s": 250, "accel_mm_s2": 2500, "decel_mm_s2": 2500,
     "dwell_s": 0.2, "moving_mass_kg": 0.5, "load_n": 10, "load_direction": "opposes"},
]  # fmt: skip
TEXT = "300:250:2500:2500:0.2:2.5:10:opposes;-300:250:2500:2500:0.2:0.5:10:opposes"
AXIS = {"load_n": 10, "speed_mm_s": 250, "length_mm": 500}
#: Out slowly with a 4 kg part against 15 N, back fast with the 1.5 kg carriage.
SLOW_OUT_FAST_BACK = [
    {"distance_mm": 300, "speed_mm_s": 150, "accel_mm_s2": 1500, "decel_mm_s2": 1500,
     "dwell_s": 0.3, "moving_mass_kg": 4, "load_n": 15, "load_direction": "opposes"},
    {"distance_mm": -300, "speed_mm_s": 250, "accel_mm_s2": 2500, "decel_mm_s2": 2000,
     "dwell_s": 0.7, "moving_mass_kg": 1.5, "load_n": 5, "load_direction": "opposes"},
]  # fmt: skip
SLOW_AXIS = {"load_n": 0, "speed_mm_s": 250, "length_mm": 500}


def test_the_compact_text_reads_back_exactly() -> None:
    moves = [MoveIn.model_validate(m) for m in MOVES]
    assert moves_text(moves) == TEXT
    assert [MoveIn.model_validate(m) for m in parse_moves_text(TEXT)] == moves


def test_moves_as_json_and_as_text_give_the_same_candidate(client: TestClient) -> None:
    as_json = evaluate(client, "B8000-L10", **AXIS, moves=MOVES)
    as_text = evaluate(client, "B8000-L10", **AXIS, moves=TEXT)
    assert as_json == as_text
    assert as_json["torque"]["rms_nm"] > 0.0
    # the balance the energy rows keep: motor work - braking = load + thread + drag
    balance = sum(as_json[k] for k in ("cycle_load_work_j", "cycle_thread_loss_j",
                                       "cycle_drag_loss_j"))  # fmt: skip
    assert as_json["cycle_motor_work_j"] - as_json["cycle_regen_j"] == pytest.approx(balance)


def test_a_library_stepper_reports_its_copper_loss(client: TestClient) -> None:
    """STEPPERONLINE 17HS19-2004S1 (2.0 A, 1.4 ohm, the library's values) over the 3 s
    cycle, microstepped: (2.0 / sqrt 2)^2 x 2 x 1.4 x 3 = 16.8 J; at full steps (the
    default) both windings carry 2.0 A all the time, 33.6 J; a cycle with no motor has
    none."""
    stepper = evaluate(
        client, "B8000-L10", **AXIS, moves=MOVES, motor="17hs19-2004s1", microsteps=16
    )
    assert stepper["cycle_copper_loss_j"] == pytest.approx(16.8)
    full = evaluate(client, "B8000-L10", **AXIS, moves=MOVES, motor="17hs19-2004s1")
    assert full["cycle_copper_loss_j"] == pytest.approx(33.6)
    assert evaluate(client, "B8000-L10", **AXIS, moves=MOVES)["cycle_copper_loss_j"] is None


@pytest.mark.parametrize(
    ("moves", "field"),
    [
        ([MOVES[0], {**MOVES[1], "speed_mm_s": -1}], "moves.1.speed_mm_s"),
        ([{**MOVES[0], "distance_mm": 0}, MOVES[1]], "moves.0.distance_mm"),
        ([MOVES[0], {**MOVES[1], "load_direction": "sideways"}], "moves.1.load_direction"),
        ([MOVES[0], {**MOVES[1], "colour": "red"}], "moves.1.colour"),
        ([MOVES[0]], "moves"),  # does not return to its start
        ([{**MOVES[0], "distance_mm": 600}, {**MOVES[1], "distance_mm": -600}], "moves"),
        ("300:250:2500:2500:0.2:x;-300:250:2500:2500", "moves.0.moving_mass_kg"),
    ],
    ids=["speed", "zero-distance", "direction", "unknown", "open", "span", "text"],
)
def test_a_bad_move_is_refused_by_its_index_and_field(
    client: TestClient, moves: Any, field: str
) -> None:
    body = {"application": {**AXIS, "moves": moves}, "screw": {"catalog_id": "B8000-L10"}}
    response = client.post(f"{API}/evaluate", json=body)
    assert response.status_code == 422, response.text
    assert "application." + field in [d["field"] for d in response.json()["detail"]]


def test_the_share_link_carries_the_moves(client: TestClient) -> None:
    """The select's share link holds the moves as one text; the page it opens reads them
    (no unknown parameter), and the API's GET with the same text gives the same result."""
    posted = client.post(f"{API}/select", json={**AXIS, "moves": MOVES})
    assert posted.status_code == 200, posted.text
    share = posted.json()["share_url"]
    assert parse_qs(urlsplit(share).query)["moves"] == [TEXT]
    page = client.get(share)
    assert page.status_code == 200 and "Unknown parameter" not in page.text
    query = "&".join(f"{k}={v}" for k, v in {**AXIS, "moves": TEXT}.items())
    got = client.get(f"{API}/select?{query}")
    assert got.status_code == 200, got.text
    assert got.json()["candidates"] == posted.json()["candidates"]


def test_a_cycle_of_moves_gives_the_stroke_the_duty_and_ratings_need(client: TestClient) -> None:
    """The moves give the stroke (the span the nut covers), so the inputs that need one
    are read with them: hours a day, a required life and the motor's continuous torque.
    The cycle of MOVES takes 2 x (0.1 + 1.1 + 0.1 + 0.2) = 3 s, so 8 h a day is 9,600
    cycles a day, and the life in years is the one at 9,600 cycles a day."""
    duty = {"required_life_years": 1, "motor_rms_torque_nm": 0.5}
    by_hours = evaluate(client, "B8000-L10", **AXIS, moves=MOVES, hours_per_day=8, **duty)
    by_cycles = evaluate(client, "B8000-L10", **AXIS, moves=MOVES, cycles_per_day=9600, **duty)
    assert by_hours["life"]["years"] == pytest.approx(by_cycles["life"]["years"])
    assert by_hours["life"]["years"][0] > 0.0
    names = {c["name"] for c in by_hours["checks"]}
    assert "motor_rms" in names and names & {"life", "wear_life"}, names


def test_break_away_is_the_hardest_start_of_any_move(client: TestClient) -> None:
    """Tr12x3 in bronze, oiled (lead 3 mm, d2 10.5 mm, 30 deg, mu_s 0.16) with a 1e-4 kg m^2
    rotor, 1 kg each way. Out: 30 N against the motion at 0.1 m/s^2, the most thrust to
    start (30.1 N). Back: 27 N at 1 m/s^2, 28 N to start but ten times the acceleration.
    By hand, the back move's start: tan(lead angle) = 3 / (pi 10.5) = 0.090946, eta_s =
    (cos 15 - 0.16 x 0.090946) / (cos 15 + 0.16 / 0.090946) = 0.349100; the thread 28 x
    0.003 / (2 pi 0.349100) = 0.038300 N m; the screw (9.3079e-6 kg m^2/m x 0.3 m) and
    rotor 1.02792e-4 kg m^2 at 2 pi x 1 / 0.003 rad/s^2, 0.215284 N m: 0.253583 N m, above
    the out move's start and every moving segment."""
    moves = [
        {"distance_mm": 100, "speed_mm_s": 20, "accel_mm_s2": 100, "dwell_s": 0.5,
         "moving_mass_kg": 1, "load_n": 30, "load_direction": "opposes"},
        {"distance_mm": -100, "speed_mm_s": 30, "accel_mm_s2": 1000, "dwell_s": 0.5,
         "moving_mass_kg": 1, "load_n": 27, "load_direction": "opposes"},
    ]  # fmt: skip
    axis = {"load_n": 0, "speed_mm_s": 30, "length_mm": 300, "motor_inertia_kg_m2": 1e-4}
    axis["lubrication"] = "oiled"
    torque = evaluate(client, "Tr12x3-bronze", **axis, moves=moves)["torque"]
    assert torque["breakaway_nm"] == pytest.approx(0.253583, rel=1e-5)
    assert torque["peak_motor_nm"] == torque["breakaway_nm"] > torque["peak_nm"]
    assert torque["peak_segment"] == "starting from rest"


def test_a_thrust_fix_in_a_cycle_of_moves_blames_the_moves_not_the_mass(
    client: TestClient,
) -> None:
    """ZBX8000-L10 fails its PV on a cycle out with 4 kg and 40 N, back with 1.5 kg and
    5 N. Each move carries its own load, so the load input lowers no thrust: the fix says
    the moves' masses and loads exceed the thrust it allows, not the moving mass alone
    (whose m a is 6 N of the 46 N)."""
    moves = [{**SLOW_OUT_FAST_BACK[0], "load_n": 40}, SLOW_OUT_FAST_BACK[1]]
    pv = check(evaluate(client, "ZBX8000-L10", **SLOW_AXIS, moves=moves), "pv")
    assert not pv["passed"]
    assert "the moves' own masses and loads exceed" in pv["fix"]
    assert "moving mass alone" not in pv["fix"]


def test_the_pv_of_a_cycle_is_each_moves_thrust_at_its_own_speed(client: TestClient) -> None:
    """ZBX8000-L10 (thread depth 1.397 mm, PV limit 0.105 MPa m/s): out with 4 kg and 15 N
    at 150 mm/s (900 rpm), 21 N accelerating; back with 1.5 kg and 5 N at 250 mm/s
    (1500 rpm), 8.75 N accelerating. The seed's PV = F n / (180 h): out 21 x 900 /
    (180 x 1.397 mm) = 0.07516 MPa m/s, back 0.0522. The out move's thrust at the back
    move's speed, 0.1253, is no segment of the cycle: the nut passes at 72 %."""
    candidate = evaluate(client, "ZBX8000-L10", **SLOW_AXIS, moves=SLOW_OUT_FAST_BACK)
    assert candidate["pv"]["value_mpa_m_s"] == pytest.approx(21 * 900 / (180 * 1.397e-3) / 1e6)
    pv = check(candidate, "pv")
    assert pv["passed"] and pv["utilization"] == pytest.approx(0.07516 / 0.105, rel=1e-3)
    assert "21 N at 900 rpm" in pv["message"]
    # the point judged is reported: the out move's 21 N at its own 150 mm/s
    assert candidate["pv"]["judged_thrust_n"] == pytest.approx(21.0)
    assert candidate["pv"]["judged_speed_mm_s"] == pytest.approx(150.0)


def test_a_cycle_of_moves_is_offered_no_change_of_an_input_its_moves_replace(
    client: TestClient,
) -> None:
    """A 20 kg lift as two moves at 150 and 300 mm/s on the TR-304 family: the nuts slide
    too fast. The speed input is not the moves' speed, so no change of it is offered (it
    would change nothing); each fix caps every move's speed instead."""
    moves = "500:150:1000:1000:1:20:0:auto;-500:300:1000:1000:1:20:0:auto"
    query = {"orientation": "vertical", "load_n": 0, "speed_mm_s": 150, "length_mm": 700,
             "moves": moves, "family": "TR-304"}  # fmt: skip
    body = client.get(f"{API}/select", params=query).json()
    assert body["counts"]["passed"] == 0
    changed = {key for change in body["summary"]["changes"] for key in change["inputs"]}
    assert not changed & {"speed_mm_s", "accel_mm_s2", "moving_mass_kg", "load_n"}
    nearest = body["rejected"][0]["id"]
    fixes = [c["fix"] for c in evaluate(client, nearest, **query)["checks"] if not c["passed"]]
    sliding = next(f for f in fixes if "larger lead" in f)
    assert sliding.startswith("Run every move at most")


def test_a_torque_fix_names_only_what_the_axis_has_to_lower(client: TestClient) -> None:
    """A pure-inertia axis (no load, 5 kg) on too small a drive: the torque fix offers a
    lower moving mass or acceleration, not a lower load, which is already 0."""
    axis = {"load_n": 0, "moving_mass_kg": 5, "speed_mm_s": 200, "length_mm": 500,
            "stroke_mm": 300, "accel_mm_s2": 5000, "max_torque_nm": 0.01}  # fmt: skip
    fix = check(evaluate(client, "B8000-L10", **axis), "torque")["fix"]
    assert "lower moving mass or acceleration" in fix and "load" not in fix


def test_too_many_cycles_a_day_name_the_moves_they_are_made_of(client: TestClient) -> None:
    """The cycle of MOVES takes 3 s: 30,000 cycles a day would take 90,000 s. The refusal
    speaks of its moves, not of out and back."""
    body = {"application": {**AXIS, "moves": MOVES, "cycles_per_day": 30_000},
            "screw": {"catalog_id": "B8000-L10"}}  # fmt: skip
    response = client.post(f"{API}/evaluate", json=body)
    assert response.status_code == 422
    (detail,) = response.json()["detail"]
    assert detail["field"].endswith("cycles_per_day")
    assert "must be at most 28800: one cycle (its moves, with the dwells)" in detail["message"]


#: A vertical pick-and-place of four moves on B7000-L8 (lead 8 mm, d_p 9.890125 mm,
#: 29 deg Acme, uncoated: mu 0.15 running), the gripper 2 kg down, 5 kg back up, a 20 N
#: pull-out (a weight-like load, fixed) on the slow first 20 mm up.
PICK_AND_PLACE = [
    {"distance_mm": -80, "speed_mm_s": 60, "accel_mm_s2": 600, "dwell_s": 0,
     "moving_mass_kg": 2, "load_n": 0, "load_direction": "fixed"},
    {"distance_mm": -20, "speed_mm_s": 15, "accel_mm_s2": 300, "dwell_s": 0.5,
     "moving_mass_kg": 2, "load_n": 0, "load_direction": "fixed"},
    {"distance_mm": 20, "speed_mm_s": 15, "accel_mm_s2": 300, "dwell_s": 0,
     "moving_mass_kg": 5, "load_n": 20, "load_direction": "fixed"},
    {"distance_mm": 80, "speed_mm_s": 60, "accel_mm_s2": 600, "dwell_s": 1,
     "moving_mass_kg": 5, "load_n": 0, "load_direction": "fixed"},
]  # fmt: skip


def test_the_peak_of_a_cycle_of_more_than_two_moves_is_named_by_its_own_move(
    client: TestClient,
) -> None:
    """The peak of four moves lies in the third one's ramp up, and is named so (the
    names of out and back alone, six segments for twelve, failed on the ninth).

    By hand: move 3 accelerates 5 kg at 0.3 m/s^2 against its 5 x 9.80665 = 49.03325 N
    weight and the 20 N: 70.53325 N. tan(lead angle) = 8 / (pi 9.890125) = 0.257479,
    eta = (cos 14.5 - 0.15 x 0.257479) / (cos 14.5 + 0.15 / 0.257479) = 0.599414; the
    thread 70.53325 x 0.008 / (2 pi 0.599414) = 0.149822 N m; the screw (2.47e-7 kg m^2
    per inch x 400 / 25.4) and the rotor's 68 g cm^2, 1.068976e-5 kg m^2, at 2 pi 0.3 /
    0.008 = 235.619 rad/s^2: 0.002519 N m; 0.152341 N m. The fast move up (4) needs
    (52.03325 x 0.0021241 + 1.068976e-5 x 471.239 =) 0.115563 N m, each move down less."""
    axis = {"orientation": "vertical", "load_n": 0, "speed_mm_s": 60, "length_mm": 400,
            "motor": "sy42sth47-1684b"}  # fmt: skip
    torque = evaluate(client, "B7000-L8", **axis, moves=PICK_AND_PLACE)["torque"]
    assert torque["peak_nm"] == pytest.approx(0.152341, rel=1e-5)
    assert torque["peak_segment"] == "accelerating up, move 3"


def test_the_peak_of_a_cycle_names_the_direction_its_move_runs(client: TestClient) -> None:
    """Two moves out, one back (horizontal, 10 kg on guides of friction 0.003, B7000-L8):
    the peak is the second move's ramp up, 10 x 1 + 0.003 x 10 x 9.80665 + 50 = 60.294 N
    out (the thread at running friction, above the break-away at static friction), not a
    move back (the out-and-back names put the fourth moving segment on the way back)."""
    moves = [
        {"distance_mm": 300, "speed_mm_s": 400, "accel_mm_s2": 2000, "decel_mm_s2": 3000,
         "dwell_s": 0.2, "moving_mass_kg": 10, "load_n": 15, "load_direction": "opposes"},
        {"distance_mm": 100, "speed_mm_s": 100, "accel_mm_s2": 1000, "dwell_s": 5,
         "moving_mass_kg": 10, "load_n": 50, "load_direction": "opposes"},
        {"distance_mm": -400, "speed_mm_s": 500, "accel_mm_s2": 2500, "dwell_s": 10,
         "moving_mass_kg": 10, "load_n": 0, "load_direction": "opposes"},
    ]  # fmt: skip
    axis = {"load_n": 0, "speed_mm_s": 500, "length_mm": 600, "guide_friction": 0.003}
    candidate = evaluate(client, "B7000-L8", **axis, moves=moves)
    assert candidate["peak_axial_load_n"] == pytest.approx(60.2941995)
    assert candidate["torque"]["peak_segment"] == "accelerating out, move 2"


def test_a_move_without_its_own_mass_load_or_dwell_carries_the_axiss(
    client: TestClient,
) -> None:
    """A move's dwell, mass, load and load direction left out are the axis's scalar
    inputs: the cycle out and back over 300 mm given as two bare moves (distance, speed,
    ramps) is the axis's own out and back over a 300 mm stroke, number for number (it
    was judged at no load and no mass: a 5 kN axis passed on B6000-L10-TFE at 0 N)."""
    axis = {"load_n": 5000, "moving_mass_kg": 8, "speed_mm_s": 50, "length_mm": 500,
            "accel_mm_s2": 500, "dwell_s": 0.3, "load_direction": "opposes"}  # fmt: skip
    bare = "300:50:500;-300:50:500"
    by_moves = evaluate(client, "B6000-L10-TFE", **axis, moves=bare)
    by_stroke = evaluate(client, "B6000-L10-TFE", **axis, stroke_mm=300)
    assert by_moves["axial_load_n"] == by_stroke["axial_load_n"] == 5000
    # the same torques; the peak's segment named by its move ("move 1") in a cycle of moves
    same = [k for k in by_stroke["torque"] if k != "peak_segment"]
    assert [by_moves["torque"][k] for k in same] == [by_stroke["torque"][k] for k in same]
    assert by_moves["utilization"] == by_stroke["utilization"]
    assert not by_moves["passed"] and by_moves["governing_check"] == "pv"
    # a value a move gives is its own: no load back (0 N), the mass alone moved
    own = evaluate(client, "B6000-L10-TFE", **axis, moves="300:50:500;-300:50:500::::0")
    assert own["torque"]["rms_nm"] < by_moves["torque"]["rms_nm"]
