"""The compact select gives numbers to 6 significant figures, but a utilisation a hair
past its limit does not round to exactly 1 (at the limit, which passes): a drive whose
maximum is the torque B8000-L10 needs over 1 + 3e-7 failed the torque check at a
utilisation shown as 1.0."""

import pytest
from fastapi.testclient import TestClient

AXIS = {"load_n": 100, "speed_mm_s": 40, "length_mm": 500, "lead_mm": 10, "family": "B"}


def _needed_nm(client: TestClient) -> float:
    query = {**AXIS, "catalog_id": "B8000-L10", "max_torque_nm": 10}
    candidate = client.get("/api/v1/evaluate", params=query).json()["candidate"]
    return float(candidate["torque"]["required_nm"])


@pytest.mark.parametrize("past", [3e-7, -3e-7], ids=["a-hair-past", "a-hair-short"])
def test_a_utilisation_near_its_limit_keeps_its_side(client: TestClient, past: float) -> None:
    drive = _needed_nm(client) / (1.0 + past)
    answer = client.get("/api/v1/select", params={**AXIS, "max_torque_nm": drive, "limit": 100})
    body = answer.json()
    if past > 0:
        (screw,) = [c for c in body["rejected"] if c["id"] == "B8000-L10"]
        (torque,) = [f for f in screw["failed"] if f["name"] == "torque"]
        assert torque["utilization"] > 1.0
    else:
        (screw,) = [c for c in body["candidates"] if c["id"] == "B8000-L10"]
        assert screw["utilization"]["torque"] < 1.0
