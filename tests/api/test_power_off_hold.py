"""Issue 29, item 8: "must hold with the power off" as one requirement, answered yes or no
with its margin; the catalog's rule of thumb beside the friction calculation, saying which
governs; the surest holds ranked first."""

import math

import pytest
from bs4 import BeautifulSoup
from fastapi.testclient import TestClient

from tests.api.calls import check, evaluate, names

#: 20 kg on a vertical Tr16x4 with an acetal (POM) nut (mu_s 0.20, catalog
#: iso-trapezoidal/common.toml, handbook), d_p = 14 mm, 30-degree thread (a_n = 15 deg).
VERTICAL = {"load_n": 0.0, "moving_mass_kg": 20.0, "orientation": "vertical",
            "speed_mm_s": 50.0, "length_mm": 500.0}  # fmt: skip
COS_15 = math.cos(math.radians(15.0))


def lock_lead_mm(factor: float) -> float:
    """Shigley sec. 8-2: the longest lead that self-locks, pi d_p f mu_s / cos a_n [mm]."""
    return math.pi * 14.0 * factor * 0.20 / COS_15


def test_the_thread_holds_with_its_margin(client: TestClient) -> None:
    """f = 0.5: lead_max = pi x 14 x 0.5 x 0.20 / cos 15 = 4.553 mm, margin 4.553 / 4 =
    1.138: yes, by the thread."""
    c = evaluate(client, "Tr16x4-acetal", **VERTICAL)
    assert lock_lead_mm(0.5) == pytest.approx(4.553, abs=1e-3)
    assert c["holds_power_off"] is True and c["holds_by"] == "thread"
    assert c["hold_margin"] == pytest.approx(lock_lead_mm(0.5) / 4.0, rel=1e-9)
    assert check(c, "back_driving")["passed"]


def test_a_thin_margin_is_a_no_and_a_fail(client: TestClient) -> None:
    """f = 0.4: lead_max = 3.642 mm < 4 mm, margin 0.911: no, and the check fails."""
    c = evaluate(client, "Tr16x4-acetal", **VERTICAL, self_locking_friction_factor=0.4)
    assert c["hold_margin"] == pytest.approx(lock_lead_mm(0.4) / 4.0, rel=1e-9)
    assert c["hold_margin"] == pytest.approx(0.9106, abs=1e-4)
    assert c["holds_power_off"] is False and not c["passed"]
    assert not check(c, "back_driving")["passed"]


def test_a_brake_answers_with_its_own_margin(client: TestClient) -> None:
    """f = 0.4 and a 0.3 N m brake: the thread's 0.911 is not enough, the brake's margin is
    0.3 N m over the torque needed (the larger of the seed's and the friction's at f mu_s,
    times a brake's service factor 1.5 where no holding factor is given)."""
    c = evaluate(
        client, "Tr16x4-acetal", **VERTICAL, self_locking_friction_factor=0.4, brake_torque_nm=0.3
    )
    needed = c["holding_torque"]["brake_nm"]
    assert needed > 0.0
    assert c["holds_by"] == "brake" and c["holds_power_off"] is True
    assert c["hold_margin"] == pytest.approx(0.3 / (1.5 * needed), rel=1e-9)


def test_no_requirement_no_answer_and_no_check(client: TestClient) -> None:
    """hold_power_off false: the energised motor holds; the back-driving check and the
    answer are left out (the thread that would fail at f = 0.4 is no longer rejected)."""
    c = evaluate(
        client, "Tr16x4-acetal", **VERTICAL, self_locking_friction_factor=0.4,
        hold_power_off=False,
    )  # fmt: skip
    assert c["holds_power_off"] is None and c["hold_margin"] is None
    assert "back_driving" not in names(c)


def test_nothing_held_nothing_to_answer(client: TestClient) -> None:
    """A horizontal axis whose load opposes the motion holds nothing at rest."""
    c = evaluate(client, "Tr16x4-acetal", load_n=50.0, speed_mm_s=50.0, length_mm=500.0)
    assert c["holds_power_off"] is None and c["holds_by"] is None


def test_a_load_of_fixed_direction_on_a_horizontal_axis_is_held_back_not_down(
    client: TestClient,
) -> None:
    """A spring or a press on a horizontal axis (``load_direction`` fixed) is held at rest
    like a weight: the same check, named for a load held at rest (it said "vertical
    axis"), which drives the screw back, not down. Tr16x4-acetal self-locks with its
    margin (lead_max 4.553 mm); Tr16x8(P4) (two-start) does not."""
    held = {"load_n": 200.0, "load_direction": "fixed", "speed_mm_s": 50.0, "length_mm": 500.0}
    locks, slips = (
        evaluate(client, "Tr16x4-acetal", **held),
        evaluate(client, "Tr16x8(P4)-acetal", **held),
    )
    assert locks["holds_by"] == "thread" and slips["holds_power_off"] is False
    for c in (locks, slips):
        found = check(c, "back_driving")
        assert found["label"] == "Self-locking (load held at rest, no brake)"
        assert "drive the screw back" in found["message"] and "down" not in found["message"]
    vertical = check(evaluate(client, "Tr16x8(P4)-acetal", **VERTICAL), "back_driving")
    assert "drive the screw down" in vertical["message"]


