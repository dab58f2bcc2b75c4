"""POST /api/v1/machine: stacked axes sized together, the top axis first."""

import json
from typing import Any

import pytest
from fastapi.testclient import TestClient

from tests.machine_axes import X, Z

JSON = {"content-type": "application/json"}


def printer(**z: Any) -> dict[str, Any]:
    return {
        "axes": [
            {"name": "Z", "inputs": Z, "frame_kg": 0.3, "motor_kg": 0.4, **z},
            {"name": "X", "inputs": X, "frame_kg": 0.5, "motor_kg": 0.4},
            {"name": "Y", "inputs": {**X, "moving_mass_kg": 0.5}, "motor_kg": 0.4},
        ]
    }


def test_a_printer_gantry_is_sized_top_down(client: TestClient) -> None:
    r = client.post("/api/v1/machine", json=printer())
    assert r.status_code == 200
    z, x, y = r.json()["axes"]
    assert [a["name"] for a in (z, x, y)] == ["Z", "X", "Y"]
    assert z["total_kg"] == pytest.approx(0.5 + 0.3 + 0.4 + z["screw_kg"], rel=1e-12)
    assert x["carried_kg"] == pytest.approx(z["total_kg"], rel=1e-12)
    assert x["sized_mass_kg"] == pytest.approx(0.8 + z["total_kg"], rel=1e-12)
    assert y["carried_kg"] == pytest.approx(x["total_kg"], rel=1e-12)
    for a in (z, x, y):
        assert a["chosen"]["id"] == a["candidates"][0]["id"] and a["passed"] > 0
        assert f"moving_mass_kg={a['sized_mass_kg']:g}"[:18] in a["share_url"]
    assert r.json()["moved_kg"] == pytest.approx(y["sized_mass_kg"], rel=1e-12)


def test_the_axis_share_link_reproduces_its_choice(client: TestClient) -> None:
    x = client.post("/api/v1/machine", json=printer()).json()["axes"][1]
    page = client.get(x["share_url"])
    assert page.status_code == 200 and x["chosen"]["id"] in page.text


def test_choosing_another_z_screw_changes_what_x_carries(client: TestClient) -> None:
    first = client.post("/api/v1/machine", json=printer()).json()["axes"]
    other = first[0]["candidates"][-1]["id"]
    second = client.post("/api/v1/machine", json=printer(choice=other)).json()["axes"]
    assert second[0]["chosen"]["id"] == other
    change = second[0]["screw_kg"] - first[0]["screw_kg"]
    assert second[1]["carried_kg"] - first[1]["carried_kg"] == pytest.approx(change, rel=1e-9)


def test_a_bad_machine_is_refused_by_field(client: TestClient) -> None:
    r = client.post("/api/v1/machine", json=printer(choice="Tr99x1-gold"))
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "axes.0.choice"
    four = printer()
    four["axes"].append(four["axes"][-1])
    assert client.post("/api/v1/machine", json=four).status_code == 422
    bad = printer()
    bad["axes"][1]["inputs"] = {**X, "speed_mm_s": -1}
    r = client.post("/api/v1/machine", json=bad)
    assert r.status_code == 422 and "speed_mm_s" in str(r.json()["detail"])


def test_an_axis_share_link_carries_its_moves_with_the_mass_above(client: TestClient) -> None:
    moves = "300:100:1000:1000:0.2:1:0:auto;-300:100:1000:1000:0.2:0.5:0:auto"
    body = printer()
    body["axes"][1]["inputs"] = {**X, "moves": moves}
    r = client.post("/api/v1/machine", json=body)
    assert r.status_code == 200
    z, x = r.json()["axes"][:2]
    page = client.get(x["share_url"])
    assert page.status_code == 200 and x["chosen"]["id"] in page.text
    assert f"{1 + z['total_kg']!r}"[:8] in x["share_url"]


def test_an_upper_axis_of_moves_hands_down_its_heaviest_moves_mass(client: TestClient) -> None:
    """Z given as moves, down empty-handed with 2 kg and up with a 3 kg part (its scalar
    moving mass left at 0): Z is sized with 3 kg and X carries those 3 kg with Z's frame,
    motor and screw; the bottom axis moves its own 0.8 kg and all that."""
    moves = "-150:10:200:200:0.5:2:0:auto;150:10:200:200:0.5:3:0:auto"
    body = printer()
    body["axes"][0]["inputs"] = {**Z, "moving_mass_kg": 0, "moves": moves}
    body["axes"] = body["axes"][:2]
    r = client.post("/api/v1/machine", json=body)
    assert r.status_code == 200, r.text
    z, x = r.json()["axes"]
    assert z["sized_mass_kg"] == pytest.approx(3.0, rel=1e-12)
    assert z["total_kg"] == pytest.approx(3.0 + 0.3 + 0.4 + z["screw_kg"], rel=1e-12)
    assert x["carried_kg"] == pytest.approx(z["total_kg"], rel=1e-12)
    assert r.json()["moved_kg"] == pytest.approx(0.8 + z["total_kg"], rel=1e-12)


