"""Ranking by the torque the results show (issue 21, item 6), through the API.

Under a move the table's torque is the peak motor torque of either move or of starting
from rest, rotor included (``torque.peak_motor_nm``); "lowest torque" orders by it, and
"lowest RMS torque" by the cycle's RMS (``torque.rms_nm``). Without a move both order by
the drive torque while accelerating (``torque.total_nm``), the torque shown then."""

from typing import Any

import pytest
from fastapi.testclient import TestClient

#: The pick-and-place axis of issue 21: 0.5 kg at 10 m/s^2 with a NEMA 17 rotor
#: (5.4e-6 kg m^2). Its peak torque and its accelerating torque order differently.
PICK_AND_PLACE = {
    "load_n": 0, "speed_mm_s": 250, "length_mm": 300, "stroke_mm": 200, "accel_mm_s2": 10000,
    "moving_mass_kg": 0.5, "motor_inertia_kg_m2": 5.4e-6, "limit": 100, "advice": "reject",
}  # fmt: skip


def candidates(client: TestClient, **query: Any) -> list[dict[str, Any]]:
    response = client.get("/api/v1/select", params=query)
    assert response.status_code == 200, response.text
    found: list[dict[str, Any]] = response.json()["candidates"]
    assert len(found) > 10
    return found


#: The pick-and-place slower (20 mm/s, 2 m/s^2) with the nuts oiled: the bronze nuts
#: (static friction 0.16 over 0.13 running) pass, and start from rest above their
#: accelerating torque, so the two torques order differently.
SLOW_OILED = {**PICK_AND_PLACE, "speed_mm_s": 20, "accel_mm_s2": 2000, "lubrication": "oiled"}


def test_lowest_torque_orders_by_the_peak_motor_torque_shown(client: TestClient) -> None:
    found = candidates(client, **SLOW_OILED, rank_by="torque")
    peak = [c["torque"]["peak_motor_nm"] for c in found]
    assert peak == sorted(peak)
    accelerating = [c["torque"]["total_nm"] for c in found]
    assert accelerating != sorted(accelerating), "here the two torques order differently"
    assert all(p >= a - 1e-12 for p, a in zip(peak, accelerating, strict=True))


def test_lowest_rms_torque_orders_by_the_rms_shown(client: TestClient) -> None:
    found = candidates(client, **PICK_AND_PLACE, rank_by="rms")
    rms = [c["torque"]["rms_nm"] for c in found]
    assert rms == sorted(rms)
    peak = [c["torque"]["peak_motor_nm"] for c in found]
    assert peak != sorted(peak), "the RMS ranking is not the peak ranking here"


@pytest.mark.parametrize("rank_by", ["torque", "rms"])
def test_without_a_move_both_order_by_the_drive_torque(client: TestClient, rank_by: str) -> None:
    found = candidates(
        client, load_n=50, speed_mm_s=200, length_mm=500, limit=100, advice="reject",
        rank_by=rank_by,
    )  # fmt: skip
    # no move, no RMS torque: the compact form leaves it out
    assert all("rms_nm" not in c["torque"] for c in found)
    total = [c["torque"]["total_nm"] for c in found]
    assert total == sorted(total)


def test_warned_screws_follow_clean_ones_each_part_by_the_peak(client: TestClient) -> None:
    found = candidates(client, **{**PICK_AND_PLACE, "advice": "warn"}, rank_by="torque")
    order = [(bool(c["warned"]), c["torque"]["peak_motor_nm"]) for c in found]
    assert order == sorted(order)


def test_the_retired_advice_rank_reads_as_warn(client: TestClient) -> None:
    """'rank' did what 'warn' does (a warned screw ranks after every clean one) and is no
    longer offered; links and calls that carry it get the 'warn' answer, on the page too.
    Lead 10 mm at 150 mm/s: the seed's traverse table recommends at most 100 mm/s for
    leads of 2.5 to 12 mm, so every seed screw carries a warning (test_axis_physics_api)."""
    axis = {"load_n": 10, "speed_mm_s": 150, "length_mm": 300, "lead_mm": 10, "limit": 30}
    old = client.get("/api/v1/select", params={**axis, "advice": "rank"})
    assert old.status_code == 200, old.text
    warn = client.get("/api/v1/select", params={**axis, "advice": "warn"}).json()
    assert any(c["warned"] for c in warn["candidates"]), "the case has warned screws"
    assert old.json()["candidates"] == warn["candidates"]
    page = {"load": 10, "speed": 150, "length": 300, "lead": 10, "limit": 30}
    assert client.get("/", params={**page, "advice": "rank"}).status_code == 200
    schema = client.get("/openapi.json").json()["components"]["schemas"]["ApplicationIn"]
    assert schema["properties"]["advice"]["enum"] == ["warn", "reject"]


def test_longest_life_orders_ball_screws_by_their_l10_among_the_leadscrews(
    client: TestClient,
) -> None:
    """Ranked by life, each candidate's shown life band orders the list (its low end, in
    travel), a ball nut's L10 life among the leadscrews' wear or rated lives: the ball
    screws, having no rated or wear life, all came last whatever their L10."""
    found = candidates(
        client, load_n=300, speed_mm_s=50, length_mm=500, stroke_mm=300, cycles_per_day=2000,
        limit=100, rank_by="life", detail="full",
    )  # fmt: skip
    lows = [c["life"]["travel_km"][0] for c in found if c.get("life")]
    assert lows == sorted(lows, reverse=True)
    kinds = [c["screw_type"] for c in found if c.get("life")]
    assert kinds[0] == "ball" and "lead" in kinds
    assert [c for c in found if not c.get("life")] == found[len(lows) :]