def test_the_rule_of_thumb_says_which_governs(client: TestClient) -> None:
    """Tr16x4: lead 4 mm is not under OD / 8 = 2 mm, so the catalog's rule says it
    back-drives, while friction at 0.5 x 0.20 holds it: the row says the friction
    calculation governs. Where they agree (f = 0.4: both say it back-drives) it is silent."""
    c = evaluate(client, "Tr16x4-acetal", **VERTICAL)
    assert not c["seed_rule_no_backdrive"] and c["holds_power_off"]
    assert "governs" in c["holding_rule"] and "back-drives" in c["holding_rule"]
    agree = evaluate(client, "Tr16x4-acetal", **VERTICAL, self_locking_friction_factor=0.4)
    assert agree["holding_rule"] is None


def test_surest_holds_rank_first(client: TestClient) -> None:
    """With the requirement (the default), the passing screws whose thread alone holds
    come first, each group in the torque's order; without it the order is the torque's.
    With a brake of 2 N m the long leads hold only by the brake: they come after."""
    held = client.post("/api/v1/select", params={"detail": "full"}, json={**VERTICAL, "limit": 30})
    rows = held.json()["candidates"]
    assert len(rows) == 30 and all(c["hold_margin"] >= 1.0 for c in rows)
    by_thread = [c["holds_by"] == "thread" for c in rows]
    assert by_thread == sorted(by_thread, reverse=True)
    torques = [c["torque"]["total_nm"] for c in rows if c["holds_by"] == "thread"]
    assert torques == sorted(torques)
    braked = client.post(
        "/api/v1/select", params={"detail": "full"},
        json={**VERTICAL, "limit": 100, "brake_torque_nm": 2.0},
    ).json()["candidates"]  # fmt: skip
    on_brake = [c["holds_by"] != "thread" for c in braked]
    assert any(on_brake) and not on_brake[0] and on_brake == sorted(on_brake)
    free = client.post(
        "/api/v1/select", params={"detail": "full"},
        json={**VERTICAL, "limit": 30, "hold_power_off": False},
    ).json()["candidates"]  # fmt: skip
    torques = [c["torque"]["total_nm"] for c in free]  # no stroke: the torque shown
    assert torques == sorted(torques)
    assert {c["hold_margin"] for c in free} == {None}


def test_the_results_row_answers_and_says_which_governs(client: TestClient) -> None:
    """On the page each row of a vertical axis answers yes or no with its margin; where
    the rule of thumb disagrees the row says the friction calculation governs. Answered
    "no" (the energised motor holds), the rows carry no answer."""
    page = {"load": "0", "moving_mass_kg": "20", "orientation": "vertical", "speed": "50",
            "length": "500"}  # fmt: skip
    rows = BeautifulSoup(client.get("/", params=page).text, "html.parser")
    answers = [a.text for a in rows.select("td.backdrive .hold-answer")]
    assert answers and all(a.startswith("Holds power-off: yes, margin ") for a in answers)
    notes = [n.text for n in rows.select("td.backdrive .rule-note")]
    assert notes and all("friction calculation governs" in n for n in notes)
    off = client.get("/", params={**page, "hold_power_off": "false"}).text
    assert BeautifulSoup(off, "html.parser").select("td.backdrive .hold-answer") == []


def test_a_slower_move_is_offered_where_the_nearest_screws_cannot_hold(
    client: TestClient,
) -> None:
    """8 kg lifted at 100 mm/s (1 m/s^2, 300 mm stroke) by a NEMA 17 stepper
    (17HS19-2004S1), held with the power off: no screw passes. The nearest fail on the
    screw itself (a lead too coarse to self-lock, or a torque the curve does not give at
    any speed); the fine leads that self-lock are further off, failing the motor curve at
    their high rpm, and a slower move admits them. The summary offers that speed,
    verified: at it, screws pass."""
    body = {"load_n": 0, "moving_mass_kg": 8, "orientation": "vertical", "speed_mm_s": 100,
            "length_mm": 400, "stroke_mm": 300, "accel_mm_s2": 1000,
            "motor": "17hs19-2004s1", "hold_power_off": True}  # fmt: skip
    r = client.post("/api/v1/select", json=body)
    assert r.status_code == 200, r.text
    summary = r.json()["summary"]
    assert r.json()["counts"]["passed"] == 0
    remedy = summary["remedies"][0]
    assert set(remedy["inputs"]) == {"speed_mm_s"} and remedy["passing"] > 0
    assert "reduce the linear speed to" in summary["message"]
    slower = client.post(
        "/api/v1/select", json={**body, **remedy["inputs"]}, params={"detail": "full"}
    ).json()
    assert slower["counts"]["passed"] == remedy["passing"]
    assert all(c["holds_power_off"] for c in slower["candidates"])
    for change in summary["changes"]:
        again = {**body, **change["inputs"]}
        admitted = client.post(
            "/api/v1/evaluate",
            json={"application": again, "screw": {"catalog_id": change["admits"]}},
        ).json()
        assert admitted["candidate"]["passed"], change