def test_each_axis_gives_its_energy_per_cycle_from_the_output_table(client: TestClient) -> None:
    """The machine's energy figures are the chosen screw's own, as the select call gives
    them (the output table's energy rows), and balance: motor work - braking = work on
    the load + thread and drag losses."""
    z = client.post("/api/v1/machine", json=printer()).json()["axes"][0]
    e = z["energy_j"]
    alone = client.post(
        "/api/v1/evaluate?detail=full",
        json={"application": Z, "screw": {"catalog_id": z["chosen"]["id"]}},
    ).json()["candidate"]
    for key, value in e.items():
        assert value == pytest.approx(alone[key], rel=1e-12, abs=1e-15) if value else True
    drive = e["cycle_motor_work_j"] - e["cycle_regen_j"]
    losses = e["cycle_load_work_j"] + e["cycle_thread_loss_j"] + e["cycle_drag_loss_j"]
    assert drive == pytest.approx(losses, rel=1e-9)
    assert z["verdict"].startswith(("Governed", "Passes", "Fails"))


def test_an_axiss_library_motor_brings_its_curves_provenance(client: TestClient) -> None:
    """X's 17HS19-2004S1 curve is drawn at the library's assumed 24 V drive: where it
    governs an axis's candidate, the limit is assumed, as on the selector."""
    axis = {**X, "moving_mass_kg": 6, "speed_mm_s": 200, "accel_mm_s2": 3000, "lead_mm": 8}
    r = client.post("/api/v1/machine", json={"axes": [{"name": "X", "inputs": axis}]})
    found = [c for c in r.json()["axes"][0]["candidates"] if c["governing_check"] == "motor_curve"]
    assert found and all(c["governing_limit_provenance"] == "assumed" for c in found)


def test_a_machines_own_bad_values_are_named_by_axis(client: TestClient) -> None:
    """A frame mass of NaN is not a finite number (not "at most 10000"); an unknown motor
    on an axis is refused on that axis's input; two axes of one name are refused (the
    answer names the governing axis by its name)."""
    nan = printer()
    nan["axes"][1]["frame_kg"] = float("nan")
    r = client.post("/api/v1/machine", content=json.dumps(nan), headers=JSON)
    assert r.status_code == 422
    (detail,) = r.json()["detail"]
    assert detail["field"] == "axes.1.frame_kg" and "finite" in detail["message"]
    motor = printer()
    motor["axes"][1]["inputs"] = {**X, "motor": "nope"}
    r = client.post("/api/v1/machine", json=motor)
    assert r.status_code == 422
    assert r.json()["detail"][0]["field"] == "axes.1.inputs.motor"
    twice = printer()
    twice["axes"][1]["name"] = "z"
    r = client.post("/api/v1/machine", json=twice)
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "axes"
    assert "Z, z repeats" in r.json()["detail"][0]["message"]
    blank = printer()
    blank["axes"][1]["name"] = "  "
    r = client.post("/api/v1/machine", json=blank)
    assert r.status_code == 422 and r.json()["detail"][0]["field"] == "axes.1.name"


def test_an_empty_choice_is_the_first_ranked_as_on_the_page(client: TestClient) -> None:
    """The page sends an empty choice for an axis left to its first-ranked screw: so may
    the API, with the same answer as no choice."""
    given = client.post("/api/v1/machine", json=printer(choice="")).json()
    plain = client.post("/api/v1/machine", json=printer()).json()
    assert given["axes"][0]["chosen"]["id"] == plain["axes"][0]["chosen"]["id"]


def test_a_vertical_axis_under_a_vertical_one_is_told_the_thrust_it_leaves_out(
    client: TestClient,
) -> None:
    """Z (0.5 kg, 200 mm/s^2, no load) on a vertical lift: Z's thrust beyond its weight,
    0.5 kg x 0.2 m/s^2 = 0.1 N, reaches the lift's nut when both move; X, horizontal
    under Z, takes it in its guides (0 N)."""
    lift = {**Z, "moving_mass_kg": 0.2, "lead_mm": None}
    body = {"axes": [{"name": "Z", "inputs": Z}, {"name": "L", "inputs": lift}]}
    z, low = client.post("/api/v1/machine", json=body).json()["axes"]
    assert (z["parallel"], z["parallel_thrust_n"]) == ([], 0.0)
    assert low["parallel"] == ["Z"] and low["parallel_thrust_n"] == pytest.approx(0.1, rel=1e-12)
    x = client.post("/api/v1/machine", json=printer()).json()["axes"][1]
    assert (x["parallel"], x["parallel_thrust_n"]) == ([], 0.0)


