"""Ball screws rated no better than their maker, HIWIN GmbH, Ballscrews & Accessories,
BS-08-2-EN-1704-K, rates them (the families under catalog/hiwin/)."""

import math

import pytest
from fastapi.testclient import TestClient


def _check(client: TestClient, name: str, **params: object) -> dict:  # type: ignore[type-arg]
    r = client.get("/api/v1/evaluate", params=params)
    assert r.status_code == 200, r.text
    candidate = r.json()["candidate"]
    return next(c for c in candidate["checks"] if c["name"] == name) | {"screw": candidate}


def test_a_fixed_free_ball_screw_whirls_where_hiwin_says(client: TestClient) -> None:
    """R20-05K4-FSC, 1000 mm, fixed-free, at 48 mm/s (576 rpm). HIWIN F 3.27: n_k =
    2.71e8 x 0.147 x d_k / l_s^2, at most 0.8 n_k: 552 rpm for its 17.32 mm root, so
    576 rpm fails. The beam alone allowed 599 rpm, a pass."""
    check = _check(
        client,
        "critical_speed",
        catalog_id="R20-05K4-FSC",
        load_n=1000,
        speed_mm_s=48,
        length_mm=1000,
        end_fixity="fixed-free",
    )
    d_k = check["screw"]["root_diameter_mm"]
    hiwin = 0.8 * 2.71e8 * 0.147 * d_k / 1000.0**2
    assert check["value"] == 576.0
    assert abs(check["limit"] / hiwin - 1.0) < 0.01
    assert not check["passed"]
    assert "HIWIN's mounting factor" in check["message"]


def test_a_fast_lead_ball_screw_drives_at_most_at_hiwins_efficiency(client: TestClient) -> None:
    """R25-25K2-FSCDIN, an 18.8 degree lead angle: the thread's efficiency at the ball
    track's friction (HIWIN Fig. 2.1, mu 0.01) is 0.968, above the 0.85 to 0.95 HIWIN F
    3.15 gives for the drive torque T_a = F P / (2000 pi eta_1). At most 0.95: 500 N on
    the 25 mm lead needs 500 x 0.025 / (2 pi 0.95) = 2.094 N m (1.8 % more than at 0.968)."""
    r = client.get(
        "/api/v1/evaluate",
        params={"catalog_id": "R25-25K2-FSCDIN", "load_n": 500, "speed_mm_s": 50, "length_mm": 800},
    )
    assert r.status_code == 200, r.text
    screw = r.json()["candidate"]
    assert screw["efficiency"] == 0.95
    assert screw["torque"]["load_nm"] == pytest.approx(500 * 0.025 / (2 * math.pi * 0.95), rel=1e-6)
