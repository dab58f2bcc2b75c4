"""The peak-torque cell names the segment the peak occurs in (issue 34, item 5): under a
hard stop the peak is the braking torque of a deceleration, not the torque while
accelerating, and a start from rest (the break-away) is named as such."""

import copy
import json

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

#: 10 kg moved 300 mm at 100 mm/s, started gently (0.1 m/s^2) and stopped hard (20 m/s^2):
#: braking 10 kg at 20 m/s^2 is a 200 N thrust, far above the 10 N load and the 1 N m a
#: of the start, so the peak is a deceleration
HARD_STOP = {
    "load_n": 10,
    "speed_mm_s": 100,
    "length_mm": 500,
    "stroke_mm": 300,
    "accel_mm_s2": 100,
    "decel_mm_s2": 20000,
    "moving_mass_kg": 10,
}
GENTLE = {**HARD_STOP, "accel_mm_s2": 2000, "decel_mm_s2": 2000}


#: the candidates of each body asked for, by its JSON: the hard stop's are read by two tests
ANSWERS: dict[str, list[dict[str, object]]] = {}


def _candidates(client: TestClient, body: dict[str, object]) -> list[dict[str, object]]:
    """The full candidates of ``body`` (up to 100), asked for once per body."""
    key = json.dumps(body, sort_keys=True)
    if key not in ANSWERS:
        response = client.post("/api/v1/select?detail=full", json={**body, "limit": 100})
        assert response.status_code == 200, response.text
        ANSWERS[key] = response.json()["candidates"]
    return copy.deepcopy(ANSWERS[key])


@pytest.mark.parametrize("body", [HARD_STOP, GENTLE, {**HARD_STOP, "orientation": "vertical"}])
def test_the_named_segment_carries_the_peak(client: TestClient, body: dict[str, object]) -> None:
    for c in _candidates(client, body):
        torque = c["torque"]
        assert isinstance(torque, dict)
        where, peak = torque["peak_segment"], torque["peak_motor_nm"]
        if where == "starting from rest":
            assert torque["breakaway_nm"] == pytest.approx(peak, rel=1e-9)
            continue
        word, direction = where.rsplit(" ", 1)
        name = {"accelerating": "accelerate", "decelerating": "decelerate"}.get(word, "constant")
        segments = c["segments"]
        assert isinstance(segments, list)
        (segment,) = [s for s in segments if (s["name"], s["direction"]) == (name, direction)]
        assert abs(segment["torque_nm"]) == pytest.approx(peak, rel=1e-9)


def test_a_hard_stop_peaks_while_decelerating_and_the_cell_says_so(client: TestClient) -> None:
    # a preloaded ball nut's drag (R32-40K2-FSC: about 1.25 N m at the assumed 5 % preload)
    # outweighs the braking thrust through its lead, so its peak is the accelerating one:
    # the premise (the thrust decides) holds for the sliding nuts
    found = [c for c in _candidates(client, HARD_STOP) if c["screw_type"] == "lead"]
    assert {c["torque"]["peak_segment"] for c in found} == {"decelerating out"}  # type: ignore[index]
    query = {
        "load": 10,
        "speed": 100,
        "length": 500,
        "stroke": 300,
        "accel": 100,
        "decel": 20000,
        "moving_mass_kg": 10,
    }
    page = BeautifulSoup(client.get("/", params=query).text, "html.parser")
    cells = page.select("tbody.candidate td .peak-segment")
    assert cells and {cell.text for cell in cells} == {"decelerating out"}
    # the accelerating torque is still shown, on its own line, named as such
    assert all(cell.find_parent("td").select_one(".torque-total") for cell in cells)
