"""Ball screws rated no better than their maker, HIWIN GmbH, Ballscrews & Accessories,
BS-08-2-EN-1704-K, rates them (the families under catalog/hiwin/)."""

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


def test_a_short_stroke_carries_the_whole_first_band_of_its_class(client: TestClient) -> None:
    """R12-05K4-FSCDIN, rolled T7, over a 100 mm stroke against 0.05 mm: HIWIN Table 3.3
    v300p = 52 um is the variation allowed within any 300 mm, not a rate, so the 100 mm
    carry all of it (ISO 3408-3 transport rule, at least v300p; Steinmeyer's rolled T7,
    52 um up to 315 mm), with the nut's 0.02 mm play (Table 4.4): 0.072 mm, a fail. Taken
    as 52 x 100 / 300 = 17.3 um it passed at 0.0373 mm."""
    check = _check(
        client,
        "accuracy",
        catalog_id="R12-05K4-FSCDIN",
        load_n=200,
        speed_mm_s=100,
        length_mm=300,
        stroke_mm=100,
        positioning_tolerance_mm=0.05,
    )
    assert check["screw"]["accuracy"]["lead_error_mm"] == pytest.approx(0.052)
    assert check["value"] == pytest.approx(0.052 + 0.02)
    assert not check["passed"]


@pytest.mark.parametrize(
    ("catalog_id", "stroke_mm", "lead_error_mm"),
    [
        # ISO 3408-3 transport rule, 2 x (600 / 300) x 52 um (HIWIN Table 3.3 v300p)
        pytest.param("R16-05T3-FSIDIN", 600, 2 * 600 / 300 * 0.052, id="rolled-T7-600mm"),
        # HIWIN Table 3.4, T3: 12 um up to 315 mm, 21 um for 800-1000 mm
        pytest.param("R16-16K2-FSC", 100, 0.012, id="ground-T3-100mm"),
        pytest.param("R16-16K2-FSC", 900, 0.021, id="ground-T3-900mm"),
    ],
)
def test_the_lead_error_is_the_limit_deviation_of_the_class(
    client: TestClient, catalog_id: str, stroke_mm: float, lead_error_mm: float
) -> None:
    """The limit deviation e_p of the screw's ISO 3408-3 class over the stroke (HIWIN
    BS-08-2-EN-1704-K sec. 3.5.3): 0.208, 0.012 and 0.021 mm, where the stroke share of
    v300p gave 0.104, 0.004 and 0.036 mm."""
    check = _check(
        client,
        "accuracy",
        catalog_id=catalog_id,
        load_n=100,
        speed_mm_s=100,
        length_mm=stroke_mm + 200,
        stroke_mm=stroke_mm,
        positioning_tolerance_mm=1.0,
    )
    assert check["screw"]["accuracy"]["lead_error_mm"] == pytest.approx(lead_error_mm)