def test_a_vertical_lift_is_sized_and_linked_with_the_load_standing_on_it(
    client: TestClient,
) -> None:
    """Z (vertical, a 100 N load acting as a weight) on a vertical lift L: Z's load stands
    on L's nut whether either moves, so L is sized and linked with 100 N acting down on
    top of the mass it carries; what Z passes beyond that when both move is its m a,
    0.5 kg x 0.2 m/s^2 = 0.1 N. L answers as the single axis of those inputs does."""
    lift = {**Z, "moving_mass_kg": 0.2, "lead_mm": None}
    body = {"axes": [{"name": "Z", "inputs": {**Z, "load_n": 100}}, {"name": "L", "inputs": lift}]}
    z, low = client.post("/api/v1/machine", json=body).json()["axes"]
    assert z["standing_load_n"] == 0.0 and low["standing_load_n"] == 100.0
    assert low["parallel_thrust_n"] == pytest.approx(0.1, rel=1e-9)
    alone = {**lift, "moving_mass_kg": low["sized_mass_kg"], "load_n": 100}
    alone["load_direction"] = "fixed"
    single = client.post("/api/v1/select", json=alone).json()["candidates"][0]
    assert single["id"] == low["chosen"]["id"]
    assert single["torque"] == low["chosen"]["torque"]
    assert "load=100" in low["share_url"] and "load_direction=fixed" in low["share_url"]
    page = client.get(low["share_url"])
    assert page.status_code == 200 and low["chosen"]["id"] in page.text


def test_a_lift_whose_friction_opposes_its_motion_still_carries_the_press_above(
    client: TestClient,
) -> None:
    """Z presses 3000 N down (a load acting one way) on a vertical W whose own 20 N of
    friction opposes its motion: the 3000 N stands on W's nut all the time, so W is sized
    with 3020 N up and 2980 N down (W's friction against each move). It was sized with
    the 20 N alone, and passed a ball screw rated about a week at this duty. Its share
    link carries the two moves and reproduces the choice, and W of those moves alone is
    the same answer."""
    z = {
        "load_n": 3000, "speed_mm_s": 100, "length_mm": 400, "stroke_mm": 300,
        "cycles_per_day": 2000, "required_life_years": 5, "moving_mass_kg": 10,
        "orientation": "vertical", "family": ["HIWIN-ROLLED"], "brake_torque_nm": 10,
    }  # fmt: skip
    w = {**z, "load_n": 20, "load_direction": "opposes", "length_mm": 600, "stroke_mm": 400}
    axes = [{"name": "Z", "inputs": z, "frame_kg": 5}, {"name": "W", "inputs": w}]
    low = client.post("/api/v1/machine", json={"axes": axes}).json()["axes"][1]
    assert low["standing_load_n"] == 3000.0
    moves = "400:100:1000:1000:::3020:fixed;-400:100:1000:1000:::2980:fixed"
    alone = {**w, "moving_mass_kg": low["sized_mass_kg"], "moves": moves}
    single = client.post("/api/v1/select", json=alone).json()["candidates"][0]
    assert single["id"] == low["chosen"]["id"] and single["torque"] == low["chosen"]["torque"]
    # the ball screw the 20 N alone let through fails its life at the 3000 N standing load
    assert low["chosen"]["id"] != "R12-05K4-FSCDIN"
    evaluated = client.post(
        "/api/v1/evaluate", json={"application": alone, "screw": {"catalog_id": "R12-05K4-FSCDIN"}}
    ).json()
    assert evaluated["candidate"]["passed"] is False
    assert "3020" in low["share_url"] and "2980" in low["share_url"]
    page = client.get(low["share_url"])
    assert page.status_code == 200 and low["chosen"]["id"] in page.text


def test_axes_of_bare_moves_take_their_mass_and_load_from_the_axis(client: TestClient) -> None:
    """Moves that leave out their mass and load (a share link's moves, as the page writes
    them from empty cells) are the axis's: X of bare moves under Z carries Z as X's own
    stroke does, and a lift of bare moves under Z with a 100 N load stands that load on
    its nut. Both were answered with a 500 (the mass above added to a move's None)."""
    bare = "300:100:1000;-300:100:1000"
    by_moves = printer()
    by_moves["axes"][1]["inputs"] = {**X, "moves": bare}
    r = client.post("/api/v1/machine", json=by_moves)
    assert r.status_code == 200, r.text
    x_moves = r.json()["axes"][1]
    x_stroke = client.post("/api/v1/machine", json=printer()).json()["axes"][1]
    assert x_moves["carried_kg"] == x_stroke["carried_kg"] > 0
    assert x_moves["sized_mass_kg"] == pytest.approx(x_stroke["sized_mass_kg"], rel=1e-12)
    assert x_moves["chosen"]["id"] == x_stroke["chosen"]["id"]
    assert client.get(x_moves["share_url"]).status_code == 200
    lift = {**Z, "moving_mass_kg": 0.2, "lead_mm": None, "moves": "150:10:200;-150:10:200"}
    body = {"axes": [{"name": "Z", "inputs": {**Z, "load_n": 100}}, {"name": "L", "inputs": lift}]}
    r = client.post("/api/v1/machine", json=body)
    assert r.status_code == 200, r.text
    low = r.json()["axes"][1]
    assert low["standing_load_n"] == 100.0
    page = client.get(low["share_url"])
    assert page.status_code == 200 and low["chosen"]["id"] in page.text
