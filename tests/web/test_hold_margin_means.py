"""The power-off hold's answer on the results row, "margin M× (means)": the margin is the
margin of the means it names. It was the larger of the thread's and the brake's under the
name of the one that holds: a thread self-locking at 1.57× read "margin 241.52×
(self-locking)" (the 0.5 N m brake's), and a 0.001 N m brake at 0.48× read "margin 0.92×
(brake)" (the thread's)."""

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

#: 2 kg held on a vertical axis, with a brake of ``brake_torque_nm``.
HELD = {"load_n": 0, "moving_mass_kg": 2, "orientation": "vertical", "speed_mm_s": 50,
        "length_mm": 400, "hold_power_off": True, "holding_source": "brake"}  # fmt: skip
PAGE = {"load": "0", "moving_mass_kg": "2", "orientation": "vertical", "speed": "50",
        "length": "400", "holding_source": "brake"}  # fmt: skip


def _evaluate(client: TestClient, screw: str, brake_nm: float) -> dict:
    query = {**HELD, "brake_torque_nm": brake_nm, "catalog_id": screw}
    return client.get("/api/v1/evaluate", params=query).json()["candidate"]


def test_a_self_locking_thread_answers_with_its_own_margin(client: TestClient) -> None:
    """Tr8x1.5-ptfe self-locks (lead_max / lead = pi x 7.25 x 0.5 x 0.15 / cos 15 deg /
    1.5 = 1.179, at half its static friction 0.15) beside a 0.5 N m brake that would hold
    it many times over: the thread holds, at its margin."""
    c = _evaluate(client, "Tr8x1.5-ptfe", 0.5)
    thread = c["max_self_locking_lead_with_margin_mm"] / c["lead_mm"]
    assert thread == pytest.approx(1.179, abs=1e-3)
    assert (c["holds_by"], c["holds_power_off"]) == ("thread", True)
    assert c["hold_margin"] == pytest.approx(thread, rel=1e-12)
    page = BeautifulSoup(
        client.get("/", params={**PAGE, "brake_torque": "0.5"}).text, "html.parser"
    )
    row = page.select_one('tbody.candidate[data-id="Tr8x1.5-ptfe"] .hold-answer')
    assert row is not None and row.text == "Holds power-off: yes, margin 1.18× (self-locking)"


def test_a_brake_too_weak_answers_with_its_margin_not_the_threads(client: TestClient) -> None:
    """B10000-L2 does not self-lock (the thread's 0.92); the 0.001 N m brake holds 0.48 of
    the torque it must: the answer is no, at the brake's margin."""
    c = _evaluate(client, "B10000-L2", 0.001)
    thread = c["max_self_locking_lead_with_margin_mm"] / c["lead_mm"]
    brake = 0.001 / c["holding_torque"]["brake_to_fit_nm"]
    assert thread == pytest.approx(0.917, abs=1e-3) and brake == pytest.approx(0.477, abs=1e-3)
    assert (c["holds_by"], c["holds_power_off"]) == ("brake", False)
    assert c["hold_margin"] == pytest.approx(brake, rel=1e-12)


def test_a_thread_that_does_not_hold_without_a_brake_is_no_on_versus(
    client: TestClient,
) -> None:
    """No brake torque given: a ball screw's thread does not hold, its margin is the
    thread's, and the versus page answers no for it (and yes for the leadscrew that
    self-locks)."""
    versus = client.get("/api/v1/versus", params=HELD).json()["sides"]
    ball = versus[1]["candidate"]
    assert (ball["holds_by"], ball["holds_power_off"]) == ("thread", False)
    thread = ball["max_self_locking_lead_with_margin_mm"] / ball["lead_mm"]
    assert ball["hold_margin"] == pytest.approx(thread, rel=1e-12)
    page = BeautifulSoup(client.get("/versus", params=PAGE).text, "html.parser")
    cells = [td.text for td in page.select('tr[data-row="holds_power_off"] td')]
    assert cells == ["yes: the thread self-locks", "no: a brake is needed"]
